// Objects (reference manual 3.4 "Objects"; parse.cpp in POV-Ray): finite and infinite shapes,
// CSG, meshes, light sources and the object modifiers. Transforms after a texture move the
// texture with the object, as POV-Ray does.
#include <cstdio>
#include <cmath>
#include <unordered_set>

#include "formats/pov/literal_list.h"
#include "formats/pov/parser_impl.h"
#include "formats/pov/solids.h"

namespace glint::pov {

namespace {

const std::unordered_set<std::string>& object_keywords() {
    static const std::unordered_set<std::string> k = {
        "sphere", "plane", "box", "cylinder", "cone", "disc", "torus", "triangle",
        "smooth_triangle", "mesh", "mesh2", "union", "merge", "intersection", "difference",
        "object", "light_source", "text", "obj_file"};
    return k;
}

const std::unordered_set<std::string>& unsupported_objects() {
    static const std::unordered_set<std::string> k = {
        "isosurface", "julia_fractal", "parametric", "sphere_sweep", "bicubic_patch", "ovus",
        "lemon", "light_group"};
    return k;
}

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
}

// Textures of CSG children are in world space too: they follow every enclosing transform.
void transform_child_textures(PovObject& o, const Transform& t) {
    if (o.texture) transform_texture(*o.texture, t);
    for (auto& c : o.children) transform_child_textures(c, t);
}

}  // namespace

// extensions.cpp: after the keyword `blender_light` (at kloc).
scene::Light parse_blender_light(Parser& p, const FileLoc& kloc);

bool Parser::is_object_keyword(const Token& t) const {
    return t.kind == TokKind::Word && !lookup(t.text) &&
           (object_keywords().count(t.text) > 0 || is_solid_keyword(t.text));
}

void Parser::apply_transform(PovObject& o, const Transform& t) {
    o.obj.transform = o.obj.transform.then(t);
    if (o.texture) transform_texture(*o.texture, t);
    for (auto& c : o.children) transform_child_textures(c, t);
    for (auto& l : o.lights) transform_light(l, t);
    for (auto& b : o.obj.bounded_by) b.transform = b.transform.then(t);
    for (auto& c : o.obj.clipped_by) c.transform = c.transform.then(t);
}

static scene::Object plain_object(const PovObject& p) {
    scene::Object o = p.obj;
    if (auto csg = std::get_if<scene::Csg>(&o.shape)) {
        csg->children.clear();
        for (const auto& c : p.children) csg->children.push_back(plain_object(c));
    }
    o.material = -1;
    return o;
}

static void parse_mesh_triangle(Parser& p, scene::Mesh& mesh, bool smooth) {
    p.expect_open(smooth ? "smooth_triangle" : "triangle");
    FileLoc o = p.loc();
    scene::MeshFace f;
    for (int i = 0; i < 3; ++i) {
        if (i > 0) p.skip_comma();
        f.v[i] = static_cast<int>(mesh.positions.size());
        mesh.positions.push_back(p.parse_vector());
        if (smooth) {
            p.skip_comma();
            f.n[i] = static_cast<int>(mesh.normals.size());
            mesh.normals.push_back(p.parse_vector());
        }
    }
    for (;;) {
        if (p.accept("uv_vectors")) {
            for (int i = 0; i < 3; ++i) {
                if (i > 0) p.skip_comma();
                Num n = p.parse_num(2);
                f.uv[i] = static_cast<int>(mesh.uvs.size());
                mesh.uvs.push_back({n.v[0], n.v[1]});
            }
        } else if (p.accept("texture")) {
            p.expect_open("texture");
            FileLoc to = p.loc();
            scene::Texture t = p.parse_texture_body();
            p.expect_close("texture", to);
            f.material = p.add_material(t, scene::Interior{}, to);
        } else {
            break;
        }
    }
    p.expect_close(smooth ? "smooth_triangle" : "triangle", o);
    mesh.faces.push_back(f);
}

