// POV-Ray's command line in `glint render`: switches and .ini files read into PovSettings,
// the animation loop's frames and clocks (POV-Ray 3.7's AnimationProcessing), output names,
// and end to end through the glint binary (GLINT_BINARY).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "io/image_compare.h"

#include "formats/pov/command_line.h"

namespace fs = std::filesystem;
using namespace glint::pov;

namespace {

PovSettings parse(const std::vector<std::string>& args) { return read_pov_arguments(args); }

std::string usage_error(const std::vector<std::string>& args) {
    try {
        parse(args);
    } catch (const glint::Error& e) {
        EXPECT_EQ(e.kind(), glint::ErrorKind::Usage);
        return e.what();
    }
    return "(no error)";
}

class TempDir {
  public:
    explicit TempDir(const std::string& name)
        : dir_(fs::temp_directory_path() /
               ("glint_pov_cli_" + name + "_" + std::to_string(::getpid()))) {
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    ~TempDir() { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    void write(const std::string& name, const std::string& text) const {
        std::ofstream(dir_ / name) << text;
    }
    const fs::path& dir() const { return dir_; }

  private:
    fs::path dir_;
};

}  // namespace

TEST(PovSwitches, SizeInputOutputAndLibraryPaths) {
    PovSettings s = parse({"+Iscene.pov", "+Oout.png", "+W640", "+h480", "+L/a", "+L/b"});
    EXPECT_EQ(s.input, "scene.pov");
    EXPECT_EQ(s.output, "out.png");
    EXPECT_EQ(s.width, 640);
    EXPECT_EQ(s.height, 480);  // switches are case-insensitive
    EXPECT_EQ(s.library_paths, (std::vector<std::string>{"/a", "/b"}));
    EXPECT_TRUE(s.warnings.empty());
    EXPECT_EQ(parse({"+I\"my scene.pov\""}).input, "my scene.pov");
}

TEST(PovSwitches, AntiAliasing) {
    PovSettings s = parse({"+A0.1", "+AM1", "+R4", "-J"});
    EXPECT_EQ(s.antialias, true);
    EXPECT_DOUBLE_EQ(*s.aa_threshold, 0.1);
    EXPECT_EQ(s.sampling_method, 1);
    EXPECT_EQ(s.aa_depth, 4);
    EXPECT_EQ(s.jitter, false);
    PovSettings off = parse({"+A", "-A"});  // the last one wins
    EXPECT_EQ(off.antialias, false);
    EXPECT_FALSE(off.aa_threshold.has_value());
    EXPECT_EQ(parse({"+J0.5"}).jitter, true);
    EXPECT_DOUBLE_EQ(*parse({"+J0.5"}).jitter_amount, 0.5);
    EXPECT_DOUBLE_EQ(*parse({"+J3"}).jitter_amount, 1.0);  // POV-Ray clips it to [0, 1]
    EXPECT_FALSE(parse({"+J"}).jitter_amount.has_value());
    EXPECT_EQ(usage_error({"+AM4"}), "+AM4: sampling method must be 1, 2 or 3");
    EXPECT_EQ(usage_error({"+A5"}), "+A5: threshold must be in [0, 3]");
}

TEST(PovSwitches, ClockAndAnimation) {
    PovSettings s = parse({"+K0.25", "+KFI2", "+KFF20", "+KI1.5", "+KF3", "+KC", "+SF5",
                           "+EF0.5", "+WT2"});
    EXPECT_DOUBLE_EQ(*s.clock, 0.25);
    EXPECT_EQ(s.initial_frame, 2);
    EXPECT_EQ(s.final_frame, 20);
    EXPECT_DOUBLE_EQ(*s.initial_clock, 1.5);
    EXPECT_DOUBLE_EQ(*s.final_clock, 3);
    EXPECT_EQ(s.cyclic, true);
    EXPECT_DOUBLE_EQ(*s.subset_start, 5);
    EXPECT_DOUBLE_EQ(*s.subset_end, 0.5);
    EXPECT_EQ(s.threads, 2);
    EXPECT_EQ(parse({"+KC", "-KC"}).cyclic, false);
}

TEST(PovSwitches, OutputTypeAndIgnoredOptions) {
    PovSettings s = parse({"+FN", "-D", "+V", "-P", "+Q9", "+GA", "+X"});
    EXPECT_EQ(s.output_type, 'N');
    ASSERT_EQ(s.warnings.size(), 6u);
    EXPECT_EQ(s.warnings[0], "-D (display) is ignored");
    EXPECT_EQ(s.warnings[1], "+V (verbose) is ignored");
    EXPECT_EQ(s.warnings[3], "+Q9 (quality (glint always renders at full quality)) is ignored");
    PovSettings t = parse({"+FT", "+UA", "+SC0.5"});
    EXPECT_EQ(t.output_type, 'T');
    ASSERT_EQ(t.warnings.size(), 3u);
    EXPECT_EQ(t.warnings[1], "+UA (output alpha) is not supported and is ignored");
    EXPECT_EQ(t.warnings[2],
              "+SC0.5 (partial render (start column)) is not supported and is ignored");
    EXPECT_EQ(parse({"+FE"}).output_type, 'E');
    EXPECT_EQ(usage_error({"+FZ"}),
              "+FZ: unknown output file type 'Z' (N png, E exr, H hdr, J jpeg, T/C targa, P ppm, "
              "B bmp, S system)");
}

TEST(PovSwitches, UnknownAndMalformedSwitchesAreUsageErrors) {
    EXPECT_EQ(usage_error({"+Zfoo"}), "unknown POV-Ray option '+Zfoo'");
    EXPECT_EQ(usage_error({"+Wabc"}), "+Wabc: expected a number, got 'abc'");
    EXPECT_EQ(usage_error({"+W0"}), "+W0: must be in 1..65536");
    EXPECT_EQ(usage_error({"+KFF2.5"}), "+KFF2.5: expected an integer, got '2.5'");
    EXPECT_EQ(usage_error({"+I"}), "+I: missing file name");
    EXPECT_EQ(usage_error({"+O-"}), "+O-: writing the image to standard output is not supported");
}

TEST(PovArgs, SplitKeepsGlintFlagsAndTheirValues) {
    std::vector<std::string> argv = {"glint", "render", "scene.pov", "-o",  "out.png",
                                     "+W640", "-A",     "-W",        "100", "-v",
                                     "-I",    "inc",    "--clock",   "-1",  "anim.ini[Low]",
                                     "-Iother.pov", "+KFF3"};
    SplitArgs split = split_render_args(argv, 2);
    EXPECT_EQ(split.glint,
              (std::vector<std::string>{"glint", "render", "scene.pov", "-o", "out.png", "-W",
                                        "100", "-v", "-I", "inc", "--clock", "-1"}));
    EXPECT_EQ(split.pov, (std::vector<std::string>{"+W640", "-A", "anim.ini[Low]",
                                                   "-Iother.pov", "+KFF3"}));
}

TEST(PovIni, KeysSectionsCommentsAndSwitchLines) {
    TempDir t("ini");
    t.write("res.ini",
            "; POV-Ray's RES.INI example\n"
            "Input_File_Name = \"my scene.pov\"  ; a comment\n"
            "+W120 +H100\n"
            "[Low]\n"
            "+W80 +H60\n"
            "[Really High]\n"
            "width=800\n"
            "HEIGHT=600\n"
            "Antialias=on\n"
            "Antialias_Threshold=0.2\n"
            "Antialias_Depth=2\n"
            "Sampling_Method=1\n"
            "Jitter=off\n"
            "Library_Path=/inc\n"
            "Declare=Size=2.5\n"
            "Output_File_Type=N\n"
            "Display=off\n"
            "Verbose=on\n"
            "Pause_When_Done=off\n");
    PovSettings top = parse({t.path("res.ini")});
    EXPECT_EQ(top.input, "my scene.pov");
    EXPECT_EQ(top.width, 120);
    EXPECT_EQ(top.height, 100);
    PovSettings low = parse({t.path("res.ini[low]")});  // labels ignore case
    EXPECT_FALSE(low.input.has_value());                 // a label skips the unlabeled top
    EXPECT_EQ(low.width, 80);
    PovSettings high = parse({t.path("res.ini[Really High]")});
    EXPECT_EQ(high.width, 800);
    EXPECT_EQ(high.height, 600);
    EXPECT_EQ(high.antialias, true);
    EXPECT_DOUBLE_EQ(*high.aa_threshold, 0.2);
    EXPECT_EQ(high.aa_depth, 2);
    EXPECT_EQ(high.jitter, false);
    EXPECT_EQ(high.library_paths, std::vector<std::string>{"/inc"});
    ASSERT_EQ(high.declares.size(), 1u);
    EXPECT_EQ(high.declares[0].first, "Size");
    EXPECT_DOUBLE_EQ(high.declares[0].second, 2.5);
    EXPECT_EQ(high.output_type, 'N');
    ASSERT_EQ(high.warnings.size(), 3u);
    EXPECT_EQ(high.warnings[0], t.path("res.ini") + ":17: Display is ignored");
    EXPECT_EQ(usage_error({t.path("res.ini[Medium]")}),
              t.path("res.ini[Medium]") + ": no section [medium] in " + t.path("res.ini"));
    // Switches and .ini files apply in command-line order.
    EXPECT_EQ(parse({"+W5", t.path("res.ini")}).width, 120);
    EXPECT_EQ(parse({t.path("res.ini"), "+W5"}).width, 5);
}

TEST(PovIni, AnimationKeysNestingAndErrors) {
    TempDir t("ini2");
    t.write("inner.ini", "Final_Frame=12\n");
    t.write("anim.ini",
            "Initial_Frame=2\nInitial_Clock=0.5\nFinal_Clock=2\nSubset_Start_Frame=3\n"
            "Subset_End_Frame=0.5\nCyclic_Animation=yes\n" + t.path("inner") + "\n");
    PovSettings s = parse({t.path("anim.ini")});
    EXPECT_EQ(s.initial_frame, 2);
    EXPECT_EQ(s.final_frame, 12);  // from the nested inner.ini (.ini assumed)
    EXPECT_DOUBLE_EQ(*s.initial_clock, 0.5);
    EXPECT_DOUBLE_EQ(*s.final_clock, 2);
    EXPECT_DOUBLE_EQ(*s.subset_start, 3);
    EXPECT_DOUBLE_EQ(*s.subset_end, 0.5);
    EXPECT_EQ(s.cyclic, true);
    t.write("bad.ini", "Frobnicate=3\n");
    EXPECT_EQ(usage_error({t.path("bad.ini")}),
              t.path("bad.ini") + ":1: Frobnicate: unknown POV-Ray ini option");
    t.write("bad2.ini", "Width=wide\n");
    EXPECT_EQ(usage_error({t.path("bad2.ini")}),
              t.path("bad2.ini") + ":1: Width: expected a number, got 'wide'");
    t.write("bad3.ini", "Declare=1x=2\n");
    EXPECT_EQ(usage_error({t.path("bad3.ini")}),
              t.path("bad3.ini") + ":1: Declare: '1x' is not an identifier");
    try {
        parse({t.path("missing.ini")});
        ADD_FAILURE() << "no error";
    } catch (const glint::Error& e) {
        EXPECT_EQ(e.kind(), glint::ErrorKind::MissingFile);
    }
}

TEST(PovAnimation, ClockRunsLinearlyFromInitialToFinal) {
    PovSettings s;
    s.final_frame = 5;
    AnimationPlan p = plan_animation(s);
    ASSERT_TRUE(p.animated);
    ASSERT_EQ(p.frames.size(), 5u);
    EXPECT_EQ(p.frames[0].number, 1);
    EXPECT_DOUBLE_EQ(p.frames[0].clock, 0.0);
    EXPECT_DOUBLE_EQ(p.frames[2].clock, 0.5);
    EXPECT_DOUBLE_EQ(p.frames[4].clock, 1.0);
    EXPECT_DOUBLE_EQ(p.clock_delta, 0.25);
    EXPECT_EQ(p.digits, 1);
    EXPECT_FALSE(plan_animation(PovSettings{}).animated);
}

TEST(PovAnimation, CyclicStopsOneStepShortOfTheFinalClock) {
    // A 10-frame cyclic animation runs the clock 0.0 .. 0.9 (manual 3.2.1.4).
    PovSettings s;
    s.final_frame = 10;
    s.cyclic = true;
    AnimationPlan p = plan_animation(s);
    ASSERT_EQ(p.frames.size(), 10u);
    EXPECT_EQ(p.frames.back().number, 10);
    EXPECT_NEAR(p.frames.back().clock, 0.9, 1e-12);
    EXPECT_NEAR(p.clock_delta, 0.1, 1e-12);
    EXPECT_EQ(p.digits, 2);  // POV-Ray counts the digits of final_frame + 1 (11)
}

TEST(PovAnimation, SubsetsByNumberAndFractionKeepTheClock) {
    PovSettings s;
    s.final_frame = 100;
    s.subset_start = 30;
    s.subset_end = 40;
    AnimationPlan p = plan_animation(s);
    ASSERT_EQ(p.frames.size(), 11u);
    EXPECT_EQ(p.frames.front().number, 30);
    EXPECT_NEAR(p.frames.front().clock, 29.0 / 99.0, 1e-12);
    EXPECT_EQ(p.digits, 3);
    s.subset_start = 0.25;  // a fraction of the 100 frames
    s.subset_end = 0.5;
    p = plan_animation(s);
    EXPECT_EQ(p.frames.front().number, 25);
    EXPECT_EQ(p.frames.back().number, 50);
    PovSettings c;
    c.initial_frame = 3;
    c.final_frame = 5;
    c.initial_clock = 10;
    c.final_clock = 20;
    p = plan_animation(c);
    ASSERT_EQ(p.frames.size(), 3u);
    EXPECT_DOUBLE_EQ(p.frames[1].clock, 15);
    EXPECT_EQ(p.frames[1].number, 4);
}

// glint's --frames: the animation itself where POV-Ray's options define none, a subset of
// theirs where they do.
TEST(PovAnimation, FrameRangeIsTheAnimationOrASubsetOfIt) {
    PovSettings own;
    apply_frame_range(own, 4, 6);
    AnimationPlan p = plan_animation(own);
    ASSERT_EQ(p.frames.size(), 3u);
    EXPECT_EQ(p.frames.front().number, 4);
    EXPECT_DOUBLE_EQ(p.frames.front().clock, 0.0);
    EXPECT_DOUBLE_EQ(p.frames.back().clock, 1.0);
    PovSettings theirs;
    theirs.initial_frame = 1;
    theirs.final_frame = 11;
    apply_frame_range(theirs, 6, 7);
    p = plan_animation(theirs);
    ASSERT_EQ(p.frames.size(), 2u);
    EXPECT_EQ(p.frames.front().number, 6);
    EXPECT_DOUBLE_EQ(p.frames.front().clock, 0.5);  // the clock of the whole 1..11 animation
}

TEST(PovAnimation, OutputNamesAreZeroPadded) {
    EXPECT_EQ(frame_output_name("out.png", 7, 2), "out07.png");
    EXPECT_EQ(frame_output_name("dir/out.png", 12, 3), "dir/out012.png");
    EXPECT_EQ(frame_output_name("out.png", 123, 2), "out123.png");
}

// ---------------------------------------------------------------- end to end

namespace {

struct GlintRun {
    int exit_code = -1;
    std::string err;
};

GlintRun run_glint(const TempDir& t, const std::string& args) {
    std::string cmd = "cd '" + t.dir().string() + "' && '" + GLINT_BINARY + "' " + args +
                      " --progress=none >/dev/null 2>stderr.txt";
    int status = std::system(cmd.c_str());
    GlintRun r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(t.dir() / "stderr.txt");
    r.err.assign(std::istreambuf_iterator<char>(in), {});
    return r;
}

// A sphere moving right with the clock, brightness from a Declare'd float.
const char* kScene =
    "#version 3.7;\n"
    "global_settings { assumed_gamma 1 }\n"
    "#ifndef (Bright) #declare Bright = 1; #end\n"
    "camera { location <0, 0, -5> look_at 0 }\n"
    "light_source { <0, 5, -5> rgb Bright }\n"
    "sphere { <-1 + 2 * clock, 0, 0>, 0.6 pigment { rgb <1, clock_on, frame_number / 10> } }\n";

}  // namespace

TEST(PovCliEndToEnd, SwitchesRenderLikeGlintFlags) {
    TempDir t("e2e");
    t.write("scene.pov", kScene);
    GlintRun pov = run_glint(t, "render +Iscene.pov +Opov.png +W32 +H24 -D -V +K0.5");
    ASSERT_EQ(pov.exit_code, 0) << pov.err;
    EXPECT_NE(pov.err.find("glint: warning: -D (display) is ignored"), std::string::npos)
        << pov.err;
    GlintRun glint = run_glint(t, "render scene.pov -o glint.png -W 32 -H 24 --clock 0.5");
    ASSERT_EQ(glint.exit_code, 0) << glint.err;
    auto a = glint::io::read_rgb8(t.path("pov.png"));
    auto b = glint::io::read_rgb8(t.path("glint.png"));
    EXPECT_EQ(a.width, 32);
    EXPECT_EQ(a.rgb, b.rgb);
    // Without +O the image is named after the scene, as POV-Ray names it.
    ASSERT_EQ(run_glint(t, "render +Iscene +W8 +H6").exit_code, 0);
    EXPECT_TRUE(fs::exists(t.path("scene.png")));
    GlintRun bad = run_glint(t, "render scene.pov +Zap");
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.err.find("unknown POV-Ray option '+Zap'"), std::string::npos) << bad.err;
}

// +A, +AM2 and +J map onto --aa and --aa-jitter; POV-Ray's default jitter moves sub-samples.
TEST(PovCliEndToEnd, AntiAliasingSwitchesRenderLikeGlintFlags) {
    TempDir t("e2e_aa");
    t.write("scene.pov", kScene);
    auto same = [&](const std::string& pov_flags, const std::string& glint_flags) {
        GlintRun a = run_glint(t, "render scene.pov -o a.png -W 40 -H 30 " + pov_flags);
        GlintRun b = run_glint(t, "render scene.pov -o b.png -W 40 -H 30 " + glint_flags);
        EXPECT_EQ(a.exit_code, 0) << a.err;
        EXPECT_EQ(b.exit_code, 0) << b.err;
        return glint::io::read_rgb8(t.path("a.png")).rgb ==
               glint::io::read_rgb8(t.path("b.png")).rgb;
    };
    EXPECT_TRUE(same("+A0.1", "--aa adaptive:0.1"));  // jitter 1.0 on both sides
    EXPECT_TRUE(same("+A0.1 -J", "--aa adaptive:0.1 --aa-jitter 0"));
    EXPECT_TRUE(same("+A0.1 +J0.5", "--aa adaptive:0.1 --aa-jitter 0.5"));
    EXPECT_TRUE(same("+A0.1 +AM2 +R2", "--aa adaptive2:0.1 +R2"));
    EXPECT_FALSE(same("+A0.1", "--aa adaptive:0.1 --aa-jitter 0"));
    EXPECT_FALSE(same("+A0.1 +AM2", "--aa adaptive:0.1"));
    GlintRun am3 = run_glint(t, "render scene.pov -o c.png -W 8 -H 6 +A +AM3");
    EXPECT_EQ(am3.exit_code, 0) << am3.err;
    EXPECT_NE(am3.err.find("sampling method 3 (+AM3) is not a POV-Ray 3.7 method"),
              std::string::npos) << am3.err;
}

TEST(PovCliEndToEnd, IniAnimationWritesNumberedFrames) {
    TempDir t("anim");
    t.write("scene.pov", kScene);
    t.write("anim.ini",
            "Input_File_Name=scene.pov\nOutput_File_Name=frame.png\nWidth=16\nHeight=12\n"
            "Initial_Frame=1\nFinal_Frame=10\nSubset_Start_Frame=9\nDeclare=Bright=0.5\n"
            "Display=off\n");
    GlintRun r = run_glint(t, "render anim.ini");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(t.path("frame09.png")));
    EXPECT_TRUE(fs::exists(t.path("frame10.png")));
    EXPECT_FALSE(fs::exists(t.path("frame08.png")));
    // clock_on is 1 and frame_number/10 is 1 at frame 10: pigment rgb <1, 1, 1>.
    auto img = glint::io::read_rgb8(t.path("frame10.png"));
    auto center = [&](const glint::io::Rgb8Image& im) {
        size_t i = (static_cast<size_t>(im.height / 2) * im.width + im.width - 5) * 3;
        return std::vector<int>{im.rgb[i], im.rgb[i + 1], im.rgb[i + 2]};
    };
    std::vector<int> c = center(img);
    EXPECT_GT(c[0], 0);
    EXPECT_EQ(c[0], c[1]);
    EXPECT_EQ(c[1], c[2]);
}

TEST(PovCliEndToEnd, DeclareAndAnimationIdentifiersReachTheScene) {
    TempDir t("ids");
    t.write("ids.pov",
            "#version 3.7;\n"
            "#if (Size != 2.5 | frame_number != 3 | initial_frame != 2 | final_frame != 4 |"
            " clock_delta != 0.5 | clock != 1.5 | initial_clock != 1 | final_clock != 2 |"
            " clock_on != 1)\n"
            "#error \"wrong animation identifiers\"\n#end\n"
            "background { rgb 1 }\n");
    GlintRun r = run_glint(t, "render ids.pov -o ids.png +W4 +H4 +KFI2 +KFF4 +KI1 +KF2 +SF3 +EF3 "
                         "Declare.ini");
    EXPECT_EQ(r.exit_code, 3) << r.err;  // Declare.ini does not exist yet
    t.write("Declare.ini", "Declare=Size=2.5\n");
    r = run_glint(t, "render ids.pov -o ids.png +W4 +H4 +KFI2 +KFF4 +KI1 +KF2 +SF3 +EF3 "
                     "Declare.ini");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(t.path("ids3.png")));
}
