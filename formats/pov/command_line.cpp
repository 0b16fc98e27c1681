#include "formats/pov/command_line.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/error.h"

namespace glint::pov {

namespace {

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

std::string trim(const std::string& s) {
    size_t b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return "";
    size_t e = s.find_last_not_of(" \t\r\n");
    return s.substr(b, e - b + 1);
}

// POV-Ray allows a value in single or double quotes (file names with blanks).
std::string unquote(const std::string& s) {
    if (s.size() >= 2 && (s.front() == '"' || s.front() == '\'') && s.back() == s.front())
        return s.substr(1, s.size() - 2);
    return s;
}

Error usage(const std::string& message) { return Error(ErrorKind::Usage, {}, message); }

double to_double(const std::string& text, const std::string& what) {
    const char* begin = text.c_str();
    char* end = nullptr;
    double v = std::strtod(begin, &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v))
        throw usage(what + ": expected a number, got '" + text + "'");
    return v;
}

int to_int(const std::string& text, const std::string& what) {
    double v = to_double(text, what);
    if (v != std::floor(v) || std::fabs(v) > 1e9)
        throw usage(what + ": expected an integer, got '" + text + "'");
    return static_cast<int>(v);
}

bool to_bool(const std::string& text, const std::string& what) {
    std::string t = lower(text);
    if (t == "on" || t == "true" || t == "yes" || t == "1") return true;
    if (t == "off" || t == "false" || t == "no" || t == "0") return false;
    throw usage(what + ": expected on/off (true/false, yes/no, 1/0), got '" + text + "'");
}

int positive(int v, const std::string& what) {
    if (v < 1 || v > (1 << 16)) throw usage(what + ": must be in 1.." + std::to_string(1 << 16));
    return v;
}

void ignored(PovSettings& s, const std::string& what) {
    s.warnings.push_back(what + " is ignored");
}

void not_supported(PovSettings& s, const std::string& what) {
    s.warnings.push_back(what + " is not supported and is ignored");
}

void set_output_type(PovSettings& s, char type, const std::string& what) {
    type = static_cast<char>(std::toupper(static_cast<unsigned char>(type)));
    if (std::string("NEHJTCPBS").find(type) == std::string::npos)
        throw usage(what + ": unknown output file type '" + std::string(1, type) +
                    "' (N png, E exr, H hdr, J jpeg, T/C targa, P ppm, B bmp, S system)");
    s.output_type = type;
    if (extension_for_output_type(type).empty())
        s.warnings.push_back(what + ": glint cannot write this file type; the output name's "
                                    "extension decides (PNG when glint picks the name)");
}

// Display, console and speed options: POV-Ray's interactive side, which glint does not have.
struct Switch {
    const char* name;  // upper case
    enum Kind { Ignored, NotSupported } kind;
    const char* what;
};
constexpr Switch kPassive[] = {
    {"SC", Switch::NotSupported, "partial render (start column)"},
    {"SR", Switch::NotSupported, "partial render (start row)"},
    {"EC", Switch::NotSupported, "partial render (end column)"},
    {"ER", Switch::NotSupported, "partial render (end row)"},
    {"SP", Switch::Ignored, "mosaic preview"},
    {"EP", Switch::Ignored, "mosaic preview"},
    {"SU", Switch::Ignored, "split unions"},
    {"AG", Switch::NotSupported, "anti-aliasing gamma"},
    {"UA", Switch::NotSupported, "output alpha"},
    {"UD", Switch::Ignored, "draw vistas"},
    {"UF", Switch::NotSupported, "field rendering"},
    {"UO", Switch::NotSupported, "odd field"},
    {"UL", Switch::Ignored, "light buffer"},
    {"UV", Switch::Ignored, "vista buffer"},
    {"UR", Switch::Ignored, "remove bounds"},
    {"MB", Switch::Ignored, "bounding threshold"},
    {"MV", Switch::NotSupported, "language version"},
    {"MI", Switch::Ignored, "max image buffer"},
    {"HI", Switch::NotSupported, "include header"},
    {"WL", Switch::Ignored, "warning level"},
    {"RVP", Switch::Ignored, "vain pretrace"},
    {"GA", Switch::Ignored, "console output"},
    {"GD", Switch::Ignored, "debug console output"},
    {"GF", Switch::Ignored, "fatal console output"},
    {"GR", Switch::Ignored, "render console output"},
    {"GS", Switch::Ignored, "statistics console output"},
    {"GW", Switch::Ignored, "warning console output"},
    {"GI", Switch::Ignored, "create ini file"},
    {"GP", Switch::Ignored, "console paging"},
    {"D", Switch::Ignored, "display"},
    {"V", Switch::Ignored, "verbose"},
    {"P", Switch::Ignored, "pause when done"},
    {"X", Switch::Ignored, "test abort"},
    {"C", Switch::Ignored, "continue trace"},
    {"Q", Switch::Ignored, "quality (glint always renders at full quality)"},
};

bool starts_with(const std::string& s, const char* prefix) {
    return s.compare(0, std::char_traits<char>::length(prefix), prefix) == 0;
}

}  // namespace

