#include "app/scene_loading.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "app/cli_common.h"
#include "core/error.h"
#include "core/log.h"
#include "core/memory.h"
#include "formats/blender/blender_importer.h"
#include "formats/obj/obj_importer.h"
#include "formats/pov/parser.h"
#include "render/render.h"
#include "scene/validate.h"

namespace glint::app {

void add_scene_options(CLI::App& cmd, SceneRequest& request, bool scene_required) {
    cmd.add_option("SCENE", request.path, "POV-Ray scene (.pov), OBJ model (.obj) or Blender exchange (.json)")->required(scene_required);
    cmd.add_option("-I,--include", request.include_dirs, "Include folder (repeatable)")
        ->allow_extra_args(false);  // one folder per -I, so `-I dir scene.pov` works
    cmd.add_option("--clock", request.clock, "Value of `clock` in the scene")
        ->capture_default_str();
    cmd.add_option("-W,--width", request.width, "Image width in pixels (image_width)")
        ->capture_default_str()
        ->check(CLI::Range(1, 1 << 16));
    cmd.add_option("-H,--height", request.height, "Image height in pixels (image_height)")
        ->capture_default_str()
        ->check(CLI::Range(1, 1 << 16));
    // Resource limits: a scene that passes one stops with exit code 4 and its location.
    SceneRequest::Limits& l = request.limits;
    cmd.add_option("--max-loop-iterations", l.loop_iterations,
                   "Limit: iterations of one #while/#for loop")
        ->capture_default_str()->check(CLI::PositiveNumber);
    cmd.add_option("--max-recursion", l.recursion, "Limit: nested macro calls")
        ->capture_default_str()->check(CLI::PositiveNumber);
    cmd.add_option("--max-include-depth", l.include_depth, "Limit: nested #include files")
        ->capture_default_str()->check(CLI::PositiveNumber);
    cmd.add_option("--max-array-size", l.array_size, "Limit: elements of one array")
        ->capture_default_str()->check(CLI::PositiveNumber);
    cmd.add_option("--max-string-length", l.string_length, "Limit: bytes of one string")
        ->capture_default_str()->check(CLI::PositiveNumber);
    cmd.add_option("--max-triangles", l.triangles, "Limit: mesh triangles in the scene")
        ->capture_default_str()->check(CLI::PositiveNumber);
    cmd.add_option("--max-objects", l.objects, "Limit: top-level objects in the scene")
        ->capture_default_str()->check(CLI::PositiveNumber);
    cmd.add_option("--max-image-pixels", l.image_pixels, "Limit: width x height of the image")
        ->capture_default_str()->check(CLI::PositiveNumber);
    if (l.memory_mib == 0)
        l.memory_mib = static_cast<long long>((physical_memory_bytes() / 4 * 3) >> 20);
    cmd.add_option("--max-memory", l.memory_mib,
                   "Limit: MiB of memory while the scene is parsed (default: 3/4 of the machine's)")
        ->capture_default_str()->check(CLI::PositiveNumber);
    cmd.add_option("--max-parse-stack", l.parse_stack_mib,
                   "Limit: MiB of stack the parser may use (how deeply a scene can nest)")
        ->capture_default_str()->check(CLI::Range(1, 65536));
}

namespace {

bool in_folder(const std::string& file, const std::string& folder) {
    return file.size() > folder.size() && file.compare(0, folder.size(), folder) == 0 &&
           file[folder.size()] == '/';
}

// Prints the parser's diagnostics as they come. Warnings from POV-Ray's standard include
// folder are counted instead of printed unless verbose: including textures.inc alone skips
// about 200 declarations that use features glint lacks, and that list would bury the
// scene's own warnings (using a skipped name is an error that names both places anyway).
class ParseDiagnosticPrinter {
  public:
    explicit ParseDiagnosticPrinter(bool verbose) : verbose_(verbose) {}

    void print(const Diagnostic& d) {
        if (d.level == Diagnostic::Level::Info) {
            // #debug text, printed as POV-Ray prints it: as is, newlines included.
            std::fputs(d.message.c_str(), stderr);
            return;
        }
        if (!verbose_ && in_folder(d.loc.filename(), kPovIncludeDir)) {
            ++hidden_;
            return;
        }
        std::fputs(format_diagnostic(d.loc, "warning", d.message).c_str(), stderr);
    }

    void summary() const {
        if (hidden_ > 0)
            std::fprintf(stderr, "glint: note: %d warning(s) from %s not shown (-v shows them)\n",
                         hidden_, kPovIncludeDir);
    }

