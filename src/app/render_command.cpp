// `glint render SCENE.pov -o OUT`: parse, render, encode, write; nothing is written unless
// every stage succeeds.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/scene_loading.h"
#include "io/image_output.h"
#include "io/progress.h"
#include "io/scene_encoding.h"
#include "render/render.h"
#include "scene/features.h"

namespace glint::app {

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
            "--aa " + text + ": " + why + " (expected none, adaptive, adaptive:T or grid:N)");
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
    } else if (mode == "adaptive") {
        options.aa = render::AaMode::Adaptive;
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

io::ProgressStyle progress_style(const std::string& flag) {
    if (flag.empty())
        return isatty(STDERR_FILENO) ? io::ProgressStyle::Bar : io::ProgressStyle::None;
    if (flag == "bar") return io::ProgressStyle::Bar;
    if (flag == "lines") return io::ProgressStyle::Lines;
    return io::ProgressStyle::None;
}

// Refuses an output path that cannot work before spending time on the render.
void check_output_path(const std::string& path) {
    io::output_format_for(path);  // throws for an unsupported extension
    namespace fs = std::filesystem;
    fs::path parent = fs::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty() && !fs::is_directory(parent, ec))
        throw Error(ErrorKind::Output, {},
                    "cannot write " + path + ": folder " + parent.string() + " does not exist");
    if (fs::is_directory(path, ec))
        throw Error(ErrorKind::Output, {}, "cannot write " + path + ": it is a folder");
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

CLI::App* add_render_command(CLI::App& app, RenderArgs& args) {
    CLI::App* cmd = app.add_subcommand("render", "Render a POV-Ray scene to an image");
    add_scene_options(*cmd, args.scene);
    cmd->add_option("-o,--output", args.output,
                    "Output image; format from the extension: png, exr, tif, hdr, jpg")
        ->required();
    cmd->add_option("--aa", args.aa, "Anti-aliasing: none, adaptive[:T] (POV-Ray +A), grid:N")
        ->capture_default_str();
    cmd->add_option("--threads", args.threads, "Worker threads (0: all hardware threads)")
        ->capture_default_str()
        ->check(CLI::Range(0, 4096));
    cmd->add_flag("-v,--verbose", args.verbose, "Print features used and skipped, and timings");
    cmd->add_option("--progress", args.progress,
                    "Progress on stderr: bar, lines (`progress 0.42`), none "
                    "(default: bar on a terminal, none otherwise)")
        ->check(CLI::IsMember({"bar", "lines", "none"}));
    return cmd;
}

int run_render(const RenderArgs& args) {
    install_signal_handlers();
    Clock::time_point start = Clock::now();

    render::RenderOptions options;
    options.width = args.scene.width;
    options.height = args.scene.height;
    options.threads = args.threads;
    options.cancel = &cancel_flag();
    parse_aa(args.aa, options);
    check_output_path(args.output);

    scene::Scene scene = load_scene(args.scene, args.verbose);
    double parse_seconds = seconds_since(start);
    if (cancel_flag().load()) throw Error(ErrorKind::Cancelled, {}, "interrupted");

    io::ProgressReporter progress(progress_style(args.progress), stderr);
    options.progress = [&progress](double f) { progress.update(f); };
    Diagnostics diag([&args](const Diagnostic& d) {
        if (d.level == Diagnostic::Level::Warning)
            std::fputs(format_diagnostic(d.loc, "warning", d.message).c_str(), stderr);
        else if (args.verbose)
            std::fprintf(stderr, "%s\n", d.message.c_str());
    });
    render::RenderResult result;
    try {
        result = render::render(scene, options, diag);
    } catch (...) {
        progress.abandon();
        throw;
    }
    progress.finish();
    if (cancel_flag().load()) throw Error(ErrorKind::Cancelled, {}, "interrupted");

    io::OutputEncoding encoding = io::output_encoding_for(scene);
    Clock::time_point write_start = Clock::now();
    io::write_image(result.image, args.output, encoding);
    double write_seconds = seconds_since(write_start);

    if (args.verbose) {
        print_features(result.features);
        std::fprintf(stderr, "image: %dx%d, aa %s, 8/16-bit encoding %s\n", result.image.width,
                     result.image.height, args.aa.c_str(), encoding_name(encoding).c_str());
        std::fprintf(stderr,
                     "time: parse %.3f s, prepare %.3f s, render %.3f s, write %.3f s, "
                     "total %.3f s\n",
                     parse_seconds, result.prepare_seconds, result.render_seconds, write_seconds,
                     seconds_since(start));
    }
    return kExitOk;
}

}  // namespace glint::app
