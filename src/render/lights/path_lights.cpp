#include "render/lights/path_lights.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "render/sampling/warp.h"

namespace glint::render {
namespace {

double average(const Color& c) { return (c.r + c.g + c.b) * (1.0 / 3.0); }

// POV-Ray's cubic_spline(low, high, pos) for the spot cone's edge.
double smooth_step(double low, double high, double pos) {
    if (pos <= low) return 0;
    if (pos >= high) return 1;
    const double t = (pos - low) / (high - low);
    return (3 - 2 * t) * t * t;
}

// Whether the linear part of `x` is a rotation times a uniform scale; *scale gets the scale.
bool similarity(const Transform& x, double* scale) {
    const Vec3 c[3] = {x.vector(Vec3(1, 0, 0)), x.vector(Vec3(0, 1, 0)), x.vector(Vec3(0, 0, 1))};
    const double s2 = length_squared(c[0]);
    constexpr double kTol = 1e-9;
    for (int i = 0; i < 3; ++i) {
        if (std::fabs(length_squared(c[i]) - s2) > kTol * s2) return false;
        if (std::fabs(dot(c[i], c[(i + 1) % 3])) > kTol * s2) return false;
    }
    *scale = std::sqrt(s2);
    return s2 > 0 && std::isfinite(s2);
}

// Spheres and discs in one object beyond which the object is left to BSDF sampling.
constexpr size_t kMaxShapesPerObject = 64;
constexpr size_t kMaxLocatableTris = 64;

// Cone sampling needs the point clearly outside the sphere: a point on it (the sphere's own
// shading points) sees the inside of the sphere, which area sampling covers.
bool outside_sphere(double dist2_to_centre, double radius2) {
    return dist2_to_centre > radius2 * (1 + 1e-6);
}

// Solid angle of the spherical triangle of unit directions a, b, c (Van Oosterom & Strackee
// 1983: tan(A / 2) = |a . (b x c)| / (1 + a.b + b.c + c.a)).
double spherical_triangle_area(const Vec3& a, const Vec3& b, const Vec3& c) {
    const double num = std::fabs(dot(a, cross(b, c)));
    const double den = 1 + dot(a, b) + dot(b, c) + dot(c, a);
    return 2 * std::atan2(num, den);
}

// A direction uniformly distributed (in solid angle) over the spherical triangle of unit
// directions a, b, c whose solid angle is `area` (spherical_triangle_area): Arvo, "Stratified
// Sampling of Spherical Triangles" (SIGGRAPH 1995). u.u picks the sub-triangle (a, b, c')
// with area u.u times the whole; u.v the point along the arc from b to c'. The pdf the caller
// uses is 1 / area with the same area, and sin and cos of the angle alpha at a come from
// the arcs' plane normals, so one sincos is the only transcendental call.
bool sample_spherical_triangle(const Vec3& a, const Vec3& b, const Vec3& c, double area,
                               Sample2 u, Vec3* w) {
    Vec3 n_ab = cross(a, b), n_ac = cross(a, c);
    if (!(length_squared(n_ab) > 0) || !(length_squared(n_ac) > 0) || !(area > 0)) return false;
    n_ab = normalize(n_ab);
    n_ac = normalize(n_ac);
    // alpha: the angle at a between the arcs towards b and towards c (the dihedral angle of
    // their planes); its sine is positive, as the triangle runs the same way round as these.
    const double cos_a = std::clamp(dot(n_ab, n_ac), -1.0, 1.0);
    const double sin_a = length(cross(n_ab, n_ac));
    const double sub = u.u * area;
    const double sin_sub = std::sin(sub), cos_sub = std::cos(sub);
    // sin and cos of (sub - alpha).
    const double s = sin_sub * cos_a - cos_sub * sin_a, t = cos_sub * cos_a + sin_sub * sin_a;
    const double k1 = t - cos_a;
    const double k2 = s + sin_a * dot(a, b);
    const double den = (k2 * s + k1 * t) * sin_a;
    if (!(std::fabs(den) > 0)) return false;
    const double q = std::clamp(((k2 * t - k1 * s) * cos_a - k2) / den, -1.0, 1.0);
    const Vec3 c_perp = c - a * dot(c, a);
    if (!(length_squared(c_perp) > 0)) return false;
    const Vec3 c2 = a * q + normalize(c_perp) * std::sqrt(std::max(0.0, 1 - q * q));
    const double z = 1 - u.v * (1 - dot(c2, b));
    const Vec3 perp = c2 - b * dot(c2, b);
    if (!(length_squared(perp) > 0)) {
        *w = b;
        return true;
    }
    *w = normalize(b * z + normalize(perp) * std::sqrt(std::max(0.0, 1 - z * z)));
    return is_finite(*w);
}

}  // namespace

double PathLights::tri_solid_angle(const Tri& t, const Vec3& p, Vec3 dirs[3]) {
    if (!t.locatable) return 0;
    // Cycles 3.4's rule (light.h): the solid angle pays where the triangle's longest edge is
    // longer than its plane is far; elsewhere sampling by area is about as good and cheaper.
    const double h = dot(p - t.p0, t.n);
    const double longest = std::max(
        {length_squared(t.e1), length_squared(t.e2), length_squared(t.e2 - t.e1)});
    if (!(longest > h * h)) return 0;
    const Vec3 a = t.p0 - p, b = a + t.e1, c = a + t.e2;
    const double la = length(a), lb = length(b), lc = length(c);
    if (!(la > 0) || !(lb > 0) || !(lc > 0)) return 0;
    const Vec3 ua = a / la, ub = b / lb, uc = c / lc;
    const double area = spherical_triangle_area(ua, ub, uc);
    if (dirs) {
        dirs[0] = ua;
        dirs[1] = ub;
        dirs[2] = uc;
    }
    // Tiny or degenerate spherical triangles: area sampling (the same rule in pdf and sample).
    return area > 1e-6 && std::isfinite(area) ? area : 0.0;
}

PathLights::PathLights(const scene::Scene& scene, const std::vector<Color>& emission,
                       const EnvironmentDistribution::Radiance& environment,
                       const TextureCache* textures, int world, bool light_tree)
    : scene_(scene) {
    for (int i = 0; i < static_cast<int>(scene.lights.size()); ++i) {
        const scene::Light& l = scene.lights[i];
        if (l.blender) {
            slots_.push_back({SlotKind::Blender, static_cast<int>(blender_.size())});
            blender_.emplace_back(l);
            blender_light_index_.push_back(i);
            visible_blender_ = visible_blender_ || blender_.back().visible();
        } else {
            slots_.push_back({SlotKind::Pov, i});
        }
    }
    object_emitter_.assign(scene.objects.size(), kNotSampled);
    for (int oi = 0; oi < static_cast<int>(scene.objects.size()); ++oi) {
        const scene::Object& o = scene.objects[oi];
        // A moving or deforming emitter is not where its transform and vertices say at most
        // times: BSDF rays alone find it (unweighted, so still unbiased, only noisier).
        if (!o.motion.empty()) continue;
        if (const auto* ref = std::get_if<scene::MeshRef>(&o.shape);
            ref && ref->mesh >= 0 && ref->mesh < static_cast<int>(scene.meshes.size()) &&
            !scene.meshes[static_cast<size_t>(ref->mesh)].motion_positions.empty())
            continue;
        Gathered g;
        gather(o, o.transform, o.material, emission, &g);
        // BSDF rays that hit the object are weighted by the pdf of the emitter they hit, so an
        // object is light-sampled only when all its emitters are handled.
        // (A hit is matched to its shape by trying each: past kMaxShapesPerObject that costs
        // more than the noise it saves.)
        if (!g.ok || (g.tris.empty() && g.shapes.empty())) continue;
        if (g.shapes.size() > kMaxShapesPerObject) continue;
        object_emitter_[oi] = static_cast<int>(groups_.size());
        groups_.push_back({!g.tris.empty(), static_cast<int>(shapes_.size()),
                           static_cast<int>(g.shapes.size()), static_cast<int>(tris_.size()),
                           static_cast<int>(g.tris.size())});
        // A BSDF hit is matched to its triangle by trying each of the object's: only objects
        // with few emitting triangles get solid-angle sampling (area sampling needs no match).
        if (g.tris.size() <= kMaxLocatableTris)
            for (Tri& t : g.tris) t.locatable = true;
        tris_.insert(tris_.end(), g.tris.begin(), g.tris.end());
        shapes_.insert(shapes_.end(), g.shapes.begin(), g.shapes.end());
    }
    std::vector<LightTreeItem> items;
    if (!tris_.empty() || !shapes_.empty()) {
        auto add_item = [&](EmitterItem::Kind kind, int index, const Bounds3& box, double power) {
            items_.push_back({kind, index});
            LightTreeItem it;
            it.box = box;
            it.power = power;  // two-sided emitters: every direction (theta_o = pi)
            items.push_back(it);
            return static_cast<int>(items_.size()) - 1;
        };
        auto tri_box = [](const Tri& t) {
            Bounds3 b;
            b.extend(t.p0);
            b.extend(t.p0 + t.e1);
            b.extend(t.p0 + t.e2);
            return b;
        };
        tri_item_.assign(tris_.size(), -1);
        shape_item_.assign(shapes_.size(), -1);
        group_item_.assign(groups_.size(), -1);
        tri_cdf_.assign(tris_.size(), 0.0);
        group_weight_.assign(groups_.size(), 0.0);
        for (int gi = 0; gi < static_cast<int>(groups_.size()); ++gi) {
            const Group& grp = groups_[gi];
            if (grp.tri_count > static_cast<int>(kMaxLocatableTris)) {
                Bounds3 box;
                double sum = 0;
                for (int k = grp.first_tri; k < grp.first_tri + grp.tri_count; ++k) {
                    box.extend(tri_box(tris_[k]));
                    sum += tris_[k].area * average(tris_[k].le);
                    tri_cdf_[k] = sum;
                }
                for (int k = grp.first_tri; k < grp.first_tri + grp.tri_count; ++k)
                    tri_cdf_[k] /= sum;
                group_weight_[gi] = sum;
                group_item_[gi] = add_item(EmitterItem::Kind::Group, gi, box, sum);
            } else {
                for (int k = grp.first_tri; k < grp.first_tri + grp.tri_count; ++k)
                    tri_item_[k] = add_item(EmitterItem::Kind::Tri, k, tri_box(tris_[k]),
                                            tris_[k].area * average(tris_[k].le));
            }
            for (int k = grp.first_shape; k < grp.first_shape + grp.shape_count; ++k)
                shape_item_[k] = add_item(EmitterItem::Kind::Shape, k, shape_bounds(shapes_[k]),
                                          shapes_[k].weight);
        }
        slots_.push_back({SlotKind::Emitters, -1});
    }
    if (world != 0) {
        // A node graph: importance-sampled by its radiance unless it is the same everywhere.
        has_env_ = world == 2 || (environment && average(environment(Vec3(0, 0, 1))) > 0);
        if (has_env_) {
            slots_.push_back({SlotKind::Environment, -1});
            if (world == 2 && environment) env_.emplace(environment, EnvironmentGrid{256, 128, 2});
        }
    } else {
        has_env_ = average(scene.background.rgb) > 0 ||
                   (scene.sky_sphere && !scene.sky_sphere->pigments.empty());
        if (has_env_) {
            slots_.push_back({SlotKind::Environment, -1});
            if (environment && !environment_uniform(scene))
                env_.emplace(environment, environment_grid(scene, textures));
        }
    }
    // Next-event estimation samples every slot while there are few. Past that, the lights
    // that have a place (all but POV-Ray's parallel and cylinder lights and Blender's suns)
    // join the emitters in the light tree, and one slot stands for the tree.
    nee_ = slots_;
    blender_item_.assign(blender_.size(), -1);
    if (static_cast<int>(slots_.size()) > kSampleAllMax) {
        std::vector<Slot> rest;
        for (const Slot& s : slots_) {
            std::optional<LightTreeItem> it;
            if (s.kind == SlotKind::Pov) it = pov_tree_item(scene_.lights[s.light]);
            if (s.kind == SlotKind::Blender) it = blender_tree_item(s.light);
            if (!it) {
                if (s.kind != SlotKind::Emitters) rest.push_back(s);
                continue;
            }
            items_.push_back({s.kind == SlotKind::Pov ? EmitterItem::Kind::PovLight
                                                      : EmitterItem::Kind::BlenderLight,
                              s.light});
            items.push_back(*it);
            if (s.kind == SlotKind::Blender)
                blender_item_[s.light] = static_cast<int>(items_.size()) - 1;
        }
        if (!items.empty()) {
            const auto env = std::find_if(rest.begin(), rest.end(), [](const Slot& s) {
                return s.kind == SlotKind::Environment;
            });
            rest.insert(env, {SlotKind::Emitters, -1});
        }
        nee_ = rest;
    }
    if (!items.empty()) emitter_tree_ = LightTree(items, light_tree);
}

// Bounds of a POV-Ray light for the tree: its point or area rectangle, its power as the
// irradiance it gives a facing surface (pi C, fading left out), a spot's cone up to its
// falloff (pov_factor: with radius 0 there is no falloff edge, only the cosine's, so the
// half space). Parallel and cylinder lights have no place: they stay slots of their own.
std::optional<LightTreeItem> PathLights::pov_tree_item(const scene::Light& l) {
    if (l.parallel || l.kind == scene::LightKind::Cylinder) return std::nullopt;
    LightTreeItem it;
    it.box.extend(l.location);
    if (l.area) {
        for (double a : {-0.5, 0.5})
            for (double b : {-0.5, 0.5})
                it.box.extend(l.location + l.area->axis1 * a + l.area->axis2 * b);
    }
    it.power = kPi * average(l.color);
    if (l.kind == scene::LightKind::Spot && length_squared(l.point_at - l.location) > 0) {
        it.axis = normalize(l.point_at - l.location);
        it.theta_o = 0;
        const double edge = l.radius > 0 ? std::clamp(l.falloff, 0.0, 90.0) : 90.0;
        it.theta_e = edge * (kPi / 180);
    }
    if (!(it.power > 0) || !std::isfinite(it.power)) return std::nullopt;
    return it;
}

// Bounds of a Blender light: its power as the irradiance it gives a facing surface at
// distance 1 (measured by a sample from ten sizes away along its axis), its extent, and for
// spots and area lights the cone they shine into. Suns have no place.
std::optional<LightTreeItem> PathLights::blender_tree_item(int k) const {
    const CyclesLight& c = blender_[k];
    if (c.type() == scene::BlenderLightType::Sun) return std::nullopt;
    const scene::BlenderLight& b = *scene_.lights[blender_light_index_[k]].blender;
    const Vec3 at = scene_.lights[blender_light_index_[k]].location;
    const double size = std::max({b.radius, b.size_x, b.size_y, 1e-3});
    LightTreeItem it;
    it.box.extend(at - Vec3(size, size, size));
    it.box.extend(at + Vec3(size, size, size));
    const Vec3 dir = length_squared(b.direction) > 0 ? normalize(b.direction) : Vec3(0, 0, -1);
    const double r = 10 * size + 1;
    CyclesLight::Sample s;
    double e = 0;
    if (c.sample(at + dir * r, {0.5, 0.5}, &s)) e = average(s.value) * r * r;
    if (s.pdf > 0) e *= std::fabs(dot(s.wi, dir));  // an area light's cosine at the receiver
    it.power = e;
    if (b.type == scene::BlenderLightType::Spot) {
        it.axis = dir;
        it.theta_o = 0;
        it.theta_e = std::clamp(b.spot_size, 0.0, 360.0) * (kPi / 360);
    } else if (b.type == scene::BlenderLightType::Area) {
        it.axis = dir;
        it.theta_o = 0;
        it.theta_e = kPi / 2;
    }
    if (!(it.power > 0) || !std::isfinite(it.power)) return std::nullopt;
    return it;
}

void PathLights::gather(const scene::Object& o, const Transform& x, int material,
                        const std::vector<Color>& emission, Gathered* g) const {
    auto emits = [&](int m) -> const Color* {
        if (m < 0 || m >= static_cast<int>(emission.size())) return nullptr;
        return average(emission[m]) > 0 ? &emission[m] : nullptr;
    };
    if (o.material >= 0) material = o.material;
    auto add = [&](const Vec3& a, const Vec3& b, const Vec3& c, int m) {
        const Color* le = emits(m);
        if (!le) return;
        Tri t;
        t.p0 = a;
        t.e1 = b - a;
        t.e2 = c - a;
        const Vec3 n = cross(t.e1, t.e2);
        t.area = 0.5 * length(n);
        if (!(t.area > 0) || !std::isfinite(t.area)) return;
        t.n = n / (2 * t.area);
        t.le = *le;
        g->tris.push_back(t);
    };
    if (const auto* tri = std::get_if<scene::Triangle>(&o.shape)) {
        add(x.point(tri->p[0]), x.point(tri->p[1]), x.point(tri->p[2]), material);
    } else if (const auto* st = std::get_if<scene::SmoothTriangle>(&o.shape)) {
        add(x.point(st->p[0]), x.point(st->p[1]), x.point(st->p[2]), material);
    } else if (const auto* mr = std::get_if<scene::MeshRef>(&o.shape)) {
        if (mr->mesh < 0 || mr->mesh >= static_cast<int>(scene_.meshes.size())) return;
        const scene::Mesh& m = scene_.meshes[mr->mesh];
        for (const scene::MeshFace& f : m.faces) {
            const int mat = f.material >= 0 ? f.material : material;
            if (!emits(mat)) continue;
            bool ok = true;
            for (int k = 0; k < 3; ++k)
                ok = ok && f.v[k] >= 0 && f.v[k] < static_cast<int>(m.positions.size());
            if (!ok) continue;
            add(x.point(m.positions[f.v[0]]), x.point(m.positions[f.v[1]]),
                x.point(m.positions[f.v[2]]), mat);
        }
    } else if (const auto* csg = std::get_if<scene::Csg>(&o.shape)) {
        // A union keeps every surface of its children (obj_file's OBJ parts, looks_like);
        // merge, intersection and difference cut them, so their emitters are not sampled.
        const size_t before = g->tris.size() + g->shapes.size();
        const bool whole = csg->op == scene::CsgOp::Union && !o.inverse && o.clipped_by.empty();
        for (const scene::Object& c : csg->children)
            gather(c, c.transform.then(x), material, emission, g);
        if (!whole && g->tris.size() + g->shapes.size() > before) g->ok = false;
    } else if (const Color* le = emits(material)) {
        if (o.inverse || !o.clipped_by.empty()) {
            g->ok = false;
            return;
        }
        // Spheres and discs: the whole surface, as the geometry intersects it.
        Shape e;
        e.le = *le;
        if (const auto* sp = std::get_if<scene::Sphere>(&o.shape)) {
            if (!(sp->radius > 0)) return;
            double scale = 1;
            e.sphere = true;
            if (similarity(x, &scale)) {
                e.cone = true;
                e.center = x.point(sp->center);
                e.radius = sp->radius * scale;
                e.area = 4 * kPi * e.radius * e.radius;
            } else {
                e.center = sp->center;
                e.radius = sp->radius;
                e.to_world = x;
                // For choosing among emitters only: 4 pi r^2 |det|^(2/3).
                const double det = dot(x.vector(Vec3(1, 0, 0)),
                                       cross(x.vector(Vec3(0, 1, 0)), x.vector(Vec3(0, 0, 1))));
                e.area = 4 * kPi * e.radius * e.radius * std::pow(std::fabs(det), 2.0 / 3.0);
            }
        } else if (const auto* d = std::get_if<scene::Disc>(&o.shape)) {
            if (!(d->radius > d->hole_radius) || !(length_squared(d->normal) > 0)) return;
            Vec3 s, t;
            tangents(normalize(d->normal), &s, &t);
            e.sphere = false;
            e.center = x.point(d->center);
            e.a1 = x.vector(s * d->radius);
            e.a2 = x.vector(t * d->radius);
            const Vec3 n = cross(e.a1, e.a2);
            const double hole = std::max(0.0, d->hole_radius) / d->radius;
            e.inner2 = hole * hole;
            e.area = kPi * length(n) * (1 - e.inner2);
            e.n = normalize(n);
        } else {
            // Other emitting shapes (boxes, cylinders, ...): found by BSDF sampling only.
            g->ok = false;
            return;
        }
        if (!(e.area > 0) || !std::isfinite(e.area)) return;
        e.weight = e.area * average(e.le);
        g->shapes.push_back(e);
    }
}

Color PathLights::pov_factor(const scene::Light& l, const Vec3& from_light, double dist) const {
    double att = 1;
    if (l.fade_power > 0 && l.fade_distance > 0)
        att = 2.0 / (1.0 + std::pow(dist / l.fade_distance, l.fade_power));
    if (l.kind != scene::LightKind::Point) {
        const Vec3 axis = normalize(l.point_at - l.location);
        const double c = dot(from_light, axis);
        if (c <= 0) return Color();
        double spot = l.tightness > 0 ? std::pow(c, l.tightness) : 1.0;
        const double cos_radius = std::cos(l.radius * kPi / 180);
        const double cos_falloff = std::cos(l.falloff * kPi / 180);
        if (l.radius > 0 && c < cos_radius) spot *= smooth_step(cos_falloff, cos_radius, c);
        att *= spot;
    }
    return l.color * (kPi * att);
}

bool PathLights::sample_pov(const scene::Light& l, const Vec3& p, Sample2 u, double select,
                            PathLightSample* out) const {
    if (l.parallel) {
        const Vec3 d = l.point_at - l.location;
        if (!(length_squared(d) > 0)) return false;
        out->wi = -normalize(d);
        out->dist = kInfinity;
        out->value = l.color * (kPi / select);
        out->pdf = 0;
        return true;
    }
    Vec3 q = l.location;
    if (l.area) {
        double a = u.u - 0.5, b = u.v - 0.5;
        if (l.area->circular) {
            // The ellipse inscribed in the rectangle (concentric disc mapping).
            const double x = 2 * a, y = 2 * b;
            double r = 0, phi = 0;
            if (std::fabs(x) > std::fabs(y)) {
                r = x;
                phi = (kPi / 4) * (y / x);
            } else if (y != 0) {
                r = y;
                phi = kPi / 2 - (kPi / 4) * (x / y);
            }
            a = 0.5 * r * std::cos(phi);
            b = 0.5 * r * std::sin(phi);
        }
        q = q + l.area->axis1 * a + l.area->axis2 * b;
    }
    const Vec3 d = q - p;
    const double dist = length(d);
    if (!(dist > 0)) return false;
    out->wi = d / dist;
    out->dist = dist;
    out->value = pov_factor(l, -out->wi, dist) / select;
    out->pdf = 0;
    return !out->value.is_black();
}

bool PathLights::sample_blender(int k, const Vec3& p, Sample2 u, double select,
                                PathLightSample* out) const {
    CyclesLight::Sample cs;
    if (!blender_[k].sample(p, u, &cs)) return false;
    out->wi = cs.wi;
    out->dist = cs.dist;
    out->value = cs.value / select;
    out->pdf = cs.pdf * select;
    return !out->value.is_black();
}

bool PathLights::sample(int slot, const Vec3& p, Sample2 u, PathLightSample* out) const {
    const Slot& s = nee_[slot];
    switch (s.kind) {
        case SlotKind::Pov: return sample_pov(scene_.lights[s.light], p, u, select_prob(), out);
        case SlotKind::Blender: return sample_blender(s.light, p, u, select_prob(), out);
        case SlotKind::Emitters: {
            double ur = u.u, pick = 0;
            const int it = emitter_tree_.sample(p, &ur, &pick);
            if (it < 0 || !(pick > 0)) return false;
            const EmitterItem& item = items_[static_cast<size_t>(it)];
            double select = select_prob() * pick;
            if (item.kind == EmitterItem::Kind::PovLight)
                return sample_pov(scene_.lights[item.index], p, {ur, u.v}, select, out);
            if (item.kind == EmitterItem::Kind::BlenderLight)
                return sample_blender(item.index, p, {ur, u.v}, select, out);
            if (item.kind == EmitterItem::Kind::Shape) {
                const Shape& e = shapes_[item.index];
                if (!sample_shape(e, p, {ur, u.v}, out)) return false;
                out->pdf *= select;
                if (!(out->pdf > 0) || !std::isfinite(out->pdf)) return false;
                out->value = e.le / out->pdf;
                return true;
            }
            int ti = item.index;
            if (item.kind == EmitterItem::Kind::Group) {
                double chance = 0;
                ti = pick_group_tri(item.index, &ur, &chance);
                select *= chance;
            }
            const Tri& t = tris_[ti];
            Vec3 dirs[3];
            if (const double omega = tri_solid_angle(t, p, dirs); omega > 0) {
                Vec3 w;
                if (!sample_spherical_triangle(dirs[0], dirs[1], dirs[2], omega, {ur, u.v}, &w))
                    return false;
                const double along = dot(w, t.n);
                const double dist = dot(t.p0 - p, t.n) / along;
                if (!(dist > 0) || !std::isfinite(dist)) return false;
                out->wi = w;
                out->dist = dist;
                out->pdf = select / omega;
                if (!(out->pdf > 0) || !std::isfinite(out->pdf)) return false;
                out->value = t.le / out->pdf;
                return true;
            }
            const double su = std::sqrt(ur);
            const double b1 = 1 - su, b2 = u.v * su;
            const Vec3 q = t.p0 + t.e1 * b1 + t.e2 * b2;
            const Vec3 d = q - p;
            const double dist = length(d);
            if (!(dist > 0)) return false;
            out->wi = d / dist;
            out->dist = dist;
            const double cos_l = std::fabs(dot(t.n, out->wi));
            if (!(cos_l > 0)) return false;
            out->pdf = select / t.area * dist * dist / cos_l;
            if (!(out->pdf > 0) || !std::isfinite(out->pdf)) return false;
            out->value = t.le / out->pdf;
            return true;
        }
        case SlotKind::Environment: {
            double pdf = 1 / (4 * kPi);
            if (env_) {
                if (!env_->sample(u, &out->wi, &pdf)) return false;
            } else {
                out->wi = uniform_sphere(u);
            }
            out->dist = kInfinity;
            out->pdf = select_prob() * pdf;
            out->value = Color(1.0 / out->pdf);
            out->environment = true;
            return true;
        }
    }
    return false;
}

Color PathLights::blender_emission(const Vec3& from, const Vec3& dir, double tmin, double tmax,
                                   double bsdf_pdf, bool camera_ray) const {
    Color sum;
    if (!visible_blender_) return sum;
    for (size_t k = 0; k < blender_.size(); ++k) {
        const CyclesLight& c = blender_[k];
        if (camera_ray ? !c.visible_camera() : !c.visible()) continue;
        double t, pdf;
        Color le;
        if (!c.intersect(from, dir, tmin, tmax, &t, &le, &pdf)) continue;
        if (bsdf_pdf >= 0) {
            // Power heuristic against light sampling's pdf of the same direction (its chance
            // in the light tree from `from` when it is there).
            const double select =
                blender_item_[k] >= 0 ? select_prob() * emitter_tree_.pdf(from, blender_item_[k])
                                      : select_prob();
            const double a = bsdf_pdf * bsdf_pdf, b = pdf * select * pdf * select;
            if (!(a + b > 0)) continue;
            le *= std::isinf(a) ? 1.0 : a / (a + b);
        }
        sum += le;
    }
    return sum;
}

double PathLights::environment_pdf(const Vec3& dir) const {
    if (!has_env_) return 0;
    return select_prob() * (env_ ? env_->pdf(dir) : 1 / (4 * kPi));
}

bool PathLights::sample_shape(const Shape& e, const Vec3& p, Sample2 u,
                              PathLightSample* out) const {
    Vec3 q;
    if (e.sphere && e.cone) {
        const Vec3 to_c = e.center - p;
        const double dc2 = length_squared(to_c);
        const double r2 = e.radius * e.radius;
        if (outside_sphere(dc2, r2)) {
            // Uniform in the cone of directions the sphere subtends (pbrt-v4 Sphere::Sample):
            // 1 - cos(theta_max) computed as sin^2 / (1 + cos) keeps tiny cones exact.
            const double dc = std::sqrt(dc2);
            const double sin2_max = r2 / dc2;
            const double cos_max = std::sqrt(std::max(0.0, 1 - sin2_max));
            const double one_minus_cos_max = sin2_max / (1 + cos_max);
            const double one_minus_cos = u.u * one_minus_cos_max;
            const double cos_t = 1 - one_minus_cos;
            const double sin2_t = one_minus_cos * (2 - one_minus_cos);
            const double sin_t = std::sqrt(std::max(0.0, sin2_t));
            const double phi = 2 * kPi * u.v;
            const Vec3 w = to_c / dc;
            Vec3 a, b;
            tangents(w, &a, &b);
            out->wi = normalize(w * cos_t + (a * std::cos(phi) + b * std::sin(phi)) * sin_t);
            // The near intersection with the sphere along wi.
            const double dist = dc * cos_t - std::sqrt(std::max(0.0, r2 - dc2 * sin2_t));
            if (!(dist > 0)) return false;
            out->dist = dist;
            out->pdf = 1 / (2 * kPi * one_minus_cos_max);
            return std::isfinite(out->pdf);
        }
        const Vec3 n = uniform_sphere(u);
        q = e.center + n * e.radius;
    } else if (e.sphere) {
        q = e.to_world.point(e.center + uniform_sphere(u) * e.radius);
    } else {
        const double rho = std::sqrt(e.inner2 + u.u * (1 - e.inner2));
        const double phi = 2 * kPi * u.v;
        q = e.center + e.a1 * (rho * std::cos(phi)) + e.a2 * (rho * std::sin(phi));
    }
    const Vec3 d = q - p;
    const double dist = length(d);
    if (!(dist > 0)) return false;
    out->wi = d / dist;
    out->dist = dist;
    out->pdf = shape_pdf(e, p, q);
    return out->pdf > 0 && std::isfinite(out->pdf);
}

double PathLights::shape_pdf(const Shape& e, const Vec3& p, const Vec3& q) const {
    const Vec3 d = q - p;
    const double dist2 = length_squared(d);
    if (!(dist2 > 0)) return 0;
    const Vec3 wi = d / std::sqrt(dist2);
    if (e.sphere && e.cone) {
        const double dc2 = length_squared(e.center - p);
        const double r2 = e.radius * e.radius;
        if (outside_sphere(dc2, r2)) {
            // Cone sampling reaches only the near side: a ray that enters the sphere there.
            if (dot(q - e.center, wi) >= 0) return 0;
            const double sin2_max = r2 / dc2;
            const double cos_max = std::sqrt(std::max(0.0, 1 - sin2_max));
            return (1 + cos_max) / (2 * kPi * sin2_max);
        }
        const double cos_l = std::fabs(dot(normalize(q - e.center), wi));
        return cos_l > 0 ? dist2 / (cos_l * e.area) : 0;
    }
    if (e.sphere) {
        // Uniform on the object-space sphere; the world area element is scaled by
        // |M a x M b| for an orthonormal tangent pair (a, b) at the object-space point.
        const Vec3 qo = e.to_world.inverse_point(q);
        const Vec3 no = normalize(qo - e.center);
        Vec3 a, b;
        tangents(no, &a, &b);
        const Vec3 nw = cross(e.to_world.vector(a), e.to_world.vector(b));
        const double scale = length(nw);
        if (!(scale > 0)) return 0;
        const double cos_l = std::fabs(dot(nw, wi)) / scale;
        const double pdf_area = 1 / (4 * kPi * e.radius * e.radius * scale);
        return cos_l > 0 ? pdf_area * dist2 / cos_l : 0;
    }
    const double cos_l = std::fabs(dot(e.n, wi));
    return cos_l > 0 ? dist2 / (cos_l * e.area) : 0;
}

double PathLights::off_surface(const Shape& e, const Vec3& q) {
    if (e.sphere) {
        const Vec3 p = e.cone ? q : e.to_world.inverse_point(q);
        return std::fabs(length(p - e.center) - e.radius) / e.radius;
    }
    // Disc: distance from the plane, and from the ring in the plane's own coordinates.
    const Vec3 d = q - e.center;
    const double size = std::sqrt(e.area);
    const double h = std::fabs(dot(d, e.n)) / size;
    const double g11 = dot(e.a1, e.a1), g12 = dot(e.a1, e.a2), g22 = dot(e.a2, e.a2);
    const double det = g11 * g22 - g12 * g12;
    if (!(det > 0)) return kInfinity;
    const double b1 = dot(d, e.a1), b2 = dot(d, e.a2);
    const double x = (g22 * b1 - g12 * b2) / det, y = (g11 * b2 - g12 * b1) / det;
    const double rho2 = x * x + y * y;
    const double ring = std::max(0.0, std::max(e.inner2 - rho2, rho2 - 1));
    return h + ring;
}

int PathLights::pick_group_tri(int group, double* u, double* prob) const {
    const Group& grp = groups_[group];
    const auto first = tri_cdf_.begin() + grp.first_tri;
    const auto last = first + grp.tri_count;
    const auto it = std::upper_bound(first, last, *u);
    const int k = static_cast<int>(std::min(it, last - 1) - tri_cdf_.begin());
    const double lo = k > grp.first_tri ? tri_cdf_[k - 1] : 0.0;
    const double width = tri_cdf_[k] - lo;
    *u = width > 0 ? std::clamp((*u - lo) / width, 0.0, kOneMinusEpsilon) : 0.5;
    *prob = width;
    return k;
}

Bounds3 PathLights::shape_bounds(const Shape& e) {
    Bounds3 b;
    if (!e.sphere) {
        const Vec3 r(std::fabs(e.a1.x) + std::fabs(e.a2.x), std::fabs(e.a1.y) + std::fabs(e.a2.y),
                     std::fabs(e.a1.z) + std::fabs(e.a2.z));
        b.extend(e.center - r);
        b.extend(e.center + r);
    } else if (e.cone) {
        b.extend(e.center - Vec3(e.radius, e.radius, e.radius));
        b.extend(e.center + Vec3(e.radius, e.radius, e.radius));
    } else {
        for (int k = 0; k < 8; ++k)
            b.extend(e.to_world.point(e.center + Vec3(k & 1 ? e.radius : -e.radius,
                                                      k & 2 ? e.radius : -e.radius,
                                                      k & 4 ? e.radius : -e.radius)));
    }
    return b;
}

double PathLights::emitter_pdf(int object, const Vec3& from, const Vec3& q, const Vec3& ng,
                               const Color& le) const {
    if (!emitter_object(object) || emitter_tree_.empty()) return 0;
    const int gi = object_emitter_[object];
    const Group& grp = groups_[gi];
    // Which emitter of the object was hit: the sphere or disc the point lies on, else (when
    // the object has emitting triangles) a triangle.
    int hit_shape = -1;
    if (grp.shape_count == 1 && !grp.tris) {
        hit_shape = grp.first_shape;
    } else {
        double best = grp.tris ? 1e-6 : kInfinity;
        for (int k = grp.first_shape; k < grp.first_shape + grp.shape_count; ++k) {
            const double off = off_surface(shapes_[k], q);
            if (off < best) {
                best = off;
                hit_shape = k;
            }
        }
    }
    if (hit_shape >= 0) {
        const Shape& e = shapes_[hit_shape];
        return select_prob() * emitter_tree_.pdf(from, shape_item_[hit_shape]) *
               shape_pdf(e, from, q);
    }
    const Vec3 d = q - from;
    const double dist2 = length_squared(d);
    if (!(dist2 > 0)) return 0;
    const double cos_l = std::fabs(dot(ng, d)) / std::sqrt(dist2);
    if (!(cos_l > 0)) return 0;
    if (group_item_[gi] >= 0) {
        // Many triangles: the group's pick, then area times emission within it, uniform
        // over the triangle's area: the density per area is the same on all of them.
        return select_prob() * emitter_tree_.pdf(from, group_item_[gi]) * average(le) /
               group_weight_[gi] * dist2 / cos_l;
    }
    // The triangle the point lies on (nearest its plane among those containing it; the
    // nearest plane when none contains it, as on an edge rounding put outside both), and its
    // pdf as sample() would have used it.
    int hit_tri = -1, nearest = -1;
    double best = kInfinity, best_any = kInfinity;
    for (int k = grp.first_tri; k < grp.first_tri + grp.tri_count; ++k) {
        const Tri& t = tris_[k];
        const Vec3 dq = q - t.p0;
        const double off = std::fabs(dot(dq, t.n));
        if (off < best_any) {
            best_any = off;
            nearest = k;
        }
        const double g11 = dot(t.e1, t.e1), g12 = dot(t.e1, t.e2), g22 = dot(t.e2, t.e2);
        const double det = g11 * g22 - g12 * g12;
        if (!(det > 0)) continue;
        const double b1 = dot(dq, t.e1), b2 = dot(dq, t.e2);
        const double x = (g22 * b1 - g12 * b2) / det, y = (g11 * b2 - g12 * b1) / det;
        constexpr double kEdge = 1e-7;
        if (x < -kEdge || y < -kEdge || x + y > 1 + kEdge) continue;
        if (off < best) {
            best = off;
            hit_tri = k;
        }
    }
    if (hit_tri < 0) hit_tri = nearest;
    if (hit_tri < 0) return 0;
    const Tri& t = tris_[hit_tri];
    const double select = select_prob() * emitter_tree_.pdf(from, tri_item_[hit_tri]);
    if (const double omega = tri_solid_angle(t, from); omega > 0) return select / omega;
    return select / t.area * dist2 / cos_l;
}

}  // namespace glint::render
