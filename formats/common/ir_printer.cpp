// Text form of the IR. Stable: fixed field order, numbers with up to 6 significant digits
// (so tests do not depend on the last bits), default-valued fields omitted where noted, every
// entity with the file:line:col it came from. Indentation shows nesting.
#include "formats/common/ir_printer.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace glint::formats {

namespace {

using namespace glint::scene;

std::string num(double v) {
    if (v == 0) return "0";  // no "-0"
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}
std::string vec(const Vec3& v) { return "<" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ">"; }

std::string contained_by(const scene::Container& c) {
    return c.sphere ? " contained_by sphere " + vec(c.center) + " " + num(c.radius)
                    : " contained_by box " + vec(c.corner1) + " " + vec(c.corner2);
}
std::string rgb(const Color& c) { return "rgb <" + num(c.r) + ", " + num(c.g) + ", " + num(c.b) + ">"; }
std::string rgbft(const ColorFT& c) {
    if (c.filter == 0 && c.transmit == 0) return rgb(c.rgb);
    return "rgbft <" + num(c.rgb.r) + ", " + num(c.rgb.g) + ", " + num(c.rgb.b) + ", " +
           num(c.filter) + ", " + num(c.transmit) + ">";
}
std::string where(const FileLoc& l) { return l.valid() ? "  @" + l.to_string() : ""; }

std::string matrix(const Transform& t) {
    if (t.is_identity()) return "identity";
    const Matrix4& m = t.matrix();
    std::string s = "matrix [";
    for (int r = 0; r < 3; ++r) {
        if (r) s += "; ";
        for (int c = 0; c < 4; ++c) s += (c ? " " : "") + num(m.m[r][c]);
    }
    return s + "]";
}

class Printer {
public:
    std::ostringstream out;

    void line(int depth, const std::string& s) { out << std::string(depth * 2, ' ') << s << '\n'; }

    void pigment(int d, const std::string& label, const Pigment& p) {
        switch (p.kind) {
            case PatternKind::Plain:
                line(d, label + " " + rgbft(p.color) + tail(p));
                return;
            case PatternKind::Checker:
                line(d, label + " checker" + tail(p));
                for (const auto& e : p.entries) pigment(d + 1, "entry", e);
                return;
            case PatternKind::Gradient:
                line(d, label + " gradient " + vec(p.params.vector) + tail(p));
                break;
            case PatternKind::ImageMap: {
                const ImageMap& im = p.params.image;
                line(d, label + " image_map " + im.type + " \"" + im.file + "\" -> \"" +
                            im.resolved_path + "\" map_type " + std::to_string(im.map_type) +
                            (im.once ? " once" : "") + " interpolate " +
                            std::to_string(im.interpolate) + " filter_all " + num(im.filter_all) +
                            " transmit_all " + num(im.transmit_all) +
                            (im.gamma != 0 ? " gamma " + num(im.gamma) : "") + tail(p));
                for (const ImageMap::PaletteEdit& e : im.palette_edits)
                    if (e.index >= 0)
                        line(d + 1, std::string(e.filter ? "filter " : "transmit ") +
                                        std::to_string(e.index) + ", " + num(e.value));
                break;
            }
            default:
                line(d, label + " " + pattern_name(p.kind) + tail(p));
                for (const auto& e : p.entries) pigment(d + 1, "entry", e);
                break;
        }
        params(d + 1, p.params);
        for (const auto& e : p.pigment_map)
            for (const auto& q : e.pigment) pigment(d + 1, "[" + num(e.value) + "]", q);
        if (!p.color_map.empty()) {
            line(d + 1, "color_map");
            for (const auto& e : p.color_map) line(d + 2, "[" + num(e.value) + " " + rgbft(e.color) + "]");
        }
    }

    void normal(int d, const std::string& label, const Normal& n) {
        std::string s = label + " " + pattern_name(n.kind);
        if (n.kind == PatternKind::Gradient) s += " " + vec(n.params.vector);
        s += " amount " + num(n.amount);
        if (n.accuracy != 0.02) s += " accuracy " + num(n.accuracy);
        if (n.uv_mapping) s += " uv_mapping";
        if (!n.transform.is_identity()) s += " transform " + matrix(n.transform);
        if (n.kind == PatternKind::ImageMap) s += " bump_map \"" + n.params.image.file + "\"";
        line(d, s);
        params(d + 1, n.params);
        for (const auto& e : n.entries) normal(d + 1, "entry", e);
        for (const auto& e : n.normal_map)
            for (const auto& q : e.normal) normal(d + 1, "[" + num(e.value) + "]", q);
        for (const auto& e : n.slope_map)
            line(d + 1, "slope [" + num(e.value) + " <" + num(e.height) + ", " + num(e.slope) + ">]");
    }

