// Objects (reference manual 3.4 "Objects"; parse.cpp in POV-Ray): finite and infinite shapes,
// CSG, meshes, light sources and the object modifiers. Transforms after a texture move the
// texture with the object, as POV-Ray does.
#include <cstdio>
#include <cmath>

#include "formats/pov/object_bodies.h"

namespace glint::pov {

namespace {

void transform_light(scene::Light& l, const Transform& t) {
    l.location = t.point(l.location);
    l.point_at = t.point(l.point_at);
    if (l.blender) {  // blender_light inside a transformed CSG: its frame moves along
        scene::BlenderLight& b = *l.blender;
        b.direction = normalize(t.vector(b.direction));
        const Vec3 ax = t.vector(b.axis_x * b.size_x), ay = t.vector(b.axis_y * b.size_y);
        b.size_x = length(ax);
        b.size_y = length(ay);
        b.axis_x = ax / b.size_x;
        b.axis_y = ay / b.size_y;
    }
    if (l.area) {
        l.area->axis1 = t.vector(l.area->axis1);
        l.area->axis2 = t.vector(l.area->axis2);
    }
    if (l.projected_through) {  // moves with the light (point.cpp Transform)
        auto o = std::make_shared<scene::Object>(*l.projected_through);
        o->transform = o->transform.then(t);
        for (auto& b : o->bounded_by) b.transform = b.transform.then(t);
        for (auto& c : o->clipped_by) c.transform = c.transform.then(t);
        l.projected_through = std::move(o);
    }
}

// Textures of CSG children are in world space too: they follow every enclosing transform.
void transform_child_textures(PovObject& o, const Transform& t) {
    if (!o.uv_mapping) {  // uv-mapped textures live in uv space (objects.cpp Translate_Object)
        if (o.texture) transform_texture(*o.texture, t);
        if (o.interior_texture) transform_texture(*o.interior_texture, t);
    }
    if (o.interior) transform_interior(*o.interior, t);
    o.children.transform_textures(t);
}

bool has_component_materials(const PovObject& o) {
    if (const auto* blob = std::get_if<scene::Blob>(&o.obj.shape))
        for (const scene::BlobComponent& c : blob->components)
            if (c.material >= 0) return true;
    for (const PovObject& c : o.children.given())
        if (has_component_materials(c)) return true;
    return false;
}

// Blob::Transform moves the components' textures with the blob. A declared blob's copies
// share their component materials, so a transformed copy gets transformed copies of them.
void transform_component_materials(scene::Scene& scene, PovObject& o, const Transform& t) {
    if (auto* blob = std::get_if<scene::Blob>(&o.obj.shape)) {
        for (scene::BlobComponent& c : blob->components) {
            if (c.material < 0) continue;
            scene::Material m = scene.materials[static_cast<size_t>(c.material)];
            transform_texture(m.texture, t);
            scene.materials.push_back(std::move(m));
            c.material = static_cast<int>(scene.materials.size()) - 1;
        }
    }
    for (const PovObject& c : o.children.given())
        if (has_component_materials(c)) {
            for (PovObject& e : o.children.edit()) transform_component_materials(scene, e, t);
            return;
        }
}

}  // namespace

std::vector<PovObject>& PovChildren::edit() {
    if (!items_)
        items_ = std::make_shared<std::vector<PovObject>>();
    else if (items_.use_count() > 1)
        items_ = std::make_shared<std::vector<PovObject>>(*items_);
    for (const Transform& t : owed_)
        for (PovObject& c : *items_) transform_child_textures(c, t);
    owed_.clear();
    return *items_;
}

void PovChildren::push_back(PovObject child) { edit().push_back(std::move(child)); }

const PovObject& with_owed_transforms(const PovChildren& parent, const PovObject& c,
                                      std::optional<PovObject>* storage) {
    if (parent.owed().empty()) return c;
    storage->emplace(c);
    for (const Transform& t : parent.owed()) transform_child_textures(**storage, t);
    return **storage;
}

// extensions.cpp: after the keyword `blender_light` (at kloc).
scene::Light parse_blender_light(Parser& p, const FileLoc& kloc);

bool Parser::is_object_keyword(const Token& t) const {
    return t.kind == TokKind::Word && !lookup(t.text) && object_body_parser(t.text) != nullptr;
}

bool Parser::own_face_materials(scene::MeshRef& ref) {
    if (ref.mesh < 0 || static_cast<size_t>(ref.mesh) >= scene.meshes.size()) return false;
    auto found = face_material_ids_.find(ref.mesh);
    if (found == face_material_ids_.end()) {
        std::vector<int> ids;
        for (const scene::MeshFace& f : scene.meshes[static_cast<size_t>(ref.mesh)].faces)
            if (f.material >= 0) ids.push_back(f.material);
        std::sort(ids.begin(), ids.end());
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
        found = face_material_ids_.emplace(ref.mesh, std::move(ids)).first;
    }
    if (found->second.empty()) return false;
    if (ref.face_materials.empty())
        for (int id : found->second) ref.face_materials.emplace_back(id, id);
    return true;
}

void Parser::give_faces_interior_texture(scene::MeshRef& ref, const scene::Texture& inside) {
    if (!own_face_materials(ref)) return;
    for (auto& [from, to] : ref.face_materials) {
        scene::Material m = scene.materials[static_cast<size_t>(to)];
        m.interior_texture.assign(1, inside);
        scene.materials.push_back(std::move(m));
        to = static_cast<int>(scene.materials.size()) - 1;
    }
}

void Parser::give_faces_uv_points(scene::MeshRef& ref) {
    if (!own_face_materials(ref)) return;
    for (auto& [from, to] : ref.face_materials) {
        scene::Material m = scene.materials[static_cast<size_t>(to)];
        m.uv_points = true;
        scene.materials.push_back(std::move(m));
        to = static_cast<int>(scene.materials.size()) - 1;
    }
}

void Parser::transform_face_materials(scene::MeshRef& ref, const Transform& t) {
    if (!own_face_materials(ref)) return;
    for (auto& [from, to] : ref.face_materials) {
        scene::Material m = scene.materials[static_cast<size_t>(to)];
        transform_texture(m.texture, t);
        transform_interior(m.interior, t);
        scene.materials.push_back(std::move(m));
        to = static_cast<int>(scene.materials.size()) - 1;
    }
}

void Parser::apply_transform(PovObject& o, const Transform& t) {
    o.obj.transform = o.obj.transform.then(t);
    if (auto* ref = std::get_if<scene::MeshRef>(&o.obj.shape); ref && !o.uv_mapping)
        transform_face_materials(*ref, t);
    transform_component_materials(scene, o, t);
    if (!o.uv_mapping) {  // uv-mapped textures live in uv space (objects.cpp Translate_Object)
        if (o.texture) transform_texture(*o.texture, t);
        if (o.interior_texture) transform_texture(*o.interior_texture, t);
    }
    if (o.interior) transform_interior(*o.interior, t);
    o.children.transform_textures(t);
    for (auto& l : o.lights) transform_light(l, t);
    for (auto& b : o.obj.bounded_by) b.transform = b.transform.then(t);
    for (auto& c : o.obj.clipped_by) c.transform = c.transform.then(t);
}

scene::Object object_without_materials(const PovObject& p) {
    scene::Object o = p.obj;
    if (auto csg = std::get_if<scene::Csg>(&o.shape)) {
        csg->children.clear();
        for (const auto& c : p.children.given())
            csg->children.push_back(object_without_materials(c));
    }
    o.material = -1;
    return o;
}

bool Parser::parse_object(const Token& kw, PovObject& out) {
    if (kw.kind != TokKind::Word) return false;
    if (const Symbol* sym = lookup(kw.text)) {
        // A declared object's name alone is a copy of it, without modifiers (POV-Ray's
        // Parse_Object takes an object identifier as it takes a shape keyword).
        if (!std::holds_alternative<std::shared_ptr<const PovObject>>(sym->value)) return false;
        const FileLoc at = loc();
        PovObject po = *std::get<std::shared_ptr<const PovObject>>(use_symbol(kw).value);
        give_light_groups_new_ids(*this, po);
        if (po.obj.name.empty()) po.obj.name = kw.text;
        if (!po.left_out.empty()) warn_unsupported(*this, po.left_out, at, "the object is left out");
        out = std::move(po);
        return true;
    }
    const std::string w = kw.text;
    // POV-Ray 3.8's lemon is an undeclared identifier to 3.7, whose parse stops there.
    if (w == "lemon")
        fail("'lemon' is not a POV-Ray 3.7 shape (it came with POV-Ray 3.8); POV-Ray 3.7 stops "
             "here: undeclared identifier 'lemon'");
    if (w == "blender_light") {  // glint's extension for the Blender add-on
        out = PovObject{};
        out.is_light = true;
        out.lights.push_back(parse_blender_light(*this, loc()));
        return true;
    }
    const BodyParser body = object_body_parser(w);
    if (!body) return false;
    FileLoc kloc = loc();
    expect_open(w.c_str());
    FileLoc o = loc();
    PovObject po;
    po.obj.loc = kloc;
    // `sphere { Ident ... }`, `object { Ident ... }`: start from a declared object.
    const Token& first = peek();
    if (first.kind == TokKind::Word && lookup(first.text)) {
        const Symbol& s = use_symbol(next());
        if (auto obj = std::get_if<std::shared_ptr<const PovObject>>(&s.value)) {
            po = **obj;
            give_light_groups_new_ids(*this, po);
            if (po.obj.name.empty()) po.obj.name = first.text;
            if (!po.left_out.empty())  // said where declared; say it where the scene uses it
                warn_unsupported(*this, po.left_out, kloc, "the object is left out");
            if (w != "object" && !po.is_light && shape_name(po.obj.shape) != w &&
                !(w == "light_source" && !po.lights.empty()) &&
                !(w == "union" || w == "merge" || w == "intersection" || w == "difference"))
                fail("'" + first.text + "' is a " + shape_name(po.obj.shape) + ", not a " + w);
            parse_object_mods(po, w.c_str(), o);
            out = std::move(po);
            return true;
        }
        if (w == "object")
            fail("expected an object identifier, got " + value_kind_name(s.value) + " '" +
                 first.text + "'");
        unget();
    }
    if (body(*this, ObjectStart{w, kloc, o}, po) == BodyEnd::Modifiers)
        parse_object_mods(po, w.c_str(), o);
    out = std::move(po);
    return true;
}

void Parser::check_triangle_budget(size_t pending, const FileLoc& at) const {
    if (triangles_ + static_cast<long long>(pending) > options.max_triangles)
        fail_limit(at,
                   "the scene has more than " + std::to_string(options.max_triangles) +
                       " mesh triangles",
                   "--max-triangles");
}

void Parser::parse_light_body(scene::Light& l, std::optional<PovObject>* looks_like) {
    FileLoc opened = loc();
    // jitter, adaptive, circular and orient may come before area_light (parse.cpp sets them
    // on the light source, and POV-Ray accepts them on a point light too).
    scene::AreaLight sampling = l.area.value_or(scene::AreaLight{});
    l.location = parse_vector();
    skip_comma();
    l.color = parse_rgb();
    Transform tr;
    for (;;) {
        const Token& t = next();
        if (t.is_symbol('}')) break;
        const std::string w = t.kind == TokKind::Word ? t.text : std::string();
        if (w == "spotlight") l.kind = scene::LightKind::Spot;
        else if (w == "cylinder") l.kind = scene::LightKind::Cylinder;
        else if (w == "point_at") l.point_at = parse_vector();
        else if (w == "radius") l.radius = parse_float();
        else if (w == "falloff") l.falloff = parse_float();
        else if (w == "tightness") l.tightness = parse_float();
        else if (w == "parallel") l.parallel = allow_float(1) != 0;
        else if (w == "shadowless") l.shadowless = allow_float(1) != 0;
        else if (w == "fade_distance") l.fade_distance = parse_float();
        else if (w == "fade_power") l.fade_power = parse_float();
        else if (w == "media_interaction") l.media_interaction = allow_float(1) != 0;
        else if (w == "media_attenuation") l.media_attenuation = allow_float(1) != 0;
        else if (w == "circular" || w == "orient" || w == "jitter") {
            // Flags of the light, whether or not it is (or becomes) an area light.
            if (!l.area && w != "jitter")
                diag.warning(loc(), "'" + w + "' only affects area_light");
            bool on = allow_float(1) != 0;
            if (w == "circular") sampling.circular = on;
            if (w == "orient") sampling.orient = on;
            if (w == "jitter") sampling.jitter = on;
        } else if (w == "adaptive") {
            sampling.adaptive = to_int(parse_float());
        } else if (w == "area_light") {
            scene::AreaLight a;
            a.axis1 = parse_vector();
            skip_comma();
            a.axis2 = parse_vector();
            skip_comma();
            a.size1 = to_int(parse_float());
            skip_comma();
            a.size2 = to_int(parse_float());
            if (a.size1 < 1 || a.size2 < 1) fail("area_light sizes must be at least 1");
            l.area = a;
        } else if (w == "looks_like" && looks_like) {
            // looks_like { object mods }: moved to the light's location, casts no shadows.
            if (*looks_like) fail("only one looks_like allowed per light_source");
            expect_open("looks_like");
            FileLoc lo = loc();
            const Token& ot = next();
            PovObject obj;
            const Symbol* sym = ot.kind == TokKind::Word ? lookup(ot.text) : nullptr;
            if (sym && std::holds_alternative<std::shared_ptr<const PovObject>>(sym->value)) {
                obj = *std::get<std::shared_ptr<const PovObject>>(use_symbol(ot).value);
            } else if (!parse_object(ot, obj)) {
                fail("expected an object in looks_like, got " + got(ot));
            }
            apply_transform(obj, Transform::translate(l.location));
            parse_object_mods(obj, "looks_like", lo);
            obj.obj.no_shadow = true;
            *looks_like = std::move(obj);
        } else if (w == "photons") {
            parse_light_photons(l);
        } else if (w == "projected_through") {
            // Parse_Light_Source: one object with its modifiers (textures do not matter);
            // the light's later transforms move it too.
            if (l.projected_through)
                fail("only one projected_through is allowed per light_source");
            expect_open("projected_through");
            FileLoc po = loc();
            const Token& ot = next();
            PovObject obj;
            if (!parse_object(ot, obj))
                fail("expected an object in projected_through, got " + got(ot));
            parse_object_mods(obj, "projected_through", po);
            // Placed where the light is placed: undo the transforms read so far, which
            // transform_light applies to the light (and to this object) at the end.
            apply_transform(obj, tr.inverse());
            l.projected_through =
                std::make_shared<const scene::Object>(object_without_materials(obj));
        } else if (w == "looks_like") {
            unsupported("light_source '" + w + "'");
        } else {
            unget();
            Transform delta;
            if (!parse_transform_item(delta)) {
                if (t.kind == TokKind::End)
                    expect_close("light_source", opened);
                fail("expected a light_source item (spotlight, area_light, ...), got " +
                     got(next()));
            }
            tr = tr.then(delta);
        }
    }
    if (l.area) {
        l.area->jitter = sampling.jitter;
        l.area->circular = sampling.circular;
        l.area->orient = sampling.orient;
        l.area->adaptive = sampling.adaptive;
    }
    transform_light(l, tr);
    if (looks_like && *looks_like) apply_transform(**looks_like, tr);
}

void Parser::parse_object_mods(PovObject& o, const char* what, const FileLoc& opened) {
    auto flag = [&]() { return allow_float(1) != 0; };
    auto ensure_texture = [&]() -> scene::Texture& {
        if (!o.texture) {
            o.texture = default_texture_;
            o.texture->loc = loc();
        }
        return *o.texture;
    };
    for (;;) {
        const Token& t = next();
        if (t.is_symbol('}')) {
            // Parse_Object_Mods: the inside's texture needs one for the outside.
            if (o.interior_texture && !o.texture)
                fail("interior_texture requires an exterior texture");
            return;
        }
        if (t.kind == TokKind::End) expect_close(what, opened);
        const std::string w = t.kind == TokKind::Word && !lookup(t.text) ? t.text : std::string();
        if (w == "texture") {
            FileLoc kw = loc();
            expect_open("texture");
            FileLoc lo = loc();
            scene::Texture tex = parse_texture_body();
            expect_close("texture", lo);
            // POV-Ray's Link_Textures: a second texture is a layer over the first.
            if (o.texture)
                layer_texture(*o.texture, tex, kw);
            else
                o.texture = tex;
        } else if (w == "pigment") {
            expect_open("pigment");
            FileLoc lo = loc();
            parse_pigment_body(ensure_texture().pigment);
            expect_close("pigment", lo);
        } else if (w == "finish") {
            expect_open("finish");
            FileLoc lo = loc();
            parse_finish_body(ensure_texture().finish);
            expect_close("finish", lo);
        } else if (w == "normal") {
            expect_open("normal");
            FileLoc lo = loc();
            parse_normal_body(ensure_texture().normal);
            expect_close("normal", lo);
        } else if (w == "interior") {
            expect_open("interior");
            FileLoc lo = loc();
            scene::Interior in = o.interior.value_or(scene::Interior{});
            parse_interior_body(in);
            o.interior = in;
            expect_close("interior", lo);
        } else if (w == "material") {
            expect_open("material");
            FileLoc lo = loc();
            MaterialValue m = parse_material_body();
            expect_close("material", lo);
            if (m.texture) o.texture = m.texture;
            if (m.interior_texture) o.interior_texture = m.interior_texture;
            if (m.interior) o.interior = m.interior;
        } else if (w == "inverse") {
            o.obj.inverse = !o.obj.inverse;
        } else if (w == "hollow") {
            o.obj.hollow = flag();
        } else if (w == "no_shadow") {
            o.obj.no_shadow = flag();
        } else if (w == "no_image") {
            o.obj.no_image = flag();
        } else if (w == "no_reflection") {
            o.obj.no_reflection = flag();
        } else if (w == "double_illuminate") {
            o.obj.double_illuminate = flag();
        } else if (w == "no_radiosity") {
            o.obj.no_radiosity = flag();
        } else if (w == "hierarchy") {
            flag();
        } else if (w == "radiosity") {
            parse_radiosity_importance(&o.obj.radiosity_importance);
        } else if (w == "sturm") {
            bool on = flag();
            if (auto tor = std::get_if<scene::Torus>(&o.obj.shape)) tor->sturm = on;
        } else if (w == "open") {
            bool on = flag();
            if (auto c = std::get_if<scene::Cylinder>(&o.obj.shape)) c->open = on;
            else if (auto k = std::get_if<scene::Cone>(&o.obj.shape)) k->open = on;
            else fail("'open' applies to cylinders and cones only");
        } else if (w == "bounded_by" || w == "clipped_by") {
            bool bounded = w == "bounded_by";
            expect_open(w.c_str());
            FileLoc lo = loc();
            auto& dst = bounded ? o.obj.bounded_by : o.obj.clipped_by;
            if (accept(bounded ? "clipped_by" : "bounded_by")) {
                dst = bounded ? o.obj.clipped_by : o.obj.bounded_by;
            } else {
                dst.clear();
                for (;;) {
                    const Token& c = next();
                    PovObject child;
                    if (!parse_object(c, child)) {
                        unget();
                        break;
                    }
                    if (child.left_out.empty()) dst.push_back(object_without_materials(child));
                }
            }
            expect_close(w.c_str(), lo);
        } else if (w == "photons") {
            parse_object_photons(o.obj);
        } else if (w == "interior_texture") {
            FileLoc kw = loc();
            expect_open("interior_texture");
            FileLoc lo = loc();
            scene::Texture tex = parse_texture_body();
            expect_close("interior_texture", lo);
            // Like `texture`, a second one is a layer over the first (Link_Textures).
            if (o.interior_texture)
                layer_texture(*o.interior_texture, tex, kw);
            else
                o.interior_texture = tex;
        } else if (w == "uv_mapping") {
            // Parse_Object_Mods: the object's textures come after it, or it is an error.
            if (o.texture || o.interior_texture)
                fail("uv_mapping must come before the object's texture");
            o.uv_mapping = true;
        } else if (w == "cutaway_textures") {
            warn_unsupported(*this, w, loc(), "ignored; textures keep their usual mapping");
        } else if (w == "split_union") {
            flag();  // how POV-Ray bounds a union's parts: no effect on the image
        } else {
            unget();
            Transform delta;
            if (!parse_transform_item(delta))
                fail(std::string("expected an object modifier or '}' to close the ") + what +
                     " opened at " + std::to_string(opened.line) + ":" +
                     std::to_string(opened.column) + ", got " + got(next()));
            apply_transform(o, delta);
        }
    }
}

void Parser::parse_radiosity_importance(double* importance) {
    // radiosity { importance F } (parse.cpp): the share of a radiosity sample's rays that may
    // end on the object.
    expect_open("radiosity");
    FileLoc lo = loc();
    while (accept("importance")) {
        const double v = parse_float();
        if (!(v > 0 && v <= 1))
            fail("radiosity importance must be greater than 0.0 and at most 1.0");
        *importance = v;
    }
    expect_close("radiosity", lo);
}

void Parser::parse_object_photons(scene::Object& o) {
    // parse.cpp Parse_Object_Mods, PHOTONS_TOKEN.
    expect_open("photons");
    FileLoc lo = loc();
    for (;;) {
        if (accept("target")) {
            o.photon_target = std::max(0.0, allow_float(1));
        } else if (accept("refraction")) {
            o.photon_refraction = parse_float() != 0 ? 1 : 0;
        } else if (accept("reflection")) {
            o.photon_reflection = parse_float() != 0 ? 1 : 0;
        } else if (accept("pass_through")) {
            o.photon_pass_through = allow_float(1) != 0;
        } else if (accept("collect")) {
            o.photon_collect = allow_float(1) > 0;
        } else if (accept("split_union")) {
            allow_float(1);  // how POV-Ray bounds a union's photons: no effect here
        } else {
            break;
        }
    }
    expect_close("photons", lo);
}

void Parser::parse_light_photons(scene::Light& l) {
    expect_open("photons");
    FileLoc lo = loc();
    for (;;) {
        if (accept("refraction")) {
            l.photon_refraction = parse_float() != 0 ? 1 : 0;
        } else if (accept("reflection")) {
            l.photon_reflection = parse_float() != 0 ? 1 : 0;
        } else if (accept("area_light")) {
            l.photon_area_light = allow_float(1) != 0;
        } else {
            break;
        }
    }
    expect_close("photons", lo);
}

}  // namespace glint::pov
