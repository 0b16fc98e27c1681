// The path tracer's extra outputs and the error-against-time report: the variance image on
// pixels whose samples are Bernoulli draws (where s^2 follows from the mean exactly) and
// against a brute-force recomputation, the AOVs of a known sphere, relMSE and the curve
// readings, and `glint report` / `glint render --aov` through the CLI.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/log.h"
#include "io/image_compare.h"
#include "io/plot.h"
#include "render/camera.h"
#include "render/film/driver.h"
#include "render/render.h"
#include "unit/path_test_util.h"

namespace fs = std::filesystem;

namespace glint::render {
namespace {

scene::Material black_with_alpha(double alpha) {
    scene::Material m;
    m.pbr.derived = false;
    m.pbr.base_color = Color(0, 0, 0);
    m.pbr.specular = 0;
    m.pbr.metallic = 0;
    m.pbr.roughness = 1;
    m.pbr.alpha = alpha;
    return m;
}

TEST(PathVariance, BernoulliPixelsGiveTheAnalyticVariance) {
    // A black plane with alpha 0.3 in front of a white background: each sample is 1 (passed
    // through, probability 0.7) or 0. For 0/1 samples the sample variance is n/(n-1) m(1-m)
    // exactly, so the variance of the mean is m(1-m)/(n-1) per pixel and channel.
    scene::Scene s;
    s.camera.location = Vec3(0, 0, -4);
    s.materials.push_back(black_with_alpha(0.3));
    scene::Object o;
    o.shape = scene::Plane{Vec3(0, 0, 1), 0};
    o.material = 0;
    s.objects.push_back(o);
    s.background = scene::ColorFT(Color(1, 1, 1));
    RenderOptions opt = path_test::path_options(8, 6, 20, 8);
    opt.max_depth = 0;  // no bounce off the plane: samples are exactly 0 or 1
    opt.variance = true;
    Diagnostics diag;
    const RenderResult r = render(s, opt, diag);
    ASSERT_EQ(r.samples_per_pixel, 20);
    ASSERT_EQ(r.variance.width, 8);
    ASSERT_EQ(r.variance.height, 6);
    double mean = 0;
    int mixed = 0;
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x)
            for (int c = 0; c < 3; ++c) {
                const double m = r.image.pixel(x, y)[c];
                const double v = r.variance.pixel(x, y)[c];
                EXPECT_NEAR(v, m * (1 - m) / 19.0, 1e-6) << x << "," << y << " mean " << m;
                mean += m / (6 * 8 * 3);
                if (m > 0 && m < 1) ++mixed;
            }
    EXPECT_NEAR(mean, 0.7, 0.03);
    EXPECT_EQ(mixed, 6 * 8 * 3);  // every pixel saw both outcomes: the check is not vacuous
    EXPECT_TRUE(r.albedo.rgba.empty());  // AOVs only when asked for
}

TEST(PathVariance, MatchesBruteForceAndIsThreadIndependent) {
    // A radiance function of the sample id alone, so the test can recompute every pixel's
    // samples and their variance directly (two-pass formula in long double).
    scene::Camera cam;
    auto value = [](const SampleId& id) {
        const uint32_t h = (id.x * 73856093u) ^ (id.y * 19349663u) ^ (id.index * 83492791u);
        return 1000.0 + (h % 1000) / 100.0;  // large offset: a naive sum of squares loses digits
    };
    PathRadianceFn fn = [&](const Ray&, const SampleId& id, FirstHit*) {
        const double v = value(id);
        return Color(v, 2 * v, 0.5);
    };
    const int w = 5, h = 4, spp = 13;
    Camera camera(cam, w, h);
    PathFilm one, two;
    RenderOptions opt = path_test::path_options(w, h, spp, 8);
    opt.variance = true;
    opt.threads = 1;
    ASSERT_EQ(run_path_tiles(camera, opt, fn, &one), spp);
    opt.threads = 2;
    ASSERT_EQ(run_path_tiles(camera, opt, fn, &two), spp);
    EXPECT_EQ(one.variance.rgba, two.variance.rgba);
    EXPECT_EQ(one.image.rgba, two.image.rgba);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            long double sum = 0, sq = 0;
            for (int s = 0; s < spp; ++s) sum += static_cast<float>(value({x, y, uint32_t(s)}));
            const long double m = sum / spp;
            for (int s = 0; s < spp; ++s) {
                const long double d = static_cast<float>(value({x, y, uint32_t(s)})) - m;
                sq += d * d;
            }
            const double expect = static_cast<double>(sq / (spp - 1) / spp);
            const float* v = one.variance.pixel(x, y);
            EXPECT_NEAR(v[0], expect, 1e-5 * expect + 1e-9) << x << "," << y;
            EXPECT_NEAR(v[2], 0.0, 1e-12);  // a constant channel has no variance
        }
}

