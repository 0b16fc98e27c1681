// height_field (POV-Ray 3.7 manual 2.4.1.5; hfield.cpp): an image's values as heights on a
// grid of (width - 1) x (height - 1) cells, each split into two triangles along the diagonal
// from (x+1, z) to (x, z+1). Object space is POV-Ray's: x, z in [0, 1] (image row 0 at z = 1),
// height in [0, 1). Heights are POV-Ray's 16-bit values (imageutil.cpp, image_height_at):
// grey images 65535 * grey, 8-bit colour images 256 * red + green, palette images 256 * index.
// Intersection walks the grid cells along the ray (2D DDA) in grid space (x, z in cells,
// y in 1/65536 units) inside the box between water_level and the highest point.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/error.h"
#include "image/gif_indices.h"
#include "image/palette.h"
#include "image/png_reader.h"
#include "image/image_limits.h"
#include "core/quiet_stderr.h"
#include "render/shapes/shapes.h"

namespace glint::render {
namespace {

constexpr double kOffset = 0.001;  // HFIELD_OFFSET: the box is this much taller

class HeightFieldPrim final : public Primitive {
public:
    HeightFieldPrim(int w, int h, std::vector<uint16_t> map, bool smooth, double water,
                    const Transform& shading)
        : w_(w), h_(h), map_(std::move(map)), smooth_(smooth), shading_(shading) {
        int lo = 65535, hi = 0;
        for (uint16_t v : map_) lo = std::min<int>(lo, v), hi = std::max<int>(hi, v);
        ylo_ = std::max(static_cast<double>(lo), 65536.0 * water) - kOffset;
        yhi_ = hi + kOffset;
        sx_ = w_ - 1;
        sz_ = h_ - 1;
        if (smooth_) compute_normals();
    }

    Bounds3 bounds() const override {
        return {Vec3(0, ylo_ / 65536.0, 0) - Vec3(1e-9), Vec3(1, yhi_ / 65536.0, 1) + Vec3(1e-9)};
    }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        HitList hits;
        walk(ray, tmax, &hits, true);
        if (hits.empty()) return false;
        const LocalHit* best = &hits[0];
        for (const auto& h : hits)
            if (h.t < best->t) best = &h;
        *hit = *best;
        return true;
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        walk(ray, tmax, hits, false);
    }

    // POV-Ray's HField::Inside: below the triangle under the point (water counts as ground).
    bool inside(const Vec3& pu) const override {
        Vec3 p = to_grid(pu);
        if (p.x < 0 || p.x >= sx_ || p.z < 0 || p.z >= sz_ || p.y >= yhi_) return false;
        if (p.y < ylo_) return true;
        int px = static_cast<int>(p.x), pz = static_cast<int>(p.z);
        double x = p.x - px, z = p.z - pz;
        double water = ylo_;
        Vec3 origin, n;
        if (x + z < 1) {
            double y1 = std::max(height(px, pz), water), y2 = std::max(height(px + 1, pz), water),
                   y3 = std::max(height(px, pz + 1), water);
            origin = Vec3(px, y1, pz);
            n = Vec3(y1 - y2, 1, y1 - y3);
        } else {
            px = static_cast<int>(std::ceil(p.x));
            pz = static_cast<int>(std::ceil(p.z));
            double y1 = std::max(height(px, pz), water), y2 = std::max(height(px - 1, pz), water),
                   y3 = std::max(height(px, pz - 1), water);
            origin = Vec3(px, y1, pz);
            n = Vec3(y2 - y1, 1, y3 - y1);
        }
        return dot(p, n) < dot(origin, n);
    }

private:
    double height(int x, int z) const {
        x = std::clamp(x, 0, w_ - 1);
        z = std::clamp(z, 0, h_ - 1);
        return map_[static_cast<size_t>(z) * w_ + x];
    }
    Vec3 to_grid(const Vec3& p) const { return {p.x * sx_, p.y * 65536.0, p.z * sz_}; }
    // A grid-space normal into object (unit) space: by the inverse transpose of the scaling.
    Vec3 normal_to_object(const Vec3& n) const {
        Vec3 r(n.x * sx_, n.y * 65536.0, n.z * sz_);
        double l = length(r);
        return l > 0 ? r / l : Vec3(0, 1, 0);
    }

