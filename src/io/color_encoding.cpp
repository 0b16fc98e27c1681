#include "io/color_encoding.h"

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <sstream>

#include "core/error.h"

namespace OCIO = OCIO_NAMESPACE;

namespace glint::io {

namespace {

// POV-Ray treats a power-law curve within 1% of 1 as neutral
// (PowerLawGammaCurve::IsNeutral, source/base/image/colourspace.cpp).
bool is_neutral_gamma(double g) { return std::fabs(1.0 - g) <= 0.01; }

OCIO::ExponentTransformRcPtr exponent(double value, OCIO::TransformDirection dir) {
    auto t = OCIO::ExponentTransform::Create();
    const double v[4] = {value, value, value, 1.0};
    t->setValue(v);
    // Negative film values (possible with negative light colors) clamp to 0, as POV-Ray's
    // PowerLawGammaCurve does with max(x, 0).
    t->setNegativeStyle(OCIO::NEGATIVE_CLAMP);
    t->setDirection(dir);
    return t;
}

// The sRGB curve (IEC 61966-2-1): OCIO's ExponentWithLinearTransform with gamma 2.4 and
// offset 0.055 is the sRGB decoding; its inverse direction encodes.
OCIO::ExponentWithLinearTransformRcPtr srgb(OCIO::TransformDirection dir) {
    auto t = OCIO::ExponentWithLinearTransform::Create();
    const double gamma[4] = {2.4, 2.4, 2.4, 1.0};
    const double offset[4] = {0.055, 0.055, 0.055, 0.0};
    t->setGamma(gamma);
    t->setOffset(offset);
    t->setDirection(dir);
    return t;
}

// Appends the decoding of the film's working space to linear light; nothing when linear.
void append_working_decode(OCIO::GroupTransform& group, const OutputEncoding& encoding) {
    if (encoding.working_srgb) {
        group.appendTransform(srgb(OCIO::TRANSFORM_DIR_FORWARD));
        return;
    }
    if (!(encoding.working_gamma > 0))
        throw Error(ErrorKind::Output, {}, "working gamma must be positive");
    if (!is_neutral_gamma(encoding.working_gamma))
        group.appendTransform(exponent(encoding.working_gamma, OCIO::TRANSFORM_DIR_FORWARD));
}

void append_transfer(OCIO::GroupTransform& group, const OutputEncoding& encoding) {
    switch (encoding.transfer) {
        case OutputEncoding::Transfer::Linear:
            break;
        case OutputEncoding::Transfer::Srgb:
            group.appendTransform(srgb(OCIO::TRANSFORM_DIR_INVERSE));
            break;
        case OutputEncoding::Transfer::Gamma:
            if (!(encoding.gamma > 0))
                throw Error(ErrorKind::Output, {}, "output gamma must be positive");
            if (!is_neutral_gamma(encoding.gamma))
                group.appendTransform(exponent(encoding.gamma, OCIO::TRANSFORM_DIR_INVERSE));
            break;
    }
}

// POV-Ray replaces a working space that matches the file's curve by the identity
// (TranscodingGammaCurve::Get), which keeps legacy scenes' values exact.
bool working_matches_transfer(const OutputEncoding& e) {
    using T = OutputEncoding::Transfer;
    if (e.working_srgb) return e.transfer == T::Srgb;
    if (e.transfer == T::Gamma) return is_neutral_gamma(e.working_gamma / e.gamma);
    if (e.transfer == T::Linear) return is_neutral_gamma(e.working_gamma);
    return false;
}

OCIO::ConstCPUProcessorRcPtr make_cpu_processor(const OCIO::GroupTransformRcPtr& group) {
    if (group->getNumTransforms() == 0) return nullptr;
    try {
        // A raw config: nothing is read from disk or from $OCIO.
        OCIO::ConstConfigRcPtr config = OCIO::Config::CreateRaw();
        OCIO::ConstProcessorRcPtr processor = config->getProcessor(group);
        // Lossless optimization only: the default level swaps pow() for a fast approximation,
        // which moves values across quantization steps.
        return processor->getOptimizedCPUProcessor(OCIO::OPTIMIZATION_LOSSLESS);
    } catch (const OCIO::Exception& e) {
        throw Error(ErrorKind::Output, {}, std::string("color encoding failed: ") + e.what());
    }
}

// Null when the whole chain is the identity.
OCIO::ConstCPUProcessorRcPtr make_processor(const OutputEncoding& encoding) {
    auto group = OCIO::GroupTransform::Create();
    if (!working_matches_transfer(encoding)) {
        append_working_decode(*group, encoding);
        append_transfer(*group, encoding);
    }
    return make_cpu_processor(group);
}

void apply(const OCIO::ConstCPUProcessorRcPtr& cpu, float* rgb, int width, int height) {
    if (!cpu || width <= 0 || height <= 0) return;
    try {
        OCIO::PackedImageDesc desc(rgb, static_cast<long>(width), static_cast<long>(height), 3);
        cpu->apply(desc);
    } catch (const OCIO::Exception& e) {
        throw Error(ErrorKind::Output, {}, std::string("color encoding failed: ") + e.what());
    }
}

float finite_or_zero(float v) {
    if (std::isnan(v)) return 0.0f;
    if (std::isinf(v))
        return v > 0 ? std::numeric_limits<float>::max() : -std::numeric_limits<float>::max();
    return v;
}

float clamp01(float v) {
    if (!(v > 0.0f)) return 0.0f;  // NaN too
    return v > 1.0f ? 1.0f : v;
}

}  // namespace

std::vector<float> encode_rgb(const Image& image, const OutputEncoding& encoding) {
    const size_t n = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
    std::vector<float> rgb(n * 3);
    for (size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            // Every transfer here is monotonic and maps 0 to 0 and 1 to 1, so clamping before
            // encoding gives what POV-Ray's clip after encoding gives, and keeps NaN and
            // infinities out of OpenColorIO.
            rgb[i * 3 + c] = clamp01(image.rgba[i * 4 + c]);
        }
    }
    apply(make_processor(encoding), rgb.data(), image.width, image.height);
    for (float& v : rgb) v = clamp01(v);
    return rgb;
}