TEST(PathAov, DepthNormalAlbedoOfAKnownSphere) {
    // Unit sphere at the origin seen from (0, 0, -4): the centre pixel's first hit is the
    // sphere's nearest point, 3 away, normal (0, 0, -1); the corner pixels see nothing.
    scene::Scene s;
    s.camera.location = Vec3(0, 0, -4);
    scene::Material m;
    m.pbr.derived = false;
    m.pbr.base_color = Color(0.2, 0.4, 0.6);
    s.materials.push_back(m);
    scene::Object o;
    o.shape = scene::Sphere{Vec3(0, 0, 0), 1};
    o.material = 0;
    s.objects.push_back(o);
    s.background = scene::ColorFT(Color(0.5, 0.5, 0.5));
    RenderOptions opt = path_test::path_options(41, 31, 4, 8);
    opt.aovs = true;
    Diagnostics diag;
    const RenderResult r = render(s, opt, diag);
    ASSERT_EQ(r.depth.width, 41);
    opt.threads = 1;
    const RenderResult r1 = render(s, opt, diag);
    EXPECT_EQ(r1.depth.rgba, r.depth.rgba);  // the same whatever the thread count
    EXPECT_EQ(r1.normal.rgba, r.normal.rgba);
    EXPECT_EQ(r1.albedo.rgba, r.albedo.rgba);
    const float* d = r.depth.pixel(20, 15);
    const float* n = r.normal.pixel(20, 15);
    const float* a = r.albedo.pixel(20, 15);
    // Within the pixel's footprint (about 1.7 degrees) the distance grows to about 3.006.
    EXPECT_GE(d[0], 3.0f);
    EXPECT_LE(d[0], 3.01f);
    EXPECT_EQ(d[0], d[1]);
    EXPECT_NEAR(n[0], 0.0, 0.03);
    EXPECT_NEAR(n[1], 0.0, 0.03);
    EXPECT_NEAR(n[2], -1.0, 1e-3);
    EXPECT_NEAR(a[0], 0.2, 1e-6);
    EXPECT_NEAR(a[1], 0.4, 1e-6);
    EXPECT_NEAR(a[2], 0.6, 1e-6);
    for (const Image* img : {&r.depth, &r.normal, &r.albedo})
        for (int c = 0; c < 3; ++c) EXPECT_EQ(img->pixel(0, 0)[c], 0.0f);
    // Toward the sphere's right limb the normal turns right (+x), still facing the camera.
    int limb = 20;
    while (limb + 1 < 41 && r.depth.pixel(limb + 1, 15)[0] > 0) ++limb;
    ASSERT_GT(limb, 24);
    ASSERT_LT(limb, 40);
    const float* side = r.normal.pixel(limb - 1, 15);
    EXPECT_GT(side[0], 0.5f);
    EXPECT_LT(side[2], 0.0f);
}

}  // namespace
}  // namespace glint::render

