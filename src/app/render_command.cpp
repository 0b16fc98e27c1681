// `glint render SCENE.pov -o OUT`: parse, render, encode, write; nothing is written unless
// every stage succeeds.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/parts.h"
#include "formats/pov/command_line.h"
#include "app/scene_loading.h"
#include "image/image_library.h"
#include "io/color_encoding.h"
#include "io/image_output.h"
#include "app/progress.h"
#include "io/scene_encoding.h"
#include "render/film/film.h"
#include "render/render.h"
#include "scene/features.h"

namespace glint::app {

// POV-Ray's options (formats/pov/command_line.h).
using pov::AnimationPlan;
using pov::PovFrame;
using pov::PovSettings;
using pov::SplitArgs;
using pov::apply_frame_range;
using pov::extension_for_output_type;
using pov::frame_output_name;
using pov::plan_animation;
using pov::read_pov_arguments;
using pov::split_render_args;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// --aa none | adaptive[:T] | grid:N
void parse_aa(const std::string& text, render::RenderOptions& options) {
    auto bad = [&](const std::string& why) {
        return Error(
            ErrorKind::Usage, {},
            "--aa " + text + ": " + why +
                " (expected none, adaptive[:T], adaptive2[:T] or grid:N)");
    };
    std::string mode = text;
    std::string param;
    if (size_t colon = text.find(':'); colon != std::string::npos) {
        mode = text.substr(0, colon);
        param = text.substr(colon + 1);
        if (param.empty()) throw bad("missing value after ':'");
    }
    char* end = nullptr;
    if (mode == "none") {
        if (!param.empty()) throw bad("none takes no value");
        options.aa = render::AaMode::None;
    } else if (mode == "adaptive" || mode == "adaptive2") {
        options.aa = mode == "adaptive" ? render::AaMode::Adaptive : render::AaMode::Adaptive2;
        if (!param.empty()) {
            double t = std::strtod(param.c_str(), &end);
            if (*end != '\0' || !(t >= 0 && t <= 3)) throw bad("threshold must be in [0, 3]");
            options.aa_threshold = t;
        }
    } else if (mode == "grid") {
        if (param.empty()) throw bad("grid needs N");
        long n = std::strtol(param.c_str(), &end, 10);
        if (*end != '\0' || n < 1 || n > 64) throw bad("N must be an integer in [1, 64]");
        options.aa = render::AaMode::Grid;
        options.grid_n = static_cast<int>(n);
    } else {
        throw bad("unknown mode '" + mode + "'");
    }
}

ProgressStyle progress_style(const std::string& flag) {
    if (flag.empty())
        return isatty(STDERR_FILENO) ? ProgressStyle::Bar : ProgressStyle::None;
    if (flag == "bar") return ProgressStyle::Bar;
    if (flag == "lines") return ProgressStyle::Lines;
    return ProgressStyle::None;
}

// Refuses an output path that cannot work before spending time on the render: unsupported
// extension, missing or unwritable folder, a folder in the file's place.
void check_output_path(const std::string& path) {
    io::output_format_for(path);  // throws for an unsupported extension
    io::check_writable(path);
}

void print_features(const scene::Features& f) {
    std::string used, skipped;
    for (const std::string& s : f.used()) used += (used.empty() ? "" : ", ") + s;
    for (const std::string& s : f.skipped()) skipped += (skipped.empty() ? "" : ", ") + s;
    std::fprintf(stderr, "features used: %s\n", used.empty() ? "(none)" : used.c_str());
    std::fprintf(stderr, "skipped: %s\n", skipped.empty() ? "(nothing)" : skipped.c_str());
}

std::string encoding_name(const io::OutputEncoding& e) {
    if (e.working_srgb) return "none (pre-3.7 scene without assumed_gamma: values as rendered)";
    std::string name = e.transfer == io::OutputEncoding::Transfer::Srgb    ? "sRGB"
                       : e.transfer == io::OutputEncoding::Transfer::Gamma ? "gamma"
                                                                           : "linear";
    if (e.working_gamma != 1.0) {
        char buf[64];
        std::snprintf(buf, sizeof buf, " from working gamma %g", e.working_gamma);
        name += buf;
    }
    return name;
}

}  // namespace