// mesh2 sections: `name { count, item, item, ... }`. A list written as literal vectors of
// `dims` numbers (literal_list.h) is checked by ok(list) and, if it passes and the token limit
// allows, given to take(list) whole. Otherwise its items are read one by one, as if the fast
// path did not exist, and say what is wrong with them.
template <typename F, typename Ok, typename Take>
static void parse_counted(Parser& p, const char* name, F item, int dims, Ok ok, Take take) {
    p.expect_open(name);
    FileLoc o = p.loc();
    if (const Token* list = dims > 0 ? p.take_number_list() : nullptr) {
        LiteralList l;
        if (read_literal_list(list->text, dims, &l) && ok(l) && p.count_tokens(l.tokens, p.loc())) {
            take(l);
            p.expect_close(name, o);
            return;
        }
        p.give_back_number_list(*list);
    }
    int n = to_int(parse_float_before_points(p));
    if (n < 0) p.fail(std::string("negative count in ") + name);
    for (int i = 0; i < n; ++i) {
        p.skip_comma();
        item(i);
    }
    p.skip_comma();  // POV-Ray accepts a comma after the last item
    p.expect_close(name, o);
}

template <typename F>
static void parse_counted(Parser& p, const char* name, F item) {
    auto none = [](const LiteralList&) { return false; };
    parse_counted(p, name, item, 0, none, none);
}

// The fast path's checks and copies (parse_counted): indices as idx3 would take them, or not
// at all (then idx3 says which is out of range, and where).
static bool in_range(const LiteralList& l, int limit) {
    for (double v : l.values) {
        const int r = to_int(v);
        if (r < 0 || r >= limit) return false;
    }
    return true;
}

static void append_vectors(const LiteralList& l, std::vector<Vec3>* out) {
    out->reserve(out->size() + l.values.size() / 3);
    for (size_t k = 0; k + 2 < l.values.size(); k += 3)
        out->push_back(Vec3(l.values[k], l.values[k + 1], l.values[k + 2]));
}