bool is_pov_switch(const std::string& arg) {
    return arg.size() >= 2 && (arg[0] == '+' || arg[0] == '-') &&
           std::isalpha(static_cast<unsigned char>(arg[1]));
}

bool is_ini_argument(const std::string& arg) {
    if (arg.empty() || arg[0] == '-' || arg[0] == '+') return false;
    std::string name = arg;
    if (name.back() == ']') {
        size_t open = name.rfind('[');
        if (open == std::string::npos) return false;
        name = name.substr(0, open);
    }
    return lower(std::filesystem::path(name).extension().string()) == ".ini";
}

SplitArgs split_render_args(const std::vector<std::string>& args, size_t first) {
    // glint's render flags that take a value as the next argument.
    static const char* const kWithValue[] = {"-o", "--output", "-I", "--include", "-W",
                                             "--width", "-H", "--height", "--clock", "--aa",
                                             "--threads", "--progress"};
    static const std::string kGlintShort = "oIWHvh";
    SplitArgs out;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (i < first) {
            out.glint.push_back(a);
            continue;
        }
        bool takes_value = std::any_of(std::begin(kWithValue), std::end(kWithValue),
                                       [&](const char* f) { return a == f; });
        if (takes_value) {
            out.glint.push_back(a);
            if (i + 1 < args.size()) out.glint.push_back(args[++i]);
            continue;
        }
        if (a == "--") {  // everything after is glint's positional
            for (; i < args.size(); ++i) out.glint.push_back(args[i]);
            break;
        }
        bool pov = false;
        if (is_pov_switch(a)) {
            if (a[0] == '+') {
                pov = true;
            } else if (a[1] == 'I' && a.size() > 6 && lower(a.substr(a.size() - 4)) == ".pov") {
                pov = true;  // -Iscene.pov: POV-Ray's input, not an include folder
            } else {
                pov = kGlintShort.find(a[1]) == std::string::npos;
            }
        } else if (is_ini_argument(a)) {
            pov = true;
        }
        (pov ? out.pov : out.glint).push_back(a);
    }
    return out;
}

