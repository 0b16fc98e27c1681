// fog and rainbow statements (reference manual 3.4.4; parstxtr.cpp Parse_Fog and
// Parse_Rainbow). Values are left as POV-Ray leaves them after parsing: unit vectors, rainbow
// angles in radians with the width folded into the inner angle.
#include <algorithm>
#include <cmath>

#include "formats/pov/parser_impl.h"

namespace glint::pov {

void Parser::parse_fog() {
    expect_open("fog");
    FileLoc o = loc();
    scene::Fog fog;
    fog.loc = o;
    auto turb = [&]() { fog.turbulent = true; };
    for (;;) {
        const Token& t = next();
        if (t.is_symbol('}')) break;
        if (t.kind == TokKind::End) expect_close("fog", o);
        const std::string w = t.kind == TokKind::Word && !lookup(t.text) ? t.text : std::string();
        if (w == "color" || w == "colour" || w == "rgb" || w == "rgbf" || w == "rgbt" ||
            w == "rgbft" || w == "red" || w == "green" || w == "blue" || w == "filter" ||
            w == "transmit") {
            unget();
            fog.color = parse_color();
        } else if (w == "distance") {
            fog.distance = parse_float();
        } else if (w == "fog_type") {
            FileLoc l = loc();
            int type = to_int(parse_float());
            if (type != 1 && type != 2)
                diag.warning(l, "unknown fog type " + std::to_string(type) + " (1 or 2)");
            fog.type = type == 2 ? scene::FogType::Ground : scene::FogType::Constant;
        } else if (w == "fog_alt") {
            fog.alt = parse_float();
        } else if (w == "fog_offset") {
            fog.offset = parse_float();
        } else if (w == "turb_depth") {
            fog.turb_depth = parse_float();
        } else if (w == "up") {
            fog.up = parse_vector();
        } else if (w == "turbulence") {
            turb();
            fog.turbulence = parse_vector();
        } else if (w == "octaves") {
            turb();
            fog.octaves = std::clamp(to_int(parse_float()), 1, 10);
        } else if (w == "omega") {
            turb();
            fog.omega = parse_float();
        } else if (w == "lambda") {
            turb();
            fog.lambda = parse_float();
        } else if (w == "translate") {
            diag.warning(loc(), "a fog's up vector can't be translated");
            parse_vector();
        } else if (t.kind == TokKind::Word && lookup(t.text)) {
            // A declared float is a distance, anything else a color (CASE_FLOAT/CASE_COLOUR).
            const Symbol* sym = lookup(t.text);
            const Num* n = std::get_if<Num>(&sym->value);
            unget();
            if (n && n->terms == 1) {
                diag.warning(loc(), "fog: should use the distance keyword");
                fog.distance = parse_float();
            } else {
                fog.color = parse_color();
            }
        } else if (t.kind == TokKind::Number) {
            unget();
            diag.warning(loc(), "fog: should use the distance keyword");
            fog.distance = parse_float();
        } else {
            unget();
            Transform delta;
            if (!parse_transform_item(delta))
                fail("expected a fog item (distance, color, fog_type, ...), got " + got(next()));
            fog.up = delta.vector(fog.up);
        }
    }
    double len = length(fog.up);
    if (len > 0) fog.up = fog.up / len;
    scene.fogs.push_back(fog);
}

void Parser::parse_rainbow() {
    expect_open("rainbow");
    FileLoc o = loc();
    scene::Rainbow r;
    r.loc = o;
    r.antisolar = Vec3(0, 0, 0);
    bool have_falloff = false, have_arc = false;
    bool have_map = false;
    for (;;) {
        const Token& t = next();
        if (t.is_symbol('}')) break;
        if (t.kind == TokKind::End) expect_close("rainbow", o);
        const std::string w = t.kind == TokKind::Word && !lookup(t.text) ? t.text : std::string();
        if (w == "angle") {
            r.angle = parse_float();
        } else if (w == "direction") {
            r.antisolar = parse_vector();
        } else if (w == "color_map" || w == "colour_map") {
            expect_open(w.c_str());
            FileLoc mo = loc();
            r.color_map = parse_color_map_body();
            expect_close(w.c_str(), mo);
            have_map = true;
        } else if (w == "distance") {
            r.distance = parse_float();
        } else if (w == "jitter") {
            r.jitter = parse_float();
        } else if (w == "width") {
            r.width = parse_float();
        } else if (w == "up") {
            r.up = parse_vector();
        } else if (w == "falloff_angle" || w == "arc_angle") {
            peek();
            FileLoc l = loc();
            double a = parse_float();
            if (a < 0.0 || a > 360.0)
                fail_at(l, std::string("illegal ") + w + " in rainbow (use 0 to 360 degrees)");
            (w == "arc_angle" ? r.arc_angle : r.falloff_angle) = a * kPi / 360.0;
            (w == "arc_angle" ? have_arc : have_falloff) = true;
        } else {
            fail("expected a rainbow item (angle, width, direction, color_map, ...), got " +
                 got(t));
        }
    }
    if (have_arc && !have_falloff) r.falloff_angle = r.arc_angle;
    if (r.arc_angle < r.falloff_angle) fail_at(o, "arc angle is smaller than falloff angle in rainbow");
    r.falloff_width = r.arc_angle - r.falloff_angle;
    if (std::fabs(dot(r.antisolar, r.antisolar)) < kPovEpsilon)
        fail_at(o, "rainbow's direction vector is zero");
    if (std::fabs(dot(r.up, r.up)) < kPovEpsilon) fail_at(o, "rainbow's up vector is zero");
    r.antisolar = normalize(r.antisolar);
    r.up = normalize(r.up);
    if (std::fabs(1.0 - std::fabs(dot(r.up, r.antisolar))) < kPovEpsilon)
        fail_at(o, "rainbow's up and direction vector are co-linear");
    // Make up perpendicular to the antisolar direction.
    r.right = normalize(cross(r.up, r.antisolar));
    r.up = normalize(cross(r.antisolar, r.right));
    r.angle = (r.angle - 0.5 * r.width) * kPi / 180.0;
    r.width *= kPi / 180.0;
    if (!have_map) diag.warning(o, "rainbow without a color_map has no effect");
    scene.rainbows.push_back(r);
}

}  // namespace glint::pov