std::vector<float> linear_rgba(const Image& image, const OutputEncoding& encoding) {
    const size_t n = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
    std::vector<float> rgba(n * 4);
    for (size_t i = 0; i < n * 4; ++i) rgba[i] = finite_or_zero(image.rgba[i]);
    auto group = OCIO::GroupTransform::Create();
    append_working_decode(*group, encoding);
    if (group->getNumTransforms() == 0) return rgba;  // linear film: no color transform at all
    std::vector<float> rgb(n * 3);
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = rgba[i * 4 + c];
    apply(make_cpu_processor(group), rgb.data(), image.width, image.height);
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) rgba[i * 4 + c] = finite_or_zero(rgb[i * 3 + c]);
    return rgba;
}

float encode_value(float value, const OutputEncoding& encoding) {
    Image one;
    one.width = 1;
    one.height = 1;
    one.rgba = {value, value, value, 1.0f};
    return encode_rgb(one, encoding)[0];
}

// --- Blender's view transforms ---

namespace {

namespace fs = std::filesystem;

bool is_file(const fs::path& p) {
    std::error_code ec;
    return fs::is_regular_file(p, ec);
}

// "3.4" before "3.10" before "4.0": numeric, part by part, newest first.
bool newer_version(const std::string& a, const std::string& b) {
    auto parts = [](const std::string& v) {
        std::vector<long> out;
        std::istringstream in(v);
        std::string part;
        while (std::getline(in, part, '.')) out.push_back(std::strtol(part.c_str(), nullptr, 10));
        return out;
    };
    return parts(a) > parts(b);
}

// The config.ocio of each versioned Blender data folder (ROOT/3.4/datafiles/...), newest first.
std::vector<fs::path> versioned_configs(const fs::path& root) {
    const fs::path rel = fs::path("datafiles") / "colormanagement" / "config.ocio";
    std::vector<std::string> versions;
    std::error_code ec;
    for (fs::directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec)) {
        std::string name = it->path().filename().string();
        if (!name.empty() && std::isdigit(static_cast<unsigned char>(name[0])) &&
            name.find_first_not_of("0123456789.") == std::string::npos)
            versions.push_back(name);
    }
    std::sort(versions.begin(), versions.end(), newer_version);
    std::vector<fs::path> out;
    for (const std::string& v : versions) out.push_back(root / v / rel);
    if (out.empty()) out.push_back(root / "<version>" / rel);  // named in the error message
    return out;
}

