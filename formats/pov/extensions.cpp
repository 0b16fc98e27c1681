// glint's own extensions to the POV-Ray language (GRAMMAR.md "glint extensions"), kept apart
// from POV-Ray's grammar:
// - `blender_light { TYPE items }`: a Blender 3.4 light as the glint Blender add-on writes it
//   (docs/pbr-mapping.md "Blender lights"). Every item is optional (Blender's defaults), each
//   may be given once, and only for the types it applies to.
// - `obj_file { "model.obj" ... }`: an OBJ/MTL model placed as one object.
#include <cmath>
#include <set>

#include "formats/obj/obj_importer.h"
#include "formats/pov/parser_impl.h"

namespace glint::pov {

namespace {

using scene::BlenderLightType;

const char* type_name(BlenderLightType t) {
    switch (t) {
        case BlenderLightType::Point: return "point";
        case BlenderLightType::Spot: return "spot";
        case BlenderLightType::Sun: return "sun";
        case BlenderLightType::Area: return "area";
    }
    return "?";
}

// The types an item applies to, as text ("" for an unknown item).
const char* applies_to(const std::string& w) {
    if (w == "color" || w == "power" || w == "visible_camera") return "point spot sun area";
    if (w == "location") return "point spot area";
    if (w == "direction") return "spot sun area";
    if (w == "radius") return "point spot";
    if (w == "spot_size" || w == "spot_blend") return "spot";
    if (w == "angle") return "sun";
    if (w == "shape" || w == "size" || w == "axis_x" || w == "axis_y" || w == "spread")
        return "area";
    return "";
}

bool applies(const std::string& w, BlenderLightType t) {
    const std::string list = std::string(" ") + applies_to(w) + " ";
    return list.find(std::string(" ") + type_name(t) + " ") != std::string::npos;
}

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

}  // namespace

// After the keyword `blender_light` (at `kloc`).
scene::Light parse_blender_light(Parser& p, const FileLoc& kloc) {
    p.expect_open("blender_light");
    const FileLoc opened = p.loc();
    scene::Light l;
    l.loc = kloc;
    scene::BlenderLight b;
    const Token& first = p.next();
    if (first.is("point")) b.type = BlenderLightType::Point;
    else if (first.is("spot")) b.type = BlenderLightType::Spot;
    else if (first.is("sun")) b.type = BlenderLightType::Sun;
    else if (first.is("area")) b.type = BlenderLightType::Area;
    else
        p.fail("blender_light: expected the light type first (point, spot, sun or area), got " +
               p.got(first));
    const std::string type = type_name(b.type);
    std::set<std::string> seen;
    // A float item in [lo, hi] (lo_open: (lo, hi]); the error names the item and the value.
    auto ranged = [&](const FileLoc& at, const std::string& w, double lo, double hi,
                      bool lo_open) {
        double v = p.parse_float();
        // Degrees converted from Blender's single-precision radians overshoot a little.
        if (v > hi && v <= hi * (1 + 1e-6)) v = hi;
        if (!std::isfinite(v) || (lo_open ? !(v > lo) : !(v >= lo)) || !(v <= hi)) {
            const std::string rule =
                std::isinf(hi) ? (lo_open ? "must be positive" : "must not be negative")
                               : std::string("must be in ") + (lo_open ? "(" : "[") +
                                     number(lo) + ", " + number(hi) + "]";
            p.fail_at(at, "blender_light " + w + " " + rule + ", got " + number(v));
        }
        return v;
    };
    auto unit_vector = [&](const FileLoc& at, const std::string& w) {
        const Vec3 v = p.parse_vector();
        if (!is_finite(v) || !(length_squared(v) > 0))
            p.fail_at(at, "blender_light " + w + " must be a non-zero vector");
        return normalize(v);
    };
    for (;;) {
        const Token& t = p.next();
        if (t.is_symbol('}')) break;
        if (t.kind == TokKind::End) p.expect_close("blender_light", opened);
        const FileLoc at = p.loc();
        const std::string w = t.kind == TokKind::Word ? t.text : std::string();
        if (*applies_to(w) == '\0')
            p.fail("expected a blender_light item (location, direction, color, power, radius, "
                   "spot_size, spot_blend, angle, shape, size, axis_x, axis_y, spread, "
                   "visible_camera) or '}', got " + p.got(t));
        if (!applies(w, b.type))
            p.fail_at(at, "blender_light: '" + w + "' does not apply to a " + type +
                              " light (only to: " + applies_to(w) + ")");
        if (!seen.insert(w).second) p.fail_at(at, "blender_light: '" + w + "' given twice");
        if (w == "location") {
            l.location = p.parse_vector();
            if (!is_finite(l.location)) p.fail_at(at, "blender_light location is not finite");
        } else if (w == "direction") {
            b.direction = unit_vector(at, w);
        } else if (w == "color") {
            l.color = p.parse_rgb();
            if (!(l.color.r >= 0) || !(l.color.g >= 0) || !(l.color.b >= 0) ||
                !std::isfinite(l.color.sum()))
                p.fail_at(at, "blender_light color must be finite and not negative");
        } else if (w == "power") {
            b.power = ranged(at, w, 0, kInfinity, false);
        } else if (w == "radius") {
            b.radius = ranged(at, w, 0, kInfinity, false);
        } else if (w == "spot_size") {
            b.spot_size = ranged(at, w, 0, 180, true);
        } else if (w == "spot_blend") {
            b.spot_blend = ranged(at, w, 0, 1, false);
        } else if (w == "angle") {
            b.angle = ranged(at, w, 0, 180, false);
        } else if (w == "shape") {
            const Token& s = p.next();
            if (s.is("rectangle")) b.ellipse = false;
            else if (s.is("ellipse")) b.ellipse = true;
            else p.fail("blender_light shape must be rectangle or ellipse, got " + p.got(s));
        } else if (w == "size") {
            Num n = p.parse_num(2);
            if (n.terms != 2)
                p.fail_at(at, "blender_light size must be a 2-vector <size_x, size_y>");
            if (!(n.v[0] > 0) || !(n.v[1] > 0) || !std::isfinite(n.v[0]) ||
                !std::isfinite(n.v[1]))
                p.fail_at(at, "blender_light size must be positive, got <" + number(n.v[0]) +
                                  ", " + number(n.v[1]) + ">");
            b.size_x = n.v[0];
            b.size_y = n.v[1];
        } else if (w == "axis_x") {
            b.axis_x = unit_vector(at, w);
        } else if (w == "axis_y") {
            b.axis_y = unit_vector(at, w);
        } else if (w == "spread") {
            b.spread = ranged(at, w, 0, 180, false);
        } else if (w == "visible_camera") {
            b.visible_camera = p.allow_float(1) != 0;
        }
    }
    if (b.type == BlenderLightType::Area && !(length_squared(cross(b.axis_x, b.axis_y)) > 1e-12))
        p.fail_at(kloc, "blender_light area: axis_x and axis_y must not be parallel");
    l.blender = b;
    return l;
}

// obj_file { "model.obj" [transforms] [texture { ... }] }, after its opening brace (at
// `opened`): the OBJ/MTL model as one object, a union of its OBJ objects. A texture given here
// replaces the MTL materials of every face.
void Parser::parse_obj_file(PovObject& po, const FileLoc& opened) {
    peek();
    FileLoc floc = loc();
    std::string file = parse_string();
    std::string path = resolve_file(file, floc);
    const size_t objects_before = scene.objects.size();
    const size_t meshes_before = scene.meshes.size();
    // OBJ is right-handed and y-up; mirroring z shows the model as authored in POV-Ray's
    // left-handed space (as the model viewer does).
    obj::import_obj(path, scene, Transform::scale(Vec3(1, 1, -1)), -1, diag);
    size_t added = 0;
    for (size_t m = meshes_before; m < scene.meshes.size(); ++m)
        added += scene.meshes[m].faces.size();
    check_triangle_budget(added, floc);
    count_triangles(added);
    std::vector<scene::Object> parts(scene.objects.begin() + objects_before,
                                     scene.objects.end());
    scene.objects.resize(objects_before);
    if (parts.empty()) fail_at(floc, "'" + file + "' has no faces");
    po.obj.shape = scene::Csg{};
    for (auto& part : parts) {
        PovObject child;
        child.obj = std::move(part);
        po.children.push_back(std::move(child));
    }
    parse_object_mods(po, "obj_file", opened);
    if (po.texture) {
        // A texture given here replaces the MTL materials of every face.
        for (size_t m = meshes_before; m < scene.meshes.size(); ++m)
            for (auto& f : scene.meshes[m].faces) f.material = -1;
        for (auto& c : po.children.edit()) c.obj.material = -1;
    }
}

}  // namespace glint::pov
