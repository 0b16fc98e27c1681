// `glint convert IN.exr -o OUT.png`: a linear float image (a render written earlier) to a
// display image, POV-Ray's sRGB encoding by default or Blender's view transform with --view.
// Also home of the --view flags that `glint render` shares.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "app/cli_common.h"
#include "app/commands.h"
#include "io/color_encoding.h"
#include "io/image_output.h"

namespace glint::app {

void add_view_options(CLI::App& cmd, io::ViewSettings& view) {
    cmd.add_option("--view", view.view,
                   "8/16-bit output through Blender's color management instead of POV-Ray's "
                   "sRGB: a view of its sRGB display, Standard or Filmic (also Filmic Log, Raw, "
                   "False Color); the same pixels Blender 3.4 saves for the linear image");
    cmd.add_option("--look", view.look,
                   "With --view: a look of the config, e.g. 'Medium High Contrast' (default None)");
    cmd.add_option("--exposure", view.exposure, "With --view: exposure in stops (default 0)");
    cmd.add_option("--gamma", view.gamma, "With --view: display gamma (default 1)");
    cmd.add_option("--ocio-config", view.config_path,
                   "With --view: the OpenColorIO config (default: $OCIO, else Blender's "
                   "datafiles/colormanagement/config.ocio)");
}

io::ViewSettings checked_view_settings(const io::ViewSettings& view) {
    if (!view.active()) {
        if (!view.look.empty() || view.exposure != 0.0f || view.gamma != 1.0f ||
            !view.config_path.empty())
            throw Error(ErrorKind::Usage, {},
                        "--look, --exposure, --gamma and --ocio-config need --view (Standard or "
                        "Filmic)");
        return view;
    }
    return io::resolve_view(view);
}

CLI::App* add_convert_command(CLI::App& app, ConvertArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "convert",
        "Convert a linear EXR/HDR render for display (sRGB or a Blender view)");
    cmd->footer(
        "Convert a linear float image (.exr, .hdr, e.g. a glint render) to OUT: 8/16-bit "
        "formats get POV-Ray's sRGB encoding, or Blender's view transform with --view");
    cmd->add_option("IN", args.input, "Linear float image (.exr or .hdr)")->required();
    cmd->add_option("-o,--output", args.output,
                    "Output image; format from the extension: png, jpg, tif, exr, hdr")
        ->required();
    add_view_options(*cmd, args.view);
    cmd->add_flag("-v,--verbose", args.verbose, "Print the encoding used");
    return cmd;
}

int run_convert(const ConvertArgs& args) {
    io::output_format_for(args.output);  // refuse a bad extension before reading
    io::OutputEncoding encoding;         // linear input, POV-Ray's sRGB unless --view
    encoding.view = checked_view_settings(args.view);
    if (encoding.view.active() && io::is_float_format(args.output))
        std::fprintf(stderr,
                     "glint: warning: --view %s does not apply to %s: float images stay linear\n",
                     encoding.view.view.c_str(), args.output.c_str());
    bool has_alpha = false;
    Image image = io::read_float_image(args.input, &has_alpha);
    encoding.alpha = has_alpha;
    io::write_image(image, args.output, encoding);
    if (args.verbose)
        std::fprintf(stderr, "%s: %dx%d, %s\n", args.output.c_str(), image.width, image.height,
                     encoding.view.active() ? io::describe_view(encoding.view).c_str()
                                            : "sRGB (POV-Ray 3.7's encoding)");
    return kExitOk;
}

}  // namespace glint::app