static void parse_mesh2(Parser& p, scene::Mesh& mesh) {
    auto any_list = [](const LiteralList&) { return true; };
    std::vector<int> textures;
    auto idx3 = [&](const char* what, int limit) {
        p.peek();
        FileLoc at = p.loc();
        Vec3 v = p.parse_vector();
        std::array<int, 3> r{to_int(v.x), to_int(v.y), to_int(v.z)};
        for (int k = 0; k < 3; ++k)
            if (r[k] < 0 || r[k] >= limit) {
                // The value as written: 2e72 clamped to int would read as 2147483647.
                char shown[32];
                std::snprintf(shown, sizeof shown, "%.10g", v[k]);
                p.fail_at(at, std::string(what) + " index " + shown + " is out of range (0.." +
                                  std::to_string(limit - 1) + ")");
            }
        return r;
    };
    for (;;) {
        if (p.accept("vertex_vectors")) {
            parse_counted(p, "vertex_vectors", [&](int) { mesh.positions.push_back(p.parse_vector()); },
                          3, any_list, [&](const LiteralList& l) { append_vectors(l, &mesh.positions); });
        } else if (p.accept("normal_vectors")) {
            parse_counted(p, "normal_vectors", [&](int) { mesh.normals.push_back(p.parse_vector()); },
                          3, any_list, [&](const LiteralList& l) { append_vectors(l, &mesh.normals); });
        } else if (p.accept("uv_vectors")) {
            parse_counted(p, "uv_vectors", [&](int) {
                Num n = p.parse_num(2);
                mesh.uvs.push_back({n.v[0], n.v[1]});
            }, 2, any_list, [&](const LiteralList& l) {
                for (size_t k = 0; k + 1 < l.values.size(); k += 2)
                    mesh.uvs.push_back({l.values[k], l.values[k + 1]});
            });
        } else if (p.accept("texture_list")) {
            parse_counted(p, "texture_list", [&](int) {
                p.expect("texture", "in texture_list");
                p.expect_open("texture");
                FileLoc to = p.loc();
                scene::Texture t = p.parse_texture_body();
                p.expect_close("texture", to);
                textures.push_back(p.add_material(t, scene::Interior{}, to));
            });
        } else if (p.accept("face_indices")) {
            int nv = static_cast<int>(mesh.positions.size());
            // With a texture_list a face may name textures after its vector: token by token.
            auto faces_ok = [&](const LiteralList& l) { return textures.empty() && in_range(l, nv); };
            auto take_faces = [&](const LiteralList& l) {
                for (size_t k = 0; k + 2 < l.values.size(); k += 3) {
                    scene::MeshFace f;
                    f.v = {to_int(l.values[k]), to_int(l.values[k + 1]), to_int(l.values[k + 2])};
                    mesh.faces.push_back(f);
                }
            };
            parse_counted(p, "face_indices", [&](int) {
                scene::MeshFace f;
                f.v = idx3("vertex", nv);
                if (p.peek().is(",") && !textures.empty()) {
                    p.skip_comma();
                    if (p.next_is_expression_start() && p.peek().kind != TokKind::Symbol) {
                        int t = to_int(p.parse_float());
                        if (t < 0 || t >= static_cast<int>(textures.size()))
                            p.fail("texture index out of range");
                        f.material = textures[t];
                        if (p.accept(",")) {
                            if (p.peek().kind == TokKind::Number) {
                                p.parse_float();  // per-vertex textures: the first one is used
                                p.skip_comma();
                                p.parse_float();
                            } else {
                                p.unget();
                            }
                        }
                    }
                }
                mesh.faces.push_back(f);
            }, 3, faces_ok, take_faces);
        } else if (p.accept("normal_indices")) {
            int nn = static_cast<int>(mesh.normals.size());
            size_t i = 0;
            parse_counted(p, "normal_indices", [&](int) {
                auto r = idx3("normal", nn);
                if (i < mesh.faces.size()) mesh.faces[i].n = r;
                ++i;
            }, 3, [&](const LiteralList& l) { return in_range(l, nn); },
               [&](const LiteralList& l) {
                for (size_t k = 0; k + 2 < l.values.size(); k += 3, ++i)
                    if (i < mesh.faces.size())
                        mesh.faces[i].n = {to_int(l.values[k]), to_int(l.values[k + 1]),
                                           to_int(l.values[k + 2])};
            });
        } else if (p.accept("uv_indices")) {
            int nu = static_cast<int>(mesh.uvs.size());
            size_t i = 0;
            parse_counted(p, "uv_indices", [&](int) {
                auto r = idx3("uv", nu);
                if (i < mesh.faces.size()) mesh.faces[i].uv = r;
                ++i;
            }, 3, [&](const LiteralList& l) { return in_range(l, nu); },
               [&](const LiteralList& l) {
                for (size_t k = 0; k + 2 < l.values.size(); k += 3, ++i)
                    if (i < mesh.faces.size())
                        mesh.faces[i].uv = {to_int(l.values[k]), to_int(l.values[k + 1]),
                                            to_int(l.values[k + 2])};
            });
        } else {
            break;
        }
    }
    // Without normal_indices, mesh2 uses the normal with the vertex's index (POV-Ray rule).
    if (!mesh.normals.empty()) {
        for (auto& f : mesh.faces)
            if (f.n[0] < 0 && mesh.normals.size() == mesh.positions.size()) f.n = f.v;
    }
    if (!mesh.uvs.empty()) {
        for (auto& f : mesh.faces)
            if (f.uv[0] < 0 && mesh.uvs.size() == mesh.positions.size()) f.uv = f.v;
    }
}

