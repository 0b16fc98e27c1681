#include "render/textures/pigment.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace glint::render {
namespace {

using scene::ColorFT;
using scene::PatternKind;

// POV-Ray's wrap(): v modulo m in [0, m).
double wrap(double v, double m) {
    double r = std::fmod(v, m);
    if (r < 0) r += m;
    if (r >= m) r = 0;
    return r;
}

ColorFT lookup_color_map(const std::vector<scene::ColorMapEntry>& map, double value) {
    if (map.empty()) return ColorFT{};
    BlendPick b = search_blend_map(map, value);
    if (b.prev == b.cur) return map[b.cur].color;
    return scene::lerp(map[b.prev].color, map[b.cur].color, b.fraction);
}

std::vector<scene::ColorMapEntry> make_map(
    std::initializer_list<std::pair<double, Color>> entries) {
    std::vector<scene::ColorMapEntry> m;
    for (const auto& [v, c] : entries) m.push_back({v, ColorFT(c)});
    return m;
}

}  // namespace

const std::vector<scene::ColorMapEntry>& default_color_map(PatternKind kind) {
    // pigment.cpp's default maps (Post_Pigment).
    static const auto kGray = make_map({{0.0, {0, 0, 0}}, {1.0, {1, 1, 1}}});
    static const auto kBozo = make_map({{0.4, {1, 1, 1}}, {0.4, {0, 1, 0}}, {0.6, {0, 1, 0}},
                                        {0.6, {0, 0, 1}}, {0.8, {0, 0, 1}}, {0.8, {1, 0, 0}}});
    static const auto kWood = make_map({{0.6, {0.666, 0.312, 0.2}}, {0.6, {0.4, 0.1333, 0.066}}});
    static const auto kMandel = make_map({{0.001, {0, 0, 0}}, {0.001, {0, 1, 1}},
                                          {0.012, {1, 1, 0}}, {0.015, {1, 0, 1}},
                                          {0.1, {0, 1, 1}}});
    static const auto kAgate = make_map({{0.0, {1, 1, 1}}, {0.5, {0.95, 0.75, 0.5}},
                                         {0.5, {0.9, 0.7, 0.5}}, {0.6, {0.9, 0.7, 0.4}},
                                         {0.6, {1.0, 0.7, 0.4}}, {1.0, {0.6, 0.3, 0.0}}});
    static const auto kRadial = make_map(
        {{0.0, {0, 1, 1}}, {0.333, {1, 1, 0}}, {0.666, {1, 0, 1}}, {1.0, {0, 1, 1}}});
    static const auto kMarble =
        make_map({{0.0, {0.9, 0.8, 0.8}}, {0.9, {0.9, 0.08, 0.08}}, {0.9, {0, 0, 0}}});
    switch (kind) {
        case PatternKind::Bozo: return kBozo;
        case PatternKind::Wood: return kWood;
        case PatternKind::Mandel: return kMandel;
        case PatternKind::Agate: return kAgate;
        case PatternKind::Radial: return kRadial;
        case PatternKind::Marble: return kMarble;
        default: return kGray;
    }
}

double PigmentEvaluator::pattern_value(const scene::Pigment& pigment, const Vec3& local) const {
    return evaluate_pattern(pigment.kind, pigment.params, local, ctx_);
}

bool PigmentEvaluator::evaluate(const scene::Pigment& pigment, const PatternPoint& at,
                                ColorFT* out) const {
    Vec3 p = at.p;
    if (pigment.uv_mapping) p = uv_mapped(at);
    if ((at.normal && at.normal != ctx_.normal) ||
        (at.ray_dir && at.ray_dir != ctx_.ray_dir)) {  // the slope and aoi patterns read them
        PigmentEvaluator on_surface(*this);
        on_surface.ctx_.normal = at.normal;
        on_surface.ctx_.ray_dir = at.ray_dir;
        return on_surface.eval(pigment, p, out);
    }
    return eval(pigment, p, out);
}