namespace glint::io {
namespace {

TEST(LinearMetrics, IdenticalImagesHaveZeroError) {
    LinearImage a;
    a.width = 3;
    a.height = 2;
    a.rgb = {0, 0.5f, 1, 2, 3, 4, 0.1f, 0.2f, 0.3f, 10, 20, 30, 0, 0, 0, 1, 1, 1};
    const LinearMetrics m = compare_linear(a, a);
    EXPECT_EQ(m.relmse, 0.0);
    EXPECT_EQ(m.rmse, 0.0);
    EXPECT_EQ(m.nonfinite, 0);
}

TEST(LinearMetrics, RelMseFollowsTheFormula) {
    LinearImage r, x;
    r.width = x.width = 1;
    r.height = x.height = 1;
    r.rgb = {0, 1, 0.3f};
    x.rgb = {0.1f, 1.5f, 0.3f};
    const LinearMetrics m = compare_linear(x, r);
    const double d0 = 0.1f * 0.1f / 0.01, d1 = 0.25 / 1.01;
    EXPECT_NEAR(m.relmse, (d0 + d1) / 3, 1e-6);
    EXPECT_NEAR(m.rmse, std::sqrt((0.1f * 0.1f + 0.25) / 3), 1e-6);
}

TEST(CurveReading, PowerLawIsReadExactly) {
    // relMSE = 1/t: between steps and beyond them the log-log line is the power law itself.
    const std::vector<double> t{1, 4, 16}, e{1, 0.25, 0.0625};
    CurveReading r = curve_x_at_y(t, e, 0.5);
    EXPECT_EQ(r.where, CurveReading::Where::Interpolated);
    EXPECT_NEAR(r.value, 2.0, 1e-12);
    r = curve_x_at_y(t, e, 0.01);
    EXPECT_EQ(r.where, CurveReading::Where::Extrapolated);
    EXPECT_NEAR(r.value, 100.0, 1e-9);
    r = curve_x_at_y(t, e, 2);
    EXPECT_EQ(r.where, CurveReading::Where::AtMost);
    EXPECT_EQ(r.value, 1.0);
    r = curve_y_at_x(t, e, 0.5);  // before the first step: no value read off
    EXPECT_EQ(r.where, CurveReading::Where::Before);
    EXPECT_EQ(r.value, 1.0);
    r = curve_y_at_x(t, e, 64);
    EXPECT_EQ(r.where, CurveReading::Where::Extrapolated);
    EXPECT_NEAR(r.value, 1.0 / 64, 1e-12);
    r = curve_y_at_x(t, e, 8);
    EXPECT_EQ(r.where, CurveReading::Where::Interpolated);
    EXPECT_NEAR(r.value, 0.125, 1e-12);
    EXPECT_EQ(decade_label(-2), "0.01");
    EXPECT_EQ(decade_label(2), "100");
    EXPECT_EQ(decade_label(-5), "1e-5");
}

}  // namespace
}  // namespace glint::io

namespace {

struct RunResult {
    int exit_code = -1;
    std::string out, err;
};

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

class ReportCli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("glint_report_test_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        std::ofstream(dir_ / "scene.pov")
            << "camera { location <0, 0, -4> look_at <0, 0, 0> }\n"
               "light_source { <5, 5, -5> color rgb 1 }\n"
               "background { rgb 0.2 }\n"
               "sphere { 0, 1 pigment { rgb <0.8, 0.5, 0.3> } }\n";
    }
    void TearDown() override { fs::remove_all(dir_); }

    RunResult run(const std::string& args) {
        const std::string cmd = std::string("'") + GLINT_BINARY + "' " + args + " >'" +
                                path("stdout.txt") + "' 2>'" + path("stderr.txt") + "'";
        const int status = std::system(cmd.c_str());
        RunResult r;
        r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        r.out = slurp(dir_ / "stdout.txt");
        r.err = slurp(dir_ / "stderr.txt");
        return r;
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    void make_reference() {
        RunResult r = run("render '" + path("scene.pov") + "' -o '" + path("ref.exr") +
                          "' --integrator path --spp 64 -W 16 -H 12 --threads 1");
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }

    fs::path dir_;
};

std::vector<std::vector<std::string>> read_csv(const std::string& text) {
    std::vector<std::vector<std::string>> rows;
    std::stringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::stringstream ls(line);
        std::string cell;
        while (std::getline(ls, cell, ',')) cells.push_back(cell);
        rows.push_back(cells);
    }
    return rows;
}