bool Parser::parse_object(const Token& kw, PovObject& out) {
    if (kw.kind != TokKind::Word || lookup(kw.text)) return false;
    const std::string w = kw.text;
    if (unsupported_objects().count(w)) {
        FileLoc at = loc();
        out = skip_unsupported_object(*this, w, at);
        return true;
    }
    if (w == "blender_light") {  // glint's extension for the Blender add-on
        out = PovObject{};
        out.is_light = true;
        out.lights.push_back(parse_blender_light(*this, loc()));
        return true;
    }
    if (!object_keywords().count(w) && !is_solid_keyword(w)) return false;
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
    if (w == "sphere") {
        scene::Sphere s;
        s.center = parse_vector();
        skip_comma();
        s.radius = parse_float();
        po.obj.shape = s;
    } else if (w == "plane") {
        scene::Plane s;
        FileLoc l = loc();
        Vec3 n = parse_vector();
        if (length(n) < kPovEpsilon) fail_at(l, "degenerate plane normal");
        s.normal = normalize(n);  // POV-Ray normalizes the normal, not the distance
        skip_comma();
        s.distance = parse_float();
        po.obj.shape = s;
    } else if (w == "box") {
        scene::Box s;
        s.corner1 = parse_vector();
        skip_comma();
        s.corner2 = parse_vector();
        po.obj.shape = s;
    } else if (w == "cylinder") {
        scene::Cylinder s;
        s.base = parse_vector();
        skip_comma();
        s.cap = parse_vector();
        skip_comma();
        s.radius = parse_float();
        po.obj.shape = s;
    } else if (w == "cone") {
        scene::Cone s;
        s.base = parse_vector();
        skip_comma();
        s.base_radius = parse_float();
        skip_comma();
        s.cap = parse_vector();
        skip_comma();
        s.cap_radius = parse_float();
        po.obj.shape = s;
    } else if (w == "disc") {
        scene::Disc s;
        s.center = parse_vector();
        skip_comma();
        Vec3 n = parse_vector();
        if (length(n) < 1e-10) fail("degenerate disc normal");
        s.normal = normalize(n);
        skip_comma();
        s.radius = parse_float();
        skip_comma();
        if (next_is_expression_start()) s.hole_radius = parse_float();
        po.obj.shape = s;
    } else if (w == "torus") {
        scene::Torus s;
        s.major = parse_float();
        skip_comma();
        s.minor = parse_float();
        po.obj.shape = s;
    } else if (w == "triangle") {
        scene::Triangle s;
        for (int i = 0; i < 3; ++i) {
            if (i > 0) skip_comma();
            s.p[i] = parse_vector();
        }
        po.obj.shape = s;
    } else if (w == "smooth_triangle") {
        scene::SmoothTriangle s;
        for (int i = 0; i < 3; ++i) {
            if (i > 0) skip_comma();
            s.p[i] = parse_vector();
            skip_comma();
            s.n[i] = parse_vector();
        }
        po.obj.shape = s;
    } else if (w == "mesh" || w == "mesh2") {
        scene::Mesh mesh;
        mesh.loc = kloc;
        auto check_triangles = [&](size_t more) {
            if (triangles_ + static_cast<long long>(more) > options.max_triangles)
                fail_limit(kloc,
                           "the scene has more than " + std::to_string(options.max_triangles) +
                               " mesh triangles",
                           "--max-triangles");
        };
        if (w == "mesh") {
            for (;;) {
                if (accept("triangle")) parse_mesh_triangle(*this, mesh, false);
                else if (accept("smooth_triangle")) parse_mesh_triangle(*this, mesh, true);
                else break;
                check_triangles(mesh.faces.size());
            }
        } else {
            parse_mesh2(*this, mesh);
        }
        check_triangles(mesh.faces.size());
        triangles_ += static_cast<long long>(mesh.faces.size());
        if (accept("inside_vector")) {
            mesh.has_inside_vector = true;
            mesh.inside_vector = parse_vector();
        }
        if (mesh.faces.empty()) fail_at(kloc, "the " + w + " has no triangles");
        scene.meshes.push_back(std::move(mesh));
        po.obj.shape = scene::MeshRef{static_cast<int>(scene.meshes.size()) - 1};
    } else if (w == "union" || w == "merge" || w == "intersection" || w == "difference") {
        scene::Csg csg;
        csg.op = w == "union" ? scene::CsgOp::Union : w == "merge" ? scene::CsgOp::Merge
               : w == "intersection" ? scene::CsgOp::Intersection : scene::CsgOp::Difference;
        po.obj.shape = csg;
        for (;;) {
            const Token& t = next();
            PovObject child;
            if (!parse_object(t, child)) {
                unget();
                break;
            }
            for (auto& l : child.lights) po.lights.push_back(l);
            child.lights.clear();
            if (!child.left_out.empty()) po.left_out = child.left_out;
            else if (!child.is_light) po.children.push_back(std::move(child));
        }
        // Only when every child was left out does the CSG go too; otherwise it keeps the rest.
        if (!po.children.empty()) po.left_out.clear();
    } else if (is_solid_keyword(w)) {
        parse_solid_body(*this, w, kloc, &po.obj.shape, &po.left_out);
    } else if (w == "text") {
        // text { ttf "font.ttf" "string" thickness, <offset> } (parse.cpp Parse_TrueType).
        scene::Text s;
        // POV-Ray's built-in font (`internal N` instead of `ttf "file"`) is not in glint:
        // the text is read and left out.
        const bool internal = accept("internal");
        if (internal) {
            warn_unsupported(*this, "text with a built-in font ('internal')", loc(),
                             "the object is left out");
            parse_float();
            po.left_out = "text";
        } else {
            expect("ttf", "in text (ttf \"font.ttf\" \"string\" thickness, offset)");
        }
        peek();
        FileLoc floc = loc();
        if (internal) {
            s.text = parse_string();
            skip_comma();
            parse_float();
            skip_comma();
            parse_vector();
            parse_object_mods(po, w.c_str(), o);
            out = std::move(po);
            return true;
        }
        s.file = parse_string();
        // Like POV-Ray's Locate_File, a name without its extension also finds "name.ttf".
        try {
            s.font = resolve_file(s.file, floc);
        } catch (const Error& e) {
            if (e.kind() != ErrorKind::MissingFile) throw;
            try {
                s.font = resolve_file(s.file + ".ttf", floc);
            } catch (const Error&) {
                throw e;
            }
        }
        skip_comma();
        s.text = parse_string();
        skip_comma();
        s.thickness = parse_float();
        skip_comma();
        s.offset = parse_vector();
        po.obj.shape = s;
        // POV-Ray turns every text object by 0.001 degrees about each axis "to fix cracks in
        // text that lies along an axis"; the same rays must hit the same glyph edges.
        po.obj.transform = Transform::rotate_xyz_degrees(Vec3(0.001, 0.001, 0.001));
    } else if (w == "obj_file") {  // glint's extension (extensions.cpp)
        parse_obj_file(po, o);
        out = std::move(po);
        return true;
    } else if (w == "light_source") {
        scene::Light l;
        l.loc = kloc;
        po.is_light = true;
        std::optional<PovObject> looks_like;
        parse_light_body(l, &looks_like);
        po.lights.push_back(l);
        if (looks_like) {
            // The light carries its looks_like object: a union holding it, placed with the
            // light (parse.cpp makes it a child of the light source).
            po.is_light = false;
            po.obj.shape = scene::Csg{};
            po.children.push_back(std::move(*looks_like));
        }
        out = std::move(po);
        return true;
    } else {  // object { sphere { ... } mods }
        const Token& t = next();
        if (!parse_object(t, po)) fail("expected an object identifier or object, got " + got(t));
    }
    parse_object_mods(po, w.c_str(), o);
    out = std::move(po);
    return true;
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
        else if (w == "media_interaction" || w == "media_attenuation") allow_float(1);
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
        } else if (w == "projected_through" || w == "photons") {
            warn_unsupported(*this, w, loc(), "ignored in light_source");
            skip_braced_block(*this, w);
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
        if (t.is_symbol('}')) return;
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
        } else if (w == "no_radiosity" || w == "hierarchy") {
            flag();
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
                    if (child.left_out.empty()) dst.push_back(plain_object(child));
                }
            }
            expect_close(w.c_str(), lo);
        } else if (w == "photons" || w == "radiosity" || w == "interior_texture") {
            warn_unsupported(*this, w, loc(), "the object's " + w + " block is ignored");
            skip_braced_block(*this, w);
        } else if (w == "uv_mapping" || w == "cutaway_textures") {
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

}  // namespace glint::pov