    // A texture: plain (pigment, normal, finish, then the layers drawn over it) or patterned.
    void texture_body(int d, const Texture& t) {
        if (t.kind != PatternKind::Plain) {
            std::string s = std::string("texture ") + pattern_name(t.kind);
            if (t.kind == PatternKind::Gradient) s += " " + vec(t.params.vector);
            if (t.kind == PatternKind::ImageMap)  // material_map
                s += " \"" + t.params.image.file + "\" map_type " +
                     std::to_string(t.params.image.map_type) + (t.params.image.once ? " once" : "");
            if (t.uv_mapping) s += " uv_mapping";
            if (!t.transform.is_identity()) s += " transform " + matrix(t.transform);
            line(d, s);
            params(d + 1, t.params);
            for (const auto& e : t.entries) {
                line(d + 1, "entry");
                texture_body(d + 2, e);
            }
            for (const auto& e : t.texture_map)
                for (const auto& q : e.texture) {
                    line(d + 1, "[" + num(e.value) + "]");
                    texture_body(d + 2, q);
                }
            return;
        }
        pigment(d, "pigment", t.pigment);
        if (t.normal.kind != PatternKind::Plain || t.normal.amount != 0) normal(d, "normal", t.normal);
        finish(d, t.finish);
        for (const auto& l : t.layers) {
            line(d, "layer");
            texture_body(d + 1, l);
        }
    }

    static std::string tail(const Pigment& p) {
        std::string s;
        if (p.uv_mapping) s += " uv_mapping";
        if (!p.transform.is_identity()) s += " transform " + matrix(p.transform);
        return s;
    }

    void params(int d, const PatternParams& pp) {
        std::string s;
        if (pp.frequency != 1) s += " frequency " + num(pp.frequency);
        if (pp.phase != 0) s += " phase " + num(pp.phase);
        static const char* kWaves[] = {"ramp", "triangle", "sine", "scallop", "cubic", "poly"};
        if (pp.wave != WaveType::Ramp)
            s += std::string(" wave ") + kWaves[static_cast<int>(pp.wave)] + " " + num(pp.wave_exponent);
        for (const Warp& w : pp.warps) {
            if (w.kind == WarpKind::ClassicTurbulence || w.kind == WarpKind::Turbulence)
                s += std::string(w.kind == WarpKind::Turbulence ? " warp" : "") + " turbulence " +
                     vec(w.turbulence.amount) + " octaves " + std::to_string(w.turbulence.octaves) +
                     " omega " + num(w.turbulence.omega) + " lambda " + num(w.turbulence.lambda);
            else if (w.kind == WarpKind::Transform)
                s += " warp transform " + matrix(w.transform);
            else if (w.kind == WarpKind::Repeat)
                s += " warp repeat " + vec(w.direction) + " offset " + vec(w.offset) + " flip " +
                     vec(w.flip);
            else if (w.kind == WarpKind::BlackHole)
                s += " warp black_hole " + vec(w.center) + " " + num(w.radius) + " strength " +
                     num(w.strength) + " falloff " + num(w.falloff) + (w.inverse ? " inverse" : "");
            else
                s += " warp " + std::to_string(static_cast<int>(w.kind)) + " orientation " +
                     vec(w.orientation) + " dist_exp " + num(w.dist_exp);
        }
        const PatternParams def;
        if (pp.noise_generator != 0) s += " noise_generator " + std::to_string(pp.noise_generator);
        if (pp.agate_turb != def.agate_turb) s += " agate_turb " + num(pp.agate_turb);
        if (!(pp.brick_size == def.brick_size)) s += " brick_size " + vec(pp.brick_size);
        if (pp.mortar != def.mortar) s += " mortar " + num(pp.mortar);
        if (pp.arms != 0) s += " arms " + std::to_string(pp.arms);
        if (pp.control0 != 1 || pp.control1 != 1)
            s += " control " + num(pp.control0) + " " + num(pp.control1);
        if (pp.crackle_metric != 2 || pp.crackle_offset != 0 || pp.crackle_solid ||
            !(pp.crackle_form == def.crackle_form))
            s += " crackle metric " + num(pp.crackle_metric) + " offset " + num(pp.crackle_offset) +
                 (pp.crackle_solid ? " solid" : "") + " form " + vec(pp.crackle_form);
        if (pp.facets_coords != 0 || pp.facets_size != def.facets_size || pp.facets_metric != 2)
            s += " facets coords " + num(pp.facets_coords) + " size " + num(pp.facets_size) +
                 " metric " + num(pp.facets_metric);
        if (pp.iterations != 0)
            s += " fractal iterations " + std::to_string(pp.iterations) + " exponent " +
                 num(pp.fractal_exponent) + " julia <" + num(pp.julia_param.x) + ", " +
                 num(pp.julia_param.y) + "> exterior " + std::to_string(pp.exterior_type) + " " +
                 num(pp.exterior_factor) + " interior " + std::to_string(pp.interior_type) + " " +
                 num(pp.interior_factor);
        if (!s.empty()) line(d, "params" + s);
    }

