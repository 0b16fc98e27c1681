// TrueType glyph outlines laid out as POV-Ray 3.7's text object lays them out (truetype.cpp
// ProcessNewTTF): outlines through FreeType in font units scaled to 1 em, glyph placement from
// the hmtx and kern tables, the offset vector added after each character. Used by the text
// primitive (text.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"

namespace glint::render {

// One closed contour as stored in the font: points with their on-curve flags, the first point
// repeated at the end (POV-Ray walks contours that way, off-curve first points included).
struct GlyphContour {
    std::vector<Vec2> p;
    std::vector<uint8_t> on_curve;
};

struct Glyph {
    std::vector<GlyphContour> contours;
    Vec2 offset;  // where the glyph's outline sits in the text's space
    Vec2 lo, hi;  // outline bounds, in the glyph's own space
    // +1 when the filled side lies right of the contour direction (TrueType's clockwise outer
    // contours), -1 for fonts wound the other way; makes side normals point out of the solid.
    double winding = 1;
};

struct TextGlyphs {
    std::vector<Glyph> glyphs;  // one per character, spaces included (without contours)
};

// Lays `text` (one character per byte, POV-Ray's default ASCII charset) out in the font at
// `font_path`, `offset` added after each character. Throws glint::Error (MissingFile) when
// the file cannot be read as a TrueType font.
TextGlyphs layout_text(const std::string& font_path, const std::string& text, const Vec3& offset);

}  // namespace glint::render
