// The glint subcommands. Each registers its flags on the CLI11 app and runs from a plain
// struct of parsed arguments, returning the process exit code (cli_common.h).
#pragma once

#include <string>
#include <vector>

#include "app/scene_loading.h"
#include "io/image_output.h"

namespace CLI {
class App;
}

namespace glint::app {

struct RenderArgs {
    SceneRequest scene;  // SCENE, -I, --clock, --width/--height (also the image size)
    std::string output;
    std::string aa = "none";
    int threads = 0;
    int aa_depth = 3;  // POV-Ray's +R (adaptive anti-aliasing recursion depth)
    double aa_jitter = 1.0;  // --aa-jitter: POV-Ray's +J amount (0: -J)
    bool verbose = false;
    std::string progress;  // empty: bar on a terminal, none otherwise
    // Path tracer (--integrator path): samples per pixel, bounces, sampler seed, time limit.
    std::string integrator = "whitted";
    int spp = 16;
    int max_depth = 8;
    unsigned seed = 0;
    bool no_light_tree = false;  // --no-light-tree
    // --adaptive, --adaptive-threshold, --adaptive-min-samples (any of them turns it on)
    bool adaptive = false;
    double adaptive_threshold = 0;
    int adaptive_min_samples = 0;
    double time_limit = 0;
    long photons = 0;             // --integrator sppm: photons per pass (0: one per pixel)
    double photon_radius = 2.0;   // --integrator sppm: initial radius in pixel footprints
    // Path tracer outputs beside OUT: --aov albedo,normal,depth and --variance write
    // <out-stem>.<name>.exr (render_command.cpp: aov_output_path).
    std::string aov;
    bool variance = false;
    // --save-partial: on SIGINT/SIGTERM write what was rendered (render_command.cpp).
    bool save_partial = false;
    // --exit-with-parent: stop, as on SIGTERM, once the process that started glint has ended.
    bool exit_with_parent = false;
    // Parts of a render (parts.h): --region x0,y0,x1,y1; --frames A-B (the animation, or a
    // subset of the one POV-Ray's options define); --frame K (one frame of it);
    // --skip-existing (leave an output that is already this job's complete part alone).
    std::string region;
    std::string frames;
    int frame = -1;
    bool skip_existing = false;
    bool animation_frame = false;  // set by run_render for each frame of an animation
    // --view/--look/--exposure/--gamma/--ocio-config: Blender's color management for 8-bit
    // output (convert_command.cpp: add_view_options).
    io::ViewSettings view;
    // POV-Ray switches and .ini files (formats/pov/command_line.h), in command-line order.
    // glint's own flags, where given, win over them; `given` records which were.
    std::vector<std::string> pov_args;
    struct {
        bool width = false, height = false, aa = false, aa_jitter = false, threads = false;
        bool clock = false;
        bool integrator = false, spp = false, seed = false, max_depth = false;
        bool adaptive = false;
    } given;
};

// `glint merge PART... -o OUT` (merge_command.cpp).
struct MergeArgs {
    std::vector<std::string> parts;
    std::string output;
    bool verify = false;  // --verify: check the parts (frames), write nothing
};

// `glint farm submit SCENE -o OUT --tiles N | --frames A-B` (farm_command.cpp).
struct FarmArgs {
    std::string scene;
    std::string output;
    int tiles = 0;
    std::string frames;
    std::string partition;
    std::string dir;        // the job's folder; default OUT-stem.farm beside OUT
    int cpus = 0;           // --cpus-per-task (0: Slurm's default)
    int retries = 2;        // attempts after a failed one, inside the task
    bool dry_run = false;
    bool no_submit = false;  // write the job's files, submit nothing (other schedulers)
    std::vector<std::string> render_args;  // passed to every `glint render`
};

struct IrArgs {
    SceneRequest scene;
};

struct CompareArgs {
    std::string a;
    std::string b;
    std::string diff;
    double tolerance = 2;
    double min_fraction = 0.99;
    // VALIDATION.md's "close" (renders that draw their own random numbers): also agree when
    // SSIM >= 0.95 and the mean absolute 8-bit difference is at most 2% (5.1 / 255).
    bool close = false;
};

// `glint report` (report_command.cpp): error against run time for the path tracer and a peer.
struct ReportArgs {
    SceneRequest scene;  // SCENE, -I, --clock, --width/--height (default: the reference's size)
    std::string reference;
    std::string spp_steps = "1,4,16,64";
    std::string integrators = "path";  // glint's curves: a comma list of path, sppm
    long photons = 0;                  // sppm: photons per pass (0: one per pixel)
    std::string out = "report";
    int max_depth = 8;
    unsigned seed = 0;
    int seeds = 1;  // renders per step (seeds seed, seed + 1, ...)
    int threads = 0;
    std::string peer;        // shell command with {spp}, {out}, optional {time} and {seed}
    std::string peer_steps;  // empty: spp_steps
    std::string peer_name = "peer";
    bool verbose = false;
    bool given_width = false, given_height = false, given_max_depth = false;
};

// `glint convert IN.exr -o OUT.png [--view ...]` (convert_command.cpp).
struct ConvertArgs {
    std::string input;
    std::string output;
    io::ViewSettings view;
    bool verbose = false;
};

CLI::App* add_render_command(CLI::App& app, RenderArgs& args);
CLI::App* add_convert_command(CLI::App& app, ConvertArgs& args);
// Blender's Color Management flags, shared by render and convert.
void add_view_options(CLI::App& cmd, io::ViewSettings& view);
// Usage error for --look/--exposure/--gamma/--ocio-config set without --view; with --view the
// settings checked against the config (config_path resolved).
io::ViewSettings checked_view_settings(const io::ViewSettings& view);
int run_convert(const ConvertArgs& args);
CLI::App* add_ir_command(CLI::App& app, IrArgs& args);
CLI::App* add_compare_command(CLI::App& app, CompareArgs& args);
CLI::App* add_report_command(CLI::App& app, ReportArgs& args);

int run_render(const RenderArgs& args);
// The settings a render of `args` uses: glint's flags with POV-Ray's switches and .ini files
// merged in (image size, output name, ...), as run_render merges them.
RenderArgs effective_render_args(const RenderArgs& args);
// Where --aov NAME (and --variance) writes for OUTPUT: OUT's folder/<OUT's stem>.NAME.exr.
std::string aov_output_path(const std::string& output, const std::string& name);
// Where POV-Ray arguments may appear: argv with the POV-Ray ones of `glint render` taken out
// into `pov_args` (see split_render_args); other commands' arguments pass unchanged.
std::vector<std::string> take_pov_arguments(const std::vector<std::string>& argv,
                                            std::vector<std::string>& pov_args);
int run_ir(const IrArgs& args);
int run_compare(const CompareArgs& args);
int run_report(const ReportArgs& args);
CLI::App* add_merge_command(CLI::App& app, MergeArgs& args);
int run_merge(const MergeArgs& args);
CLI::App* add_farm_command(CLI::App& app, FarmArgs& args);
int run_farm(const FarmArgs& args);

}  // namespace glint::app