    void finish(int d, const Finish& f) {
        std::string s = "finish ambient " + rgb(f.ambient) + " diffuse " + num(f.diffuse) +
                        " brilliance " + num(f.brilliance) + " phong " + num(f.phong) +
                        " phong_size " + num(f.phong_size) + " specular " + num(f.specular) +
                        " roughness " + num(f.roughness) + " metallic " + num(f.metallic);
        if (!f.emission.is_black()) s += " emission " + rgb(f.emission);
        if (f.conserve_energy) s += " conserve_energy";
        if (f.crand != 0) s += " crand " + num(f.crand);
        if (f.subsurface) s += " subsurface translucency " + rgb(f.translucency);
        line(d, s);
        const Reflection& r = f.reflection;
        if (!r.min.is_black() || !r.max.is_black() || r.fresnel || r.metallic != 0 ||
            r.exponent != 1 || r.falloff != 1)
            line(d + 1, "reflection min " + rgb(r.min) + " max " + rgb(r.max) + " falloff " +
                            num(r.falloff) + (r.fresnel ? " fresnel" : "") + " metallic " +
                            num(r.metallic) + " exponent " + num(r.exponent));
    }

    void media(int d, const Media& m) {
        line(d, "media method " + std::to_string(m.method) + " intervals " +
                    std::to_string(m.intervals) + " samples " + std::to_string(m.min_samples) +
                    "," + std::to_string(m.max_samples) + " jitter " + num(m.jitter) +
                    " aa_threshold " + num(m.aa_threshold) + " aa_level " +
                    std::to_string(m.aa_level) + " confidence " + num(m.confidence) +
                    " variance " + num(m.variance) + " ratio " + num(m.ratio) +
                    (m.collect ? "" : " collect off") + where(m.loc));
        line(d + 1, "absorption " + rgb(m.absorption) + " emission " + rgb(m.emission) +
                        " scattering " + std::to_string(static_cast<int>(m.type)) + " " +
                        rgb(m.scattering) + " eccentricity " + num(m.eccentricity) +
                        " extinction " + num(m.extinction));
        for (const Pigment& dn : m.density) pigment(d + 1, "density", dn);
    }

    void material(int i, const Material& m) {
        line(0, "material " + std::to_string(i) + where(m.loc));
        texture_body(1, m.texture);
        for (const Texture& t : m.interior_texture) {
            line(1, "interior_texture");
            texture_body(2, t);
        }
        const Interior& in = m.interior;
        Interior def;
        if (in.ior != def.ior || in.dispersion != def.dispersion || in.caustics != def.caustics ||
            in.fade_distance != def.fade_distance || in.fade_power != def.fade_power ||
            !(in.fade_color == def.fade_color) || in.old_refraction != def.old_refraction)
            line(1, "interior ior " + num(in.ior) + " dispersion " + num(in.dispersion) +
                        " caustics " + num(in.caustics) + " fade_distance " + num(in.fade_distance) +
                        " fade_power " + num(in.fade_power) + " fade_color " + rgb(in.fade_color) +
                        (in.old_refraction != 1 ? " refraction " + num(in.old_refraction) : ""));
        for (const Media& md : in.media) media(1, md);
        if (!m.pbr.derived) {
            const Pbr& p = m.pbr;
            line(1, "pbr base " + rgb(p.base_color) + " metallic " + num(p.metallic) + " roughness " +
                        num(p.roughness) + " specular " + num(p.specular) + " ior " + num(p.ior) +
                        " transmission " + num(p.transmission) + " alpha " + num(p.alpha));
        }
    }

