#include "render/textures/pigment.h"

#include <cmath>

#include "core/error.h"

namespace glint::render {
namespace {

using scene::ColorFT;

double checker_value(const Vec3& p) {
    // pattern.cpp checker_pattern: parity of the summed floors, nudged by EPSILON.
    long long v = static_cast<long long>(std::floor(p.x + kPovEpsilon) +
                                         std::floor(p.y + kPovEpsilon) +
                                         std::floor(p.z + kPovEpsilon));
    return (v & 1) ? 1.0 : 0.0;
}

double gradient_value(const Vec3& p, const Vec3& axis) {
    // pattern.cpp gradient_pattern: values above 1 wrap; negative ones are wrapped later.
    double r = dot(p, axis);
    return r > 1.0 ? std::fmod(r, 1.0) : r;
}

double triangle_wave(double v) {
    double offset = v - std::floor(v);
    return offset >= 0.5 ? 2.0 * (1.0 - offset) : 2.0 * offset;
}

// POV-Ray's wrap(): v modulo m in [0, m).
double wrap(double v, double m) {
    double r = std::fmod(v, m);
    if (r < 0) r += m;
    if (r >= m) r = 0;
    return r;
}

// Search_Blend_Map + interpolation for color maps (texture.cpp, pigment.cpp).
ColorFT lookup_color_map(const std::vector<scene::ColorMapEntry>& map, double value) {
    if (map.empty()) return ColorFT{};
    const scene::ColorMapEntry* prev;
    const scene::ColorMapEntry* cur;
    size_t last = map.size() - 1;
    if (value >= map[last].value) {
        prev = cur = &map[last];
    } else {
        size_t i = 0;
        prev = cur = &map[0];
        while (value > map[i].value) {
            prev = &map[i];
            ++i;
            cur = &map[i];
        }
        if (value == cur->value) prev = cur;
    }
    if (prev == cur) return cur->color;
    double f = (value - prev->value) / (cur->value - prev->value);
    return scene::lerp(prev->color, cur->color, f);
}

}  // namespace

const std::vector<scene::ColorMapEntry>& default_color_map() {
    static const std::vector<scene::ColorMapEntry> kMap = {
        {0.0, ColorFT(Color(0, 0, 0))},
        {1.0, ColorFT(Color(1, 1, 1))},
    };
    return kMap;
}

double PigmentEvaluator::pattern_value(const scene::Pigment& pigment, const Vec3& local) {
    const scene::PatternParams& pp = pigment.params;
    double value = 0;
    switch (pigment.kind) {
        case scene::PatternKind::Checker: value = checker_value(local); break;
        case scene::PatternKind::Gradient: value = gradient_value(local, pp.vector); break;
        default: return 0;
    }
    // Evaluate_TPat: frequency/phase (with POV-Ray's 1.00001 modulus), then the wave type.
    if (pp.frequency != 0.0) value = std::fmod(value * pp.frequency + pp.phase, 1.00001);
    if (value < 0.0) value -= std::floor(value);
    switch (pp.wave) {
        case scene::WaveType::Ramp: break;
        case scene::WaveType::Sine: value = (1.0 + std::sin(value * 2 * kPi)) * 0.5; break;
        case scene::WaveType::Triangle: value = triangle_wave(value); break;
        case scene::WaveType::Scallop: value = std::fabs(std::sin(value * 0.5 * 2 * kPi)); break;
        case scene::WaveType::Cubic: value = value * value * (-2.0 * value + 3.0); break;
        case scene::WaveType::Poly: value = std::pow(value, pp.wave_exponent); break;
    }
    return value;
}

bool PigmentEvaluator::evaluate(const scene::Pigment& pigment, const PatternPoint& at,
                                ColorFT* out) const {
    Vec3 p = at.p;
    if (pigment.uv_mapping) {
        if (!at.has_uv) {
            throw Error(ErrorKind::Render, pigment.loc,
                        "uv_mapping on a surface that has no uv coordinates");
        }
        p = Vec3(at.uv.x, at.uv.y, 0);
    }
    return eval(pigment, p, out);
}

bool PigmentEvaluator::eval(const scene::Pigment& pigment, const Vec3& parent,
                            ColorFT* out) const {
    // Warp_EPoint: the pattern's own transform, applied inversely to the point.
    Vec3 local = pigment.transform.is_identity() ? parent
                                                 : pigment.transform.inverse_point(parent);
    switch (pigment.kind) {
        case scene::PatternKind::Plain:
            *out = pigment.color;
            return true;
        case scene::PatternKind::ImageMap:
            return image_map(pigment, local, out);
        case scene::PatternKind::Checker: {
            double v = pattern_value(pigment, local);
            if (pigment.entries.size() >= 2) {
                // Block pattern map: entry 0 at value 0, entry 1 at value 1; no blending
                // between them for the values 0 and 1 a checker produces.
                // Entry transforms are absolute (entry pattern -> world, the importer has
                // composed the parent's), so entries see the same point as their parent.
                const scene::Pigment& e = pigment.entries[v >= 1.0 ? 1 : 0];
                bool found = eval(e, parent, out);
                if (v > 0.0 && v < 1.0) {
                    ColorFT other;
                    found |= eval(pigment.entries[0], parent, &other);
                    *out = scene::lerp(other, *out, v);
                }
                return found;
            }
            // Check_Default_Map: blue and green.
            static const std::vector<scene::ColorMapEntry> kCheckDefault = {
                {0.0, ColorFT(Color(0, 0, 1))}, {1.0, ColorFT(Color(0, 1, 0))}};
            *out = lookup_color_map(kCheckDefault, v);
            return true;
        }
        case scene::PatternKind::Gradient: {
            double v = pattern_value(pigment, local);
            const auto& map = pigment.color_map.empty() ? default_color_map() : pigment.color_map;
            *out = lookup_color_map(map, v);
            return true;
        }
        default: break;
    }
    throw Error(ErrorKind::Render, pigment.loc, "pigment pattern not supported by the renderer");
}

bool PigmentEvaluator::image_map(const scene::Pigment& pigment, const Vec3& q,
                                 ColorFT* out) const {
    const scene::ImageMap& im = pigment.params.image;
    const ImageTexture* tex = textures_ ? textures_->find(im) : nullptr;
    if (!tex) throw Error(ErrorKind::Render, im.loc, "image '" + im.file + "' was not loaded");
    const double w = tex->width(), h = tex->height();
    const ColorFT kClear(Color(1, 1, 1), 0, 1);
    double u = 0, v = 0;
    // map_pos + the per-type mappers (imageutil.cpp).
    auto angle_from_x = [](double x, double z) {
        if (z == 0.0) return x > 0 ? 0.0 : kPi;
        double len = std::sqrt(x * x + z * z);
        double theta = std::acos(x / len);
        return z < 0.0 ? 2 * kPi - theta : theta;
    };
    switch (im.map_type) {
        case 1: {  // spherical
            double len = length(q);
            if (len == 0.0) { *out = kClear; return false; }
            Vec3 n = q / len;
            double phi = 0.5 + std::asin(std::clamp(n.y, -1.0, 1.0)) / kPi;
            double lxz = std::sqrt(n.x * n.x + n.z * n.z);
            double theta = lxz == 0.0 ? 0.0 : angle_from_x(n.x / lxz, n.z / lxz) / (2 * kPi);
            u = theta * w;
            v = phi * h;
            break;
        }
        case 2: {  // cylindrical
            if (im.once && (q.y < 0.0 || q.y > 1.0)) { *out = kClear; return false; }
            v = std::fmod(q.y * h, h);
            double len = length(q);
            if (len == 0.0) { *out = kClear; return false; }
            double x = q.x / len, z = q.z / len;
            double lxz = std::sqrt(x * x + z * z);
            if (lxz == 0.0) { *out = kClear; return false; }
            u = angle_from_x(x / lxz, z / lxz) / (2 * kPi) * w;
            break;
        }
        case 0:
        default: {  // planar, POV-Ray's default gradient <1, -1, 0>: x -> u, y -> v
            if (im.once && (q.x < 0.0 || q.x > 1.0)) { *out = kClear; return false; }
            u = std::fmod(q.x * w, w);
            if (im.once && (q.y < 0.0 || q.y > 1.0)) { *out = kClear; return false; }
            v = std::fmod(q.y * h, h);
            break;
        }
    }
    double xc = u + kPovEpsilon;
    double yc = v + kPovEpsilon;
    if (im.once && (xc >= w || yc >= h || xc < 0.0 || yc < 0.0)) {
        *out = kClear;
        return false;
    }
    xc = wrap(xc, w);
    yc = wrap(-yc, h);  // image rows run top-down

    const int iw = tex->width(), ih = tex->height();
    auto fetch = [&](double x, double y) {
        int ix, iy;
        if (im.once) {
            ix = x < 0.0 ? 0 : (x >= iw ? iw - 1 : static_cast<int>(x));
            iy = y < 0.0 ? 0 : (y >= ih ? ih - 1 : static_cast<int>(y));
        } else {
            ix = static_cast<int>(wrap(x, iw));
            iy = static_cast<int>(wrap(y, ih));
        }
        const float* t = tex->texel(ix, iy);
        return ColorFT(Color(t[0], t[1], t[2]), t[3] + im.filter_all, t[4] + im.transmit_all);
    };
    switch (im.interpolate) {
        case 2:
        case 4: {
            double x = xc + 0.5, y = yc + 0.5;
            int ix = static_cast<int>(x), iy = static_cast<int>(y);
            ColorFT c[4] = {fetch(ix, iy), fetch(ix - 1.0, iy), fetch(ix, iy - 1.0),
                            fetch(ix - 1.0, iy - 1.0)};
            double p = x - ix, r = y - iy;
            double f[4];
            if (im.interpolate == 2) {
                f[0] = p * r;
                f[1] = (1 - p) * r;
                f[2] = p * (1 - r);
                f[3] = (1 - p) * (1 - r);
            } else {
                double wts[4] = {1.0 / ((1 - p) * (1 - p) + (1 - r) * (1 - r)),
                                 1.0 / (p * p + (1 - r) * (1 - r)),
                                 1.0 / ((1 - p) * (1 - p) + r * r), 1.0 / (p * p + r * r)};
                double sum = wts[0] + wts[1] + wts[2] + wts[3];
                for (int i = 0; i < 4; ++i) f[i] = std::isfinite(sum) ? wts[i] / sum : 0.0;
                if (!std::isfinite(sum)) {
                    // Exactly on a texel centre: that texel alone.
                    for (int i = 0; i < 4; ++i) f[i] = std::isinf(wts[i]) ? 1.0 : 0.0;
                }
            }
            ColorFT sum;
            for (int i = 0; i < 4; ++i) sum = sum + c[i] * f[i];
            *out = sum;
            return true;
        }
        case 3: {  // bicubic
            double x = xc + 0.5, y = yc + 0.5;
            int ix = static_cast<int>(x), iy = static_cast<int>(y);
            auto cubic = [](double t, double* f) {
                double p = t - static_cast<int>(t), q = 1 - p;
                f[0] = -0.5 * p * q * q;
                f[1] = 0.5 * q * (q * (3 * p + 1) + 1);
                f[2] = 0.5 * p * (p * (3 * q + 1) + 1);
                f[3] = -0.5 * q * p * p;
            };
            double fx[4], fy[4];
            cubic(x, fx);
            cubic(y, fy);
            ColorFT sum;
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j)
                    sum = sum + fetch(ix + i - 2.0, iy + j - 2.0) * (fx[i] * fy[j]);
            *out = sum;
            return true;
        }
        default:
            *out = fetch(xc, yc);
            return true;
    }
}

}  // namespace glint::render