std::vector<std::string> take_pov_arguments(const std::vector<std::string>& argv,
                                            std::vector<std::string>& pov_args) {
    for (size_t i = 1; i < argv.size(); ++i) {
        if (!argv[i].empty() && argv[i][0] == '-') continue;  // --help, --version
        if (argv[i] != "render") break;
        SplitArgs split = split_render_args(argv, i + 1);
        pov_args = split.pov;
        return split.glint;
    }
    return argv;
}

CLI::App* add_render_command(CLI::App& app, RenderArgs& args) {
    CLI::App* cmd =
        app.add_subcommand("render", "Render a POV-Ray scene or an OBJ/MTL model to an image");
    cmd->footer(
        "SCENE is a POV-Ray scene (.pov) or an OBJ/MTL model (.obj: framed by a camera and lit "
        "by a default rig). POV-Ray's own switches (+W640 +H480 +A0.3 +Iscene.pov +Oout.png "
        "+KFF10 ...) and .ini files (scene.ini, res.ini[Low]) are accepted too; glint's flags "
        "win over them");
    add_scene_options(*cmd, args.scene, /*scene_required=*/false);
    cmd->add_option("-o,--output", args.output,
                    "Output image; format from the extension: png, exr, tif, hdr, jpg "
                    "(with POV-Ray options it may be left out: the scene's name with .png, as "
                    "POV-Ray names it)");
    cmd->add_option("--aa", args.aa,
                    "Anti-aliasing: none, adaptive[:T] (POV-Ray +A, sampling method 1), "
                    "adaptive2[:T] (+AM2, recursive), grid:N")
        ->capture_default_str();
    cmd->add_option("--aa-jitter", args.aa_jitter,
                    "Adaptive anti-aliasing: jitter of the sub-samples, as POV-Ray's +J amount "
                    "(0 turns it off, as -J)")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
    cmd->add_option("--threads", args.threads, "Worker threads (0: all hardware threads)")
        ->capture_default_str()
        ->check(CLI::Range(0, 4096));
    cmd->add_option("--integrator", args.integrator,
                    "whitted (POV-Ray's classic model), path (Monte Carlo path tracer) or sppm "
                    "(stochastic progressive photon mapping: the path tracer's materials and "
                    "lights, caustics of point lights too; --spp passes)")
        ->capture_default_str()
        ->check(CLI::IsMember({"whitted", "path", "sppm"}));
    cmd->add_option("--spp", args.spp, "Path tracer: samples per pixel (at most, with --time-limit)")
        ->capture_default_str()
        ->check(CLI::Range(1, 1 << 24));
    cmd->add_option("--max-depth", args.max_depth, "Path tracer: maximum bounces")
        ->capture_default_str()
        ->check(CLI::Range(0, 4096));
    cmd->add_option("--seed", args.seed, "Path tracer: sampler seed")->capture_default_str();
    cmd->add_flag("--adaptive", args.adaptive,
                  "Path tracer: adaptive sampling as Cycles' Noise Threshold (a pixel stops "
                  "once its noise estimate is under the threshold; a Blender scene's own "
                  "setting applies without it)");
    cmd->add_option("--adaptive-threshold", args.adaptive_threshold,
                    "Adaptive sampling: Cycles' noise threshold (0: automatic, from --spp)")
        ->check(CLI::Range(0.0, 1.0));
    cmd->add_option("--adaptive-min-samples", args.adaptive_min_samples,
                    "Adaptive sampling: samples every pixel takes first (0: automatic)")
        ->check(CLI::Range(0, 1 << 24));
    cmd->add_flag("--no-light-tree", args.no_light_tree,
                  "Path tracer: pick emitting objects by their power alone, not from the shading "
                  "point by the light tree (for comparisons, as Cycles' Light Tree unchecked)");
    cmd->add_option("--photons", args.photons,
                    "sppm: photons per pass (0: one per pixel of the image)")
        ->capture_default_str()
        ->check(CLI::Range(0L, 1L << 30));
    cmd->add_option("--photon-radius", args.photon_radius,
                    "sppm: initial gather radius, in pixel footprints at the visible point")
        ->capture_default_str()
        ->check(CLI::Range(0.01, 1000.0));
    cmd->add_option("--time-limit", args.time_limit,
                    "Path tracer: stop after the progressive pass that passes S seconds (0: none)")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1e9));
    cmd->add_option("--aov", args.aov,
                    "Path tracer: also write linear EXRs beside OUT, a comma list of albedo "
                    "(OUT-stem.albedo.exr: the first visible hit's base color, an emitter's "
                    "emission when its base is black), normal (.normal.exr: world-space shading "
                    "normal facing the camera, -1..1), depth (.depth.exr, channel Z: distance "
                    "along the camera ray); each the mean over the pixel's samples, a sample "
                    "that hits nothing counting 0 (so depth 0 where nothing is hit)");
    cmd->add_flag("--save-partial", args.save_partial,
                  "On SIGINT/SIGTERM write what was rendered, still atomically, then exit 130: "
                  "Whitted the finished 32x32 tiles and transparent black elsewhere; the path "
                  "tracer every pixel at the samples of its last finished progressive pass "
                  "(1, 2, 4, 8, ... spp). The file's ImageDescription says how much");
    cmd->add_flag("--exit-with-parent", args.exit_with_parent,
                  "Stop as on SIGTERM when the process that started glint ends (for programs "
                  "that run glint, such as the Blender add-on: a crash of theirs leaves no "
                  "glint rendering)");
    cmd->add_flag("--variance", args.variance,
                  "Path tracer: also write OUT-stem.variance.exr, per pixel and channel the "
                  "variance of the pixel's mean (sample variance / n; 0 with fewer than 2 "
                  "samples)");
    cmd->add_option("--region", args.region,
                    "Render only the pixels x0..x1-1, y0..y1-1 (x0,y0,x1,y1; 0 at the top left) "
                    "of the image, each as the whole render has it, bit for bit; the file is "
                    "that rectangle, its metadata says where it belongs (glint merge joins "
                    "them)");
    cmd->add_option("--frames", args.frames,
                    "Render frames A to B of an animation (A-B): POV-Ray's Initial_Frame and "
                    "Final_Frame, the clock running from 0 (+KI) to 1 (+KF) over them; where "
                    "POV-Ray options define the animation, the frames of it to render (+SF, "
                    "+EF). Output names get the frame number, as POV-Ray's do");
    cmd->add_option("--frame", args.frame,
                    "Render only frame K of the animation (--frames or POV-Ray's options)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_flag("--skip-existing", args.skip_existing,
                  "Leave the output alone when it is already this render's complete result "
                  "(read back in full, its job signature and region those of this command): "
                  "reruns of a farm job render only what is missing");
    add_view_options(*cmd, args.view);
    cmd->add_flag("-v,--verbose", args.verbose, "Print features used and skipped, and timings");
    cmd->add_option("--progress", args.progress,
                    "Progress on stderr: bar, lines (`progress 0.42`), none "
                    "(default: bar on a terminal, none otherwise)")
        ->check(CLI::IsMember({"bar", "lines", "none"}));
    cmd->parse_complete_callback([cmd, &args] {
        args.given.width = cmd->count("--width") > 0;
        args.given.height = cmd->count("--height") > 0;
        args.given.aa = cmd->count("--aa") > 0;
        args.given.aa_jitter = cmd->count("--aa-jitter") > 0;
        args.given.threads = cmd->count("--threads") > 0;
        args.given.clock = cmd->count("--clock") > 0;
        args.given.integrator = cmd->count("--integrator") > 0;
        args.given.spp = cmd->count("--spp") > 0;
        args.given.seed = cmd->count("--seed") > 0;
        args.given.adaptive = cmd->count("--adaptive") + cmd->count("--adaptive-threshold") +
                                  cmd->count("--adaptive-min-samples") > 0;
        args.given.max_depth = cmd->count("--max-depth") > 0;
    });
    return cmd;
}