    static std::string shape(const Shape& s) {
        return std::visit(
            [](const auto& v) -> std::string {
                using T = std::decay_t<decltype(v)>;
                if constexpr (std::is_same_v<T, Sphere>) return "sphere " + vec(v.center) + " " + num(v.radius);
                else if constexpr (std::is_same_v<T, Plane>) return "plane " + vec(v.normal) + " " + num(v.distance);
                else if constexpr (std::is_same_v<T, Box>) return "box " + vec(v.corner1) + " " + vec(v.corner2);
                else if constexpr (std::is_same_v<T, Cylinder>)
                    return "cylinder " + vec(v.base) + " " + vec(v.cap) + " " + num(v.radius) + (v.open ? " open" : "");
                else if constexpr (std::is_same_v<T, Cone>)
                    return "cone " + vec(v.base) + " " + num(v.base_radius) + " " + vec(v.cap) + " " +
                           num(v.cap_radius) + (v.open ? " open" : "");
                else if constexpr (std::is_same_v<T, Disc>)
                    return "disc " + vec(v.center) + " " + vec(v.normal) + " " + num(v.radius) + " " + num(v.hole_radius);
                else if constexpr (std::is_same_v<T, Torus>)
                    return "torus " + num(v.major) + " " + num(v.minor) + (v.sturm ? " sturm" : "");
                else if constexpr (std::is_same_v<T, Triangle>)
                    return "triangle " + vec(v.p[0]) + " " + vec(v.p[1]) + " " + vec(v.p[2]);
                else if constexpr (std::is_same_v<T, SmoothTriangle>)
                    return "smooth_triangle " + vec(v.p[0]) + " " + vec(v.n[0]) + " " + vec(v.p[1]) + " " +
                           vec(v.n[1]) + " " + vec(v.p[2]) + " " + vec(v.n[2]);
                else if constexpr (std::is_same_v<T, MeshRef>) return "mesh_ref " + std::to_string(v.mesh);
                else if constexpr (std::is_same_v<T, Quadric>)
                    return "quadric " + vec(v.square) + " " + vec(v.mixed) + " " + vec(v.linear) + " " +
                           num(v.constant);
                else if constexpr (std::is_same_v<T, Polygon>) {
                    std::string r = "polygon " + std::to_string(v.points.size());
                    for (const Vec3& p : v.points) r += " " + vec(p);
                    return r;
                } else if constexpr (std::is_same_v<T, Prism> || std::is_same_v<T, Lathe> ||
                                     std::is_same_v<T, Sor>) {
                    static const char* kSplines[] = {"linear_spline", "quadratic_spline",
                                                     "cubic_spline", "bezier_spline"};
                    std::string r;
                    if constexpr (std::is_same_v<T, Prism>)
                        r = std::string("prism ") + kSplines[static_cast<int>(v.spline)] +
                            (v.conic ? " conic_sweep " : " linear_sweep ") + num(v.height1) + " " +
                            num(v.height2);
                    else if constexpr (std::is_same_v<T, Lathe>)
                        r = std::string("lathe ") + kSplines[static_cast<int>(v.spline)];
                    else
                        r = "sor";
                    r += " " + std::to_string(v.points.size());
                    for (const Vec2& p : v.points) r += " <" + num(p.x) + ", " + num(p.y) + ">";
                    if constexpr (!std::is_same_v<T, Lathe>)
                        if (v.open) r += " open";
                    if (v.sturm) r += " sturm";
                    return r;
                } else if constexpr (std::is_same_v<T, Superellipsoid>)
                    return "superellipsoid " + num(v.e) + " " + num(v.n);
                else if constexpr (std::is_same_v<T, Blob>) {
                    std::string r = "blob threshold " + num(v.threshold);
                    for (const BlobComponent& c : v.components) {
                        r += c.cylinder ? " (cylinder " + vec(c.center) + " " + vec(c.apex)
                                        : " (sphere " + vec(c.center);
                        r += " " + num(c.radius) + " strength " + num(c.strength);
                        if (!c.transform.is_identity()) r += " transform " + matrix(c.transform);
                        if (c.material >= 0) r += " material " + std::to_string(c.material);
                        r += ")";
                    }
                    return r;
                } else if constexpr (std::is_same_v<T, HeightField>)
                    return (v.heights.empty()
                                ? std::string("height_field ") + (v.pot ? "pot " : "") + "\"" +
                                      v.file + "\""
                                : "height_field function " + std::to_string(v.grid_w) + " " +
                                      std::to_string(v.grid_h)) +
                           " water_level " + num(v.water_level) + (v.smooth ? " smooth" : "");
                else if constexpr (std::is_same_v<T, Poly>) {
                    std::string r = "poly " + std::to_string(v.order);
                    for (double c : v.coefficients) r += " " + num(c);
                    return r + (v.sturm ? " sturm" : "");
                }
                else if constexpr (std::is_same_v<T, Text>)
                    return "text ttf \"" + v.file + "\" \"" + v.text + "\" " + num(v.thickness) + " " +
                           vec(v.offset);
                else if constexpr (std::is_same_v<T, JuliaFractal>) {
                    static const char* kFns[] = {
                        "exp",   "ln",   "sin",   "asin", "cos",   "acos",
                        "tan",   "atan", "sinh",  "asinh", "cosh", "acosh",
                        "tanh",  "atanh", "pwr",  "sqr",  "cube",  "reciprocal"};
                    auto v4 = [&](const double* a) {
                        return "<" + num(a[0]) + ", " + num(a[1]) + ", " + num(a[2]) + ", " +
                               num(a[3]) + ">";
                    };
                    std::string r = "julia_fractal " + v4(v.c) +
                                    (v.algebra == JuliaAlgebra::Quaternion ? " quaternion "
                                                                           : " hypercomplex ") +
                                    kFns[static_cast<int>(v.function)];
                    if (v.function == JuliaFunction::Pwr)
                        r += " (" + num(v.exponent.x) + ", " + num(v.exponent.y) + ")";
                    return r + " max_iteration " + std::to_string(v.max_iteration) +
                           " precision " + num(v.precision) + " slice " + v4(v.slice) + " " +
                           num(v.slice_distance);
                } else if constexpr (std::is_same_v<T, BicubicPatch>) {
                    std::string r = "bicubic_patch type " + std::to_string(v.type) +
                                    " flatness " + num(v.flatness) + " u_steps " +
                                    std::to_string(v.u_steps) + " v_steps " +
                                    std::to_string(v.v_steps);
                    for (const auto& row : v.points)
                        for (const Vec3& p : row) r += " " + vec(p);
                    return r;
                } else if constexpr (std::is_same_v<T, Isosurface>) {
                    std::string r = "isosurface function " + std::to_string(v.function) +
                                     contained_by(v.container);
                    r += " threshold " + num(v.threshold) + " accuracy " + num(v.accuracy) +
                         " max_gradient " + num(v.max_gradient) + " max_trace " +
                         std::to_string(v.max_trace);
                    if (v.evaluate)
                        r += " evaluate " + num(v.eval[0]) + " " + num(v.eval[1]) + " " +
                             num(v.eval[2]);
                    return r + (v.open ? " open" : "");
                } else if constexpr (std::is_same_v<T, SphereSweep>) {
                    static const char* kSplines[] = {"linear_spline", "b_spline", "cubic_spline"};
                    std::string r = std::string("sphere_sweep ") +
                                    kSplines[static_cast<int>(v.spline)] + " " +
                                    std::to_string(v.spheres.size());
                    for (const Sphere& c : v.spheres) r += " " + vec(c.center) + " " + num(c.radius);
                    return r + " tolerance " + num(v.tolerance);
                } else if constexpr (std::is_same_v<T, Ovus>) {
                    return "ovus " + num(v.bottom_radius) + " " + num(v.top_radius);
                } else if constexpr (std::is_same_v<T, Parametric>) {
                    std::string r = "parametric functions " + std::to_string(v.function[0]) + " " +
                                    std::to_string(v.function[1]) + " " +
                                    std::to_string(v.function[2]) + " uv " + num(v.uv_min.x) +
                                    " " + num(v.uv_min.y) + " " + num(v.uv_max.x) + " " +
                                    num(v.uv_max.y) +
                                    contained_by(v.container);
                    r += " accuracy " + num(v.accuracy) + " max_gradient " + num(v.max_gradient);
                    if (v.precompute[0] || v.precompute[1] || v.precompute[2]) {
                        r += " precompute " + std::to_string(v.precompute_depth);
                        for (int i = 0; i < 3; ++i)
                            if (v.precompute[i]) r += std::string(" ") + "xyz"[i];
                    }
                    return r;
                } else {
                    static const char* kOps[] = {"union", "merge", "intersection", "difference"};
                    return std::string(kOps[static_cast<int>(v.op)]) + " (" +
                           std::to_string(v.children.size()) + " children)";
                }
            },
            s);
    }

