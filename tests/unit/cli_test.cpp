// The CLI contract from the outside: exit codes, `glint compare` output, and that failures
// leave no output file. Runs the built glint binary (GLINT_BINARY).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <sstream>
#include <thread>
#include <vector>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/image_compare.h"

namespace fs = std::filesystem;

namespace {

struct RunResult {
    int exit_code = -1;
    std::string out;  // stdout
    std::string err;  // stderr
};

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

class CliTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("glint_cli_test_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    RunResult run(const std::string& args) { return run_env("", args); }
    // With `env` ("NAME=value ...") before the command.
    RunResult run_env(const std::string& env, const std::string& args) {
        std::string cmd = env + "'" + GLINT_BINARY + "' " + args + " >'" +
                          (dir_ / "stdout.txt").string() + "' 2>'" +
                          (dir_ / "stderr.txt").string() + "'";
        int status = std::system(cmd.c_str());
        RunResult r;
        r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        r.out = slurp(dir_ / "stdout.txt");
        r.err = slurp(dir_ / "stderr.txt");
        fs::remove(dir_ / "stdout.txt");
        fs::remove(dir_ / "stderr.txt");
        return r;
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    void write_text(const std::string& name, const std::string& text) {
        std::ofstream(dir_ / name) << text;
    }
    // Files in the test folder other than the inputs we made.
    int count_files() const {
        int n = 0;
        for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++n;
        return n;
    }

    fs::path dir_;
};

glint::io::Rgb8Image flat(int w, int h, unsigned char v) {
    glint::io::Rgb8Image img;
    img.width = w;
    img.height = h;
    img.rgb.assign(static_cast<size_t>(w) * h * 3, v);
    return img;
}

}  // namespace

TEST_F(CliTest, NoSubcommandIsAUsageError) {
    EXPECT_EQ(run("").exit_code, 1);
    EXPECT_EQ(run("frobnicate").exit_code, 1);
    EXPECT_EQ(run("render").exit_code, 1);  // SCENE and -o are required
    EXPECT_EQ(run("--help").exit_code, 0);
}

TEST_F(CliTest, HelpSaysOneShortLinePerSubcommandAndNamesObj) {
    RunResult r = run("--help");
    ASSERT_EQ(r.exit_code, 0);
    EXPECT_NE(r.out.find("OBJ"), std::string::npos) << r.out;
    const size_t list = r.out.find("Subcommands:");
    ASSERT_NE(list, std::string::npos) << r.out;
    std::istringstream lines(r.out.substr(list));
    std::string line;
    std::getline(lines, line);
    int commands = 0;
    while (std::getline(lines, line) && !line.empty()) {
        ++commands;
        EXPECT_LE(line.size(), 100u) << "a paragraph, not a line: " << line;
    }
    EXPECT_EQ(commands, 7) << r.out;  // render ir compare report convert merge farm
    // The long explanations stay in each subcommand's own help.
    EXPECT_NE(run("render --help").out.find("POV-Ray's own switches"), std::string::npos);
}

TEST_F(CliTest, CompareAgreeingImagesExitsZero) {
    glint::io::Rgb8Image a = flat(10, 10, 100);
    glint::io::Rgb8Image b = a;
    b.rgb[0] = 102;  // within the default tolerance of 2
    glint::io::write_rgb8_png(a, path("a.png"));
    glint::io::write_rgb8_png(b, path("b.png"));
    RunResult r = run("compare '" + path("a.png") + "' '" + path("b.png") + "'");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out,
              "within=1.000000 rmse=0.1155 max=2@0,0 pixels=100 mae=0.0067 ssim=1.000000 "
              "relmse=3.55486e-06 rmse_linear=0.000313538\n");
}

