// `glint report SCENE --reference REF.exr`: error against run time (VALIDATION.md). Renders the
// scene with the path tracer at increasing samples per pixel, measures each render's wall time
// and its error against the reference (relMSE, RMSE, SSIM), optionally does the same for a peer
// renderer's command line, and writes report.csv, report.png (log-log relMSE vs seconds) and
// report.txt (the table with the equal-time and equal-error ratios read off the curves).
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/scene_loading.h"
#include "core/log.h"
#include "io/color_encoding.h"
#include "io/image_compare.h"
#include "io/image_output.h"
#include "io/plot.h"
#include "io/scene_encoding.h"
#include "render/render.h"

namespace glint::app {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// One renderer at one sample count: over its seeds, the mean of each error and the median of
// the seconds.
struct Step {
    std::string renderer;
    int spp = 0;
    double seconds = 0;
    io::LinearMetrics metrics;
    double ssim = 0;
    int seeds = 0;
    double relmse_min = 0, relmse_max = 0;
};

struct Run {
    double seconds;
    io::LinearMetrics metrics;
    double ssim;
};

// "1,4,16" -> {1, 4, 16}, sorted and without repeats.
std::vector<int> parse_steps(const std::string& flag, const std::string& text) {
    std::vector<int> steps;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        char* end = nullptr;
        const long v = std::strtol(item.c_str(), &end, 10);
        if (item.empty() || *end != '\0' || v < 1 || v > (1 << 24))
            throw Error(ErrorKind::Usage, {},
                        flag + " " + text + ": '" + item +
                            "' is not a sample count (a comma list of integers 1 .. 16777216)");
        steps.push_back(static_cast<int>(v));
    }
    if (steps.empty()) throw Error(ErrorKind::Usage, {}, flag + " is empty");
    std::sort(steps.begin(), steps.end());
    steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
    return steps;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
    for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
    return s;
}

// A name usable in file names: letters, digits, '-', '_' and '.', the rest '_'.
std::string file_safe(const std::string& name) {
    std::string s = name.empty() ? "peer" : name;
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.')
            c = '_';
    return s;
}

std::string shell_quote(const std::string& s) { return "'" + replace_all(s, "'", "'\\''") + "'"; }

// Runs `sh -c command` with stdout and stderr into `log`; returns the wait status.
int run_shell(const std::string& command, const std::string& log) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) throw Error(ErrorKind::Output, {}, "cannot write " + log);
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fd);
        throw Error(ErrorKind::Render, {}, "cannot start the peer command: fork failed");
    }
    if (pid == 0) {
        ::dup2(fd, STDOUT_FILENO);
        ::dup2(fd, STDERR_FILENO);
        ::close(fd);
        ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    ::close(fd);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) throw Error(ErrorKind::Render, {}, "waiting for the peer failed");
        if (cancel_flag().load()) ::kill(pid, SIGTERM);
    }
    return status;
}

Run measure(double seconds, const io::LinearImage& image, const io::LinearImage& reference) {
    return {seconds, io::compare_linear(image, reference),
            io::compute_ssim(io::encode_srgb8(image), io::encode_srgb8(reference))};
}

// The expected error is what a curve should show, and one seed's error is one draw of it: the
// mean over the seeds. The seconds are the median (a slow outlier on a shared machine is noise).
Step summarize(const std::string& renderer, int spp, const std::vector<Run>& runs) {
    Step s;
    s.renderer = renderer;
    s.spp = spp;
    s.seeds = static_cast<int>(runs.size());
    std::vector<double> seconds;
    s.relmse_min = runs.front().metrics.relmse;
    s.relmse_max = runs.front().metrics.relmse;
    for (const Run& r : runs) {
        seconds.push_back(r.seconds);
        s.metrics.relmse += r.metrics.relmse / s.seeds;
        s.metrics.rmse += r.metrics.rmse / s.seeds;
        s.metrics.nonfinite = std::max(s.metrics.nonfinite, r.metrics.nonfinite);
        s.ssim += r.ssim / s.seeds;
        s.relmse_min = std::min(s.relmse_min, r.metrics.relmse);
        s.relmse_max = std::max(s.relmse_max, r.metrics.relmse);
    }
    std::sort(seconds.begin(), seconds.end());
    const size_t n = seconds.size();
    s.seconds = n % 2 ? seconds[n / 2] : (seconds[n / 2 - 1] + seconds[n / 2]) / 2;
    return s;
}

