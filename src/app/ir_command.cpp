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
    add_scene_options(*cmd, args.scene);
    return cmd;
}

int run_ir(const IrArgs& args) {
    scene::Scene scene = load_scene(args.scene, /*verbose=*/false);
    std::string text = formats::print_ir(scene);
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::fflush(stdout);
    return kExitOk;
}

}  // namespace glint::app