void apply_pov_switch(const std::string& sw, PovSettings& s) {
    if (!is_pov_switch(sw)) throw usage("not a POV-Ray switch: '" + sw + "'");
    const bool on = sw[0] == '+';
    const std::string body = sw.substr(1);
    const std::string key = upper(body);
    auto rest = [&](size_t n) { return unquote(body.substr(n)); };
    auto need = [&](size_t n, const char* what) {
        std::string r = rest(n);
        if (r.empty()) throw usage(sw + ": missing " + std::string(what));
        return r;
    };
    // Longest names first where one is a prefix of another (KFI/KFF/KF/KI/KC before K).
    if (starts_with(key, "KFI")) {
        s.initial_frame = to_int(need(3, "frame number"), sw);
    } else if (starts_with(key, "KFF")) {
        s.final_frame = to_int(need(3, "frame number"), sw);
    } else if (starts_with(key, "KF")) {
        s.final_clock = to_double(need(2, "clock value"), sw);
    } else if (starts_with(key, "KI")) {
        s.initial_clock = to_double(need(2, "clock value"), sw);
    } else if (starts_with(key, "KC")) {
        if (!rest(2).empty()) throw usage(sw + ": +KC takes no value");
        s.cyclic = on;
    } else if (starts_with(key, "K")) {
        s.clock = to_double(need(1, "clock value"), sw);
    } else if (starts_with(key, "STP")) {
        s.frame_step = std::max(1, to_int(need(3, "frame step"), sw));
    } else if (starts_with(key, "SF")) {
        s.subset_start = to_double(need(2, "frame"), sw);
    } else if (starts_with(key, "EF")) {
        s.subset_end = to_double(need(2, "frame"), sw);
    } else if (starts_with(key, "AM")) {
        int m = to_int(need(2, "sampling method"), sw);
        if (m < 1 || m > 3) throw usage(sw + ": sampling method must be 1, 2 or 3");
        s.sampling_method = m;
    } else if (starts_with(key, "WT")) {
        int n = to_int(need(2, "thread count"), sw);
        if (n < 1 || n > 4096) throw usage(sw + ": thread count must be in 1..4096");
        s.threads = n;
    } else if (starts_with(key, "HI") || starts_with(key, "WL")) {
        for (const Switch& p : kPassive)
            if (starts_with(key, p.name)) {
                (p.kind == Switch::Ignored ? ignored : not_supported)(s, sw + " (" + p.what + ")");
                return;
            }
    } else if (starts_with(key, "W")) {
        s.width = positive(to_int(need(1, "width"), sw), sw);
    } else if (starts_with(key, "H")) {
        s.height = positive(to_int(need(1, "height"), sw), sw);
    } else if (starts_with(key, "I")) {
        s.input = need(1, "file name");
    } else if (starts_with(key, "O")) {
        std::string o = need(1, "file name");
        if (o == "-") throw usage(sw + ": writing the image to standard output is not supported");
        s.output = o;
    } else if (starts_with(key, "L")) {
        s.library_paths.push_back(need(1, "folder"));
    } else if (key == "A" || (key[0] == 'A' && key.size() > 1 &&
                              (std::isdigit(static_cast<unsigned char>(key[1])) || key[1] == '.'))) {
        s.antialias = on;
        if (key.size() > 1) {
            double t = to_double(rest(1), sw);
            if (!(t >= 0 && t <= 3)) throw usage(sw + ": threshold must be in [0, 3]");
            s.aa_threshold = t;
        }
    } else if (key == "R" || (key[0] == 'R' && key.size() > 1 &&
                              std::isdigit(static_cast<unsigned char>(key[1])))) {
        int d = to_int(need(1, "depth"), sw);
        if (d < 1 || d > 9) throw usage(sw + ": anti-aliasing depth must be in 1..9");
        s.aa_depth = d;
    } else if (key == "J" || (key[0] == 'J' && key.size() > 1 &&
                              (std::isdigit(static_cast<unsigned char>(key[1])) || key[1] == '.'))) {
        if (key.size() > 1) s.jitter_amount = std::clamp(to_double(rest(1), sw), 0.0, 1.0);
        s.jitter = on;
    } else if (starts_with(key, "F") &&
               (key.size() == 1 || std::isalpha(static_cast<unsigned char>(key[1])))) {
        if (!on) {
            s.warnings.push_back(sw + " (no output file) is ignored: glint always writes the image");
        } else if (key.size() > 1) {
            std::string bits = key.substr(2);
            if (!bits.empty()) to_int(bits, sw);  // +FN16: bit depth follows the format in glint
            set_output_type(s, key[1], sw);
        }
    } else {
        for (const Switch& p : kPassive) {
            if (!starts_with(key, p.name)) continue;
            // A one-letter entry matches only itself plus an optional value (+D, +D0, +Q9).
            size_t n = std::char_traits<char>::length(p.name);
            if (key.size() > n && std::isalpha(static_cast<unsigned char>(key[n])) && n == 1 &&
                p.name[0] != 'G')
                continue;
            (p.kind == Switch::Ignored ? ignored : not_supported)(s, sw + " (" + p.what + ")");
            return;
        }
        throw usage("unknown POV-Ray option '" + sw + "'");
    }
}

