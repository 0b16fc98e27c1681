#include "io/color_encoding.h"

#include <OpenColorIO/OpenColorIO.h>

#include <cmath>

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
OCIO::ExponentWithLinearTransformRcPtr srgb_encode() {
    auto t = OCIO::ExponentWithLinearTransform::Create();
    const double gamma[4] = {2.4, 2.4, 2.4, 1.0};
    const double offset[4] = {0.055, 0.055, 0.055, 0.0};
    t->setGamma(gamma);
    t->setOffset(offset);
    t->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
    return t;
}

// Null when the whole chain is the identity (legacy POV-Ray scenes without gamma handling).
OCIO::ConstCPUProcessorRcPtr make_processor(const OutputEncoding& encoding) {
    if (!(encoding.working_gamma > 0))
        throw Error(ErrorKind::Output, {}, "working gamma must be positive");
    auto group = OCIO::GroupTransform::Create();
    if (!is_neutral_gamma(encoding.working_gamma))
        group->appendTransform(exponent(encoding.working_gamma, OCIO::TRANSFORM_DIR_FORWARD));
    switch (encoding.transfer) {
        case OutputEncoding::Transfer::Linear:
            break;
        case OutputEncoding::Transfer::Srgb:
            group->appendTransform(srgb_encode());
            break;
        case OutputEncoding::Transfer::Gamma:
            if (!(encoding.gamma > 0))
                throw Error(ErrorKind::Output, {}, "output gamma must be positive");
            if (!is_neutral_gamma(encoding.gamma))
                group->appendTransform(exponent(encoding.gamma, OCIO::TRANSFORM_DIR_INVERSE));
            break;
    }
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
    OCIO::ConstCPUProcessorRcPtr cpu = make_processor(encoding);
    if (cpu && n > 0) {
        try {
            OCIO::PackedImageDesc desc(rgb.data(), static_cast<long>(image.width),
                                       static_cast<long>(image.height), 3);
            cpu->apply(desc);
        } catch (const OCIO::Exception& e) {
            throw Error(ErrorKind::Output, {}, std::string("color encoding failed: ") + e.what());
        }
    }
    for (float& v : rgb) v = clamp01(v);
    return rgb;
}

float encode_value(float value, const OutputEncoding& encoding) {
    render::Image one;
    one.width = 1;
    one.height = 1;
    one.rgba = {value, value, value, 1.0f};
    return encode_rgb(one, encoding)[0];
}

}  // namespace glint::io