TEST_F(ReportCli, WritesCsvPlotAndSummaryWithAPeer) {
    make_reference();
    RunResult r = run("report '" + path("scene.pov") + "' --reference '" + path("ref.exr") +
                      "' --spp-steps 4,1,2 --threads 1 --out '" + path("rep") +
                      "' --peer \"cp '" + path("ref.exr") +
                      "' {out}\" --peer-steps 1,3 --peer-name copy");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto rows = read_csv(slurp(dir_ / "rep" / "report.csv"));
    ASSERT_EQ(rows.size(), 6u);
    EXPECT_EQ(rows[0], (std::vector<std::string>{"renderer", "spp", "seconds", "relmse", "rmse",
                                                 "ssim", "seeds", "relmse_min", "relmse_max"}));
    const int spp[] = {1, 2, 4, 1, 3};
    for (int i = 1; i <= 5; ++i) {
        ASSERT_EQ(rows[i].size(), 9u);
        EXPECT_EQ(rows[i][6], "1");
        EXPECT_EQ(rows[i][7], rows[i][3]);
        EXPECT_EQ(rows[i][8], rows[i][3]);
        EXPECT_EQ(rows[i][0], i <= 3 ? "glint" : "copy");
        EXPECT_EQ(std::stoi(rows[i][1]), spp[i - 1]);
        EXPECT_GT(std::stod(rows[i][2]), 0.0);
    }
    // glint's error falls with samples; the peer that copies the reference has none.
    EXPECT_LT(std::stod(rows[3][3]), std::stod(rows[1][3]));
    EXPECT_GT(std::stod(rows[1][3]), 0.0);
    EXPECT_EQ(std::stod(rows[4][3]), 0.0);
    EXPECT_EQ(std::stod(rows[4][5]), 1.0);
    const std::string txt = slurp(dir_ / "rep" / "report.txt");
    EXPECT_NE(txt.find("equal-error: at glint's final relMSE"), std::string::npos) << txt;
    EXPECT_NE(txt.find("equal-time: at glint's final time"), std::string::npos) << txt;
    EXPECT_EQ(r.out, txt);
    auto in = OIIO::ImageInput::open(path("rep/report.png"));
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().width, 640);
    EXPECT_EQ(in->spec().height, 400);
    EXPECT_TRUE(fs::exists(dir_ / "rep" / "glint-4.exr"));
}

