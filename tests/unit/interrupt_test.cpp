// Interruption and output failures from the outside (issue 6, deliverable 5): SIGINT with and
// without --save-partial, and unwritable or full output paths. Runs the built glint binary.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "render/film/driver.h"

namespace fs = std::filesystem;

namespace {

// A scene with no black pixel (sky color), so unrendered (black) pixels stand out.
constexpr const char* kScene =
    "#version 3.7;\n"
    "global_settings { assumed_gamma 1 }\n"
    "background { rgb <0.2, 0.3, 0.5> }\n"
    "camera { location <0, 1, -4> look_at 0 }\n"
    "light_source { <3, 5, -3> rgb 1 }\n"
    "sphere { 0, 1 pigment { rgb <1, 0.4, 0.2> } finish { phong 0.5 reflection 0.3 } }\n"
    "plane { y, -1 pigment { checker rgb 1 rgb 0.2 } finish { reflection 0.2 } }\n";

std::string slurp_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

struct Exit {
    bool ended = false;   // ended by itself (not killed by the test)
    int code = -1;        // exit status; -1 when ended by a signal
    double seconds = 0;   // from the signal (or the start) to the end
};

// Runs glint with `args`; with `signal_after` > 0 sends SIGINT that long after the first
// `progress` line on stderr (so the render has started; give --progress lines). `fsize_limit`
// > 0 caps the size of the files it writes (RLIMIT_FSIZE, SIGXFSZ ignored), so a write fails
// part way as on a full disk. stderr goes to `err_path`.
Exit run_glint(std::vector<std::string> args, const std::string& err_path,
               std::chrono::milliseconds signal_after = std::chrono::milliseconds(0),
               rlim_t fsize_limit = 0) {
    args.insert(args.begin(), GLINT_BINARY);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    Exit r;
    // Empty the stderr file first: the child truncates it only once it runs, and until then the
    // wait for a `progress` line below would read the previous run's lines and signal early
    // (under load, before any tile had finished).
    std::ofstream(err_path, std::ios::trunc).close();
    const auto start = std::chrono::steady_clock::now();
    pid_t pid = fork();
    if (pid < 0) return r;
    if (pid == 0) {
        if (!std::freopen(err_path.c_str(), "w", stderr)) _exit(126);
        if (fsize_limit > 0) {
            ::signal(SIGXFSZ, SIG_IGN);  // stays ignored across exec: write() fails with EFBIG
            rlimit lim{fsize_limit, fsize_limit};
            if (::setrlimit(RLIMIT_FSIZE, &lim) != 0) _exit(126);
        }
        execv(GLINT_BINARY, argv.data());
        _exit(127);
    }
    auto sent = start;
    if (signal_after.count() > 0) {
        while (slurp_file(err_path).find("progress ") == std::string::npos &&
               waitpid(pid, nullptr, WNOHANG) == 0 &&
               std::chrono::steady_clock::now() < start + std::chrono::seconds(180))
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        std::this_thread::sleep_for(signal_after);
        kill(pid, SIGINT);
        sent = std::chrono::steady_clock::now();
    }
    int status = 0;
    pid_t done = 0;
    // Generous: an uninterrupted render of the sanitizer build on a loaded CI machine took over
    // 30 s. The stop time after a signal is asserted separately (< 1 s).
    while ((done = waitpid(pid, &status, WNOHANG)) == 0 &&
           std::chrono::steady_clock::now() < sent + std::chrono::seconds(180))
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
    r.ended = done == pid;
    if (!r.ended) {
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
    }
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

struct Picture {
    int width = 0, height = 0, channels = 0;
    std::vector<float> data;
    std::string partial;      // the glint:partial attribute
    std::string description;  // ImageDescription
};

Picture read_picture(const std::string& path) {
    Picture p;
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) return p;
    const OIIO::ImageSpec& spec = in->spec();
    p.width = spec.width;
    p.height = spec.height;
    p.channels = spec.nchannels;
    p.partial = spec.get_string_attribute("glint:partial");
    p.description = spec.get_string_attribute("ImageDescription");
    p.data.resize(static_cast<size_t>(p.width) * p.height * p.channels);
    if (!in->read_image(0, 0, 0, p.channels, OIIO::TypeDesc::FLOAT, p.data.data()))
        p.data.clear();
    return p;
}

class InterruptTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("glint_interrupt_test_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        std::ofstream(dir_ / "s.pov") << kScene;
    }
    void TearDown() override {
        std::error_code ec;
        fs::permissions(dir_ / "ro", fs::perms::owner_all, ec);
        fs::remove_all(dir_);
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    std::string err() const { return slurp_file(path("err.txt")); }
    // Everything in the test folder besides s.pov and err.txt (and the `keep` names).
    std::vector<std::string> extra_files(const std::vector<std::string>& keep = {}) const {
        std::vector<std::string> names;
        for (const auto& e : fs::recursive_directory_iterator(dir_)) {
            const std::string n = fs::relative(e.path(), dir_).string();
            if (n == "s.pov" || n == "err.txt" || e.is_directory()) continue;
            if (std::find(keep.begin(), keep.end(), n) != keep.end()) continue;
            names.push_back(n);
        }
        return names;
    }
    fs::path dir_;
};

}  // namespace

