#include "app/scene_loading.h"

#include <cstdio>
#include <filesystem>

#include "app/cli_common.h"
#include "core/error.h"
#include "core/log.h"
#include "formats/pov/parser.h"
#include "scene/validate.h"

namespace glint::app {

namespace {

void print_diagnostic(const Diagnostic& d, bool verbose) {
    if (d.level == Diagnostic::Level::Warning) {
        std::fputs(format_diagnostic(d.loc, "warning", d.message).c_str(), stderr);
    } else if (verbose) {
        std::fprintf(stderr, "%s\n", d.message.c_str());
    }
}

}  // namespace

scene::Scene load_scene(const SceneRequest& request, bool verbose) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(request.path, ec))
        throw Error(ErrorKind::MissingFile, {}, "scene file not found: " + request.path);
    if (fs::is_directory(request.path, ec))
        throw Error(ErrorKind::MissingFile, {}, "scene path is a folder: " + request.path);

    pov::ParseOptions options;
    options.include_dirs = include_search_path(request.include_dirs);
    options.clock = request.clock;
    options.image_width = request.width;
    options.image_height = request.height;
    Diagnostics diag([verbose](const Diagnostic& d) { print_diagnostic(d, verbose); });
    scene::Scene scene = pov::parse_file(request.path, options, diag);
    scene::validate(scene);
    return scene;
}

}  // namespace glint::app