// Blender's config.ocio candidates in search order.
std::vector<fs::path> blender_config_candidates() {
    const fs::path rel = fs::path("datafiles") / "colormanagement" / "config.ocio";
    std::vector<fs::path> out;
    for (const char* root : {"/usr/share/blender", "/usr/local/share/blender"}) {
        out.push_back(fs::path(root) / rel);
        for (const fs::path& p : versioned_configs(root)) out.push_back(p);
    }
    // Blender's own tarball keeps its data beside the executable: <dir>/3.4/datafiles/...
    if (const char* path = std::getenv("PATH")) {
        std::istringstream dirs(path);
        std::string dir;
        while (std::getline(dirs, dir, ':')) {
            if (dir.empty()) continue;
            fs::path exe = fs::path(dir) / "blender";
            if (!is_file(exe)) continue;
            std::error_code ec;
            fs::path real = fs::canonical(exe, ec);
            if (ec) continue;
            for (const fs::path& p : versioned_configs(real.parent_path()))
                if (is_file(p)) out.push_back(p);
            break;
        }
    }
    return out;
}

OCIO::ConstConfigRcPtr load_config(const std::string& path) {
    try {
        return OCIO::Config::CreateFromFile(path.c_str());
    } catch (const OCIO::Exception& e) {
        throw Error(ErrorKind::MissingFile, {},
                    "cannot read the OpenColorIO config " + path + ": " + e.what());
    }
}

bool no_look(const std::string& look) { return look.empty() || look == "None"; }

std::string join(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? "(none)" : out;
}

// Blender 3.4's display processor (intern/opencolorio, createDisplayProcessor): exposure in
// scene linear, the look into its process space, the display/view (looks bypassed when one
// was applied), then gamma. Scale and exponent are computed in single precision as Blender
// computes them from its float settings.
OCIO::ConstCPUProcessorRcPtr blender_display_processor(const OCIO::ConstConfigRcPtr& config,
                                                       const ViewSettings& view) {
    OCIO::ConstColorSpaceRcPtr scene_linear = config->getColorSpace(OCIO::ROLE_SCENE_LINEAR);
    if (!scene_linear)
        throw Error(ErrorKind::Output, {},
                    "the OpenColorIO config " + view.config_path + " has no scene_linear role");
    std::string input = scene_linear->getName();
    auto group = OCIO::GroupTransform::Create();

    const float scale = std::pow(2.0f, view.exposure);
    if (scale != 1.0f) {
        auto to_linear = OCIO::ColorSpaceTransform::Create();
        to_linear->setSrc(input.c_str());
        to_linear->setDst(OCIO::ROLE_SCENE_LINEAR);
        group->appendTransform(to_linear);
        input = OCIO::ROLE_SCENE_LINEAR;
        const double s = scale;
        const double m[16] = {s, 0, 0, 0, 0, s, 0, 0, 0, 0, s, 0, 0, 0, 0, 1};
        auto matrix = OCIO::MatrixTransform::Create();
        matrix->setMatrix(m);
        group->appendTransform(matrix);
    }

    bool use_look = !no_look(view.look);
    if (use_look) {
        const char* look_space = OCIO::LookTransform::GetLooksResultColorSpace(
            config, config->getCurrentContext(), view.look.c_str());
        if (look_space && look_space[0]) {
            auto look = OCIO::LookTransform::Create();
            look->setSrc(input.c_str());
            look->setDst(look_space);
            look->setLooks(view.look.c_str());
            group->appendTransform(look);
            input = look_space;
        } else {
            use_look = false;
        }
    }

    auto display = OCIO::DisplayViewTransform::Create();
    display->setSrc(input.c_str());
    display->setLooksBypass(use_look);
    display->setView(view.view.c_str());
    display->setDisplay(view.display.c_str());
    group->appendTransform(display);

    const float exponent = 1.0f / std::max(FLT_EPSILON, view.gamma);
    if (exponent != 1.0f) {
        const double e = exponent;
        const double v[4] = {e, e, e, 1.0};
        auto power = OCIO::ExponentTransform::Create();
        power->setValue(v);
        group->appendTransform(power);
    }
    // Blender's default CPU processor (default optimization), not glint's lossless one: the
    // point is Blender's numbers.
    return config->getProcessor(group)->getDefaultCPUProcessor();
}

}  // namespace