namespace {

// Resolves POV-Ray's input name as POV-Ray does: as given, with .pov added when it has no
// extension, then in the library paths.
std::string resolve_pov_input(const std::string& name, const std::vector<std::string>& library) {
    namespace fs = std::filesystem;
    std::error_code ec;
    std::vector<std::string> names{name};
    if (fs::path(name).extension().empty()) names.push_back(name + ".pov");
    for (const std::string& n : names)
        if (fs::is_regular_file(n, ec)) return n;
    if (fs::path(name).is_relative())
        for (const std::string& dir : library)
            for (const std::string& n : names)
                if (fs::is_regular_file(fs::path(dir) / n, ec)) return (fs::path(dir) / n).string();
    return name;  // load_scene reports it missing
}

void warn(const std::string& message) {
    std::fprintf(stderr, "glint: warning: %s\n", message.c_str());
}

// glint's flags plus POV-Ray's settings: the render of one frame.
RenderArgs merge_pov_settings(const RenderArgs& args, const PovSettings& pov) {
    namespace fs = std::filesystem;
    RenderArgs a = args;
    for (const std::string& w : pov.warnings) warn(w);
    a.scene.include_dirs.insert(a.scene.include_dirs.end(), pov.library_paths.begin(),
                                pov.library_paths.end());
    if (a.scene.path.empty()) {
        if (!pov.input)
            throw Error(ErrorKind::Usage, {},
                        "no scene to render: give SCENE.pov, +Iscene.pov or an .ini file with "
                        "Input_File_Name");
        a.scene.path = resolve_pov_input(*pov.input, pov.library_paths);
    }
    if (!args.given.width && pov.width) a.scene.width = *pov.width;
    if (!args.given.height && pov.height) a.scene.height = *pov.height;
    if (!args.given.threads && pov.threads) a.threads = *pov.threads;
    if (!args.given.clock && pov.clock) a.scene.clock = *pov.clock;
    a.scene.clock_on = args.given.clock || pov.clock.has_value();
    a.scene.declares = pov.declares;
    if (!args.given.aa && pov.antialias.value_or(false)) {
        int method = pov.sampling_method.value_or(1);
        if (method > 2)
            warn("anti-aliasing sampling method " + std::to_string(method) +
                 " (+AM" + std::to_string(method) + ") is not a POV-Ray 3.7 method: using "
                 "method 1");
        char buf[64];
        std::snprintf(buf, sizeof buf, "%s:%.17g", method == 2 ? "adaptive2" : "adaptive",
                      pov.aa_threshold.value_or(0.3));
        a.aa = buf;
    } else if (!args.given.aa && pov.antialias) {
        a.aa = "none";
    }
    if (pov.aa_depth) a.aa_depth = *pov.aa_depth;
    if (!args.given.aa_jitter && pov.jitter)
        a.aa_jitter = *pov.jitter ? pov.jitter_amount.value_or(1.0) : 0.0;
    else if (!args.given.aa_jitter && pov.jitter_amount)
        a.aa_jitter = *pov.jitter_amount;
    if (a.output.empty()) {
        // POV-Ray's default: the scene's name with the format's extension, in the current
        // folder (or in the folder +O names, when it ends with a slash).
        std::string ext = pov.output_type ? extension_for_output_type(*pov.output_type) : "";
        if (ext.empty()) ext = ".png";
        std::string stem = fs::path(a.scene.path).stem().string();
        std::string out = pov.output.value_or("");
        std::error_code ec;
        if (out.empty())
            out = stem + ext;
        else if (out.back() == '/' || fs::is_directory(out, ec))
            out = (fs::path(out) / (stem + ext)).string();
        else if (fs::path(out).extension().empty())
            out += ext;
        a.output = out;
    }
    return a;
}

int render_frame(const RenderArgs& args);

// The image and its side files (--aov, --variance): all of them or none.
struct Outputs {
    const Image* image = nullptr;
    const Image* albedo = nullptr;
    const Image* normal = nullptr;
    const Image* depth = nullptr;
    const Image* variance = nullptr;
};

// The AOVs --aov names, each once, in the order given.
std::vector<std::string> parse_aov_list(const std::string& text) {
    std::vector<std::string> names;
    size_t start = 0;
    while (start <= text.size()) {
        size_t comma = text.find(',', start);
        if (comma == std::string::npos) comma = text.size();
        std::string name = text.substr(start, comma - start);
        if (name != "albedo" && name != "normal" && name != "depth")
            throw Error(ErrorKind::Usage, {},
                        "--aov " + text + ": unknown AOV '" + name +
                            "' (expected a comma list of albedo, normal, depth)");
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
        start = comma + 1;
    }
    return names;
}

}  // namespace