  private:
    bool verbose_;
    int hidden_ = 0;
};

}  // namespace

scene::Scene load_scene(const SceneRequest& request, bool verbose) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(request.path, ec))
        throw Error(ErrorKind::MissingFile, {}, "scene file not found: " + request.path);
    if (fs::is_directory(request.path, ec))
        throw Error(ErrorKind::MissingFile, {}, "scene path is a folder: " + request.path);

    const SceneRequest::Limits& limits = request.limits;
    const long long pixels = static_cast<long long>(request.width) * request.height;
    if (pixels > limits.image_pixels)
        throw Error(ErrorKind::Render, {},
                    "the image is " + std::to_string(request.width) + "x" +
                        std::to_string(request.height) + " = " + std::to_string(pixels) +
                        " pixels, more than " + std::to_string(limits.image_pixels) +
                        " (limit: --max-image-pixels)");

    std::string ext = fs::path(request.path).extension().string();
    for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (ext == ".obj") {
        // A model alone: framed by a camera and lit by a default rig (obj_importer.h).
        ParseDiagnosticPrinter printer(verbose);
        Diagnostics diag([&printer](const Diagnostic& d) { printer.print(d); });
        scene::Scene scene = obj::viewer_scene(request.path, request.width, request.height, diag);
        long long triangles = 0;
        for (const scene::Mesh& m : scene.meshes) triangles += static_cast<long long>(m.faces.size());
        if (triangles > limits.triangles)
            throw Error(ErrorKind::Render, {},
                        request.path + " has " + std::to_string(triangles) +
                            " triangles, more than " + std::to_string(limits.triangles) +
                            " (limit: --max-triangles)");
        scene::validate(scene);
        return scene;
    }

    if (blender::is_blender_exchange(request.path)) {
        // The Blender add-on's exchange (formats/blender/FORMAT.md).
        ParseDiagnosticPrinter printer(verbose);
        Diagnostics diag([&printer](const Diagnostic& d) { printer.print(d); });
        blender::ImportLimits bl;
        bl.triangles = limits.triangles;
        bl.objects = limits.objects;
        scene::Scene scene = blender::import_blender(request.path, bl, diag);
        scene::validate(scene);
        return scene;
    }

    pov::ParseOptions options;
    options.include_dirs = include_search_path(request.include_dirs);
    options.clock = request.clock;
    options.clock_on = request.clock_on;
    options.clock_delta = request.clock_delta;
    options.initial_clock = request.initial_clock;
    options.final_clock = request.final_clock;
    options.initial_frame = request.initial_frame;
    options.final_frame = request.final_frame;
    options.frame_number = request.frame_number;
    options.declares = request.declares;
    options.image_width = request.width;
    options.image_height = request.height;
    options.max_loop_iterations = limits.loop_iterations;
    options.max_macro_depth = limits.recursion;
    options.max_include_depth = limits.include_depth;
    options.max_array_elements = limits.array_size;
    options.max_string_length = limits.string_length;
    options.max_triangles = limits.triangles;
    options.max_objects = limits.objects;
    options.max_parse_stack_mib = limits.parse_stack_mib;
    options.max_memory_mib = limits.memory_mib;
    options.prepare_object = render::prepare_object_query;  // trace(), inside(), extents
    options.pattern_hook = render::parse_time_pattern;   // pattern functions called while parsing
    options.cancel = &cancel_flag();                      // SIGINT/SIGTERM stop the parse too
    ParseDiagnosticPrinter printer(verbose);
    Diagnostics diag([&printer](const Diagnostic& d) { printer.print(d); });
    scene::Scene scene = pov::parse_file(request.path, options, diag);
    printer.summary();
    scene::validate(scene);
    return scene;
}

void apply_blender_render(const scene::BlenderRender& b, const GivenSettings& given,
                          render::RenderOptions* options) {
    if (!given.width) options->width = b.width;
    if (!given.height) options->height = b.height;
    if (!given.integrator) options->integrator = render::IntegratorKind::Path;
    if (!given.spp) options->spp = b.samples;
    if (!given.seed) options->seed = static_cast<uint32_t>(b.seed);
    if (!given.max_depth) options->max_depth = b.max_bounces + 1;
    options->pixel_filter = b.pixel_filter == "BOX"        ? render::PixelFilterKind::Box
                            : b.pixel_filter == "GAUSSIAN" ? render::PixelFilterKind::Gaussian
                                                           : render::PixelFilterKind::BlackmanHarris;
    options->filter_width = b.filter_width;
    options->clamp_direct = b.clamp_direct;
    options->clamp_indirect = b.clamp_indirect;
    options->filter_glossy = b.filter_glossy;
    if (!given.adaptive) {
        options->adaptive = b.adaptive_sampling;
        options->adaptive_threshold = b.adaptive_threshold;
        options->adaptive_min_samples = b.adaptive_min_samples;
    }
    // Cycles' limits per kind stay whatever --max-depth says of the total (the add-on
    // passes its own total), as Cycles' own panel keeps them apart.
    options->diffuse_bounces = b.diffuse_bounces;
    options->glossy_bounces = b.glossy_bounces;
    options->transmission_bounces = b.transmission_bounces;
    options->transparent_bounces = b.transparent_bounces;
    options->volume_bounces = b.volume_bounces;
    options->film_transparent = b.film_transparent;
    options->film_transparent_glass = b.film_transparent_glass;
    options->volume_step_rate = b.volume_step_rate;
    options->volume_max_steps = b.volume_max_steps;
}

}  // namespace glint::app
