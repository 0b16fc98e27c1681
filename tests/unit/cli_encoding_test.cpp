// End to end against POV-Ray itself: flat colors rendered by the installed povray and by glint
// must give identical PNG values under each of POV-Ray 3.7's gamma regimes (assumed_gamma 1,
// assumed_gamma 2.2, #version 3.6 without assumed_gamma, no #version). Skipped without povray.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/image_compare.h"

namespace fs = std::filesystem;

namespace {

// Six boxes side by side, one pixel column pair each, seen by an orthographic camera with
// ambient 1 and no lights: the film value is exactly the pigment value. Covers the sRGB linear
// segment (0.002), mid values, and clipping (1.5).
std::string scene(const std::string& header) {
    std::string s = header + "\n";
    s += "camera { orthographic location <0, 0, -1> look_at <0, 0, 0> right x*6 up y*2 }\n";
    const char* values[] = {"0.002", "0.1", "0.3", "0.5", "0.8", "1.5"};
    for (int i = 0; i < 6; ++i) {
        s += "box { <" + std::to_string(i - 3) + ", -1, 0>, <" + std::to_string(i - 2) +
             ", 1, 1> pigment { rgb <" + values[i] + ", " + values[5 - i] +
             ", 0.25> } finish { ambient 1 diffuse 0 } }\n";
    }
    return s;
}

bool have_povray() { return std::system("command -v povray >/dev/null 2>&1") == 0; }

void check_regime(const std::string& name, const std::string& header) {
    fs::path dir =
        fs::temp_directory_path() / ("glint_encoding_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "s.pov") << scene(header);
    // POV-Ray may only write under its working directory: run it there.
    std::string pov = "cd '" + dir.string() +
                      "' && povray +Is.pov +Opov.png +W12 +H2 -D -A +WT1 -V -GA >pov.log 2>&1";
    ASSERT_EQ(std::system(pov.c_str()), 0) << "povray failed, see " << dir / "pov.log";
    std::string glint = std::string("'") + GLINT_BINARY + "' render '" + (dir / "s.pov").string() +
                        "' -o '" + (dir / "glint.png").string() +
                        "' --width 12 --height 2 --progress=none 2>'" +
                        (dir / "glint.log").string() + "'";
    ASSERT_EQ(std::system(glint.c_str()), 0) << "glint failed, see " << dir / "glint.log";
    glint::io::Rgb8Image a = glint::io::read_rgb8((dir / "glint.png").string());
    glint::io::Rgb8Image b = glint::io::read_rgb8((dir / "pov.png").string());
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    for (size_t i = 0; i < a.rgb.size(); ++i)
        ASSERT_EQ(int(a.rgb[i]), int(b.rgb[i]))
            << name << ": pixel " << i / 3 % a.width << " channel " << i % 3;
    fs::remove_all(dir);
}

}  // namespace

TEST(CliEncoding, AssumedGamma1MatchesPovRay) {
    if (!have_povray()) GTEST_SKIP() << "povray not installed";
    check_regime("g1", "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }");
}

TEST(CliEncoding, AssumedGamma22MatchesPovRay) {
    if (!have_povray()) GTEST_SKIP() << "povray not installed";
    check_regime("g22", "#version 3.7;\nglobal_settings { assumed_gamma 2.2 }");
}

TEST(CliEncoding, Version37WithoutAssumedGammaMatchesPovRay) {
    if (!have_povray()) GTEST_SKIP() << "povray not installed";
    check_regime("v37", "#version 3.7;");
}

TEST(CliEncoding, Version36WithoutAssumedGammaMatchesPovRay) {
    if (!have_povray()) GTEST_SKIP() << "povray not installed";
    check_regime("v36", "#version 3.6;");
}

TEST(CliEncoding, NoVersionMatchesPovRay) {
    // POV-Ray reads a scene without #version as 3.62: gamma handling off.
    if (!have_povray()) GTEST_SKIP() << "povray not installed";
    check_regime("none", "// no #version");
}