std::string aov_output_path(const std::string& output, const std::string& name) {
    namespace fs = std::filesystem;
    fs::path out(output);
    return (out.parent_path() / (out.stem().string() + "." + name + ".exr")).string();
}

namespace {

void write_outputs(const RenderArgs& args, const std::vector<std::string>& aovs,
                   const io::OutputEncoding& encoding, const Outputs& out,
                   const io::ImageMetadata& metadata) {
    io::OutputBatch batch;
    io::write_image(*out.image, args.output, encoding, metadata, &batch);
    for (const std::string& name : aovs) {
        const Image& aov = name == "albedo"   ? *out.albedo
                                   : name == "normal" ? *out.normal
                                                      : *out.depth;
        io::write_float_exr(aov, aov_output_path(args.output, name), name == "depth" ? 1 : 3,
                            metadata, &batch);
    }
    if (args.variance)
        io::write_float_exr(*out.variance, aov_output_path(args.output, "variance"), 3, metadata,
                            &batch);
    batch.commit();
}

// --save-partial: writes what the interrupted render finished; returns the exit code.
int save_partial(const RenderArgs& args, const std::vector<std::string>& aovs,
                 const io::OutputEncoding& encoding, const render::PartialRender& p) {
    std::string what;
    if (p.samples_per_pixel > 0)
        what = std::to_string(p.samples_per_pixel) + " of " + std::to_string(p.spp_requested) +
               " samples per pixel (the last finished pass)";
    else
        what = std::to_string(p.tiles_done) + " of " + std::to_string(p.tiles_total) +
               " tiles of 32x32 pixels" + (p.spp_requested > 0 ? " at 1 sample per pixel" : "") +
               ", the rest black";
    std::string key = p.samples_per_pixel > 0
                          ? "spp " + std::to_string(p.samples_per_pixel) + "/" +
                                std::to_string(p.spp_requested)
                          : "tiles " + std::to_string(p.tiles_done) + "/" +
                                std::to_string(p.tiles_total);
    const io::ImageMetadata metadata = {
        {"ImageDescription", "glint: interrupted render, " + what},
        {"glint:partial", key},
    };
    const render::PathFilm& f = p.film;
    write_outputs(args, aovs, encoding, {&f.image, &f.albedo, &f.normal, &f.depth, &f.variance},
                  metadata);
    std::fprintf(stderr, "glint: interrupted; partial image written to %s (%s)\n",
                 args.output.c_str(), what.c_str());
    return kExitInterrupted;
}

}  // namespace