bool PigmentEvaluator::eval(const scene::Pigment& pigment, const Vec3& parent,
                            ColorFT* out) const {
    // Warp_EPoint: the pattern's own transform, applied inversely to the point; map and block
    // entries are evaluated in the warped pattern space (their transforms are relative).
    const scene::PatternParams& pp = pigment.params;
    Vec3 local = pigment.transform.is_identity() ? parent
                                                 : pigment.transform.inverse_point(parent);
    switch (pigment.kind) {
        case PatternKind::Plain:
            *out = pigment.color;
            return true;
        case PatternKind::ImageMap:
            return image_map(pigment, pp.warps.empty() ? local : warp_point(pigment.kind, pp, local),
                             out);
        case PatternKind::Average: {
            // Do_Average_Pigments: weights need not sum to 1.
            Vec3 tp = pp.warps.empty() ? local : warp_point(pigment.kind, pp, local);
            ColorFT sum;
            double total = 0;
            for (const scene::PigmentMapEntry& e : pigment.pigment_map) {
                ColorFT c;
                eval(e.pigment[0], tp, &c);
                sum = sum + c * e.value;
                total += e.value;
            }
            *out = sum * (1.0 / total);
            return true;
        }
        default: break;
    }
    const double value = evaluate_pattern(pigment.kind, pp, local, ctx_);
    if (is_block_pattern(pigment.kind)) {
        if (pigment.entries.empty()) {
            // An IR pigment without entries: POV-Ray's default map (checker: blue, green).
            static const Color kDefault[] = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}};
            *out = ColorFT(kDefault[block_index(value, 4)]);
            return true;
        }
        const scene::Pigment& e = pigment.entries[block_index(value, pigment.entries.size())];
        if (e.kind == PatternKind::Plain) {
            *out = e.color;
            return true;
        }
        return eval(e, pp.warps.empty() ? local : warp_point(pigment.kind, pp, local), out);
    }
    if (pigment.pigment_map.empty()) {
        const bool own_map = !pigment.color_map.empty();
        const bool mandel2 = pigment.kind != PatternKind::Mandel || pp.fractal_exponent == 2;
        const auto& map = own_map  ? pigment.color_map
                          : mandel2 ? default_color_map(pigment.kind)
                                    : default_color_map(PatternKind::Gradient);
        *out = lookup_color_map(map, value);
        return true;
    }
    // pigment_map: the two entries around the value, each in the warped pattern space.
    const auto& map = pigment.pigment_map;
    BlendPick b = search_blend_map(map, value);
    Vec3 tp = pp.warps.empty() ? local : warp_point(pigment.kind, pp, local);
    bool found = eval(map[b.cur].pigment[0], tp, out);
    if (b.prev != b.cur) {
        ColorFT prev;
        found |= eval(map[b.prev].pigment[0], tp, &prev);
        *out = scene::lerp(prev, *out, b.fraction);
    }
    return found;
}

bool PigmentEvaluator::image_map(const scene::Pigment& pigment, const Vec3& q,
                                 ColorFT* out) const {
    const scene::ImageMap& im = pigment.params.image;
    const ImageTexture* tex = textures_ ? textures_->find(im) : nullptr;
    if (!tex) throw Error(ErrorKind::Render, im.loc, "image '" + im.file + "' was not loaded");
    double xc, yc;
    if (!image_map_position(im, *tex, q, &xc, &yc)) {
        *out = ColorFT(Color(1, 1, 1), 0, 1);  // POV-Ray's clear <1,1,1,0,1>
        return false;
    }
    *out = image_map_sample(im, *tex, xc, yc);
    return true;
}

bool image_map_position(const scene::ImageMap& im, const ImageTexture& image, const Vec3& q,
                        double* xc_out, double* yc_out) {
    const ImageTexture* tex = &image;
    const double w = tex->width(), h = tex->height();
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
            if (len == 0.0) { return false; }
            Vec3 n = q / len;
            double phi = 0.5 + std::asin(std::clamp(n.y, -1.0, 1.0)) / kPi;
            double lxz = std::sqrt(n.x * n.x + n.z * n.z);
            double theta = lxz == 0.0 ? 0.0 : angle_from_x(n.x / lxz, n.z / lxz) / (2 * kPi);
            u = theta * w;
            v = phi * h;
            break;
        }
        case 2: {  // cylindrical
            if (im.once && (q.y < 0.0 || q.y > 1.0)) { return false; }
            v = std::fmod(q.y * h, h);
            double len = length(q);
            if (len == 0.0) { return false; }
            double x = q.x / len, z = q.z / len;
            double lxz = std::sqrt(x * x + z * z);
            if (lxz == 0.0) { return false; }
            u = angle_from_x(x / lxz, z / lxz) / (2 * kPi) * w;
            break;
        }
        case 5: {  // torus (torus_image_map): major radius 1, POV-Ray's gradient x
            double len = std::sqrt(q.x * q.x + q.z * q.z);
            if (len == 0.0) { return false; }
            double theta = q.z == 0.0 ? (q.x > 0 ? 0.0 : kPi) : std::acos(q.x / len);
            if (q.z != 0.0 && q.z < 0.0) theta = 2 * kPi - theta;
            theta = 0.0 - theta;
            double x = len - 1.0;
            double l2 = std::sqrt(x * x + q.y * q.y);
            double phi = std::acos(-x / l2);
            if (q.y > 0.0) phi = 2 * kPi - phi;
            u = -(theta / (2 * kPi)) * w;
            v = (phi / (2 * kPi)) * h;
            break;
        }
        case 0:
        default: {  // planar, POV-Ray's default gradient <1, -1, 0>: x -> u, y -> v
            if (im.once && (q.x < 0.0 || q.x > 1.0)) { return false; }
            u = std::fmod(q.x * w, w);
            if (im.once && (q.y < 0.0 || q.y > 1.0)) { return false; }
            v = std::fmod(q.y * h, h);
            break;
        }
    }
    double xc = u + kPovEpsilon;
    double yc = v + kPovEpsilon;
    if (im.once && (xc >= w || yc >= h || xc < 0.0 || yc < 0.0)) {
        return false;
    }
    *xc_out = wrap(xc, w);
    *yc_out = wrap(-yc, h);  // image rows run top-down
    return true;
}