    void object(int d, const Object& o, const std::string& label) {
        std::string s = label + shape(o.shape) + " material " + std::to_string(o.material);
        if (o.inverse) s += " inverse";
        if (o.hollow) s += " hollow";
        if (o.no_shadow) s += " no_shadow";
        if (o.no_image) s += " no_image";
        if (o.no_reflection) s += " no_reflection";
        if (o.double_illuminate) s += " double_illuminate";
        if (o.no_radiosity) s += " no_radiosity";
        if (o.radiosity_importance >= 0) s += " radiosity_importance " + num(o.radiosity_importance);
        if (o.photon_target > 0) s += " photons_target " + num(o.photon_target);
        if (o.photon_refraction >= 0) s += " photons_refraction " + std::to_string(o.photon_refraction);
        if (o.photon_reflection >= 0) s += " photons_reflection " + std::to_string(o.photon_reflection);
        if (o.photon_pass_through) s += " photons_pass_through";
        if (!o.photon_collect) s += " photons_collect off";
        if (!o.name.empty()) s += " name " + o.name;
        line(d, s + where(o.loc));
        if (!o.transform.is_identity()) line(d + 1, "transform " + matrix(o.transform));
        for (const Matrix4& m : o.motion) line(d + 1, "motion " + matrix(Transform(m, m)));
        for (const auto& b : o.bounded_by) object(d + 1, b, "bounded_by ");
        for (const auto& c : o.clipped_by) object(d + 1, c, "clipped_by ");
        if (auto csg = std::get_if<Csg>(&o.shape))
            for (const auto& c : csg->children) object(d + 1, c, "");
    }