// Whitted, interrupted: each 32x32 tile of the partial image is the uninterrupted render's
// tile bit for bit, or black; some of each kind. Without --save-partial nothing is written.
TEST_F(InterruptTest, WhittedSavePartialKeepsFinishedTiles) {
    const std::vector<std::string> common = {"render", path("s.pov"), "--width", "256",
                                             "--height", "192", "--aa", "grid:6", "--threads",
                                             "1", "--progress", "lines"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> a = common;
        a.insert(a.end(), extra.begin(), extra.end());
        return a;
    };
    const auto t0 = std::chrono::steady_clock::now();
    Exit full = run_glint(with({"-o", path("full.exr")}), path("err.txt"));
    const double full_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_EQ(full.code, 0) << err();
    // Signal at about a third of the render.
    const auto delay = std::chrono::milliseconds(static_cast<int>(full_seconds * 1000 / 3));

    Exit none = run_glint(with({"-o", path("none.exr")}), path("err.txt"), delay);
    ASSERT_TRUE(none.ended);
    EXPECT_EQ(none.code, 130) << err();
    EXPECT_LT(none.seconds, 1.0);
    EXPECT_FALSE(fs::exists(path("none.exr")));

    Exit part = run_glint(with({"-o", path("part.exr"), "--save-partial"}), path("err.txt"), delay);
    ASSERT_TRUE(part.ended);
    EXPECT_EQ(part.code, 130) << err();
    EXPECT_LT(part.seconds, 1.0);
    std::printf("Whitted: stopped %.3f s after SIGINT (%.3f s with --save-partial)\n",
                none.seconds, part.seconds);
    EXPECT_NE(err().find("partial image written to"), std::string::npos) << err();
    EXPECT_EQ(extra_files({"full.exr", "part.exr"}), std::vector<std::string>{});

    const Picture a = read_picture(path("full.exr"));
    const Picture b = read_picture(path("part.exr"));
    ASSERT_FALSE(a.data.empty());
    ASSERT_FALSE(b.data.empty());
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    ASSERT_EQ(a.channels, b.channels);
    int same = 0, black = 0, total = 0;
    for (int ty = 0; ty < a.height; ty += 32)
        for (int tx = 0; tx < a.width; tx += 32) {
            bool is_same = true, is_black = true;
            for (int y = ty; y < std::min(ty + 32, a.height); ++y)
                for (int x = tx; x < std::min(tx + 32, a.width); ++x)
                    for (int c = 0; c < 3; ++c) {
                        const size_t i = (static_cast<size_t>(y) * a.width + x) * a.channels + c;
                        is_same = is_same && a.data[i] == b.data[i];
                        is_black = is_black && b.data[i] == 0.0f;
                    }
            ++total;
            same += is_same;
            black += is_black && !is_same;
            EXPECT_TRUE(is_same || is_black) << "tile at " << tx << "," << ty;
        }
    EXPECT_EQ(same + black, total);
    EXPECT_GT(same, 0);
    EXPECT_GT(black, 0);
    EXPECT_EQ(b.partial, "tiles " + std::to_string(same) + "/" + std::to_string(total));
    EXPECT_NE(b.description.find("interrupted"), std::string::npos) << b.description;
}

