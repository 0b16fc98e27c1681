#include "io/color_encoding.h"

#include <OpenColorIO/OpenColorIO.h>

#include <cmath>
#include <limits>

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

std::vector<float> encode_rgb(const render::Image& image, const OutputEncoding& encoding) {
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

std::vector<float> linear_rgba(const render::Image& image, const OutputEncoding& encoding) {
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
    render::Image one;
    one.width = 1;
    one.height = 1;
    one.rgba = {value, value, value, 1.0f};
    return encode_rgb(one, encoding)[0];
}

}  // namespace glint::io