    void walk(const Ray& ray, double tmax, HitList* hits, bool first_only) const {
        Vec3 o = to_grid(ray.origin), d = to_grid(ray.dir);
        // Clip to the box [0, sx] x [ylo, yhi] x [0, sz].
        double t0 = 0, t1 = tmax;
        Vec3 lo(0, ylo_, 0), hi(sx_, yhi_, sz_);
        for (int a = 0; a < 3; ++a) {
            if (d[a] == 0) {
                if (o[a] < lo[a] || o[a] > hi[a]) return;
                continue;
            }
            double ta = (lo[a] - o[a]) / d[a], tb = (hi[a] - o[a]) / d[a];
            if (ta > tb) std::swap(ta, tb);
            t0 = std::max(t0, ta);
            t1 = std::min(t1, tb);
            if (t0 > t1) return;
        }
        double tmin = std::max(t0, 1e-9 * length(o) / std::max(length(d), 1e-300));
        // 2D DDA over cells.
        Vec3 s = o + d * t0;
        int cx = std::clamp(static_cast<int>(std::floor(s.x)), 0, w_ - 2);
        int cz = std::clamp(static_cast<int>(std::floor(s.z)), 0, h_ - 2);
        int stepx = d.x > 0 ? 1 : d.x < 0 ? -1 : 0, stepz = d.z > 0 ? 1 : d.z < 0 ? -1 : 0;
        auto next_t = [&](int c, double oc, double dc, int step) {
            if (step == 0) return kInfinity;
            double edge = step > 0 ? c + 1 : c;
            return (edge - oc) / dc;
        };
        double tx = next_t(cx, o.x, d.x, stepx), tz = next_t(cz, o.z, d.z, stepz);
        double tcell = t0;
        while (true) {
            double tend = std::min({tx, tz, t1});
            // The ray's height range in this cell.
            double ya = o.y + d.y * tcell, yb = o.y + d.y * tend;
            bool found = cell(cx, cz, o, d, std::min(ya, yb), std::max(ya, yb), tmin, t1, ray,
                              hits);
            if (found && first_only) return;
            if (tend >= t1) return;
            if (tx < tz) {
                cx += stepx;
                tcell = tx;
                tx = next_t(cx, o.x, d.x, stepx);
                if (cx < 0 || cx > w_ - 2) return;
            } else {
                cz += stepz;
                tcell = tz;
                tz = next_t(cz, o.z, d.z, stepz);
                if (cz < 0 || cz > h_ - 2) return;
            }
        }
    }

    // POV-Ray's intersect_pixel: the two triangles of cell (x, z).
    bool cell(int x, int z, const Vec3& o, const Vec3& d, double ya, double yb, double tmin,
              double tmax, const Ray& ray, HitList* hits) const {
        double y1 = height(x, z), y2 = height(x + 1, z), y3 = height(x, z + 1),
               y4 = height(x + 1, z + 1);
        double m23 = std::min(y2, y3), M23 = std::max(y2, y3);
        if (std::max(std::max(y1, y4), M23) < ya || std::min(std::min(y1, y4), m23) > yb)
            return false;
        bool found = false;
        for (int tri = 0; tri < 2; ++tri) {
            double yc = tri ? y4 : y1;
            if (std::max(yc, M23) < ya || std::min(yc, m23) > yb) continue;
            Vec3 P = tri ? Vec3(x + 1, y4, z + 1) : Vec3(x, y1, z);
            Vec3 N = tri ? Vec3(y3 - y4, 1, y2 - y4) : Vec3(y1 - y2, 1, y1 - y3);
            double dn = dot(N, d);
            if (std::fabs(dn) <= 1e-10 * length(N) * length(d)) continue;
            double t = dot(N, P - o) / dn;
            if (!(t >= tmin && t <= tmax)) continue;
            double s = o.x + t * d.x - x, u = o.z + t * d.z - z;
            // POV-Ray lets each triangle reach 1e-4 cells past its edges; that much lets a
            // shadow ray leaving one triangle hit its neighbour's overhang (dark specks on
            // smooth terrain), so the margin here only closes rounding cracks.
            constexpr double kMargin = 1e-9;
            bool in = tri ? (s <= 1 + kMargin && u <= 1 + kMargin && s + u >= 1 - kMargin)
                          : (s >= -kMargin && u >= -kMargin && s + u <= 1 + kMargin);
            if (!in) continue;
            LocalHit& h = hits->emplace_back();
            h.t = t;
            h.p = ray.origin + ray.dir * t;
            h.p_error = rounding_error(h.p, 8) + Vec3(1e-9);
            h.ng = normal_to_object(N);
            h.n = smooth_ ? smooth_normal(o + d * t) : h.ng;
            if (dot(h.n, h.ng) < 0) h.n = h.ng;
            found = true;
        }
        return found;
    }