void apply_ini_option(const std::string& key_in, const std::string& value_in, PovSettings& s,
                      const std::string& where) {
    const std::string key = lower(trim(key_in));
    const std::string value = unquote(trim(value_in));
    const std::string what = where + ": " + trim(key_in);
    auto b = [&] { return to_bool(value, what); };
    auto f = [&] { return to_double(value, what); };
    auto i = [&] { return to_int(value, what); };
    if (key == "input_file_name" || key == "input_file") s.input = value;
    else if (key == "output_file_name" || key == "output_file") {
        if (value == "-") throw usage(what + ": writing to standard output is not supported");
        s.output = value;
    } else if (key == "width") s.width = positive(i(), what);
    else if (key == "height") s.height = positive(i(), what);
    else if (key == "antialias") s.antialias = b();
    else if (key == "antialias_threshold") {
        double t = f();
        if (!(t >= 0 && t <= 3)) throw usage(what + ": threshold must be in [0, 3]");
        s.aa_threshold = t;
    } else if (key == "antialias_depth") {
        int d = i();
        if (d < 1 || d > 9) throw usage(what + ": depth must be in 1..9");
        s.aa_depth = d;
    } else if (key == "sampling_method") {
        int m = i();
        if (m < 1 || m > 3) throw usage(what + ": sampling method must be 1, 2 or 3");
        s.sampling_method = m;
    } else if (key == "jitter") s.jitter = b();
    else if (key == "jitter_amount") s.jitter_amount = std::clamp(f(), 0.0, 1.0);
    else if (key == "library_path") s.library_paths.push_back(value);
    else if (key == "clock") s.clock = f();
    else if (key == "initial_frame") s.initial_frame = i();
    else if (key == "final_frame") s.final_frame = i();
    else if (key == "initial_clock") s.initial_clock = f();
    else if (key == "final_clock") s.final_clock = f();
    else if (key == "subset_start_frame") s.subset_start = f();
    else if (key == "subset_end_frame") s.subset_end = f();
    else if (key == "frame_step") s.frame_step = std::max(1, i());
    else if (key == "cyclic_animation") s.cyclic = b();
    else if (key == "work_threads") {
        int n = i();
        if (n < 1 || n > 4096) throw usage(what + ": must be in 1..4096");
        s.threads = n;
    } else if (key == "declare") {
        size_t eq = value.find('=');
        if (eq == std::string::npos || eq == 0)
            throw usage(what + ": expected Declare=Name=Value, got '" + value + "'");
        std::string name = trim(value.substr(0, eq));
        bool ok = !std::isdigit(static_cast<unsigned char>(name[0]));
        for (char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
        if (!ok) throw usage(what + ": '" + name + "' is not an identifier");
        s.declares.emplace_back(name, to_double(trim(value.substr(eq + 1)), what));
    } else if (key == "output_file_type") {
        if (value.empty()) throw usage(what + ": missing file type letter");
        set_output_type(s, value[0], what);
    } else if (key == "output_to_file") {
        if (!b()) s.warnings.push_back(what + "=off is ignored: glint always writes the image");
    } else if (key == "bits_per_color" || key == "compression") {
        i();
        ignored(s, what);
    } else {
        static const char* const kIgnored[] = {
            "display", "verbose", "pause_when_done", "display_gamma", "draw_vistas",
            "test_abort", "test_abort_count", "continue_trace", "create_ini", "all_console",
            "debug_console", "fatal_console", "render_console", "statistic_console",
            "warning_console", "all_file", "debug_file", "fatal_file", "render_file",
            "statistic_file", "warning_file", "preview_start_size", "preview_end_size",
            "bounding", "bounding_threshold", "light_buffer", "vista_buffer", "remove_bounds",
            "split_unions", "quality", "warning_level", "palette", "video_mode", "max_image_buffer",
            "pre_scene_command", "pre_frame_command", "post_scene_command",
            "post_frame_command", "user_abort_command", "fatal_error_command",
            "pre_scene_return", "pre_frame_return", "post_scene_return", "post_frame_return",
            "user_abort_return", "fatal_error_return", "histogram_type", "histogram_name",
            "histogram_grid_size", "append_file", "radiosity_vain_pretrace", "buffer_output",
            "buffer_size", "file_gamma", "dither", "dither_method", "output_file_gamma"};
        static const char* const kNotSupported[] = {
            "start_column", "start_row", "end_column", "end_row", "antialias_gamma",
            "output_alpha", "field_render", "odd_field", "version", "include_header",
            "clockless_animation", "real_time_raytracing", "radiosity_file_name",
            "radiosity_from_file", "radiosity_to_file", "hf_gray_16"};
        for (const char* k : kIgnored)
            if (key == k) return ignored(s, what);
        for (const char* k : kNotSupported)
            if (key == k) return not_supported(s, what);
        throw usage(what + ": unknown POV-Ray ini option");
    }
}

void read_pov_ini(const std::string& spec, PovSettings& s, int depth) {
    if (depth > 10) throw usage(spec + ": .ini files nested more than 10 deep");
    std::string path = spec;
    std::string section;
    bool want_section = false;
    if (!path.empty() && path.back() == ']') {
        size_t open = path.rfind('[');
        if (open != std::string::npos) {
            section = lower(trim(path.substr(open + 1, path.size() - open - 2)));
            path = path.substr(0, open);
            want_section = true;
        }
    }
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(path, ec) && fs::path(path).extension().empty() && fs::exists(path + ".ini", ec))
        path += ".ini";  // POV-Ray assumes .ini for a bare name
    std::ifstream in(path);
    if (!in || fs::is_directory(path, ec))
        throw Error(ErrorKind::MissingFile, {}, "cannot read the .ini file " + path);
    bool active = !want_section;
    bool found = !want_section;
    std::string line;
    int line_no = 0;
    while (std::getline(in, line)) {
        ++line_no;
        const std::string where = path + ":" + std::to_string(line_no);
        // A ';' starts a comment, except inside quotes.
        char quote = 0;
        for (size_t k = 0; k < line.size(); ++k) {
            char c = line[k];
            if (quote) {
                if (c == quote) quote = 0;
            } else if (c == '"' || c == '\'') {
                quote = c;
            } else if (c == ';' || (c == '/' && k + 1 < line.size() && line[k + 1] == '/')) {
                line.resize(k);
                break;
            }
        }
        line = trim(line);
        if (line.empty()) continue;
        if (line.front() == '[') {
            if (line.back() != ']') throw usage(where + ": unclosed section label '" + line + "'");
            active = want_section && lower(trim(line.substr(1, line.size() - 2))) == section;
            found = found || active;
            continue;
        }
        if (!active) continue;
        size_t eq = line.find('=');
        if (line[0] == '+' || line[0] == '-') {
            // Switches, several per line.
            size_t k = 0;
            while (k < line.size()) {
                size_t end = line.find_first_of(" \t", k);
                std::string sw = line.substr(k, end == std::string::npos ? end : end - k);
                try {
                    apply_pov_switch(sw, s);
                } catch (const Error& e) {
                    throw usage(where + ": " + e.what());
                }
                if (end == std::string::npos) break;
                k = line.find_first_not_of(" \t", end);
                if (k == std::string::npos) break;
            }
        } else if (eq != std::string::npos) {
            apply_ini_option(line.substr(0, eq), line.substr(eq + 1), s, where);
        } else {
            // A bare name includes another .ini, relative to the current folder as in POV-Ray;
            // also tried beside this file.
            std::string nested = unquote(line);
            fs::path beside = fs::path(path).parent_path() / nested;
            if (!fs::exists(nested, ec) && !fs::exists(nested + ".ini", ec) &&
                (fs::exists(beside, ec) || fs::exists(beside.string() + ".ini", ec)))
                nested = beside.string();
            read_pov_ini(nested, s, depth + 1);
        }
    }
    if (!found) throw usage(spec + ": no section [" + section + "] in " + path);
}