TEST_F(CliTest, CompareDifferingImagesExitsSixAndWritesDiff) {
    glint::io::Rgb8Image a = flat(10, 10, 100);
    glint::io::Rgb8Image b = a;
    for (int i = 0; i < 2; ++i) b.rgb[i * 3 + 1] = 110;  // 2 of 100 pixels off by 10
    glint::io::write_rgb8_png(a, path("a.png"));
    glint::io::write_rgb8_png(b, path("b.png"));
    RunResult r = run("compare '" + path("a.png") + "' '" + path("b.png") + "' --diff '" +
                      path("d.png") + "'");
    EXPECT_EQ(r.exit_code, 6);
    EXPECT_EQ(r.out.rfind("within=0.980000 ", 0), 0u) << r.out;
    ASSERT_TRUE(fs::exists(path("d.png")));
    glint::io::Rgb8Image d = glint::io::read_rgb8(path("d.png"));
    EXPECT_EQ(d.rgb[1], 255);
    EXPECT_EQ(d.rgb[0], 0);
    // A lower bar lets the same pair pass.
    EXPECT_EQ(run("compare '" + path("a.png") + "' '" + path("b.png") + "' --min-fraction 0.98")
                  .exit_code,
              0);
    EXPECT_EQ(run("compare '" + path("a.png") + "' '" + path("b.png") + "' --tolerance 10")
                  .exit_code,
              0);
}

TEST_F(CliTest, CompareSizeMismatchAndMissingFile) {
    glint::io::write_rgb8_png(flat(4, 4, 0), path("a.png"));
    glint::io::write_rgb8_png(flat(4, 5, 0), path("b.png"));
    RunResult r = run("compare '" + path("a.png") + "' '" + path("b.png") + "'");
    EXPECT_EQ(r.exit_code, 6);
    EXPECT_NE(r.err.find("sizes differ"), std::string::npos) << r.err;
    EXPECT_EQ(run("compare '" + path("a.png") + "' '" + path("none.png") + "'").exit_code, 3);
}

TEST_F(CliTest, RenderMissingSceneExitsThreeWithoutOutput) {
    RunResult r = run("render '" + path("none.pov") + "' -o '" + path("out.png") + "'");
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_NE(r.err.find("none.pov"), std::string::npos);
    EXPECT_EQ(count_files(), 0);
}

TEST_F(CliTest, RenderRejectsBadOutputBeforeRendering) {
    write_text("s.pov", "#version 3.7;\nsphere { 0, 1 }\n");
    RunResult r = run("render '" + path("s.pov") + "' -o '" + path("out.bmp") + "'");
    EXPECT_EQ(r.exit_code, 5) << r.err;
    EXPECT_NE(r.err.find("unsupported output format"), std::string::npos) << r.err;
    r = run("render '" + path("s.pov") + "' -o '" + path("no/such/folder/out.png") + "'");
    EXPECT_EQ(r.exit_code, 5) << r.err;
    EXPECT_EQ(count_files(), 1);  // only s.pov
}

// An EXR is written through the OpenImageIO module: without one the render fails before it
// starts (the scene is not even parsed: its #debug line never prints), and leaves nothing.
// A PNG needs no module.
TEST_F(CliTest, MissingImageModuleFailsBeforeRendering) {
    write_text("s.pov", "#version 3.7;\n#debug \"parsed\\n\"\nsphere { 0, 1 }\n");
    write_text("quick.pov", "#version 3.7;\nsphere { 0, 1 pigment { rgb 1 } }\n");
    const std::string no_module = "GLINT_IMAGE_MODULE=/nonexistent/libglint_oiio.so ";
    RunResult r = run_env(no_module, "render '" + path("s.pov") + "' -o '" + path("out.exr") + "'");
    EXPECT_EQ(r.exit_code, 5) << r.err;
    EXPECT_NE(r.err.find("cannot load glint's image module"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("parsed"), std::string::npos) << r.err;
    EXPECT_EQ(count_files(), 2);  // the two scenes
    r = run_env(no_module, "render '" + path("quick.pov") + "' -o '" + path("out.png") + "'");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(path("out.png")));
}

TEST_F(CliTest, PathTracerFlagsWarnUnderTheClassicRenderer) {
    write_text("s.pov", "#version 3.7;\nsphere { 0, 1 }\n");
    const std::string base = "render '" + path("s.pov") + "' -o '" + path("o.png") + "' -W 8 -H 6 ";
    const auto r = run(base + "--adaptive");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("--adaptive and --no-light-tree apply to the path tracer"),
              std::string::npos) << r.err;
    const auto p = run(base + "--integrator path --spp 4 --adaptive --no-light-tree");
    EXPECT_EQ(p.exit_code, 0) << p.err;
    EXPECT_EQ(p.err.find("apply to the path tracer"), std::string::npos) << p.err;
}