RenderArgs effective_render_args(const RenderArgs& args) {
    if (args.pov_args.empty()) return args;
    return merge_pov_settings(args, read_pov_arguments(args.pov_args));
}

int run_render(const RenderArgs& args) {
    install_signal_handlers();
    if (args.exit_with_parent) cancel_when_parent_exits();
    const bool frame_flags = !args.frames.empty() || args.frame >= 0;
    if (args.pov_args.empty() && !frame_flags) {
        if (args.scene.path.empty())
            throw Error(ErrorKind::Usage, {}, "no scene to render: give SCENE.pov");
        if (args.output.empty())
            throw Error(ErrorKind::Usage, {}, "no output: give -o OUT.png (or POV-Ray's +O)");
        RenderArgs a = args;
        a.scene.clock_on = args.given.clock;
        return render_frame(a);
    }
    if (args.pov_args.empty() && args.output.empty())
        throw Error(ErrorKind::Usage, {}, "no output: give -o OUT.png (or POV-Ray's +O)");
    PovSettings pov = read_pov_arguments(args.pov_args);
    if (!args.frames.empty()) {
        const FrameRange r = parse_frame_range(args.frames, "--frames");
        apply_frame_range(pov, r.first, r.last);
    }
    if (args.frame >= 0) {
        pov.subset_start = args.frame;
        pov.subset_end = args.frame;
    }
    RenderArgs a = merge_pov_settings(args, pov);
    AnimationPlan plan = plan_animation(pov);
    if (!plan.animated) {
        if (args.frame >= 0)
            throw Error(ErrorKind::Usage, {},
                        "--frame " + std::to_string(args.frame) +
                            ": no animation to take it from (give --frames A-B, or POV-Ray's "
                            "+KFI and +KFF)");
        return render_frame(a);
    }
    if (args.given.clock) warn("--clock is ignored: the animation sets the clock of each frame");
    if (plan.frames.empty()) {
        if (args.frame >= 0)
            throw Error(ErrorKind::Usage, {},
                        "--frame " + std::to_string(args.frame) + " is not a frame of the "
                        "animation (" + std::to_string(plan.initial_frame) + " to " +
                            std::to_string(plan.final_frame) + ")");
        throw Error(ErrorKind::Usage, {}, "the frame subset is empty");
    }
    for (const PovFrame& f : plan.frames) {
        RenderArgs fa = a;
        fa.scene.clock = f.clock;
        fa.scene.clock_on = true;
        fa.scene.clock_delta = plan.clock_delta;
        fa.scene.initial_clock = plan.initial_clock;
        fa.scene.final_clock = plan.final_clock;
        fa.scene.initial_frame = plan.initial_frame;
        fa.scene.final_frame = plan.final_frame;
        fa.scene.frame_number = f.number;
        fa.animation_frame = true;
        fa.output = frame_output_name(a.output, f.number, plan.digits);
        if (args.verbose)
            std::fprintf(stderr, "frame %d (%d..%d), clock %g: %s\n", f.number,
                         plan.frames.front().number, plan.frames.back().number, f.clock,
                         fa.output.c_str());
        int rc = render_frame(fa);
        if (rc != kExitOk) return rc;
    }
    return kExitOk;
}