PovSettings read_pov_arguments(const std::vector<std::string>& pov_args) {
    PovSettings s;
    for (const std::string& a : pov_args) {
        if (is_pov_switch(a))
            apply_pov_switch(a, s);
        else
            read_pov_ini(a, s);
    }
    return s;
}

AnimationPlan plan_animation(const PovSettings& s) {
    AnimationPlan plan;
    const bool cyclic = s.cyclic.value_or(false);
    plan.initial_frame = std::max(s.initial_frame.value_or(1), 0);
    plan.initial_clock = s.initial_clock.value_or(0.0);
    plan.final_frame = std::max(s.final_frame.value_or(1), plan.initial_frame);
    plan.final_clock = s.final_clock.value_or(1.0);
    plan.animated = plan.final_frame > plan.initial_frame;
    if (!plan.animated) return plan;
    const int step = std::max(s.frame_step.value_or(1), 1);
    if (cyclic) ++plan.final_frame;
    const int count = plan.final_frame - plan.initial_frame + 1;
    // A subset value in (0, 1) is a fraction of the frames; anything else a frame number.
    auto subset_frame = [&](double v) {
        v = std::max(v, 0.0);
        return (v == 0.0 || v >= 1.0) ? static_cast<int>(v) : static_cast<int>(count * v);
    };
    int start = s.subset_start ? std::max(subset_frame(*s.subset_start), plan.initial_frame)
                               : plan.initial_frame;
    int end = s.subset_end ? std::max(subset_frame(*s.subset_end), start)
                           : plan.final_frame - (cyclic ? 1 : 0);
    plan.clock_delta = (plan.final_clock - plan.initial_clock) /
                       double(plan.final_frame - plan.initial_frame);
    for (int n = start; n <= end; n += step)
        plan.frames.push_back({n, plan.initial_clock + plan.clock_delta * (n - plan.initial_frame)});
    plan.digits = 1;
    for (int v = plan.final_frame; v >= 10; v /= 10) ++plan.digits;
    return plan;
}

void apply_frame_range(PovSettings& s, int first, int last) {
    if (s.initial_frame || s.final_frame) {
        s.subset_start = first;
        s.subset_end = last;
    } else {
        s.initial_frame = first;
        s.final_frame = last;
    }
}

std::string frame_output_name(const std::string& output, int frame, int digits) {
    namespace fs = std::filesystem;
    fs::path p(output);
    std::string number = std::to_string(frame);
    if (static_cast<int>(number.size()) < digits)
        number.insert(0, static_cast<size_t>(digits) - number.size(), '0');
    fs::path name = p.stem();
    name += number;
    name += p.extension();
    return (p.parent_path() / name).string();
}

std::string extension_for_output_type(char type) {
    switch (std::toupper(static_cast<unsigned char>(type))) {
        case 'N': return ".png";
        case 'E': return ".exr";
        case 'H': return ".hdr";
        case 'J': return ".jpg";
        default: return "";
    }
}

}  // namespace glint::pov