// Path tracer, interrupted after some passes: the partial image is the full render at the
// samples per pixel it records, bit for bit, and so are its AOV and variance side files.
TEST_F(InterruptTest, PathSavePartialEqualsRenderAtCompletedSpp) {
    const std::vector<std::string> common = {
        "render", path("s.pov"), "--width", "48", "--height", "32", "--integrator", "path",
        "--seed", "7", "--threads", "2", "--progress", "lines", "--aov", "albedo", "--variance"};
    std::vector<std::string> a = common;
    a.insert(a.end(), {"-o", path("part.exr"), "--spp", "16777216", "--save-partial"});
    Exit part = run_glint(a, path("err.txt"), std::chrono::milliseconds(1000));
    ASSERT_TRUE(part.ended);
    EXPECT_EQ(part.code, 130) << err();
    EXPECT_LT(part.seconds, 1.0);
    std::printf("path: stopped and saved %.3f s after SIGINT\n", part.seconds);
    const Picture p = read_picture(path("part.exr"));
    ASSERT_FALSE(p.data.empty()) << err();
    ASSERT_EQ(p.partial.rfind("spp ", 0), 0u) << p.partial;
    const int spp = std::stoi(p.partial.substr(4));
    EXPECT_EQ(p.partial, "spp " + std::to_string(spp) + "/16777216");
    EXPECT_GE(spp, 2);
    EXPECT_EQ(spp & (spp - 1), 0) << "passes end at powers of two";
    EXPECT_EQ(read_picture(path("part.variance.exr")).partial, p.partial);

    std::vector<std::string> b = common;
    b.insert(b.end(), {"-o", path("full.exr"), "--spp", std::to_string(spp)});
    Exit full = run_glint(b, path("err.txt"));
    ASSERT_EQ(full.code, 0) << err();
    for (const char* suffix : {"", ".albedo", ".variance"}) {
        const Picture x = read_picture(path(std::string("part") + suffix + ".exr"));
        const Picture y = read_picture(path(std::string("full") + suffix + ".exr"));
        ASSERT_FALSE(x.data.empty()) << suffix;
        EXPECT_EQ(x.data, y.data) << suffix << " differs from the render at " << spp << " spp";
    }
}

// Without --save-partial the path tracer writes nothing either, side files included.
TEST_F(InterruptTest, PathInterruptWritesNothing) {
    Exit r = run_glint({"render", path("s.pov"), "-o", path("o.exr"), "--width", "48", "--height",
                        "32", "--integrator", "path", "--spp", "16777216", "--aov", "depth",
                        "--variance", "--progress", "lines"},
                       path("err.txt"), std::chrono::milliseconds(1000));
    ASSERT_TRUE(r.ended);
    EXPECT_EQ(r.code, 130);
    EXPECT_LT(r.seconds, 1.0);
    EXPECT_EQ(extra_files(), std::vector<std::string>{});
}

// Output paths that cannot be written: a clear error, exit 5, before rendering, no file.
TEST_F(InterruptTest, UnwritableOutputIsErrorFive) {
    fs::create_directories(dir_ / "adir");
    fs::create_directories(dir_ / "o.albedo.exr");  // a side file's name taken by a folder
    struct Case {
        std::vector<std::string> extra;
        std::string message;
    };
    std::vector<Case> cases = {
        {{"-o", path("nosuch/o.png")}, "does not exist"},
        {{"-o", path("adir")}, "unsupported output format"},
        {{"-o", path("adir.png")}, ""},  // fine: control case, see below
        {{"-o", path("o.exr"), "--integrator", "path", "--aov", "albedo"}, "it is a folder"},
        {{"-o", "/proc/self/o.png"}, "cannot write /proc/self/o.png"},
    };
    fs::create_directories(dir_ / "adir.png");  // a folder with an image's name
    cases[2].message = "it is a folder";
    if (::geteuid() != 0) {  // root writes into read-only folders
        fs::create_directories(dir_ / "ro");
        fs::permissions(dir_ / "ro", fs::perms::owner_read | fs::perms::owner_exec);
        cases.push_back({{"-o", path("ro/o.png")}, "Permission denied"});
    }
    for (const Case& c : cases) {
        std::vector<std::string> a = {"render", path("s.pov"), "--width", "8", "--height", "6",
                                      "--progress", "none"};
        a.insert(a.end(), c.extra.begin(), c.extra.end());
        Exit r = run_glint(a, path("err.txt"));
        const std::string e = err();
        EXPECT_EQ(r.code, 5) << c.extra[1] << ": " << e;
        EXPECT_NE(e.find("error: "), std::string::npos) << e;
        EXPECT_NE(e.find(c.message), std::string::npos) << c.extra[1] << ": " << e;
        EXPECT_EQ(extra_files(), std::vector<std::string>{}) << c.extra[1];
    }
}