// File names of one run: NAME-SPP, and -sK for the K-th seed when there are several.
std::string run_stem(const std::string& name, int spp, int seed_index, int seeds) {
    std::string stem = name + "-" + std::to_string(spp);
    if (seeds > 1) stem += "-s" + std::to_string(seed_index);
    return stem;
}

std::string format_ratio(const io::CurveReading& r, double ratio) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%.3g", r.where == io::CurveReading::Where::AtMost ? "<= " : "",
                  ratio);
    return buf;
}

std::string reading_note(const io::CurveReading& r) {
    return r.where == io::CurveReading::Where::Extrapolated
               ? " (extrapolated along the peer's last segment)"
               : "";
}

std::string format_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

// The two ratios read off `other`'s curve at `base`'s final step (above 1: base is ahead).
std::string curve_ratios(const std::string& base_name, const std::vector<Step>& base,
                         const std::string& other_name, const std::vector<Step>& other) {
    std::vector<double> pt, pe;
    for (const Step& s : other) {
        pt.push_back(s.seconds);
        pe.push_back(s.metrics.relmse);
    }
    const Step& last = base.back();
    const double gt = last.seconds, ge = last.metrics.relmse;
    std::string txt = "\nRatios of " + other_name + " to " + base_name +
                      " read off the curves (log-log interpolation between steps; above 1 "
                      "means " + base_name + " is ahead):\n";
    const io::CurveReading at_error = io::curve_x_at_y(pt, pe, ge);
    txt += "equal-error: at " + base_name + "'s final relMSE (" + format_number(ge) + " at " +
           format_number(gt) + " s) " + other_name + " needs ";
    if (at_error.where == io::CurveReading::Where::None)
        txt += "an unknown time (its curve does not reach that error or fall toward it)\n";
    else
        txt += format_ratio(at_error, at_error.value / gt) + "x the time (" +
               format_number(at_error.value) + " s)" + reading_note(at_error) + "\n";
    const io::CurveReading at_time = io::curve_y_at_x(pt, pe, gt);
    txt += "equal-time: at " + base_name + "'s final time (" + format_number(gt) + " s) " +
           other_name + "'s relMSE is ";
    if (at_time.where == io::CurveReading::Where::None || !(ge > 0))
        txt += "not comparable (too few points, or " + base_name + "'s error is 0)\n";
    else if (at_time.where == io::CurveReading::Where::Before)
        txt += "unknown: its first step already takes longer (" + format_number(pt[0]) +
               " s, relMSE " + format_number(pe[0]) + ", " + format_number(pe[0] / ge) + "x " +
               base_name + "'s final)\n";
    else
        txt += format_ratio(at_time, at_time.value / ge) + "x " + base_name + "'s (" +
               format_number(at_time.value) + ")" + reading_note(at_time) + "\n";
    return txt;
}

}  // namespace