namespace {

// Everything about this render that changes its pixels, for the job signature (parts.h): the
// region, the output's name and, in an animation, the frame are not in it (parts and frames
// of one job share it; their metadata says which they are).
std::string job_settings(const RenderArgs& a) {
    namespace fs = std::filesystem;
    std::error_code ec;
    char buf[64];
    auto num = [&](double v) {
        std::snprintf(buf, sizeof buf, "%.17g", v);
        return std::string(buf);
    };
    std::string s = "scene=" + fs::weakly_canonical(a.scene.path, ec).string();
    for (const std::string& d : a.scene.include_dirs) s += ";I=" + d;
    for (const auto& [name, value] : a.scene.declares) s += ";declare " + name + "=" + num(value);
    s += ";size=" + std::to_string(a.scene.width) + "x" + std::to_string(a.scene.height);
    s += ";aa=" + a.aa + ";aa_depth=" + std::to_string(a.aa_depth);
    if (a.aa != "none") s += ";aa_jitter=" + num(a.aa_jitter);
    s += ";integrator=" + a.integrator;
    if (a.integrator == "path" || a.integrator == "sppm")
        s += ";spp=" + std::to_string(a.spp) + ";max_depth=" + std::to_string(a.max_depth) +
             ";seed=" + std::to_string(a.seed) +
             ";light_tree=" + std::to_string(!a.no_light_tree) +
             ";adaptive=" + std::to_string(a.given.adaptive) + "," + num(a.adaptive_threshold) +
             "," + std::to_string(a.adaptive_min_samples) +
             ";time_limit=" + num(a.time_limit) + ";aov=" + a.aov +
             ";variance=" + std::to_string(a.variance);
    if (a.integrator == "sppm")
        s += ";photons=" + std::to_string(a.photons) + ";photon_radius=" + num(a.photon_radius);
    if (a.animation_frame)
        s += ";frames=" + std::to_string(a.scene.initial_frame) + "-" +
             std::to_string(a.scene.final_frame) + ";clock=" +
             num(a.scene.initial_clock.value_or(0)) + ".." + num(a.scene.final_clock.value_or(1)) +
             ";clock_delta=" + num(a.scene.clock_delta);
    else
        s += ";clock=" + num(a.scene.clock) + ";clock_on=" + std::to_string(a.scene.clock_on);
    s += ";view=" + a.view.view + "|" + a.view.look + "|" + num(a.view.exposure) + "|" +
         num(a.view.gamma) + "|" + a.view.display + "|" + a.view.config_path;
    s += ";format=" + fs::path(a.output).extension().string();
    return s;
}

// The metadata of every output: the job, the whole image's size, and the region and frame
// that this one is.
io::ImageMetadata part_metadata(const RenderArgs& a, const render::Region& region) {
    io::ImageMetadata m = {
        {kJobKey, job_signature(job_settings(a), a.scene.path)},
        {kSizeKey, std::to_string(a.scene.width) + "x" + std::to_string(a.scene.height)},
    };
    if (!region.empty()) m.emplace_back(kRegionKey, region_string(region));
    if (a.animation_frame) m.emplace_back(kFrameKey, std::to_string(a.scene.frame_number));
    return m;
}

// --skip-existing: whether `path` is already a complete output with this metadata: it reads
// back in full, at the right size, and its header carries the same job, region and frame.
bool complete_output(const std::string& path, const io::ImageMetadata& want, int width,
                     int height) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return false;
    std::string error;
    auto reader = image_library().open(path, {}, &error);
    if (!reader) return false;
    const ImageHeader& h = reader->header();
    if (h.width != width || h.height != height || h.channels < 1) return false;
    for (const auto& [key, value] : want) {
        bool found = false;
        for (const auto& [k, v] : h.text) found = found || (k == key && v == value);
        if (!found) return false;
    }
    std::vector<float> pixels(static_cast<size_t>(width) * height * h.channels);
    return reader->read(h.channels, pixels.data()).empty();
}