    void light(int i, const Light& l) {
        static const char* kKinds[] = {"point", "spotlight", "cylinder"};
        std::string s = "light " + std::to_string(i) + " " + kKinds[static_cast<int>(l.kind)] +
                        " location " + vec(l.location) + " color " + rgb(l.color);
        if (l.kind != LightKind::Point || l.parallel)
            s += " point_at " + vec(l.point_at);
        if (l.kind != LightKind::Point)
            s += " radius " + num(l.radius) + " falloff " + num(l.falloff) + " tightness " + num(l.tightness);
        if (l.parallel) s += " parallel";
        if (l.shadowless) s += " shadowless";
        if (!l.media_interaction) s += " media_interaction off";
        if (l.media_attenuation) s += " media_attenuation on";
        if (l.photon_refraction >= 0) s += " photons_refraction " + std::to_string(l.photon_refraction);
        if (l.photon_reflection >= 0) s += " photons_reflection " + std::to_string(l.photon_reflection);
        if (l.photon_area_light) s += " photons_area_light";
        if (l.fade_distance != 0 || l.fade_power != 0)
            s += " fade_distance " + num(l.fade_distance) + " fade_power " + num(l.fade_power);
        line(0, s + where(l.loc));
        if (l.area) {
            const AreaLight& a = *l.area;
            line(1, "area_light " + vec(a.axis1) + " " + vec(a.axis2) + " " + std::to_string(a.size1) +
                        " " + std::to_string(a.size2) + " adaptive " + std::to_string(a.adaptive) +
                        (a.jitter ? " jitter" : "") + (a.circular ? " circular" : "") +
                        (a.orient ? " orient" : ""));
        }
        if (l.blender) {
            const BlenderLight& b = *l.blender;
            static const char* kTypes[] = {"point", "spot", "sun", "area"};
            std::string t = std::string("blender_light ") + kTypes[static_cast<int>(b.type)] +
                            " power " + num(b.power);
            if (b.type != BlenderLightType::Point) t += " direction " + vec(b.direction);
            if (b.type == BlenderLightType::Point || b.type == BlenderLightType::Spot)
                t += " radius " + num(b.radius);
            if (b.type == BlenderLightType::Spot)
                t += " spot_size " + num(b.spot_size) + " spot_blend " + num(b.spot_blend);
            if (b.type == BlenderLightType::Sun) t += " angle " + num(b.angle);
            if (b.type == BlenderLightType::Area)
                t += std::string(b.ellipse ? " ellipse" : " rectangle") + " size " + num(b.size_x) +
                     " " + num(b.size_y) + " axis_x " + vec(b.axis_x) + " axis_y " + vec(b.axis_y) +
                     " spread " + num(b.spread);
            if (b.visible_camera) t += " visible_camera";
            line(1, t);
        }
    }
};

}  // namespace

