// triangle and smooth_triangle (POV-Ray 3.7 manual 2.4.2.5 and 2.4.2.4), and the watertight
// test they share with meshes.
#include "render/shapes/triangle.h"

#include <cmath>

#include "render/shapes/shapes.h"

namespace glint::render {

RayShear::RayShear(const Ray& ray) : origin(ray.origin) {
    Vec3 ad = abs(ray.dir);
    kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    // Keep the winding: swapping x and y when looking down -kz.
    if (ray.dir[kz] < 0) std::swap(kx, ky);
    sz = 1.0 / ray.dir[kz];
    sx = ray.dir[kx] * sz;
    sy = ray.dir[ky] * sz;
}

bool intersect_triangle(const RayShear& s, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                        double tmax, TriangleHit* hit) {
    if (!std::isfinite(s.sz)) return false;  // zero direction
    Vec3 a = p0 - s.origin, b = p1 - s.origin, c = p2 - s.origin;
    double ax = a[s.kx] - s.sx * a[s.kz], ay = a[s.ky] - s.sy * a[s.kz];
    double bx = b[s.kx] - s.sx * b[s.kz], by = b[s.ky] - s.sy * b[s.kz];
    double cx = c[s.kx] - s.sx * c[s.kz], cy = c[s.ky] - s.sy * c[s.kz];
    // Edge functions (2D cross products in the sheared frame).
    double u = cx * by - cy * bx;
    double v = ax * cy - ay * cx;
    double w = bx * ay - by * ax;
    if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return false;
    double det = u + v + w;
    if (det == 0 || !std::isfinite(det)) return false;
    double az = s.sz * a[s.kz], bz = s.sz * b[s.kz], cz = s.sz * c[s.kz];
    double t_scaled = u * az + v * bz + w * cz;
    if (det < 0 ? (t_scaled >= 0 || t_scaled < tmax * det) : (t_scaled <= 0 || t_scaled > tmax * det))
        return false;
    double inv = 1.0 / det;
    double t = t_scaled * inv;
    if (!(t < tmax)) return false;
    // Conservative bound on t's rounding error (pbrt-v4, 6.8.4 "Conservative ray-triangle t").
    double max_z = std::max({std::fabs(az), std::fabs(bz), std::fabs(cz)});
    double max_x = std::max({std::fabs(ax), std::fabs(bx), std::fabs(cx)});
    double max_y = std::max({std::fabs(ay), std::fabs(by), std::fabs(cy)});
    double dz = gamma(3) * max_z;
    double dx = gamma(5) * (max_x + max_z);
    double dy = gamma(5) * (max_y + max_z);
    double de = 2 * (gamma(2) * max_x * max_y + dy * max_x + dx * max_y);
    double max_e = std::max({std::fabs(u), std::fabs(v), std::fabs(w)});
    double dt = 3 * (gamma(3) * max_e * max_z + de * max_z + dz * max_e) * std::fabs(inv);
    if (t <= dt) return false;
    hit->t = t;
    hit->b[0] = u * inv;
    hit->b[1] = v * inv;
    hit->b[2] = w * inv;
    return true;
}

namespace {

class TrianglePrim final : public Primitive {
public:
    TrianglePrim(const Vec3 p[3], const Vec3* n) : p_{p[0], p[1], p[2]}, smooth_(n != nullptr) {
        ng_ = normalize(cross(p[1] - p[0], p[2] - p[0]));
        for (int i = 0; i < 3; ++i) n_[i] = smooth_ ? n[i] : ng_;
    }

    Bounds3 bounds() const override {
        Bounds3 b;
        for (const Vec3& p : p_) b.extend(p);
        return b;
    }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        TriangleHit th;
        if (!intersect_triangle(RayShear(ray), p_[0], p_[1], p_[2], tmax, &th)) return false;
        hit->t = th.t;
        hit->p = triangle_point(p_[0], p_[1], p_[2], th.b, &hit->p_error);
        hit->ng = ng_;
        hit->n = ng_;
        if (smooth_) {
            Vec3 n = n_[0] * th.b[0] + n_[1] * th.b[1] + n_[2] * th.b[2];
            double len = length(n);
            if (len > 0 && std::isfinite(len)) {
                n = n / len;
                hit->n = dot(n, ng_) < 0 ? -n : n;
            }
        }
        hit->has_uv = false;
        return true;
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        LocalHit h;
        if (intersect(ray, tmax, &h)) hits->push_back(h);
    }

    // POV-Ray: triangles have no inside.
    bool inside(const Vec3&) const override { return false; }

private:
    Vec3 p_[3];
    Vec3 n_[3];
    Vec3 ng_;
    bool smooth_;
};

}  // namespace

std::unique_ptr<Primitive> make_triangle(const Vec3 p[3], const Vec3* normals) {
    for (int i = 0; i < 3; ++i)
        if (!is_finite(p[i])) return nullptr;
    Vec3 c = cross(p[1] - p[0], p[2] - p[0]);
    if (!(length_squared(c) > 0) || !is_finite(c)) return nullptr;
    if (normals) {
        for (int i = 0; i < 3; ++i)
            if (!is_finite(normals[i])) {
                normals = nullptr;
                break;
            }
    }
    return std::make_unique<TrianglePrim>(p, normals);
}

}  // namespace glint::render
