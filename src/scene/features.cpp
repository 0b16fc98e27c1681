#include "scene/features.h"

namespace glint::scene {
namespace {

class Analyzer {
public:
    Analyzer(const Scene& s, Features* f) : scene_(s), f_(*f) {}

    void run() {
        f_.lights = !scene_.lights.empty();
        for (const Light& l : scene_.lights) {
            if (!l.shadowless) f_.shadows = true;
            if (l.kind == LightKind::Spot) f_.spot_lights = true;
            if (l.parallel) f_.parallel_lights = true;
            if (l.area) f_.area_lights = true;
            if (l.fade_distance > 0 && l.fade_power > 0) f_.light_fading = true;
        }
        if (scene_.sky_sphere) {
            f_.sky_sphere = true;
            for (const Pigment& p : scene_.sky_sphere->pigments) pigment(p);
        }
        for (const Media& m : scene_.media) media(m);
        // `function { pigment { ... } }` and `function { pattern { ... } }` (their images).
        for (const Function& f : scene_.functions)
            for (const Pigment& p : f.pigment) pigment(p);
        normal(scene_.camera.normal);
        f_.radiosity = scene_.global.radiosity.has_value();
        f_.photons = scene_.global.photons.has_value();
        std::vector<bool> used(scene_.materials.size(), false);
        for (const Object& o : scene_.objects) object(o, &used);
        for (size_t i = 0; i < used.size(); ++i)
            if (used[i]) material(scene_.materials[i]);
    }

private:
    void object(const Object& o, std::vector<bool>* used) {
        f_.shapes[o.shape.index()] = true;
        if (o.material >= 0) (*used)[o.material] = true;
        if (!o.bounded_by.empty() || !o.clipped_by.empty()) f_.clipping = true;
        if (const auto* csg = std::get_if<Csg>(&o.shape)) {
            f_.csg = true;
            for (const Object& c : csg->children) object(c, used);
        }
        if (const auto* m = std::get_if<MeshRef>(&o.shape)) {
            for (const MeshFace& face : scene_.meshes[m->mesh].faces)
                if (face.material >= 0) (*used)[face.material] = true;
        }
        if (const auto* b = std::get_if<Blob>(&o.shape)) {
            for (const BlobComponent& c : b->components)
                if (c.material >= 0) (*used)[c.material] = true;
        }
        for (const Object& c : o.clipped_by) object(c, used);
    }

    void media(const Media& m) {
        f_.media = true;
        for (const Pigment& d : m.density) pigment(d);
    }

    void material(const Material& m) {
        if (m.interior.fade_distance > 0) f_.interior_fading = true;
        for (const Media& md : m.interior.media) media(md);
        bool transparent = texture(m.texture);
        for (const Texture& t : m.interior_texture) transparent |= texture(t);
        if (transparent) {
            f_.transparency = true;
            if (m.interior.ior != 1.0) f_.refraction = true;
        }
    }

    // Returns whether the texture can let light through.
    bool texture(const Texture& t) {
        if (t.kind != PatternKind::Plain) {
            f_.texture_maps = true;
            if (t.kind == PatternKind::ImageMap) f_.image_textures = true;  // material_map
            pattern_kind(t.kind);
            bool transparent = false;
            for (const TextureMapEntry& e : t.texture_map) transparent |= texture(e.texture[0]);
            for (const Texture& e : t.entries) transparent |= texture(e);
            return transparent;
        }
        if (!t.layers.empty()) f_.texture_maps = true;
        bool transparent = layer(t);
        for (const Texture& l : t.layers) transparent = layer(l) && transparent;
        return transparent;
    }

    bool layer(const Texture& t) {
        const Finish& f = t.finish;
        if (!f.reflection.min.is_black() || !f.reflection.max.is_black()) f_.reflection = true;
        if (f.phong > 0 || f.specular > 0) f_.highlights = true;
        normal(t.normal);
        return pigment(t.pigment);
    }

    void normal(const Normal& n) {
        if (n.kind == PatternKind::Plain) return;
        f_.normals = true;
        if (n.kind == PatternKind::ImageMap) f_.bump_maps = f_.image_textures = true;
        if (n.uv_mapping) f_.uv_mapping = true;
        pattern_kind(n.kind);
        for (const NormalMapEntry& e : n.normal_map) normal(e.normal[0]);
        for (const Normal& e : n.entries) normal(e);
    }

    void pattern_kind(PatternKind k) {
        if (k == PatternKind::ImagePattern) f_.image_textures = true;
        if (k == PatternKind::Checker) f_.checker = true;
        else if (k == PatternKind::Gradient) f_.gradient = true;
        else if (k != PatternKind::Plain && k != PatternKind::ImageMap) f_.patterns = true;
    }