TEST_F(ReportCli, PhotonIntegratorIsACurveBesideThePathTracers) {
    make_reference();
    RunResult r = run("report '" + path("scene.pov") + "' --reference '" + path("ref.exr") +
                      "' --spp-steps 1,8 --integrator path,sppm --photons 2000 --threads 1 "
                      "--out '" + path("rep") + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto rows = read_csv(slurp(dir_ / "rep" / "report.csv"));
    ASSERT_EQ(rows.size(), 5u);
    const char* names[] = {"glint-path", "glint-path", "glint-sppm", "glint-sppm"};
    for (int i = 1; i <= 4; ++i) {
        EXPECT_EQ(rows[i][0], names[i - 1]);
        EXPECT_EQ(std::stoi(rows[i][1]), i % 2 ? 1 : 8);
    }
    // Both converge to the path tracer's reference: more passes, less error.
    EXPECT_LT(std::stod(rows[2][3]), std::stod(rows[1][3]));
    EXPECT_LT(std::stod(rows[4][3]), std::stod(rows[3][3]));
    const std::string txt = slurp(dir_ / "rep" / "report.txt");
    EXPECT_NE(txt.find("Ratios of glint-path to glint-sppm"), std::string::npos) << txt;
    EXPECT_NE(txt.find("equal-error: at glint-sppm's final relMSE"), std::string::npos) << txt;
    EXPECT_TRUE(fs::exists(dir_ / "rep" / "glint-sppm-8.exr"));
    RunResult bad = run("report '" + path("scene.pov") + "' --reference '" + path("ref.exr") +
                        "' --integrator path,whitted --out '" + path("rep2") + "'");
    EXPECT_EQ(bad.exit_code, 1) << bad.err;
    EXPECT_NE(bad.err.find("'whitted' is not an integrator the report runs"), std::string::npos)
        << bad.err;
}

TEST_F(ReportCli, PeerReportsItsOwnRenderSecondsThroughTimeFile) {
    // With {time} the peer's seconds are what it writes there, not its whole process (which
    // includes a 0.2 s sleep here); a peer that does not write the file is a clear error.
    make_reference();
    RunResult r = run("report '" + path("scene.pov") + "' --reference '" + path("ref.exr") +
                      "' --spp-steps 1 --threads 1 --out '" + path("rep") + "' --peer \"cp '" +
                      path("ref.exr") + "' {out}; sleep 0.2; echo {spp}.25 > {time}\"" +
                      " --peer-steps 1,3 --peer-name copy");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto rows = read_csv(slurp(dir_ / "rep" / "report.csv"));
    ASSERT_EQ(rows.size(), 4u);
    EXPECT_EQ(std::stod(rows[2][2]), 1.25);
    EXPECT_EQ(std::stod(rows[3][2]), 3.25);

    RunResult bad = run("report '" + path("scene.pov") + "' --reference '" + path("ref.exr") +
                        "' --spp-steps 1 --threads 1 --out '" + path("rep2") + "' --peer \"cp '" +
                        path("ref.exr") + "' {out}; true {time}\"");
    EXPECT_EQ(bad.exit_code, 4) << bad.err;
    EXPECT_NE(bad.err.find("did not write its render seconds"), std::string::npos) << bad.err;
}

TEST_F(ReportCli, SeedsAverageTheErrorOverRendersAndNumberThePeersSeeds) {
    // --seeds 3: each step is three renders, glint with seeds 5, 6, 7 and the peer with {seed}
    // 0, 1, 2; a row holds the mean relMSE, which lies inside the range of the three.
    make_reference();
    RunResult r = run("report '" + path("scene.pov") + "' --reference '" + path("ref.exr") +
                      "' --spp-steps 1,4 --seed 5 --seeds 3 --threads 1 --out '" + path("rep") +
                      "' --peer \"cp '" + path("ref.exr") + "' {out}; echo {spp}:{seed} >> '" +
                      path("seeds.txt") + "'; ls '" + path("rep") + "' | grep -c '^glint-' >> '" +
                      path("glint_files.txt") + "'\" --peer-steps 2 --peer-name copy");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(slurp(dir_ / "seeds.txt"), "2:0\n2:1\n2:2\n");
    // The renderers take turns step by step: the peer's first step runs after glint's first
    // (its three seeds' images), not after all of glint's steps.
    EXPECT_EQ(slurp(dir_ / "glint_files.txt"), "3\n3\n3\n");
    const auto rows = read_csv(slurp(dir_ / "rep" / "report.csv"));
    ASSERT_EQ(rows.size(), 4u);
    for (int i = 1; i <= 3; ++i) {
        ASSERT_EQ(rows[i].size(), 9u);
        EXPECT_EQ(rows[i][6], "3");
    }
    for (int i = 1; i <= 2; ++i) {
        const double mean = std::stod(rows[i][3]), lo = std::stod(rows[i][7]),
                     hi = std::stod(rows[i][8]);
        EXPECT_LT(lo, hi) << "three seeds, three different errors";
        EXPECT_LE(lo, mean);
        EXPECT_LE(mean, hi);
    }
    for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(fs::exists(dir_ / "rep" / ("glint-4-s" + std::to_string(k) + ".exr")));
        EXPECT_TRUE(fs::exists(dir_ / "rep" / ("copy-2-s" + std::to_string(k) + ".exr")));
    }
    // The first seed's image is the one a plain render with --seed 5 makes.
    RunResult one = run("render '" + path("scene.pov") + "' -o '" + path("s5.exr") +
                        "' --integrator path --spp 4 --seed 5 -W 16 -H 12 --threads 1");
    ASSERT_EQ(one.exit_code, 0) << one.err;
    RunResult same = run("compare '" + path("s5.exr") + "' '" + path("rep/glint-4-s0.exr") + "'");
    EXPECT_EQ(same.exit_code, 0) << same.out << same.err;
    EXPECT_NE(same.out.find(" relmse=0 rmse_linear=0\n"), std::string::npos) << same.out;

    RunResult bad = run("report '" + path("scene.pov") + "' --reference '" + path("ref.exr") +
                        "' --spp-steps 1 --seeds 2 --threads 1 --out '" + path("rep2") +
                        "' --peer \"cp '" + path("ref.exr") + "' {out}\"");
    EXPECT_EQ(bad.exit_code, 1) << bad.err;
    EXPECT_NE(bad.err.find("--seeds 2 needs {seed} in --peer"), std::string::npos) << bad.err;
    EXPECT_FALSE(fs::exists(dir_ / "rep2" / "report.csv"));
}