ColorFT image_map_sample(const scene::ImageMap& im, const ImageTexture& image, double xc,
                         double yc, int* index_out) {
    const ImageTexture* tex = &image;
    const int iw = tex->width(), ih = tex->height();
    // The palette index of the last texel fetched (palette images only).
    int fetched_index = -1;
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
        if (tex->indexed()) fetched_index = tex->index(ix, iy);
        if (im.palette_edits.empty() || !tex->indexed())
            return ColorFT(Color(t[0], t[1], t[2]), t[3] + im.filter_all, t[4] + im.transmit_all);
        // A palette image keeps filter and transmit per entry: the edits set them.
        double filter = t[3], transmit = t[4];
        const int index = tex->index(ix, iy);
        for (const scene::ImageMap::PaletteEdit& e : im.palette_edits)
            if (e.index < 0 || e.index == index) (e.filter ? filter : transmit) = e.value;
        return ColorFT(Color(t[0], t[1], t[2]), filter, transmit);
    };
    switch (im.interpolate) {
        case 2:
        case 4: {
            double x = xc + 0.5, y = yc + 0.5;
            int ix = static_cast<int>(x), iy = static_cast<int>(y);
            ColorFT c[4];
            int corner_index[4];
            const double corner[4][2] = {{0, 0}, {-1, 0}, {0, -1}, {-1, -1}};
            for (int i = 0; i < 4; ++i) {
                c[i] = fetch(ix + corner[i][0], iy + corner[i][1]);
                corner_index[i] = fetched_index;
            }
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
            double index_sum = 0;  // Interp: the indices blended and truncated
            for (int i = 0; i < 4; ++i) {
                sum = sum + c[i] * f[i];
                index_sum += corner_index[i] * f[i];
            }
            if (index_out) *index_out = tex->indexed() ? static_cast<int>(index_sum) : -1;
            return sum;
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
            double index_sum = 0;
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j) {
                    sum = sum + fetch(ix + i - 2.0, iy + j - 2.0) * (fx[i] * fy[j]);
                    index_sum += fetched_index * (fx[i] * fy[j]);
                }
            if (index_out) *index_out = tex->indexed() ? static_cast<int>(index_sum) : -1;
            return sum;
        }
        default: {
            const ColorFT c = fetch(xc, yc);
            if (index_out) *index_out = fetched_index;
            return c;
        }
    }
}

const scene::Texture& material_map_entry(const scene::Texture& tex, const TextureCache* textures,
                                         const Vec3& q) {
    const scene::ImageMap& im = tex.params.image;
    const ImageTexture* image = textures ? textures->find(im) : nullptr;
    if (!image) throw Error(ErrorKind::Render, im.loc, "image '" + im.file + "' was not loaded");
    const size_t count = tex.entries.size();
    size_t number = 0;
    double xc, yc;
    if (image_map_position(im, *image, q, &xc, &yc)) {
        // The palette index (blended like the colours under `interpolate`), or on other
        // images the red value.
        int index = -1;
        const scene::ColorFT c = image_map_sample(im, *image, xc, yc, &index);
        if (index != -1) {
            number = index > 0 ? static_cast<size_t>(index) : 0;
        } else {
            const double red = c.rgb.r * 255.0;
            number = red > 0 ? static_cast<size_t>(red) : 0;
        }
    }
    if (number > count) number %= count;
    return tex.entries[std::min(number, count - 1)];
}

}  // namespace glint::render