TEST_F(CliTest, RenderRejectsBadFlags) {
    write_text("s.pov", "#version 3.7;\nsphere { 0, 1 }\n");
    std::string base = "render '" + path("s.pov") + "' -o '" + path("o.png") + "' ";
    EXPECT_EQ(run(base + "--aa bogus").exit_code, 1);
    EXPECT_EQ(run(base + "--aa grid:0").exit_code, 1);
    EXPECT_EQ(run(base + "--aa adaptive:x").exit_code, 1);
    EXPECT_EQ(run(base + "--aa adaptive2:9").exit_code, 1);
    EXPECT_EQ(run(base + "--aa adaptive --aa-jitter 2").exit_code, 1);
    EXPECT_EQ(run(base + "--width 0").exit_code, 1);
    EXPECT_EQ(run(base + "--progress sometimes").exit_code, 1);
    EXPECT_EQ(run(base + "--threads -1").exit_code, 1);
    EXPECT_EQ(count_files(), 1);
}

TEST_F(CliTest, SceneErrorHasLocationSourceLineAndCaret) {
    write_text("bad.pov", "#version 3.7;\nsphere { 0, 1\n  pigment { rgb 1 }\n  finsh { ambient 1 }\n}\n");
    RunResult r = run("render '" + path("bad.pov") + "' -o '" + path("o.png") + "'");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    std::string where = path("bad.pov") + ":4:3: error: ";
    EXPECT_NE(r.err.find(where), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\n    finsh { ambient 1 }\n    ^\n"), std::string::npos) << r.err;
    EXPECT_EQ(count_files(), 1);
}

namespace {

constexpr const char* kSmallScene =
    "#version 3.7;\n"
    "global_settings { assumed_gamma 1 }\n"
    "camera { location <0, 1, -4> look_at 0 }\n"
    "light_source { <3, 5, -3> rgb 1 }\n"
    "sphere { 0, 1 pigment { rgb <1, 0.4, 0.2> } finish { phong 0.5 } }\n"
    "plane { y, -1 pigment { checker rgb 1 rgb 0.2 } }\n";

}  // namespace

TEST_F(CliTest, ProgressLinesAreMonotoneAndEndAtOne) {
    write_text("s.pov", kSmallScene);
    RunResult r = run("render '" + path("s.pov") + "' -o '" + path("o.png") +
                      "' --progress=lines --width 64 --height 48");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::istringstream lines(r.err);
    std::string line, last_line;
    double last = -1;
    int count = 0;
    while (std::getline(lines, line)) {
        last_line = line;
        ASSERT_EQ(line.rfind("progress ", 0), 0u) << "unexpected stderr line: " << line;
        double f = std::stod(line.substr(9));
        EXPECT_GT(f, last);
        EXPECT_LE(f, 1.0);
        last = f;
        ++count;
    }
    EXPECT_GE(count, 1);
    EXPECT_EQ(last_line, "progress 1.00");
    EXPECT_TRUE(fs::exists(path("o.png")));
}

TEST_F(CliTest, NoProgressWhenNotATerminal) {
    write_text("s.pov", kSmallScene);
    RunResult r = run("render '" + path("s.pov") + "' -o '" + path("o.png") +
                      "' --width 32 --height 24");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(r.out, "");
}

TEST_F(CliTest, VerbosePrintsFeaturesAndTimings) {
    write_text("s.pov", kSmallScene);
    RunResult r = run("render '" + path("s.pov") + "' -o '" + path("o.exr") +
                      "' -v --width 32 --height 24");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("features used: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("sphere"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("skipped: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("time: parse "), std::string::npos) << r.err;
    glint::io::Rgb8Image img = glint::io::read_rgb8(path("o.exr"));
    EXPECT_EQ(img.width, 32);
    EXPECT_EQ(img.height, 24);
}

namespace {

// Whether process `pid` has installed a handler for `sig` (the SigCgt mask of /proc/PID/status).
bool catches(pid_t pid, int sig) {
    std::ifstream in("/proc/" + std::to_string(pid) + "/status");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("SigCgt:", 0) == 0)
            return (std::stoull(line.substr(7), nullptr, 16) >> (sig - 1)) & 1;
    return false;
}

// Runs glint with `args` (stderr to /dev/null), waits until it has installed its handler for
// `sig` (on a loaded machine start-up alone, before main, can take a second), sends `sig`
// `delay` after that, and waits up to 20 s for it to end (then kills it). `seconds`: from the
// signal to the exit.
struct Signalled {
    bool ended = false;
    int status = 0;
    double seconds = 0;
};
Signalled run_and_signal(std::vector<std::string> args, std::chrono::milliseconds delay,
                         int sig) {
    args.insert(args.begin(), GLINT_BINARY);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    Signalled r;
    pid_t pid = fork();
    if (pid < 0) return r;
    if (pid == 0) {
        std::freopen("/dev/null", "w", stderr);
        execv(GLINT_BINARY, argv.data());
        _exit(127);
    }
    const auto started = std::chrono::steady_clock::now();
    while (!catches(pid, sig) &&
           std::chrono::steady_clock::now() < started + std::chrono::seconds(20)) {
        if (waitpid(pid, &r.status, WNOHANG) == pid) {  // ended before it could be signalled
            r.ended = true;
            return r;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::this_thread::sleep_for(delay);
    kill(pid, sig);
    const auto sent = std::chrono::steady_clock::now();
    pid_t done = 0;
    while ((done = waitpid(pid, &r.status, WNOHANG)) == 0 &&
           std::chrono::steady_clock::now() < sent + std::chrono::seconds(20))
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
    r.ended = done == pid;
    if (!r.ended) {
        kill(pid, SIGKILL);
        waitpid(pid, &r.status, 0);
    }
    return r;
}

}  // namespace

TEST_F(CliTest, InterruptExits130WithoutOutput) {
    // A render far too large to finish in the time before the signal.
    write_text("s.pov", kSmallScene);
    const Signalled r = run_and_signal(
        {"render", path("s.pov"), "-o", path("o.png"), "--width", "4000", "--height", "4000",
         "--aa", "grid:8", "--threads", "1", "--progress", "none"},
        std::chrono::milliseconds(1500), SIGINT);
    ASSERT_TRUE(r.ended) << "glint did not stop within 20 s of SIGINT";
    ASSERT_TRUE(WIFEXITED(r.status));
    EXPECT_EQ(WEXITSTATUS(r.status), 130);
    EXPECT_EQ(count_files(), 1);  // only s.pov: no image, no temporary
}

TEST_F(CliTest, TermDuringParsingExits130WithoutOutput) {
    // A scene whose parse would take practically forever (nested loops, each under the
    // per-loop limit): SIGTERM must stop the parser within a second.
    write_text("s.pov",
               "#version 3.7;\n#declare I = 0;\n#while (I < 1000000)\n  #declare J = 0;\n"
               "  #while (J < 1000000) #declare J = J + 1; #end\n  #declare I = I + 1;\n#end\n"
               "sphere { 0, 1 }\n");
    const Signalled r =
        run_and_signal({"render", path("s.pov"), "-o", path("o.png"), "--progress", "none"},
                       std::chrono::milliseconds(1000), SIGTERM);
    ASSERT_TRUE(r.ended) << "glint did not stop within 20 s of SIGTERM while parsing";
    ASSERT_TRUE(WIFEXITED(r.status));
    EXPECT_EQ(WEXITSTATUS(r.status), 130);
    EXPECT_LT(r.seconds, 1.0);
    EXPECT_EQ(count_files(), 1);  // only s.pov
}

TEST_F(CliTest, IncludeFlagTakesOneFolderEach) {
    fs::create_directories(dir_ / "inc");
    write_text("inc/size.inc", "#declare R = 0.5;\n");
    write_text("s.pov", "#version 3.7;\n#include \"size.inc\"\nsphere { 0, R }\n");
    // -I before the scene must not swallow the scene path.
    RunResult r = run("ir -I '" + path("inc") + "' '" + path("s.pov") + "'");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("sphere"), std::string::npos) << r.out;
    r = run("ir '" + path("s.pov") + "'");
    EXPECT_EQ(r.exit_code, 3) << r.err;  // size.inc is not found without -I
}

TEST_F(CliTest, DebugTextReachesStderr) {
    write_text("s.pov", std::string(kSmallScene) + "#debug \"checkpoint reached\\n\"\n");
    RunResult r = run("render '" + path("s.pov") + "' -o '" + path("o.png") +
                      "' --width 8 --height 6");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("checkpoint reached\n"), std::string::npos) << r.err;
}