CLI::App* add_report_command(CLI::App& app, ReportArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "report", "Error against run time of the path tracer or sppm, beside a peer");
    cmd->footer(
        "Error against run time: render SCENE with the path tracer at each --spp-steps count, "
        "compare each with --reference (relMSE = mean((x-r)^2/(r^2+0.01)), RMSE on linear "
        "values, SSIM of the sRGB 8-bit lumas), and write DIR/report.csv (renderer, spp, "
        "seconds, relmse, rmse, ssim, seeds, relmse_min, relmse_max), DIR/report.png (log-log "
        "relMSE against seconds) and DIR/report.txt; with --seeds K each step is K renders and "
        "shows their mean errors and median seconds. glint and the peer take turns, step by "
        "step. glint's seconds are the wall time of the in-process render (scene preparation "
        "and path tracing) plus the scene's parse time, measured once; a peer's seconds are its "
        "whole process, or, when its command has {time}, the seconds it writes to that file "
        "(its own render time, start-up left out). With --peer, two ratios are read off the "
        "curves (log-log interpolation between steps): equal-error = the peer's time to reach "
        "glint's final relMSE / glint's final time; equal-time = the peer's relMSE at glint's "
        "final time / glint's final relMSE (above 1: glint is ahead)");
    add_scene_options(*cmd, args.scene);
    cmd->add_option("--reference", args.reference,
                    "Reference image (EXR, linear); its size is the render size unless "
                    "--width/--height are given (they must match it)")
        ->required();
    cmd->add_option("--spp-steps", args.spp_steps, "glint's samples per pixel, a comma list")
        ->capture_default_str();
    cmd->add_option("--integrator", args.integrators,
                    "glint's integrators, a comma list of path and sppm, each its own curve "
                    "(glint-path, glint-sppm; glint alone for path alone); an sppm step's "
                    "value is its passes. With several, the later ones' ratios against the "
                    "first are read off the curves as the peer's are")
        ->capture_default_str();
    cmd->add_option("--photons", args.photons, "sppm: photons per pass (0: one per pixel)")
        ->capture_default_str()
        ->check(CLI::Range(0L, 1L << 30));
    cmd->add_option("--out", args.out, "Folder for the report (created)")->capture_default_str();
    cmd->add_option("--max-depth", args.max_depth, "Path tracer: maximum bounces")
        ->capture_default_str()
        ->check(CLI::Range(0, 4096));
    cmd->add_option("--seed", args.seed, "Path tracer: sampler seed (the first, with --seeds)")
        ->capture_default_str();
    cmd->add_option("--seeds", args.seeds,
                    "Renders per step, glint with seeds --seed, --seed + 1, ...; the step shows "
                    "their mean relMSE, RMSE and SSIM, the median seconds and the relMSE range. "
                    "One seed's error is one random draw (on the Cycles spheres scene at 1024 "
                    "spp glint's relMSE spans 7.5e-5 .. 9.2e-5 over ten seeds), so comparing "
                    "two renderers wants several. The peer command runs once per seed with "
                    "{seed} replaced by 0 .. K-1 (it maps them to seeds of its own, none of its "
                    "reference's); above 1 the command must have {seed}")
        ->capture_default_str()
        ->check(CLI::Range(1, 1024));
    cmd->add_option("--threads", args.threads, "Worker threads (0: all hardware threads)")
        ->capture_default_str()
        ->check(CLI::Range(0, 4096));
    cmd->add_option("--peer", args.peer,
                    "A peer renderer's shell command, run once per --peer-steps value with "
                    "{spp} replaced by the value, {out} by the EXR it must write (in DIR), "
                    "{time} (optional) by a file it writes its render seconds to and {seed} by "
                    "the seed's index (see --seeds); its output goes to "
                    "DIR/<peer-name>-<spp>.log (-<spp>-s<index>.log with --seeds)");
    cmd->add_option("--peer-steps", args.peer_steps,
                    "Values for the peer's {spp}, a comma list (default: --spp-steps)");
    cmd->add_option("--peer-name", args.peer_name, "The peer's name in the CSV and the legend")
        ->capture_default_str();
    cmd->add_flag("-v,--verbose", args.verbose, "Print the scene's informational messages");
    cmd->parse_complete_callback([cmd, &args] {
        args.given_width = cmd->count("--width") > 0;
        args.given_height = cmd->count("--height") > 0;
        args.given_max_depth = cmd->count("--max-depth") > 0;
    });
    return cmd;
}