    // Per-vertex normals from the four triangles around each grid point (smooth_height_field),
    // quantized like POV-Ray's 16-bit normals.
    void compute_normals() {
        normals_.resize(map_.size());
        auto add = [&](int x0, int z0, int x1, int z1, int x2, int z2, Vec3* n) {
            if (x0 < 0 || z0 < 0 || x1 < 0 || z1 < 0 || x2 < 0 || z2 < 0 || x0 >= w_ ||
                x1 >= w_ || x2 >= w_ || z0 >= h_ || z1 >= h_ || z2 >= h_)
                return 0;
            Vec3 v0(x0, height(x0, z0), z0), v1(x1, height(x1, z1), z1), v2(x2, height(x2, z2), z2);
            Vec3 nt = cross(v2 - v0, v1 - v0);
            double l = length(nt);
            nt = l > 1e-10 ? nt / l : Vec3(0, 1, 0);
            if (nt.y < 0) nt = -nt;
            *n += nt;
            return 1;
        };
        for (int z = 0; z < h_; ++z)
            for (int x = 0; x < w_; ++x) {
                Vec3 n(0);
                add(x, z, x + 1, z, x, z + 1, &n);
                add(x, z, x, z + 1, x - 1, z, &n);
                add(x, z, x - 1, z, x, z - 1, &n);
                add(x, z, x, z - 1, x + 1, z, &n);
                double l = length(n);
                n = l > 1e-10 ? n / l : Vec3(0, 1, 0);
                n = Vec3(static_cast<int>(32767 * n.x), static_cast<int>(32767 * n.y),
                         static_cast<int>(32767 * n.z));
                normals_[static_cast<size_t>(z) * w_ + x] = normal_to_object(n);
            }
    }

    Vec3 smooth_normal(const Vec3& p) const {
        int px = std::clamp(static_cast<int>(p.x), 0, w_ - 2);
        int pz = std::clamp(static_cast<int>(p.z), 0, h_ - 2);
        double x = p.x - px, z = p.z - pz;
        // POV-Ray normalizes the corner normals in world space before blending them.
        auto n = [&](int i, int k) {
            Vec3 c = shading_.normal(normals_[static_cast<size_t>(pz + k) * w_ + px + i]);
            double l = length(c);
            return l > 0 ? c / l : c;
        };
        Vec3 r = (n(0, 0) * (1 - x) + n(1, 0) * x) * (1 - z) + (n(0, 1) * (1 - x) + n(1, 1) * x) * z;
        r = shading_.inverse().normal(r);
        double l = length(r);
        return l > 0 && std::isfinite(l) ? r / l : Vec3(0, 1, 0);
    }

    int w_, h_;
    std::vector<uint16_t> map_;  // row z = 0 is the image's bottom row
    std::vector<Vec3> normals_;
    bool smooth_;
    Transform shading_;  // object space -> the space smooth normals are blended in
    double ylo_, yhi_, sx_, sz_;
};

// A .pot file: 16-bit heights from the indices of the GIF's two halves (POV-Ray's gif.cpp),
// through POV-Ray's 16-bit grey image, whose value it scales back to 65535 in float.
std::unique_ptr<Primitive> make_pot_height_field(const scene::HeightField& s,
                                                 const std::string& path, const FileLoc& at,
                                                 const Transform& shading, const char** why) {
    GifIndices gif;
    std::string err;
    if (!read_gif_indices(path, &gif, &err))
        throw Error(ErrorKind::MissingFile, at,
                    "cannot read height_field pot file '" + s.file + "': " + err);
    if (gif.width % 2 != 0)
        throw Error(ErrorKind::Scene, at, "invalid width for the pot file '" + s.file +
                                              "' (it must be even)");
    const int w = gif.width / 2, h = gif.height;
    if (w < 2 || h < 2) {
        *why = "height_field image smaller than 2x2";
        return nullptr;
    }
    check_image_size(w, h, 1, s.file, at);
    std::vector<uint16_t> map(static_cast<size_t>(w) * h);
    for (int z = 0; z < h; ++z) {
        const uint8_t* row = &gif.index[static_cast<size_t>(h - 1 - z) * gif.width];
        for (int x = 0; x < w; ++x) {
            const unsigned v = unsigned{row[x]} << 8 | row[x + w];
            const float grey = static_cast<float>(v) / 65535.0f;
            map[static_cast<size_t>(z) * w + x] = static_cast<uint16_t>(grey * 65535.0f);
        }
    }
    return std::make_unique<HeightFieldPrim>(w, h, std::move(map), s.smooth, s.water_level,
                                             shading);
}

}  // namespace