    // Returns whether the pigment can be anything but opaque.
    bool pigment(const Pigment& p) {
        bool transparent = !p.color.opaque();
        if (p.uv_mapping) f_.uv_mapping = true;
        switch (p.kind) {
            case PatternKind::Checker: f_.checker = true; break;
            case PatternKind::Gradient: f_.gradient = true; break;
            case PatternKind::ImageMap:
                f_.image_textures = true;
                // Images may carry alpha; filter/transmit_all also make them transparent.
                transparent = true;
                break;
            case PatternKind::Plain: break;
            default: pattern_kind(p.kind); break;
        }
        for (const PigmentMapEntry& e : p.pigment_map)
            for (const Pigment& q : e.pigment) transparent |= pigment(q);
        for (const ColorMapEntry& e : p.color_map)
            if (!e.color.opaque()) transparent = true;
        for (const Pigment& e : p.entries) transparent |= pigment(e);
        return transparent;
    }

    const Scene& scene_;
    Features& f_;
};

}  // namespace

const Normal* find_bump_map(const Texture& t) {
    auto in_normal = [](auto& self, const Normal& n) -> const Normal* {
        if (n.kind == PatternKind::ImageMap) return &n;
        for (const NormalMapEntry& e : n.normal_map)
            if (const Normal* r = self(self, e.normal[0])) return r;
        for (const Normal& e : n.entries)
            if (const Normal* r = self(self, e)) return r;
        return nullptr;
    };
    if (const Normal* r = in_normal(in_normal, t.normal)) return r;
    for (const Texture& l : t.layers)
        if (const Normal* r = find_bump_map(l)) return r;
    for (const TextureMapEntry& e : t.texture_map)
        if (const Normal* r = find_bump_map(e.texture[0])) return r;
    for (const Texture& e : t.entries)
        if (const Normal* r = find_bump_map(e)) return r;
    return nullptr;
}

Features analyze(const Scene& scene) {
    Features f;
    Analyzer(scene, &f).run();
    return f;
}

std::vector<std::string> Features::used() const {
    std::vector<std::string> out;
    static const Shape kSamples[] = {Sphere{}, Plane{}, Box{}, Cylinder{}, Cone{}, Disc{},
                                     Torus{}, Triangle{}, SmoothTriangle{}, MeshRef{}, Csg{},
                                     Quadric{}, Polygon{}, Prism{}, Lathe{}, Sor{},
                                     Superellipsoid{}, Blob{}, HeightField{}, Poly{}, Text{},
                                     JuliaFractal{}, BicubicPatch{}, Isosurface{},
                                     SphereSweep{}, Ovus{}, Parametric{}};
    static_assert(std::size(kSamples) == std::variant_size_v<Shape>);
    for (size_t i = 0; i < shapes.size(); ++i)
        if (shapes[i] && i != kSamples[10].index()) out.push_back(shape_name(kSamples[i]));
    auto add = [&](bool on, const char* name) {
        if (on) out.push_back(name);
    };
    add(csg, "csg");
    add(clipping, "clipped_by/bounded_by");
    add(lights, "lights");
    add(shadows, "shadows");
    add(spot_lights, "spot lights");
    add(parallel_lights, "parallel lights");
    add(area_lights, "area lights");
    add(light_fading, "light fading");
    add(reflection, "reflection");
    add(refraction, "refraction");
    add(transparency, "transparency");
    add(interior_fading, "interior fade");
    add(highlights, "phong/specular highlights");
    add(image_textures, "image textures");
    add(uv_mapping, "uv_mapping");
    add(checker, "checker");
    add(gradient, "gradient");
    add(normals, "normal perturbation");
    add(bump_maps, "bump_map");
    add(patterns, "procedural patterns");
    add(texture_maps, "texture maps/layered textures");
    add(sky_sphere, "sky_sphere");
    add(media, "media");
    add(radiosity, "radiosity");
    add(photons, "photons");
    return out;
}

std::vector<std::string> Features::skipped() const {
    std::vector<std::string> out;
    if (!image_textures) out.push_back("texture system (no image textures)");
    if (!lights) out.push_back("light sampling (no lights)");
    else if (!shadows) out.push_back("shadow rays (all lights shadowless)");
    if (!secondary_rays()) out.push_back("secondary rays (nothing reflects or refracts)");
    if (!highlights) out.push_back("highlight evaluation (no phong/specular)");
    if (!radiosity) out.push_back("radiosity pretrace and cache (no radiosity block)");
    return out;
}

}  // namespace glint::scene