// A write that fails part way (the file size limit standing in for a full disk): exit 5, an
// error naming the file, no temporary left and no partial set of files.
TEST_F(InterruptTest, FullDiskIsErrorFiveWithoutLeftovers) {
    struct Case {
        std::string name;
        std::string size;
        std::vector<std::string> extra;
    };
    const std::vector<Case> cases = {
        {"png", "256", {"-o", path("o.png")}},
        {"exr", "256", {"-o", path("o.exr")}},
        {"tif", "256", {"-o", path("o.tif")}},
        // The small PNG fits, its noisy float variance EXR does not: neither may appear.
        {"side", "32", {"-o", path("o.png"), "--integrator", "path", "--spp", "2", "--variance"}},
    };
    for (const Case& c : cases) {
        std::vector<std::string> a = {"render", path("s.pov"), "--width", c.size, "--height",
                                      c.size, "--progress", "none"};
        a.insert(a.end(), c.extra.begin(), c.extra.end());
        Exit r = run_glint(a, path("err.txt"), std::chrono::milliseconds(0), 4096);
        const std::string e = err();
        EXPECT_EQ(r.code, 5) << c.name << ": " << e;
        EXPECT_NE(e.find("error: cannot write " + path("o.")), std::string::npos) << e;
        EXPECT_EQ(extra_files(), std::vector<std::string>{}) << c.name;
    }
}

// A real full disk where the test may mount one (root with CAP_SYS_ADMIN; skipped otherwise):
// a 64 KiB tmpfs. The 16 KiB PNG fits, the set with float side files does not.
TEST_F(InterruptTest, FullTmpfsIsErrorFiveWithoutLeftovers) {
    const fs::path small = dir_ / "small";
    fs::create_directories(small);
    if (::mount("tmpfs", small.c_str(), "tmpfs", 0, "size=64k") != 0)
        GTEST_SKIP() << "cannot mount a tmpfs here: " << std::strerror(errno);
    struct Unmount {
        const fs::path& p;
        ~Unmount() { ::umount2(p.c_str(), MNT_DETACH); }
    } unmount{small};
    const std::vector<std::string> base = {"render", path("s.pov"), "--progress", "none"};
    std::vector<std::string> a = base;
    a.insert(a.end(), {"-o", (small / "a.png").string(), "--width", "128", "--height", "96"});
    Exit r = run_glint(a, path("err.txt"));
    ASSERT_EQ(r.code, 0) << err();
    std::vector<std::string> b = base;
    b.insert(b.end(), {"-o", (small / "b.png").string(), "--width", "64", "--height", "64",
                       "--integrator", "path", "--spp", "4", "--variance", "--aov",
                       "albedo,normal,depth"});
    r = run_glint(b, path("err.txt"));
    EXPECT_EQ(r.code, 5) << err();
    EXPECT_NE(err().find("No space left on device"), std::string::npos) << err();
    std::vector<std::string> left;
    for (const auto& e : fs::directory_iterator(small)) left.push_back(e.path().filename());
    EXPECT_EQ(left, std::vector<std::string>{"a.png"});
}

// --save-partial when the partial write itself fails: exit 5, nothing left.
TEST_F(InterruptTest, SavePartialWriteFailureIsErrorFive) {
    Exit r = run_glint({"render", path("s.pov"), "-o", path("o.exr"), "--width", "256",
                        "--height", "192", "--integrator", "path", "--spp", "16777216",
                        "--progress", "lines", "--save-partial"},
                       path("err.txt"), std::chrono::milliseconds(300), 4096);
    ASSERT_TRUE(r.ended);
    EXPECT_EQ(r.code, 5) << err();
    EXPECT_NE(err().find("error: cannot write"), std::string::npos) << err();
    EXPECT_EQ(extra_files(), std::vector<std::string>{});
}

