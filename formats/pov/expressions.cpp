// POV-Ray expressions (reference manual 3.2.1 "Language Basics", express.cpp in POV-Ray):
// numbers carry 1..5 components and promote like POV-Ray's Promote_Express (a float fills
// every component, a shorter vector pads with zeros); strings are a separate kind.
#include <cmath>
#include <cstdio>
#include <unordered_set>

#include "core/noise.h"
#include "formats/pov/expr_parser.h"

namespace glint::pov {

std::string value_kind_name(const Value& v) {
    switch (v.index()) {
        case 0: {
            int t = std::get<Num>(v).terms;
            return t == 1 ? "a float" : t == 2 ? "a 2-d vector" : t == 3 ? "a vector"
                                      : t == 4 ? "a 4-d vector" : "a color";
        }
        case 1: return "a string";
        case 2: return "an object";
        case 3: return "a texture";
        case 4: return "a pigment";
        case 5: return "a finish";
        case 6: return "a normal";
        case 7: return "an interior";
        case 8: return "a material";
        case 9: return "a camera";
        case 10: return "a transform";
        case 11: return "a macro";
        case 12: return "an array";
        case 13: return "a function";
        case 14: return "a spline";
        case 15: return "a file handle";
        case 16: return "a " + std::get<BlendMapValue>(v).keyword;
        case 17: return "a sky_sphere";
        case 18: return "a media";
    }
    return "a value";
}


const std::unordered_set<std::string>& color_keywords() {
    static const std::unordered_set<std::string> k = {
        "color", "colour", "rgb", "rgbf", "rgbt", "rgbft", "srgb", "srgbf", "srgbt", "srgbft",
        "red", "green", "blue", "filter", "transmit"};
    return k;
}

const std::unordered_set<std::string>& function_names() {
    static const std::unordered_set<std::string> k = {
        "abs", "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh",
        "asinh", "acosh", "atanh", "sqrt", "pow", "exp", "log", "ln", "floor", "ceil", "int",
        "mod", "div", "min", "max", "degrees", "radians", "vlength", "vdot", "vnormalize",
        "vcross", "vrotate", "vaxis_rotate", "select", "strlen", "val", "asc", "strcmp",
        "defined", "str", "concat", "chr", "substr", "strupr", "strlwr", "bitwise_and",
        "bitwise_or", "bitwise_xor", "odd", "even", "sqr", "file_exists", "seed", "rand",
        "dimensions", "dimension_size", "vturbulence", "vstr", "datetime"};
    return k;
}

const std::unordered_set<std::string>& constant_names() {
    static const std::unordered_set<std::string> k = {
        "x", "y", "z", "t", "u", "v", "pi", "tau", "true", "false", "yes", "no", "on", "off",
        "clock", "clock_delta", "clock_on", "initial_clock", "final_clock", "initial_frame",
        "final_frame", "frame_number", "image_width", "image_height", "version"};
    return k;
}

int component_index(const std::string& s) {
    if (s == "x" || s == "u" || s == "red") return 0;
    if (s == "y" || s == "v" || s == "green") return 1;
    if (s == "z" || s == "blue") return 2;
    if (s == "t" || s == "filter") return 3;
    if (s == "transmit") return 4;
    if (s == "gray" || s == "grey") return -2;
    return -1;
}

// sRGB transfer function (IEC 61966-2-1), to linear.
double srgb_decode(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}



Value Parser::parse_expression_value() { return ExprParser(*this).expr(); }

// Floats and vectors where the grammar asks for one are additive expressions, as POV-Ray's
// Parse_Float and Parse_Vector read them (Parse_Rel_Factor): comparisons, & | and ?: need
// parentheses there, so `cone { 0, 1 <0, 2, 0>, 0 }` is a radius and then a point.
Num Parser::parse_num(int terms) {
    ExprParser e(*this);
    FileLoc at = e.start();
    Num n = e.num(e.additive(), terms == 1 ? "a float" : terms == 3 ? "a vector" : "a number",
                  at);
    n.promote(terms);
    return n;
}

double Parser::parse_float() {
    ExprParser e(*this);
    FileLoc at = e.start();
    return e.as_float(e.additive(), "a float", at);
}

// The whole expression grammar (POV-Ray's Parse_Express): #if, #while, #switch and #case
// conditions, inside their parentheses.
double Parser::parse_condition() {
    ExprParser e(*this);
    FileLoc at = e.start();
    return e.as_float(e.expr(), "a float", at);
}

double Parser::parse_float_in_angle_brackets() {
    ExprParser e(*this, 1);
    FileLoc at = e.start();
    return e.as_float(e.expr(), "a float", at);
}

Vec3 Parser::parse_vector() {
    Vec3 fast;
    if (try_literal_vector(fast)) return fast;
    Num n = parse_num(3);
    return n.vec3();
}

std::string Parser::parse_string() {
    const Token& t = next();
    if (t.kind == TokKind::String) return t.text;
    if (t.kind == TokKind::Word) {
        if (lookup(t.text)) {
            const Symbol& s = use_symbol(t);
            if (auto str = std::get_if<std::string>(&s.value)) return *str;
            fail("expected a string, got " + value_kind_name(s.value) + " '" + t.text + "'");
        }
        if (function_names().count(t.text)) {
            unget();
            Value v = ExprParser(*this).factor();
            if (auto str = std::get_if<std::string>(&v)) return *str;
            fail("expected a string, got " + value_kind_name(v));
        }
    }
    fail("expected a string, got " + got(t));
}

scene::ColorFT Parser::parse_color() {
    Num c = ExprParser(*this).color(5);
    return scene::ColorFT(Color(c.v[0], c.v[1], c.v[2]), c.v[3], c.v[4]);
}

Color Parser::parse_rgb() {
    Num c = ExprParser(*this).color(3);
    return Color(c.v[0], c.v[1], c.v[2]);
}

bool Parser::next_is_expression_start() {
    const Token& t = peek();
    switch (t.kind) {
        case TokKind::Number: return true;
        case TokKind::Symbol:
            return t.is_symbol('<') || t.is_symbol('(') || t.is("-") || t.is("+") || t.is("!");
        case TokKind::Word: {
            if (const Symbol* s = lookup(t.text))
                return s->unusable || std::holds_alternative<Num>(s->value) ||
                       std::holds_alternative<FunctionRef>(s->value) ||
                       std::holds_alternative<std::shared_ptr<const scene::Spline>>(s->value);
            return constant_names().count(t.text) > 0 || function_names().count(t.text) > 0 ||
                   color_keywords().count(t.text) > 0;
        }
        default: return false;
    }
}

bool Parser::float_constant(const std::string& name, double& out) const {
    if (!constant_names().count(name) || name.size() == 1) return false;  // x y z t u v
    Num n = std::get<Num>(ExprParser(const_cast<Parser&>(*this)).constant(name));
    if (n.terms != 1) return false;
    out = n.v[0];
    return true;
}

double Parser::allow_float(double fallback) {
    return next_is_expression_start() ? parse_float() : fallback;
}

}  // namespace glint::pov

namespace glint::pov {

// The object alone, with the scene's meshes (MeshRef indices stay valid) and one material.
scene::Scene Parser::one_object_scene(const PovObject& po) const {
    scene::Scene one;
    one.meshes = scene.meshes;
    one.functions = scene.functions;  // an isosurface's function and those it calls
    one.global.noise_generator = scene.global.noise_generator;
    one.materials.resize(1);
    if (!po.is_light) {
        one.objects.push_back(object_without_materials(po));
        one.objects.back().material = 0;
    }
    return one;
}

const scene::PreparedObject& Parser::prepared_object(const std::shared_ptr<const PovObject>& po) {
    auto it = prepared_objects_.find(po.get());
    if (it == prepared_objects_.end()) {
        // An object glint left out (its warning said so) is empty here: no bounds, no hits.
        scene::Scene one;
        if (po->left_out.empty()) one = one_object_scene(*po);
        it = prepared_objects_.emplace(po.get(), std::make_pair(po, options.prepare_object(one)))
                 .first;
    }
    return *it->second.second;
}


}  // namespace glint::pov
