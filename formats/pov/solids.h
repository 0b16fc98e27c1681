// The bodies of POV-Ray's spline, implicit and image solids (parse.cpp: Parse_Quadric,
// Parse_Polygon, Parse_Prism, Parse_Lathe, Parse_Sor, Parse_Superellipsoid, Parse_Blob,
// Parse_HField, Parse_Poly, Parse_Polynom, Parse_Sphere_Sweep, Parse_Parametric). Called by
// parse_object (objects.cpp) after the opening brace; the object modifiers that follow are
// parsed there.
#pragma once

#include <string>

#include "formats/pov/parser_impl.h"

namespace glint::pov {

bool is_solid_keyword(const std::string& word);

// After `isosurface {` (isosurface_grammar.cpp).
scene::Isosurface parse_isosurface(Parser& p, const FileLoc& kw);

// contained_by { box { C1, C2 } | sphere { C, R } | } after the keyword, as isosurface and
// parametric read it: the box's corners sorted per axis; an empty body changes nothing.
void parse_contained_by(Parser& p, scene::Container* c);

// After `parametric {` (parametric_grammar.cpp); `kw`: the keyword's location.
scene::Parametric parse_parametric(Parser& p, const FileLoc& kw);


// Parses the body of the solid named `word` into `out`. `kw`: the keyword's location. A body
// glint cannot render (a height_field from a function) is read over with a warning and named
// in `left_out`, which makes the caller drop the object.
void parse_solid_body(Parser& p, const std::string& word, const FileLoc& kw, scene::Shape* out,
                      std::string* left_out);

}  // namespace glint::pov