std::string print_ir(const scene::Scene& s) {
    Printer p;
    p.line(0, "version " + num(s.version));
    for (const auto& f : s.source_files) p.line(0, "source \"" + f + "\"");
    const GlobalSettings& g = s.global;
    p.line(0, "global_settings assumed_gamma " +
                  (g.assumed_gamma ? num(*g.assumed_gamma) : std::string("default")) +
                  " ambient_light " + rgb(g.ambient_light) + " max_trace_level " +
                  std::to_string(g.max_trace_level) + " adc_bailout " + num(g.adc_bailout) +
                  " noise_generator " + std::to_string(g.noise_generator) +
                  (g.mm_per_unit != 10 ? " mm_per_unit " + num(g.mm_per_unit) : std::string()) +
                  (g.subsurface ? " subsurface samples " +
                                      std::to_string(g.subsurface_samples_diffuse) + ", " +
                                      std::to_string(g.subsurface_samples_single)
                                : std::string()));
    if (const auto& r = g.radiosity) {
        p.line(1, "radiosity brightness " + num(r->brightness) + " count " +
                      std::to_string(r->count) + ", " + std::to_string(r->direction_pool) +
                      " error_bound " + num(r->error_bound) + " gray_threshold " +
                      num(r->gray_threshold) + " low_error_factor " + num(r->low_error_factor) +
                      " minimum_reuse " + num(r->minimum_reuse) + " maximum_reuse " +
                      num(r->maximum_reuse) + " nearest_count " +
                      std::to_string(r->nearest_count) + ", " +
                      std::to_string(r->nearest_count_pretrace) + " recursion_limit " +
                      std::to_string(r->recursion_limit) + " max_sample " + num(r->max_sample) +
                      " adc_bailout " + num(r->adc_bailout) + " pretrace " +
                      num(r->pretrace_start) + " " + num(r->pretrace_end) +
                      (r->normal ? " normal" : "") + (r->media ? " media" : "") +
                      (r->subsurface ? " subsurface" : "") +
                      (r->always_sample ? " always_sample" : "") + " default_importance " +
                      num(g.radiosity_importance));
    }
    if (const auto& ph = g.photons) {
        p.line(1, "photons " + (ph->count > 0 ? "count " + std::to_string(ph->count)
                                              : "spacing " + num(ph->spacing)) +
                      " gather " + std::to_string(ph->gather_min) + ", " +
                      std::to_string(ph->gather_max) + " radius " + num(ph->radius) + ", " +
                      num(ph->radius_multiplier) + ", " + num(ph->media_radius) + ", " +
                      num(ph->media_radius_multiplier) + " jitter " + num(ph->jitter) +
                      " autostop " + num(ph->autostop) + " expand_thresholds " +
                      num(ph->expand_tolerance) + ", " + std::to_string(ph->expand_min) +
                      " max_trace_level " + std::to_string(ph->max_trace_level) +
                      " adc_bailout " + num(ph->adc_bailout) + " media " +
                      std::to_string(ph->media_steps) + ", " + num(ph->media_factor));
    }
    const Camera& c = s.camera;
    p.line(0, std::string("camera ") +
                  camera_kind_name(c.kind) +
                  where(c.loc));
    p.line(1, "location " + vec(c.location));
    p.line(1, "direction " + vec(c.direction));
    p.line(1, "right " + vec(c.right));
    p.line(1, "up " + vec(c.up));
    p.line(1, "sky " + vec(c.sky) + " angle " + num(c.angle));
    if (c.kind == CameraKind::Mesh) {
        const MeshCamera& m = c.mesh_camera;
        p.line(1, "mesh_camera rays " + std::to_string(m.rays_per_pixel) + " distribution " +
                      std::to_string(m.distribution) + " max_distance " + num(m.max_distance) +
                      (m.smooth ? " smooth" : ""));
        for (const MeshCameraMesh& mm : m.meshes)
            p.line(2, "mesh " + std::to_string(mm.mesh));
    }
    if (c.kind == CameraKind::BlenderPanorama) {
        const Panorama& q = c.panorama;
        static const char* const kTypes[] = {"equirectangular", "fisheye_equidistant",
                                             "fisheye_equisolid", "mirror_ball",
                                             "fisheye_lens_polynomial", "equiangular_cubemap_face"};
        p.line(1, std::string("panorama ") + kTypes[static_cast<int>(q.type)] + " fov " +
                      num(q.fov) + " lens " + num(q.lens) + " sensor " + num(q.sensor_width) +
                      " " + num(q.sensor_height) + " latitude " + num(q.latitude_min) + " " +
                      num(q.latitude_max) + " longitude " + num(q.longitude_min) + " " +
                      num(q.longitude_max) + " k " + num(q.k[0]) + " " + num(q.k[1]) + " " +
                      num(q.k[2]) + " " + num(q.k[3]) + " " + num(q.k[4]));
    }
    if (c.focal_blur.active()) {
        const FocalBlur& f = c.focal_blur;
        p.line(1, "focal_blur aperture " + num(f.aperture) + " focal_distance " +
                      num(f.focal_distance) + " samples " + std::to_string(f.samples_min) +
                      ", " + std::to_string(f.samples) + " confidence " + num(f.confidence) +
                      " variance " + num(f.variance));
    }
    for (const Matrix4& m : c.motion) p.line(1, "motion " + matrix(Transform(m, m)));
    p.line(0, "background " + rgbft(s.background));
    if (s.sky_sphere) {
        p.line(0, "sky_sphere emission " + rgb(s.sky_sphere->emission) + " transform " +
                      matrix(s.sky_sphere->transform) + where(s.sky_sphere->loc));
        for (const auto& pg : s.sky_sphere->pigments) p.pigment(1, "pigment", pg);
    }
    for (const Media& m : s.media) p.media(0, m);
    for (const Fog& f : s.fogs) {
        std::string l = "fog type " + std::to_string(static_cast<int>(f.type)) + " distance " +
                        num(f.distance) + " color " + rgbft(f.color);
        if (f.type == FogType::Ground)
            l += " offset " + num(f.offset) + " alt " + num(f.alt) + " up " + vec(f.up);
        if (f.turbulent)
            l += " turbulence " + vec(f.turbulence) + " octaves " + std::to_string(f.octaves) +
                 " omega " + num(f.omega) + " lambda " + num(f.lambda) + " turb_depth " +
                 num(f.turb_depth);
        p.line(0, l + where(f.loc));
    }
    for (const Rainbow& r : s.rainbows) {
        p.line(0, "rainbow angle " + num(r.angle) + " width " + num(r.width) + " distance " +
                      num(r.distance) + " jitter " + num(r.jitter) + " direction " +
                      vec(r.antisolar) + " up " + vec(r.up) + " arc_angle " + num(r.arc_angle) +
                      " falloff_angle " + num(r.falloff_angle) + " color_map " +
                      std::to_string(r.color_map.size()) + where(r.loc));
    }
    for (size_t i = 0; i < s.lights.size(); ++i) p.light(static_cast<int>(i), s.lights[i]);
    for (size_t i = 0; i < s.materials.size(); ++i) p.material(static_cast<int>(i), s.materials[i]);
    for (size_t i = 0; i < s.meshes.size(); ++i) {
        const Mesh& m = s.meshes[i];
        p.line(0, "mesh " + std::to_string(i) + " positions " + std::to_string(m.positions.size()) +
                      " normals " + std::to_string(m.normals.size()) + " uvs " +
                      std::to_string(m.uvs.size()) + " faces " + std::to_string(m.faces.size()) +
                      (m.has_inside_vector ? " inside_vector " + vec(m.inside_vector) : "") +
                      where(m.loc));
    }
    for (size_t i = 0; i < s.objects.size(); ++i)
        p.object(0, s.objects[i], "object " + std::to_string(i) + " ");
    return p.out.str();
}

}  // namespace glint::formats