TEST_F(ReportCli, FailingPeerCommandIsAClearError) {
    make_reference();
    RunResult r = run("report '" + path("scene.pov") + "' --reference '" + path("ref.exr") +
                      "' --spp-steps 1 --threads 1 --out '" + path("rep") +
                      "' --peer 'echo boom; exit 3'");
    EXPECT_EQ(r.exit_code, 4) << r.err;
    EXPECT_NE(r.err.find("peer command failed with exit status 3: echo boom; exit 3"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(slurp(dir_ / "rep" / "peer-1.log"), "boom\n");
    EXPECT_FALSE(fs::exists(dir_ / "rep" / "report.csv"));
}

TEST_F(ReportCli, BadStepsAndSizeAreUsageErrors) {
    make_reference();
    const std::string base =
        "report '" + path("scene.pov") + "' --reference '" + path("ref.exr") + "' ";
    EXPECT_EQ(run(base + "--spp-steps 1,x").exit_code, 1);
    EXPECT_EQ(run(base + "--spp-steps 0").exit_code, 1);
    RunResult r = run(base + "-W 20 --out '" + path("rep") + "'");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("differ from the reference"), std::string::npos) << r.err;
    EXPECT_EQ(run(base.substr(0, base.find(" --reference")) + " --reference '" + path("no.exr") +
                  "'")
                  .exit_code,
              3);
}

TEST_F(ReportCli, RenderWritesAovsAndVarianceBesideTheOutput) {
    RunResult r = run("render '" + path("scene.pov") + "' -o '" + path("out.png") +
                      "' --integrator path --spp 4 -W 16 -H 12 --aov depth,albedo,normal "
                      "--variance");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* name : {"out.albedo.exr", "out.normal.exr", "out.depth.exr",
                             "out.variance.exr"}) {
        auto in = OIIO::ImageInput::open(path(name));
        ASSERT_TRUE(in) << name;
        EXPECT_EQ(in->spec().width, 16);
        EXPECT_EQ(in->spec().nchannels, std::string(name) == "out.depth.exr" ? 1 : 3) << name;
    }
    r = run("render '" + path("scene.pov") + "' -o '" + path("w.png") + "' --aov depth");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("--aov needs --integrator path"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("w.png")));
    r = run("render '" + path("scene.pov") + "' -o '" + path("x.png") +
            "' --integrator path --aov depth,speed");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("unknown AOV 'speed'"), std::string::npos) << r.err;
}

TEST_F(ReportCli, CompareReadsExrAndPrintsLinearMetrics) {
    make_reference();
    RunResult r = run("compare '" + path("ref.exr") + "' '" + path("ref.exr") + "' --diff '" +
                      path("d.exr") + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find(" relmse=0 rmse_linear=0\n"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(path("d.exr")));
}

}  // namespace