std::unique_ptr<Primitive> make_height_field(const scene::HeightField& s, const FileLoc& loc,
                                             const Transform& shading, const char** why) {
    if (!s.heights.empty()) {  // a function's heights, evaluated by the importer
        if (s.grid_w < 2 || s.grid_h < 2 ||
            s.heights.size() != static_cast<size_t>(s.grid_w) * s.grid_h)
            throw Error(ErrorKind::Scene, loc, "internal: height_field grid size mismatch");
        return std::make_unique<HeightFieldPrim>(s.grid_w, s.grid_h, s.heights, s.smooth,
                                                 s.water_level, shading);
    }
    const std::string& path = s.resolved_path.empty() ? s.file : s.resolved_path;
    FileLoc at = s.file_loc.line > 0 ? s.file_loc : loc;
    if (s.pot) return make_pot_height_field(s, path, at, shading, why);
    QuietStderr quiet;  // libpng's own lines: glint's error says what went wrong
    std::string err;
    std::unique_ptr<ImageReader> in = open_image(path, {}, &err);
    if (!in)
        throw Error(ErrorKind::MissingFile, at,
                    "cannot read height_field image '" + s.file + "': " + first_line_of(err));
    const ImageHeader& spec = in->header();
    int w = spec.width, h = spec.height, nc = spec.channels;
    if (w < 2 || h < 2 || nc <= 0) {
        *why = "height_field image smaller than 2x2";
        return nullptr;
    }
    check_image_size(w, h, nc, s.file, at);
    std::vector<float> raw(static_cast<size_t>(w) * h * nc);
    err = in->read(nc, raw.data());
    if (!err.empty())
        throw Error(ErrorKind::MissingFile, at,
                    "cannot decode height_field image '" + s.file + "': " + first_line_of(err));
    const bool png_format = spec.format == "png";
    const bool high_depth = spec.type != PixelType::UInt8;
    in.reset();
    const std::vector<PaletteColor> palette_colors = read_palette(path);
    const bool palette = !palette_colors.empty();
    const bool png_grey8 = png_format && !high_depth && !palette;
    const int colors = nc >= 3 ? 3 : 1;
    std::vector<uint16_t> map(static_cast<size_t>(w) * h);
    for (int z = 0; z < h; ++z) {
        const float* row = &raw[static_cast<size_t>(h - 1 - z) * w * nc];
        for (int x = 0; x < w; ++x) {
            const float* px = row + static_cast<size_t>(x) * nc;
            double v;
            if (palette) {
                // The reader expands indices to colours: palette_index() finds them back.
                const int index = palette_index(palette_colors, px, nc);
                v = static_cast<double>(index) * 256.0;
            } else if (colors == 1 && png_grey8) {
                // POV-Ray reads 8-bit grey PNGs through a grey colour table and stores each
                // value back as uint8(grey(g, g, g) * 255) in float (png.cpp, image.cpp), which
                // truncates some levels by one.
                float g = static_cast<float>(std::round(px[0] * 255.0)) / 255.0f;
                float grey = g * 0.297f + g * 0.589f + g * 0.114f;
                auto stored = static_cast<unsigned char>(grey * 255.0f);
                v = static_cast<double>(static_cast<float>(stored) / 255.0f * 65535.0f);
            } else if (colors == 1) {
                v = static_cast<double>(static_cast<float>(px[0] * 65535.0f));
            } else if (high_depth) {
                v = (0.297f * px[0] + 0.589f * px[1] + 0.114f * px[2]) * 65535.0f;
            } else {
                v = (std::round(px[0] * 255.0) * 256.0 + std::round(px[1] * 255.0));
            }
            map[static_cast<size_t>(z) * w + x] =
                static_cast<uint16_t>(std::clamp(v, 0.0, 65535.0));
        }
    }
    return std::make_unique<HeightFieldPrim>(w, h, std::move(map), s.smooth, s.water_level,
                                             shading);
}

}  // namespace glint::render