int run_report(const ReportArgs& args) {
    install_signal_handlers();
    const std::vector<int> steps = parse_steps("--spp-steps", args.spp_steps);
    std::vector<int> peer_steps;
    if (!args.peer.empty())
        peer_steps = args.peer_steps.empty() ? steps : parse_steps("--peer-steps", args.peer_steps);
    else if (!args.peer_steps.empty())
        throw Error(ErrorKind::Usage, {}, "--peer-steps needs --peer");
    if (!args.peer.empty() && args.seeds > 1 && args.peer.find("{seed}") == std::string::npos)
        throw Error(ErrorKind::Usage, {},
                    "--seeds " + std::to_string(args.seeds) +
                        " needs {seed} in --peer: without it the peer would render one seed " +
                        std::to_string(args.seeds) + " times");

    const io::LinearImage reference = io::read_linear(args.reference);
    SceneRequest request = args.scene;
    if (!args.given_width) request.width = reference.width;
    if (!args.given_height) request.height = reference.height;
    if (request.width != reference.width || request.height != reference.height)
        throw Error(ErrorKind::Usage, {},
                    "--width/--height " + std::to_string(request.width) + "x" +
                        std::to_string(request.height) + " differ from the reference " +
                        args.reference + " (" + std::to_string(reference.width) + "x" +
                        std::to_string(reference.height) + ")");
    std::error_code ec;
    fs::create_directories(args.out, ec);
    if (!fs::is_directory(args.out, ec))
        throw Error(ErrorKind::Output, {}, "cannot create the report folder " + args.out);
    const fs::path dir(args.out);

    Clock::time_point parse_start = Clock::now();
    scene::Scene scene = load_scene(request, args.verbose);
    const double parse_seconds = seconds_since(parse_start);
    const io::OutputEncoding encoding = io::output_encoding_for(scene);
    Diagnostics diag([&args](const Diagnostic& d) {
        if (d.level == Diagnostic::Level::Warning)
            std::fputs(format_diagnostic(d.loc, "warning", d.message).c_str(), stderr);
        else if (args.verbose)
            std::fprintf(stderr, "%s\n", d.message.c_str());
    });

    // glint's integrators, each a curve: "glint" alone for the path tracer alone (as before),
    // else glint-path, glint-sppm.
    std::vector<std::string> integrators;
    {
        std::stringstream in(args.integrators);
        std::string item;
        while (std::getline(in, item, ',')) {
            if (item != "path" && item != "sppm")
                throw Error(ErrorKind::Usage, {},
                            "--integrator " + args.integrators + ": '" + item +
                                "' is not an integrator the report runs (path, sppm)");
            if (std::find(integrators.begin(), integrators.end(), item) == integrators.end())
                integrators.push_back(item);
        }
        if (integrators.empty()) throw Error(ErrorKind::Usage, {}, "--integrator is empty");
    }
    std::vector<std::string> glint_names;
    for (const std::string& i : integrators)
        glint_names.push_back(integrators.size() == 1 && i == "path" ? "glint" : "glint-" + i);
    std::vector<std::vector<Step>> glint_steps(integrators.size());
    std::vector<Step> peer_results;
    auto glint_step = [&](size_t which, int spp) {
        const std::string& name = glint_names[which];
        std::vector<Run> runs;
        for (int k = 0; k < args.seeds; ++k) {
            if (cancel_flag().load()) throw Error(ErrorKind::Cancelled, {}, "interrupted");
            render::RenderOptions options;
            options.width = request.width;
            options.height = request.height;
            options.threads = args.threads;
            options.integrator = integrators[which] == "sppm" ? render::IntegratorKind::Sppm
                                                              : render::IntegratorKind::Path;
            options.spp = spp;
            options.photons = args.photons;
            options.max_depth = args.max_depth;
            options.seed = args.seed + static_cast<unsigned>(k);
            // A Blender scene renders with its own settings (filter, bounce limits, volume
            // steps), as `glint render` renders it; the report's own flags win.
            if (scene.blender_render) {
                // (Every step takes its full samples: no adaptive sampling.)
                GivenSettings given{true, true, true, true, true, args.given_max_depth, true};
                apply_blender_render(*scene.blender_render, given, &options);
                options.integrator = integrators[which] == "sppm"
                                         ? render::IntegratorKind::Sppm
                                         : render::IntegratorKind::Path;
            }
            options.cancel = &cancel_flag();
            Clock::time_point t = Clock::now();
            render::RenderResult result = render::render(scene, options, diag);
            const double seconds = seconds_since(t) + parse_seconds;
            io::LinearImage image;
            image.width = result.image.width;
            image.height = result.image.height;
            const std::vector<float> rgba = io::linear_rgba(result.image, encoding);
            image.rgb.resize(rgba.size() / 4 * 3);
            for (size_t i = 0; i < rgba.size() / 4; ++i)
                for (int c = 0; c < 3; ++c) image.rgb[i * 3 + c] = rgba[i * 4 + c];
            io::write_linear_exr(image,
                                 (dir / (run_stem(name, spp, k, args.seeds) + ".exr")).string());
            runs.push_back(measure(seconds, image, reference));
        }
        glint_steps[which].push_back(summarize(name, spp, runs));
        std::fprintf(stderr, "%s %d %s: %.3f s, relMSE %.6g\n", name.c_str(), spp,
                     integrators[which] == "sppm" ? "passes" : "spp",
                     glint_steps[which].back().seconds, glint_steps[which].back().metrics.relmse);
    };

    std::string peer_file = file_safe(args.peer_name);
    // glint's own renders are glint-N.exr, glint-path-N.exr, glint-sppm-N.exr.
    if (peer_file.rfind("glint", 0) == 0) peer_file = "peer-" + peer_file;
    const bool own_time = args.peer.find("{time}") != std::string::npos;
    auto peer_step = [&](int spp) {
        std::vector<Run> runs;
        for (int k = 0; k < args.seeds; ++k) {
            if (cancel_flag().load()) throw Error(ErrorKind::Cancelled, {}, "interrupted");
            const std::string stem = run_stem(peer_file, spp, k, args.seeds);
            const fs::path out = dir / (stem + ".exr");
            const fs::path log = dir / (stem + ".log");
            const fs::path time_file = dir / (stem + ".seconds");
            fs::remove(out, ec);
            fs::remove(time_file, ec);
            // The numbers before the paths, so no path is searched for {spp} or {seed}.
            std::string command = replace_all(args.peer, "{spp}", std::to_string(spp));
            command = replace_all(command, "{seed}", std::to_string(k));
            command = replace_all(command, "{out}", shell_quote(out.string()));
            command = replace_all(command, "{time}", shell_quote(time_file.string()));
            Clock::time_point t = Clock::now();
            const int status = run_shell(command, log.string());
            double seconds = seconds_since(t);
            if (cancel_flag().load()) throw Error(ErrorKind::Cancelled, {}, "interrupted");
            if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
                const std::string how = WIFEXITED(status)
                                            ? "exit status " + std::to_string(WEXITSTATUS(status))
                                            : "signal " + std::to_string(WTERMSIG(status));
                throw Error(ErrorKind::Render, {},
                            "peer command failed with " + how + ": " + command + " (its output: " +
                                log.string() + ")");
            }
            if (!fs::is_regular_file(out, ec))
                throw Error(ErrorKind::Render, {},
                            "peer command did not write " + out.string() + ": " + command +
                                " (its output: " + log.string() + ")");
            if (own_time) {
                // The peer measured its own render (start-up and scene loading left out, as for
                // glint's in-process timing) and wrote the seconds to {time}.
                std::ifstream in(time_file);
                double own = 0;
                if (!(in >> own) || !(own > 0) || !std::isfinite(own))
                    throw Error(ErrorKind::Render, {},
                                "peer command did not write its render seconds to " +
                                    time_file.string() + ": " + command + " (its output: " +
                                    log.string() + ")");
                seconds = own;
            }
            const io::LinearImage image = io::read_linear(out.string());
            if (image.width != reference.width || image.height != reference.height)
                throw Error(ErrorKind::Render, {},
                            "peer image " + out.string() + " is " + std::to_string(image.width) +
                                "x" + std::to_string(image.height) + ", the reference " +
                                std::to_string(reference.width) + "x" +
                                std::to_string(reference.height) + ": " + command);
            runs.push_back(measure(seconds, image, reference));
        }
        peer_results.push_back(summarize(args.peer_name, spp, runs));
        std::fprintf(stderr, "%s %d: %.3f s, relMSE %.6g\n", args.peer_name.c_str(), spp,
                     peer_results.back().seconds, peer_results.back().metrics.relmse);
    };
    // Step by step, one renderer then the other: a shared machine's speed drifts over minutes,
    // and timing all of one renderer's steps before the other's would put that drift into the
    // ratios.
    for (size_t i = 0; i < std::max(steps.size(), peer_steps.size()); ++i) {
        if (i < steps.size())
            for (size_t k = 0; k < integrators.size(); ++k) glint_step(k, steps[i]);
        if (i < peer_steps.size()) peer_step(peer_steps[i]);
    }

    // The CSV, glint's rows first.
    std::string csv = "renderer,spp,seconds,relmse,rmse,ssim,seeds,relmse_min,relmse_max\n";
    std::vector<const std::vector<Step>*> tables;
    for (const std::vector<Step>& g : glint_steps) tables.push_back(&g);
    tables.push_back(&peer_results);
    for (const std::vector<Step>* rows : tables)
        for (const Step& s : *rows)
            csv += s.renderer + "," + std::to_string(s.spp) + "," + format_number(s.seconds) +
                   "," + format_number(s.metrics.relmse) + "," + format_number(s.metrics.rmse) +
                   "," + format_number(s.ssim) + "," + std::to_string(s.seeds) + "," +
                   format_number(s.relmse_min) + "," + format_number(s.relmse_max) + "\n";

    // The plot.
    auto series = [](const std::vector<Step>& rows, const std::string& name,
                     std::array<float, 3> color) {
        io::PlotSeries s;
        s.name = name;
        s.color = color;
        for (const Step& r : rows) {
            s.x.push_back(r.seconds);
            s.y.push_back(r.metrics.relmse);
        }
        return s;
    };
    std::vector<io::PlotSeries> curves;
    const std::array<float, 3> glint_colors[] = {{0.85f, 0.2f, 0.1f}, {0.1f, 0.6f, 0.2f}};
    for (size_t k = 0; k < glint_steps.size(); ++k)
        curves.push_back(series(glint_steps[k], glint_names[k], glint_colors[k % 2]));
    if (!peer_results.empty())
        curves.push_back(series(peer_results, args.peer_name, {0.1f, 0.35f, 0.85f}));
    io::PlotOptions plot;
    plot.title = "relMSE against time: " + fs::path(request.path).filename().string();
    plot.x_label = "seconds";
    plot.y_label = "relMSE";
    const std::string text_problem =
        io::write_loglog_plot(curves, plot, (dir / "report.png").string());
    if (!text_problem.empty())
        std::fprintf(stderr, "glint report: warning: the plot has no labels: %s\n",
                     text_problem.c_str());

    // The summary.
    std::string txt = "glint report: " + request.path + " against " + args.reference + " (" +
                      std::to_string(reference.width) + "x" + std::to_string(reference.height) +
                      ")\n";
    txt += "glint seconds: scene parse (" + format_number(parse_seconds) +
           " s, once) + wall time of the in-process render (preparation and path tracing); "
           "writing files is not counted.\n";
    if (!args.peer.empty())
        txt += args.peer_name +
               (args.peer.find("{time}") != std::string::npos
                    ? " seconds: the render seconds the command wrote to {time}: "
                    : " seconds: wall time of the whole command: ") +
               args.peer + "\n";
    txt += "relmse = mean((x-r)^2/(r^2+0.01)), rmse on linear RGB, ssim of the sRGB 8-bit "
           "lumas";
    if (args.seeds > 1)
        txt += "; each row: the mean over " + std::to_string(args.seeds) +
               " seeds (glint's " + std::to_string(args.seed) + " .. " +
               std::to_string(args.seed + static_cast<unsigned>(args.seeds) - 1) +
               ", the peer's {seed} 0 .. " + std::to_string(args.seeds - 1) +
               "), the median seconds, and the range of relmse";
    txt += ".\n\n" + csv;
    if (!peer_results.empty())
        txt += curve_ratios(glint_names[0], glint_steps[0], args.peer_name, peer_results);
    // The photon integrator against the path tracer (or whichever came first).
    for (size_t k = 1; k < glint_steps.size(); ++k)
        txt += curve_ratios(glint_names[k], glint_steps[k], glint_names[0], glint_steps[0]);
    std::ofstream(dir / "report.csv") << csv;
    std::ofstream(dir / "report.txt") << txt;
    std::fputs(txt.c_str(), stdout);
    std::fflush(stdout);
    return kExitOk;
}

}  // namespace glint::app
