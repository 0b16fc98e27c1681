// The object grammar's dispatch: each object keyword (sphere, mesh2, union, light_source, ...)
// names the function that parses its body. Parser::parse_object (objects.cpp) reads the
// keyword, the opening brace and a declared object the body may start from, then calls the
// body parser it finds here; the bodies of shapes are in object_bodies.cpp, meshes in
// meshes.cpp, the spline and implicit solids in solids.cpp.
#pragma once

#include <string>

#include "formats/pov/parser_impl.h"

namespace glint::pov {

// Where an object statement began: its keyword, the keyword's location, and the location of
// its opening brace (for the message about a missing '}').
struct ObjectStart {
    const std::string& keyword;
    FileLoc keyword_loc;
    FileLoc opened;
};

// What follows a body: the object modifiers and the closing brace (parse_object reads them),
// or nothing (the body read them itself).
enum class BodyEnd { Modifiers, Done };

using BodyParser = BodyEnd (*)(Parser& p, const ObjectStart& start, PovObject& out);

// The body parser of object keyword `word`; null when `word` starts no object.
BodyParser object_body_parser(const std::string& word);

// mesh { triangle { ... } ... } and mesh2 { vertex_vectors { ... } ... } (meshes.cpp).
BodyEnd parse_mesh_body(Parser& p, const ObjectStart& start, PovObject& out);

// light_group.cpp: the light_group object; and, for a copy of a declared object, new ids for
// the light groups inside it, so that each copy's lights light only that copy's objects.
BodyEnd light_group_body(Parser& p, const ObjectStart& start, PovObject& out);
void give_light_groups_new_ids(Parser& p, PovObject& o);

}  // namespace glint::pov
