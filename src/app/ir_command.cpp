// `glint ir SCENE.pov`: the scene as the importer understood it (formats::print_ir).
#include <CLI/CLI.hpp>
#include <cstdio>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/scene_loading.h"
#include "formats/common/ir_printer.h"

namespace glint::app {

CLI::App* add_ir_command(CLI::App& app, IrArgs& args) {
    CLI::App* cmd = app.add_subcommand("ir", "Print the scene as glint understood it");
    cmd->add_option("SCENE", args.scene, "POV-Ray scene file")->required();
    cmd->add_option("-I,--include", args.include_dirs, "Include folder (repeatable)")
        ->allow_extra_args(false);  // one folder per -I, so `-I dir scene.pov` works
    cmd->add_option("--clock", args.clock, "Value of `clock`")->capture_default_str();
    cmd->add_option("--width", args.width, "Value of image_width")
        ->capture_default_str()
        ->check(CLI::Range(1, 1 << 16));
    cmd->add_option("--height", args.height, "Value of image_height")
        ->capture_default_str()
        ->check(CLI::Range(1, 1 << 16));
    return cmd;
}

int run_ir(const IrArgs& args) {
    SceneRequest request;
    request.path = args.scene;
    request.include_dirs = args.include_dirs;
    request.clock = args.clock;
    request.width = args.width;
    request.height = args.height;
    scene::Scene scene = load_scene(request, /*verbose=*/false);
    std::string text = formats::print_ir(scene);
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::fflush(stdout);
    return kExitOk;
}

}  // namespace glint::app