// The driver itself, cancelled at a fixed point (no timing): what Interrupted carries.
namespace glint::render {
namespace {

Camera driver_camera(int w, int h) {
    scene::Camera c;
    c.location = Vec3(0, 0, -5);
    return Camera(c, w, h);
}

// Depends on the ray and the sample number, never black.
Color pattern(const Ray& r, const SampleId& id) {
    const double v = std::sin(r.dir.x * 91.7 + id.index * 0.37) * std::cos(r.dir.y * 57.3);
    return Color(0.6 + 0.4 * v, 0.1 + r.dir.x * r.dir.x, 0.5 + 0.01 * (id.index % 7));
}

TEST(InterruptDriver, PathPartialIsTheLastFinishedPassBitForBit) {
    const int w = 70, h = 45;  // 3 x 2 tiles, partial ones at the edges
    const Camera cam = driver_camera(w, h);
    for (uint32_t cancel_at : {2u, 3u, 4u, 7u, 9u}) {  // passes: [0,1) [1,2) [2,4) [4,8) [8,16)
        std::atomic<bool> cancel{false};
        RenderOptions o;
        o.width = w;
        o.height = h;
        o.spp = 64;
        o.threads = 2;
        o.aovs = true;
        o.variance = true;
        o.cancel = &cancel;
        PathRadianceFn fn = [&](const Ray& r, const SampleId& id, FirstHit* first) {
            // Cancel on the first sample of `cancel_at` in the centre pixel.
            if (id.index == cancel_at && id.x == w / 2 && id.y == h / 2) cancel = true;
            if (first) {
                first->hit = true;
                first->albedo = Color(0.3, 0.2, 0.1 * (id.index % 3));
                first->depth = 1.0 + id.index;
            }
            return pattern(r, id);
        };
        PathFilm film;
        std::shared_ptr<const PartialRender> got;
        try {
            run_path_tiles(cam, o, fn, &film);
        } catch (const Interrupted& e) {
            got = std::make_shared<PartialRender>(e.partial());
        }
        ASSERT_TRUE(got) << "not interrupted at " << cancel_at;
        int expect = 1;
        while (expect * 2 <= static_cast<int>(cancel_at)) expect *= 2;
        EXPECT_EQ(got->samples_per_pixel, expect) << cancel_at;
        EXPECT_EQ(got->spp_requested, 64);
        EXPECT_EQ(got->tiles_done, got->tiles_total);
        RenderOptions full = o;
        full.cancel = nullptr;
        full.spp = expect;
        PathFilm ref;
        EXPECT_EQ(run_path_tiles(cam, full, fn, &ref), expect);
        EXPECT_EQ(got->film.image.rgba, ref.image.rgba) << cancel_at;
        EXPECT_EQ(got->film.albedo.rgba, ref.albedo.rgba) << cancel_at;
        EXPECT_EQ(got->film.depth.rgba, ref.depth.rgba) << cancel_at;
        EXPECT_EQ(got->film.variance.rgba, ref.variance.rgba) << cancel_at;
    }
}

TEST(InterruptDriver, FirstPassAndWhittedKeepFinishedTilesOnly) {
    const int w = 100, h = 70;  // 4 x 3 tiles
    const Camera cam = driver_camera(w, h);
    RenderOptions o;
    o.width = w;
    o.height = h;
    o.threads = 1;
    o.aa = AaMode::Grid;
    o.grid_n = 2;
    const Image ref = run_tiles(cam, o, {}, pattern);
    for (bool path : {false, true}) {
        std::atomic<bool> cancel{false};
        o.cancel = &cancel;
        o.spp = 8;
        // Cancelled inside the 6th tile (x 32..63, y 32..63) on its 3rd row.
        RadianceFn fn = [&](const Ray& r, const SampleId& id) {
            if (id.x == 40 && id.y == 34) cancel = true;
            return pattern(r, id);
        };
        std::shared_ptr<const PartialRender> got;
        try {
            if (path) {
                Image img;
                run_path_tiles(cam, o, fn, &img);
            } else {
                run_tiles(cam, o, {}, fn);
            }
        } catch (const Interrupted& e) {
            got = std::make_shared<PartialRender>(e.partial());
        }
        ASSERT_TRUE(got);
        EXPECT_EQ(got->samples_per_pixel, 0);
        EXPECT_EQ(got->tiles_total, 12u);
        EXPECT_EQ(got->tiles_done, 5u) << "one thread renders tiles in order";
        Image full1;
        if (path) {
            RenderOptions one = o;
            one.cancel = nullptr;
            one.spp = 1;
            run_path_tiles(cam, one, pattern, &full1);
        }
        const Image& expect = path ? full1 : ref;
        const Image& img = got->film.image;
        ASSERT_EQ(img.rgba.size(), expect.rgba.size());
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const int tile = (y / 32) * 4 + x / 32;
                const float* p = img.pixel(x, y);
                if (tile < 5) {
                    for (int c = 0; c < 4; ++c)
                        ASSERT_EQ(p[c], expect.pixel(x, y)[c]) << x << "," << y << " " << path;
                } else {
                    for (int c = 0; c < 4; ++c) ASSERT_EQ(p[c], 0.0f) << x << "," << y;
                }
            }
    }
}

}  // namespace
}  // namespace glint::render