int render_frame(const RenderArgs& args) {
    Clock::time_point start = Clock::now();

    render::RenderOptions options;
    options.width = args.scene.width;
    options.height = args.scene.height;
    options.threads = args.threads;
    options.cancel = &cancel_flag();
    parse_aa(args.aa, options);
    options.aa_depth = args.aa_depth;
    options.aa_jitter = args.aa_jitter;
    if (args.integrator == "path") options.integrator = render::IntegratorKind::Path;
    if (args.integrator == "sppm") options.integrator = render::IntegratorKind::Sppm;
    options.photons = args.photons;
    options.photon_radius = args.photon_radius;
    options.spp = args.spp;
    options.max_depth = args.max_depth;
    options.seed = args.seed;
    options.light_tree = !args.no_light_tree;
    options.adaptive = args.given.adaptive;
    options.adaptive_threshold = args.adaptive_threshold;
    options.adaptive_min_samples = args.adaptive_min_samples;
    options.time_limit = args.time_limit;
    const std::vector<std::string> aovs =
        args.aov.empty() ? std::vector<std::string>{} : parse_aov_list(args.aov);
    if ((!aovs.empty() || args.variance) && options.integrator != render::IntegratorKind::Path)
        throw Error(ErrorKind::Usage, {},
                    std::string(aovs.empty() ? "--variance" : "--aov") +
                        " needs --integrator path (the Whitted and photon integrators have no "
                        "AOVs)");
    options.aovs = !aovs.empty();
    options.variance = args.variance;
    if (!args.region.empty()) {
        options.region = parse_region(args.region, "--region");
        const render::Region& r = options.region;
        if (r.x1 > options.width || r.y1 > options.height)
            throw Error(ErrorKind::Usage, {},
                        "--region " + args.region + " reaches past the " +
                            std::to_string(options.width) + "x" + std::to_string(options.height) +
                            " image");
    }
    check_output_path(args.output);
    for (const std::string& name : aovs) io::check_writable(aov_output_path(args.output, name));
    if (args.variance) io::check_writable(aov_output_path(args.output, "variance"));
    // Every format but PNG (which libpng writes) goes through the OpenImageIO module: load it
    // now, so that a missing or broken one fails before the render rather than after it.
    if (io::output_format_for(args.output) != "png" || !aovs.empty() || args.variance)
        (void)image_library();
    const io::ImageMetadata metadata = part_metadata(args, options.region);
    if (args.skip_existing) {
        const int w = options.region.empty() ? options.width : options.region.width();
        const int h = options.region.empty() ? options.height : options.region.height();
        bool complete = complete_output(args.output, metadata, w, h);
        for (const std::string& name : aovs)
            complete = complete && complete_output(aov_output_path(args.output, name), metadata, w, h);
        if (args.variance)
            complete = complete &&
                       complete_output(aov_output_path(args.output, "variance"), metadata, w, h);
        if (complete) {
            std::fprintf(stderr, "glint: %s is already complete (job %s), skipped\n",
                         args.output.c_str(), metadata[0].second.c_str());
            return kExitOk;
        }
    }
    // A bad view, look or missing config fails before the render, not after it.
    const io::ViewSettings view = checked_view_settings(args.view);
    if (view.active() && io::is_float_format(args.output))
        warn("--view " + view.view + " does not apply to " + args.output +
             ": float images are written linear (convert them with glint convert --view)");

    scene::Scene scene = load_scene(args.scene, args.verbose);
    if (scene.blender_render) {
        // A Blender scene carries its render settings; the flags given win over them.
        GivenSettings given;
        given.width = args.given.width;
        given.height = args.given.height;
        given.integrator = args.given.integrator;
        given.spp = args.given.spp;
        given.seed = args.given.seed;
        given.max_depth = args.given.max_depth;
        given.adaptive = args.given.adaptive;
        apply_blender_render(*scene.blender_render, given, &options);
    }
    if (options.integrator == render::IntegratorKind::Whitted &&
        (args.given.adaptive || args.no_light_tree))
        warn("--adaptive and --no-light-tree apply to the path tracer (--integrator path); "
             "the classic renderer ignores them");
    double parse_seconds = seconds_since(start);
    if (cancel_flag().load()) throw Error(ErrorKind::Cancelled, {}, "interrupted");

    ProgressReporter progress(progress_style(args.progress), stderr);
    options.progress = [&progress](double f) { progress.update(f); };
    Diagnostics diag([&args](const Diagnostic& d) {
        if (d.level == Diagnostic::Level::Warning)
            std::fputs(format_diagnostic(d.loc, "warning", d.message).c_str(), stderr);
        else if (args.verbose)
            std::fprintf(stderr, "%s\n", d.message.c_str());
    });
    io::OutputEncoding encoding = io::output_encoding_for(scene);
    encoding.view = view;
    encoding.alpha = options.film_transparent;  // a partial render's film too
    render::RenderResult result;
    try {
        result = render::render(scene, options, diag);
    } catch (const render::Interrupted& e) {
        progress.abandon();
        if (!args.save_partial) throw;
        return save_partial(args, aovs, encoding, e.partial());
    } catch (...) {
        progress.abandon();
        throw;
    }
    progress.finish();
    // A signal after the last pixel: with --save-partial the finished image is written.
    const bool interrupted = cancel_flag().load();
    if (interrupted && !args.save_partial) throw Error(ErrorKind::Cancelled, {}, "interrupted");

    // Transparent film or holdouts: RGBA (premultiplied in EXR, as Cycles writes it).
    encoding.alpha = result.alpha;
    Clock::time_point write_start = Clock::now();
    if (args.variance && result.samples_per_pixel < 2)
        warn("--variance: only " + std::to_string(result.samples_per_pixel) +
             " sample per pixel, the variance image is 0");
    write_outputs(args, aovs, encoding,
                  {&result.image, &result.albedo, &result.normal, &result.depth, &result.variance},
                  metadata);
    double write_seconds = seconds_since(write_start);
    if (interrupted) {
        std::fprintf(stderr, "glint: interrupted after the render finished; the image written "
                             "to %s is complete\n", args.output.c_str());
        return kExitInterrupted;
    }

    if (args.verbose) {
        print_features(result.features);
        std::fprintf(stderr, "image: %dx%d, aa %s, 8/16-bit encoding %s\n", result.image.width,
                     result.image.height, args.aa.c_str(),
                     encoding.view.active() ? io::describe_view(encoding.view).c_str()
                                            : encoding_name(encoding).c_str());
        if (options.integrator == render::IntegratorKind::Path)
            std::fprintf(stderr,
                         "path: %d spp, max depth %d, seed %u, %llu non-finite paths dropped, "
                         "%.2f Mrays/s\n",
                         result.samples_per_pixel, options.max_depth, options.seed,
                         static_cast<unsigned long long>(result.nonfinite_paths),
                         result.render_seconds > 0 ? result.rays / result.render_seconds * 1e-6 : 0.0);
        std::fprintf(stderr,
                     "time: parse %.3f s, prepare %.3f s, render %.3f s, write %.3f s, "
                     "total %.3f s\n",
                     parse_seconds, result.prepare_seconds, result.render_seconds, write_seconds,
                     seconds_since(start));
    }
    return kExitOk;
}

}  // namespace

}  // namespace glint::app
