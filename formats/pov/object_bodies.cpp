// The bodies of POV-Ray's objects (reference manual 3.4 "Objects"; parse.cpp Parse_Sphere,
// Parse_Plane, ..., Parse_CSG, Parse_TrueType, Parse_Light_Source), one function per keyword,
// and the table that finds them. What a body reads ends before the object modifiers, unless it
// returns BodyEnd::Done.
#include "formats/pov/object_bodies.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>

#include "formats/pov/solids.h"

namespace glint::pov {
namespace {

BodyEnd sphere_body(Parser& p, const ObjectStart&, PovObject& po) {
    scene::Sphere s;
    s.center = p.parse_vector();
    p.skip_comma();
    s.radius = p.parse_float();
    po.obj.shape = s;
    return BodyEnd::Modifiers;
}

BodyEnd plane_body(Parser& p, const ObjectStart&, PovObject& po) {
    scene::Plane s;
    FileLoc l = p.loc();
    Vec3 n = p.parse_vector();
    if (length(n) < kPovEpsilon) p.fail_at(l, "degenerate plane normal");
    s.normal = normalize(n);  // POV-Ray normalizes the normal, not the distance
    p.skip_comma();
    s.distance = p.parse_float();
    po.obj.shape = s;
    return BodyEnd::Modifiers;
}

BodyEnd box_body(Parser& p, const ObjectStart&, PovObject& po) {
    scene::Box s;
    s.corner1 = p.parse_vector();
    p.skip_comma();
    s.corner2 = p.parse_vector();
    po.obj.shape = s;
    return BodyEnd::Modifiers;
}

BodyEnd cylinder_body(Parser& p, const ObjectStart&, PovObject& po) {
    scene::Cylinder s;
    s.base = p.parse_vector();
    p.skip_comma();
    s.cap = p.parse_vector();
    p.skip_comma();
    s.radius = p.parse_float();
    po.obj.shape = s;
    return BodyEnd::Modifiers;
}

BodyEnd cone_body(Parser& p, const ObjectStart&, PovObject& po) {
    scene::Cone s;
    s.base = p.parse_vector();
    p.skip_comma();
    s.base_radius = p.parse_float();
    p.skip_comma();
    s.cap = p.parse_vector();
    p.skip_comma();
    s.cap_radius = p.parse_float();
    po.obj.shape = s;
    return BodyEnd::Modifiers;
}

BodyEnd disc_body(Parser& p, const ObjectStart&, PovObject& po) {
    scene::Disc s;
    s.center = p.parse_vector();
    p.skip_comma();
    Vec3 n = p.parse_vector();
    if (length(n) < 1e-10) p.fail("degenerate disc normal");
    s.normal = normalize(n);
    p.skip_comma();
    s.radius = p.parse_float();
    p.skip_comma();
    if (p.next_is_expression_start()) s.hole_radius = p.parse_float();
    po.obj.shape = s;
    return BodyEnd::Modifiers;
}

BodyEnd torus_body(Parser& p, const ObjectStart&, PovObject& po) {
    scene::Torus s;
    s.major = p.parse_float();
    p.skip_comma();
    s.minor = p.parse_float();
    po.obj.shape = s;
    return BodyEnd::Modifiers;
}

// ovus { bottom_radius, top_radius } (parse.cpp Parse_Ovus): a top radius of at least twice the
// bottom one makes the egg a sphere, which POV-Ray puts in its place with a warning.
BodyEnd ovus_body(Parser& p, const ObjectStart& start, PovObject& po) {
    scene::Ovus s;
    p.peek();
    const FileLoc bottom_at = p.loc();
    s.bottom_radius = p.parse_float();
    p.skip_comma();
    p.peek();
    const FileLoc top_at = p.loc();
    s.top_radius = p.parse_float();
    if (s.bottom_radius < 0) p.fail_at(bottom_at, "both ovus radii must be positive");
    if (s.top_radius < 0) p.fail_at(top_at, "both ovus radii must be positive");
    if (!(s.top_radius < 2.0 * s.bottom_radius)) {
        p.diag.warning(start.keyword_loc,
                       "ovus top radius is not less than twice the bottom radius: a sphere "
                       "takes its place, as in POV-Ray");
        po.obj.shape = scene::Sphere{Vec3(0, s.bottom_radius, 0), s.top_radius};
    } else {
        po.obj.shape = s;
    }
    return BodyEnd::Modifiers;
}

BodyEnd triangle_body(Parser& p, const ObjectStart&, PovObject& po) {
    scene::Triangle s;
    for (int i = 0; i < 3; ++i) {
        if (i > 0) p.skip_comma();
        s.p[i] = p.parse_vector();
    }
    po.obj.shape = s;
    return BodyEnd::Modifiers;
}

BodyEnd smooth_triangle_body(Parser& p, const ObjectStart&, PovObject& po) {
    scene::SmoothTriangle s;
    for (int i = 0; i < 3; ++i) {
        if (i > 0) p.skip_comma();
        s.p[i] = p.parse_vector();
        p.skip_comma();
        s.n[i] = p.parse_vector();
    }
    po.obj.shape = s;
    return BodyEnd::Modifiers;
}

// union, merge, intersection, difference: the objects inside, to the first token that is not
// one. Light sources inside go to the CSG's light list.
BodyEnd csg_body(Parser& p, const ObjectStart& start, PovObject& po) {
    const std::string& w = start.keyword;
    scene::Csg csg;
    csg.op = w == "union" ? scene::CsgOp::Union : w == "merge" ? scene::CsgOp::Merge
           : w == "intersection" ? scene::CsgOp::Intersection : scene::CsgOp::Difference;
    po.obj.shape = csg;
    for (;;) {
        const Token& t = p.next();
        PovObject child;
        if (!p.parse_object(t, child)) {
            p.unget();
            break;
        }
        for (auto& l : child.lights) po.lights.push_back(l);
        child.lights.clear();
        if (!child.left_out.empty()) po.left_out = child.left_out;
        else if (!child.is_light) po.children.push_back(std::move(child));
    }
    // Only when every child was left out does the CSG go too; otherwise it keeps the rest.
    if (!po.children.empty()) po.left_out.clear();
    return BodyEnd::Modifiers;
}

BodyEnd solid_body(Parser& p, const ObjectStart& start, PovObject& po) {
    parse_solid_body(p, start.keyword, start.keyword_loc, &po.obj.shape, &po.left_out);
    return BodyEnd::Modifiers;
}

// text { ttf "font.ttf" "string" thickness, <offset> } (parse.cpp Parse_TrueType).
BodyEnd text_body(Parser& p, const ObjectStart&, PovObject& po) {
    scene::Text s;
    if (p.accept("internal")) {
        // POV-Ray's built-in fonts (fileinputoutput.cpp IMemStream) are compiled-in copies of
        // the four fonts Debian ships with POV-Ray's includes: 1 timrom, 2 cyrvetic,
        // 3 crystal, any other number povlogo. glint reads those files.
        p.peek();
        const FileLoc floc = p.loc();
        const int id = to_int(p.parse_float());
        s.file = id == 1 ? "timrom.ttf" : id == 2 ? "cyrvetic.ttf" : id == 3 ? "crystal.ttf"
                                                                           : "povlogo.ttf";
        try {
            s.font = p.resolve_file(s.file, floc);
        } catch (const Error& e) {
            if (e.kind() != ErrorKind::MissingFile) throw;
            const std::string shipped = "/usr/share/fonts/truetype/povray/" + s.file;
            std::error_code ec;
            if (!std::filesystem::is_regular_file(shipped, ec))
                throw Error(ErrorKind::MissingFile, floc,
                            "the built-in font " + std::to_string(id) + " is POV-Ray's '" + s.file +
                                "', which is in no include folder (Debian's povray-includes "
                                "installs it)");
            s.font = shipped;
        }
    } else {
        p.expect("ttf", "in text (ttf \"font.ttf\" or internal N, \"string\" thickness, offset)");
        p.peek();
        const FileLoc floc = p.loc();
        s.file = p.parse_string();
        // Like POV-Ray's Locate_File, a name without its extension also finds "name.ttf".
        try {
            s.font = p.resolve_file(s.file, floc);
        } catch (const Error& e) {
            if (e.kind() != ErrorKind::MissingFile) throw;
            try {
                s.font = p.resolve_file(s.file + ".ttf", floc);
            } catch (const Error&) {
                throw e;
            }
        }
    }
    p.skip_comma();
    s.text = p.parse_string();
    p.skip_comma();
    s.thickness = p.parse_float();
    p.skip_comma();
    s.offset = p.parse_vector();
    po.obj.shape = s;
    // POV-Ray turns every text object by 0.001 degrees about each axis "to fix cracks in text
    // that lies along an axis"; the same rays must hit the same glyph edges.
    po.obj.transform = Transform::rotate_xyz_degrees(Vec3(0.001, 0.001, 0.001));
    return BodyEnd::Modifiers;
}

// glint's extension (extensions.cpp): reads its modifiers itself.
BodyEnd obj_file_body(Parser& p, const ObjectStart& start, PovObject& po) {
    p.parse_obj_file(po, start.opened);
    return BodyEnd::Done;
}

BodyEnd light_source_body(Parser& p, const ObjectStart& start, PovObject& po) {
    scene::Light l;
    l.loc = start.keyword_loc;
    po.is_light = true;
    std::optional<PovObject> looks_like;
    p.parse_light_body(l, &looks_like);
    po.lights.push_back(l);
    if (looks_like) {
        // The light carries its looks_like object: a union holding it, placed with the light
        // (parse.cpp makes it a child of the light source).
        po.is_light = false;
        po.obj.shape = scene::Csg{};
        po.children.push_back(std::move(*looks_like));
    }
    return BodyEnd::Done;
}

// object { sphere { ... } mods } (object { Ident mods } never gets here: parse_object starts
// from the declared object).
BodyEnd object_body(Parser& p, const ObjectStart&, PovObject& po) {
    const Token& t = p.next();
    if (!p.parse_object(t, po)) p.fail("expected an object identifier or object, got " + p.got(t));
    return BodyEnd::Modifiers;
}

}  // namespace

BodyParser object_body_parser(const std::string& word) {
    static const std::unordered_map<std::string_view, BodyParser> table = {
        {"sphere", sphere_body},
        {"plane", plane_body},
        {"box", box_body},
        {"cylinder", cylinder_body},
        {"cone", cone_body},
        {"disc", disc_body},
        {"torus", torus_body},
        {"ovus", ovus_body},
        {"triangle", triangle_body},
        {"smooth_triangle", smooth_triangle_body},
        {"mesh", parse_mesh_body},
        {"mesh2", parse_mesh_body},
        {"union", csg_body},
        {"merge", csg_body},
        {"intersection", csg_body},
        {"difference", csg_body},
        {"text", text_body},
        {"obj_file", obj_file_body},
        {"light_source", light_source_body},
        {"light_group", light_group_body},
        {"object", object_body},
    };
    auto it = table.find(word);
    if (it != table.end()) return it->second;
    return is_solid_keyword(word) ? solid_body : nullptr;
}

}  // namespace glint::pov