std::string find_ocio_config(const std::string& given) {
    if (!given.empty()) {
        if (!is_file(given))
            throw Error(ErrorKind::MissingFile, {}, "--ocio-config " + given + ": no such file");
        return given;
    }
    if (const char* env = std::getenv("OCIO"); env && env[0]) {
        if (!is_file(env))
            throw Error(ErrorKind::MissingFile, {},
                        std::string("$OCIO names ") + env + ", which does not exist");
        return env;
    }
    std::vector<std::string> searched;
    for (const fs::path& p : blender_config_candidates()) {
        if (is_file(p)) return p.string();
        if (std::find(searched.begin(), searched.end(), p.string()) == searched.end())
            searched.push_back(p.string());
    }
    std::string list;
    for (const std::string& s : searched) list += "\n  " + s;
    throw Error(ErrorKind::MissingFile, {},
                "--view needs an OpenColorIO config (Blender's config.ocio) and none was found: "
                "give --ocio-config PATH or set $OCIO; searched:" +
                    list);
}

ViewSettings resolve_view(const ViewSettings& view) {
    ViewSettings v = view;
    v.config_path = find_ocio_config(view.config_path);
    OCIO::ConstConfigRcPtr config = load_config(v.config_path);
    std::vector<std::string> displays;
    for (int i = 0; i < config->getNumDisplays(); ++i) displays.push_back(config->getDisplay(i));
    if (std::find(displays.begin(), displays.end(), v.display) == displays.end())
        throw Error(ErrorKind::Usage, {},
                    "display '" + v.display + "' is not in " + v.config_path +
                        " (displays: " + join(displays) + ")");
    std::vector<std::string> views;
    for (int i = 0; i < config->getNumViews(v.display.c_str()); ++i)
        views.push_back(config->getView(v.display.c_str(), i));
    if (std::find(views.begin(), views.end(), v.view) == views.end())
        throw Error(ErrorKind::Usage, {},
                    "--view " + v.view + ": not a view of display " + v.display + " in " +
                        v.config_path + " (views: " + join(views) + ")");
    if (!no_look(v.look) && !config->getLook(v.look.c_str())) {
        std::vector<std::string> looks{"None"};
        for (int i = 0; i < config->getNumLooks(); ++i)
            looks.push_back(config->getLookNameByIndex(i));
        throw Error(ErrorKind::Usage, {},
                    "--look " + v.look + ": not a look in " + v.config_path +
                        " (looks: " + join(looks) + ")");
    }
    if (!std::isfinite(v.exposure) || !std::isfinite(v.gamma) || !(v.gamma > 0))
        throw Error(ErrorKind::Usage, {}, "--exposure must be finite and --gamma positive");
    return v;
}

std::vector<float> view_rgba(const std::vector<float>& rgba, int width, int height,
                             const ViewSettings& view, bool straight) {
    const std::string path = find_ocio_config(view.config_path);
    ViewSettings v = view;
    v.config_path = path;
    std::vector<float> px = rgba;
    if (width <= 0 || height <= 0) return px;
    const size_t n = static_cast<size_t>(width) * static_cast<size_t>(height);
    // Blender's float buffers hold premultiplied alpha; its processor divides a partly
    // transparent pixel by alpha around the transform (OCIO_cpuProcessorApply_predivide).
    auto unpremultiply = [&] {
        for (size_t i = 0; i < n; ++i) {
            float* p = &px[i * 4];
            if (p[3] != 0.0f && p[3] != 1.0f) {
                const float inv = 1.0f / p[3];
                p[0] *= inv;
                p[1] *= inv;
                p[2] *= inv;
            }
        }
    };
    try {
        OCIO::ConstCPUProcessorRcPtr cpu = blender_display_processor(load_config(path), v);
        unpremultiply();
        OCIO::PackedImageDesc desc(px.data(), static_cast<long>(width), static_cast<long>(height),
                                   4);
        cpu->apply(desc);
    } catch (const OCIO::Exception& e) {
        throw Error(ErrorKind::Output, {}, std::string("color management failed: ") + e.what());
    }
    for (size_t i = 0; i < n; ++i) {
        float* p = &px[i * 4];
        if (p[3] != 0.0f && p[3] != 1.0f) {
            p[0] *= p[3];
            p[1] *= p[3];
            p[2] *= p[3];
        }
    }
    // The byte conversion (IMB_buffer_byte_from_float) turns premultiplied into straight alpha.
    if (straight) unpremultiply();
    return px;
}

std::string describe_view(const ViewSettings& view) {
    char buf[64];
    std::snprintf(buf, sizeof buf, ", exposure %g, gamma %g", static_cast<double>(view.exposure),
                  static_cast<double>(view.gamma));
    return "view " + view.view + ", look " + (no_look(view.look) ? "None" : view.look) + buf +
           " (display " + view.display + ", " +
           (view.config_path.empty() ? std::string("config not resolved") : view.config_path) + ")";
}

}  // namespace glint::io
