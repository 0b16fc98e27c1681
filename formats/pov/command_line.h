// POV-Ray's own command line for `glint render`: `+W640 +H480 +A0.3 +Iscene.pov +Oout.png`
// switches and .ini files (`glint render scene.ini`, `res.ini[Low]`), read into PovSettings
// and mapped onto glint's render flags; and POV-Ray's internal animation loop (Initial_Frame ..
// Final_Frame with the clock running from Initial_Clock to Final_Clock). Reference: POV-Ray 3.7
// manual 3.2 "Command-Line and INI-File Options" and 2.2.8 "Using INI Files".
// Part of the POV-Ray importer: the grammar of POV-Ray's options; the CLI (src/app: main.cpp,
// render_command.cpp, farm_command.cpp) maps them onto glint's flags.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace glint::pov {

// What POV-Ray options set. Unset fields leave glint's flags and defaults alone.
struct PovSettings {
    std::optional<std::string> input;   // +I, Input_File_Name
    std::optional<std::string> output;  // +O, Output_File_Name
    std::optional<int> width, height;   // +W, +H
    std::optional<bool> antialias;      // +A / -A
    std::optional<double> aa_threshold;
    std::optional<int> aa_depth;         // +R
    std::optional<int> sampling_method;  // +AM
    std::optional<bool> jitter;          // +J / -J
    std::optional<double> jitter_amount; // +J0.5, Jitter_Amount (POV-Ray clips it to [0, 1])
    std::vector<std::string> library_paths;  // +L (accumulates)
    std::optional<double> clock;             // +K
    std::optional<int> initial_frame, final_frame;      // +KFI, +KFF
    std::optional<double> initial_clock, final_clock;   // +KI, +KF
    std::optional<double> subset_start, subset_end;     // +SF, +EF (frame or fraction)
    std::optional<int> frame_step;                      // +STP
    std::optional<bool> cyclic;                         // +KC
    std::optional<int> threads;                         // +WT
    std::optional<char> output_type;  // +F<type>: N png, E exr, H hdr, J jpeg, T/C tga, ...
    std::vector<std::pair<std::string, double>> declares;  // Declare=Name=Value
    // `glint: warning: ...` lines for options accepted but without effect in glint, in order.
    std::vector<std::string> warnings;
};

// The POV-Ray arguments of a `glint render` command line, taken out of argv so that CLI11 sees
// only glint's own flags. An argument is POV-Ray's when it starts with '+' and a letter, when
// it starts with '-' and a letter that is not one of glint's short flags (-o -I -W -H -v -h;
// `-Iscene.pov` naming a .pov file is POV-Ray's input), or when it names an .ini file
// (`x.ini`, `x.ini[Section]`) and is not the value of a glint flag.
struct SplitArgs {
    std::vector<std::string> glint;  // argv[0], the subcommand, glint's own arguments
    std::vector<std::string> pov;    // in command-line order
};
SplitArgs split_render_args(const std::vector<std::string>& args, size_t first);

bool is_pov_switch(const std::string& arg);
bool is_ini_argument(const std::string& arg);

// Applies one switch (`+W640`, `-A`, `+KFF10`). Throws Error(Usage) for an unknown switch or
// a bad value, naming the switch.
void apply_pov_switch(const std::string& sw, PovSettings& s);
// Applies one .ini option; `key` is case-insensitive. `where` prefixes messages (file:line).
void apply_ini_option(const std::string& key, const std::string& value, PovSettings& s,
                      const std::string& where);
// Reads `file.ini` or `file.ini[Section]` (labels are case-insensitive; without one only the
// unlabeled top of the file is read; a bare name on a line includes that .ini, up to 10 deep).
// Throws Error(MissingFile) when the file cannot be read, Error(Usage) for a bad line.
void read_pov_ini(const std::string& spec, PovSettings& s, int depth = 0);
// Runs the POV-Ray arguments in order (switches and .ini files).
PovSettings read_pov_arguments(const std::vector<std::string>& pov_args);

// The frames of POV-Ray's internal animation loop, computed as POV-Ray 3.7's
// AnimationProcessing does: clock = initial_clock + (frame - initial_frame) * clock_delta with
// clock_delta = (final_clock - initial_clock) / (final_frame - initial_frame), where cyclic
// animation first adds one frame to final_frame (so the last frame stops one step short of
// final_clock); subsets select frames by number or, for values in (0, 1), by fraction.
struct PovFrame {
    int number = 0;
    double clock = 0;
};
struct AnimationPlan {
    bool animated = false;  // final_frame > initial_frame
    int initial_frame = 1, final_frame = 1;
    double initial_clock = 0, final_clock = 1, clock_delta = 0;
    int digits = 1;  // of final_frame: output names are zero-padded to it
    std::vector<PovFrame> frames;
};
AnimationPlan plan_animation(const PovSettings& s);

// glint's `--frames first-last` on top of POV-Ray's options: where those define the animation
// (+KFI/+KFF, an .ini), the frames of it to render (+SF/+EF); otherwise the animation itself
// (Initial_Frame first, Final_Frame last).
void apply_frame_range(PovSettings& s, int first, int last);

// `out.png`, frame 7 of 2 digits -> `out07.png` (the number before the extension).
std::string frame_output_name(const std::string& output, int frame, int digits);

// The extension for POV-Ray's output type letter (N png, E exr, H hdr, J jpg); an empty string
// for the types glint cannot write (T, C targa, P ppm, B bmp, S system).
std::string extension_for_output_type(char type);

}  // namespace glint::pov
