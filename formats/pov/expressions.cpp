// POV-Ray expressions (reference manual 3.2.1 "Language Basics", express.cpp in POV-Ray):
// numbers carry 1..5 components and promote like POV-Ray's Promote_Express (a float fills
// every component, a shorter vector pads with zeros); strings are a separate kind.
#include <cmath>
#include <cstdio>
#include <functional>
#include <unordered_set>

#include "core/noise.h"
#include "formats/pov/parser_impl.h"

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
    }
    return "a value";
}

namespace {

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
        "dimensions", "dimension_size", "vturbulence", "vstr"};
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

}  // namespace

// Recursive-descent expression parser; one object per top-level call keeps the
// "inside <...>" state (where '>' closes the vector instead of comparing).
class ExprParser {
public:
    explicit ExprParser(Parser& p, int vector_depth = 0) : p_(p), vector_depth_(vector_depth) {}

    // String expressions have no operators in POV-Ray, so nothing is read after a string
    // (a string #declare needs no ';' even when a macro call follows it).
    static bool is_string(const Value& v) { return std::holds_alternative<std::string>(v); }

    Value expr() {
        Value c = logical();
        if (is_string(c) || !p_.accept("?")) return c;
        double cond = as_float(c, "a condition");
        Value a = expr();
        p_.expect(":", "in a ?: expression");
        Value b = expr();
        return cond != 0 ? a : b;
    }

    // `at`: where the value began, for the message; else the last token read.
    Num num(const Value& v, const char* what, const FileLoc& at = {}) {
        if (auto n = std::get_if<Num>(&v)) return *n;
        fail(at, std::string("expected ") + what + ", got " + value_kind_name(v));
    }
    double as_float(const Value& v, const char* what, const FileLoc& at = {}) {
        Num n = num(v, what, at);
        if (n.terms != 1) fail(at, std::string("expected ") + what + ", got " + value_kind_name(v));
        return n.v[0];
    }
    [[noreturn]] void fail(const FileLoc& at, const std::string& msg) {
        if (at.valid()) p_.fail_at(at, msg);
        p_.fail(msg);
    }
    FileLoc start() {
        p_.peek();
        return p_.loc();
    }

    Value logical() {
        Value a = relational();
        for (;;) {
            if (is_string(a)) return a;
            const Token& t = p_.next();
            if (t.is("&") || t.is("|")) {
                bool is_and = t.text == "&";
                double x = as_float(a, "a float operand of '&' or '|'");
                double y = as_float(relational(), "a float operand of '&' or '|'");
                a = Num::scalar(is_and ? (x != 0 && y != 0) : (x != 0 || y != 0));
            } else {
                p_.unget();
                return a;
            }
        }
    }

    Value relational() {
        Value a = additive();
        for (;;) {
            if (is_string(a)) {
                // Strings compare like strcmp (POV-Ray 3.7: "a" < "b", S = "", S != "").
                // Only a raw look: the token after a string may be a macro call, which
                // reading it would expand.
                bool op_next = false;
                for (const char* op : {"<", "<=", "=", "!=", ">=", ">"})
                    op_next |= p_.raw_next_is(op) && !(op[0] == '>' && op[1] == 0 &&
                                                       vector_depth_ > 0);
                if (op_next) {
                    const Token& t = p_.next();
                    std::string op = t.text;
                    Value b = additive();
                    if (!is_string(b)) p_.fail("expected a string to compare with a string");
                    int c = std::get<std::string>(a).compare(std::get<std::string>(b));
                    bool r = op == "<" ? c < 0 : op == "<=" ? c <= 0 : op == ">" ? c > 0
                           : op == ">=" ? c >= 0 : op == "=" ? c == 0 : c != 0;
                    a = Num::scalar(r ? 1 : 0);
                    continue;
                }
                return a;
            }
            const Token& t = p_.next();
            if (t.kind == TokKind::Symbol && std::get<Num>(a).terms == 1 &&
                (t.text == "<" || t.text == "<=" || t.text == "=" || t.text == "!=" ||
                 t.text == ">=" || (t.text == ">" && vector_depth_ == 0))) {
                std::string op = t.text;
                double x = as_float(a, "a float to compare (vectors cannot be compared)");
                double y = as_float(additive(), "a float to compare");
                bool r = op == "<" ? x < y : op == "<=" ? x <= y : op == ">" ? x > y
                       : op == ">=" ? x >= y : op == "=" ? std::fabs(x - y) < 1e-10
                       : std::fabs(x - y) >= 1e-10;
                a = Num::scalar(r ? 1 : 0);
            } else {
                p_.unget();
                return a;
            }
        }
    }

    // Overflow (1e300 * 1e300) or inf - inf would carry NaN or infinity into the scene.
    void check_finite(const Num& r, const FileLoc& l, const std::string& what) const {
        for (int i = 0; i < r.terms; ++i)
            if (!std::isfinite(r.v[i]))
                p_.fail_at(l, "the result of " + what + " is not a finite number (overflow)");
    }

    static Num combine(Num a, Num b, char op) {
        int n = std::max(a.terms, b.terms);
        a.promote(n);
        b.promote(n);
        for (int i = 0; i < 5; ++i) {
            double x = a.v[i], y = b.v[i];
            a.v[i] = op == '+' ? x + y : op == '-' ? x - y : op == '*' ? x * y : x / y;
        }
        return a;
    }

    Value additive() {
        Value a = multiplicative();
        for (;;) {
            if (is_string(a)) return a;
            const Token& t = p_.next();
            if (t.is("+") || t.is("-")) {
                char op = t.text[0];
                FileLoc op_loc = p_.loc();
                Num x = num(a, "a number before '+' or '-'");
                Num y = num(multiplicative(), "a number after '+' or '-'");
                Num r = combine(x, y, op);
                check_finite(r, op_loc, std::string("'") + op + "'");
                a = r;
            } else {
                p_.unget();
                return a;
            }
        }
    }

    Value multiplicative() {
        Value a = unary();
        for (;;) {
            if (is_string(a)) return a;
            const Token& t = p_.next();
            if (t.is("*") || t.is("/")) {
                char op = t.text[0];
                FileLoc op_loc = p_.loc();
                Num x = num(a, "a number before '*' or '/'");
                Num y = num(unary(), "a number after '*' or '/'");
                if (op == '/') {
                    for (int i = 0; i < y.terms; ++i)
                        if (y.v[i] == 0) p_.fail_at(op_loc, "division by zero");
                }
                Num r = combine(x, y, op);
                check_finite(r, op_loc, std::string("'") + op + "'");
                a = r;
            } else {
                p_.unget();
                return a;
            }
        }
    }

    Value unary() {
        // How deeply `((((...` or `<<<<...` may nest is bounded by the parser's stack budget
        // (Parser::next), like every other kind of nesting.
        const Token& t = p_.next();
        if (t.is("-")) {
            Num n = num(unary(), "a number after '-'");
            for (double& c : n.v) c = -c;
            return n;
        }
        if (t.is("+")) return num(unary(), "a number after '+'");
        if (t.is("!")) return Num::scalar(as_float(unary(), "a float after '!'") == 0 ? 1 : 0);
        p_.unget();
        return postfix();
    }

    Value postfix() {
        Value v = factor();
        for (;;) {
            if (is_string(v)) return v;
            const Token& t = p_.next();
            if (!t.is_symbol('.')) {
                p_.unget();
                return v;
            }
            const Token& c = p_.next();
            int idx = c.kind == TokKind::Word ? component_index(c.text) : -1;
            if (idx == -1) p_.fail("expected a component name (x, y, z, red, ...) after '.'");
            Num n = num(v, "a vector or color before '.'");
            if (idx == -2) {
                // POV-Ray's grey value weights (colour.h, GREY_SCALE).
                v = Num::scalar(0.297 * n.v[0] + 0.589 * n.v[1] + 0.114 * n.v[2]);
            } else {
                if (n.terms == 1 || idx >= n.terms)
                    p_.fail("'." + c.text + "' needs a value with at least " +
                            std::to_string(idx + 1) + " components, got " + value_kind_name(v));
                v = Num::scalar(n.v[idx]);
            }
        }
    }

    Value factor() {
        const Token& t = p_.next();
        switch (t.kind) {
            case TokKind::Number: return Num::scalar(t.number);
            case TokKind::String: return t.text;
            case TokKind::Symbol:
                if (t.is_symbol('(')) {
                    int saved = vector_depth_;
                    vector_depth_ = 0;
                    Value v = expr();
                    vector_depth_ = saved;
                    p_.expect(")", "to close the parenthesis");
                    return v;
                }
                if (t.is_symbol('<')) return vector_literal();
                p_.fail("expected a value, got " + p_.got(t));
            case TokKind::Word: return word(t);
            default: p_.fail("expected a value, got " + p_.got(t));
        }
    }

    Value vector_literal() {
        Num n;
        n.terms = 0;
        ++vector_depth_;
        for (;;) {
            if (n.terms == 5) p_.fail("a vector has at most 5 components");
            n.v[n.terms++] = as_float(expr(), "a float vector component");
            const Token& t = p_.next();
            if (t.is(">")) break;
            // POV-Ray's Parse_Comma: the comma between components is optional.
            if (!t.is(",")) {
                p_.unget();
                if (!p_.next_is_expression_start())
                    p_.fail("expected ',' or '>' in the vector, got " + p_.got(p_.next()));
            } else if (p_.accept(">")) {
                break;  // a trailing comma: <0.2, 0.1, 0.5,> (POV-Ray accepts it)
            }
        }
        --vector_depth_;
        if (n.terms < 2) p_.fail("a vector needs at least 2 components");
        return n;
    }

    Value word(const Token& t) {
        if (const Symbol* s = p_.lookup(t.text)) {
            const Symbol& sym = p_.use_symbol(t);
            (void)s;
            if (auto fr = std::get_if<FunctionRef>(&sym.value)) {
                int index = fr->index;
                std::string name = t.text;
                FileLoc at = p_.loc();
                return p_.call_function_now(index, name, at);
            }
            if (auto sp = std::get_if<std::shared_ptr<const scene::Spline>>(&sym.value)) {
                auto keep = *sp;
                std::string name = t.text;
                return p_.call_spline_now(*keep, name);
            }
            if (std::holds_alternative<Num>(sym.value) ||
                std::holds_alternative<std::string>(sym.value))
                return sym.value;
            p_.fail("expected a number or string, got " + value_kind_name(sym.value) + " '" +
                    t.text + "'");
        }
        const std::string& w = t.text;
        if (color_keywords().count(w)) {
            p_.unget();
            return color(5);
        }
        if (constant_names().count(w)) return constant(w);
        if (function_names().count(w)) return function(w);
        if ((w == "trace" || w == "min_extent" || w == "max_extent") && p_.options.object_query)
            return object_function(w);
        if (w == "inside" || w == "eval_pigment") {
            // inside(Obj, P) and eval_pigment(Pig, P): read, warned about once, and 0.
            warn_unsupported(p_, w + "()", p_.loc(), "it gives 0");
            p_.expect("(", ("after '" + w + "'").c_str());
            p_.next();  // the object or pigment identifier
            p_.expect(",", ("after the first argument of " + w + "()").c_str());
            p_.parse_vector();
            p_.expect(")", ("to close " + w + "()").c_str());
            return w == "inside" ? Value(Num::scalar(0)) : Value(Num::vec(Vec3(0, 0, 0)));
        }
        static const std::unordered_set<std::string> kUnsupportedFns = {
            "eval_pigment", "trace", "inside", "min_extent",
            "max_extent", "datetime", "now"};
        if (kUnsupportedFns.count(w)) p_.unsupported("the '" + w + "' function");
        p_.fail("unknown identifier '" + w + "'");
    }

    Value constant(const std::string& w) {
        if (w == "x") return Num::vec({1, 0, 0});
        if (w == "y") return Num::vec({0, 1, 0});
        if (w == "z") return Num::vec({0, 0, 1});
        if (w == "t") return Num{{0, 0, 0, 1, 0}, 4};
        if (w == "u") return Num{{1, 0, 0, 0, 0}, 2};
        if (w == "v") return Num{{0, 1, 0, 0, 0}, 2};
        if (w == "pi") return Num::scalar(kPi);
        if (w == "tau") return Num::scalar(2 * kPi);
        if (w == "true" || w == "yes" || w == "on") return Num::scalar(1);
        if (w == "false" || w == "no" || w == "off") return Num::scalar(0);
        const ParseOptions& o = p_.options;
        if (w == "clock") return Num::scalar(o.clock);
        if (w == "initial_clock") return Num::scalar(o.initial_clock.value_or(o.clock));
        if (w == "final_clock") return Num::scalar(o.final_clock.value_or(o.clock));
        if (w == "clock_delta") return Num::scalar(o.clock_delta);
        if (w == "clock_on") return Num::scalar(o.clock_on ? 1 : 0);
        if (w == "initial_frame") return Num::scalar(o.initial_frame);
        if (w == "final_frame") return Num::scalar(o.final_frame);
        if (w == "frame_number") return Num::scalar(o.frame_number);
        if (w == "image_width") return Num::scalar(p_.options.image_width);
        if (w == "image_height") return Num::scalar(p_.options.image_height);
        return Num::scalar(p_.version);  // version
    }

    std::vector<Value> args(const std::string& name) {
        p_.expect("(", ("after '" + name + "'").c_str());
        std::vector<Value> out;
        if (p_.accept(")")) return out;
        for (;;) {
            int saved = vector_depth_;
            vector_depth_ = 0;
            out.push_back(expr());
            vector_depth_ = saved;
            const Token& t = p_.next();
            if (t.is(")")) return out;
            if (!t.is(","))
                p_.fail("expected ',' or ')' in the arguments of '" + name + "', got " +
                        p_.got(t));
        }
    }

    // trace(Obj, start, dir [, NormalVar]), min_extent(Obj), max_extent(Obj): answered by the
    // application's geometry (ParseOptions::object_query) for a scene holding only Obj.
    Value object_function(const std::string& f) {
        const FileLoc fn_loc = p_.loc();
        p_.expect("(", ("after '" + f + "'").c_str());
        const Token& t = p_.next();
        const Symbol* s = t.kind == TokKind::Word ? p_.lookup(t.text) : nullptr;
        if (s) s = &p_.use_symbol(t);
        auto obj = s ? std::get_if<std::shared_ptr<const PovObject>>(&s->value) : nullptr;
        if (!obj) p_.fail("expected an object identifier in " + f + "(), got " + p_.got(t));
        auto keep = *obj;
        // An object glint left out (its warning said so) is empty here: no bounds, no hits.
        scene::Scene one;
        if (keep->left_out.empty()) one = p_.one_object_scene(*keep);
        Vec3 lo, hi;
        if (f != "trace") {
            p_.expect(")", ("to close " + f + "()").c_str());
            bool ok = p_.options.object_query(one, kObjectBounds, Vec3(), Vec3(), lo, hi);
            // POV-Ray's bounding boxes of unbounded objects are large, not infinite.
            auto clamp = [](double v) { return std::clamp(v, -1e10, 1e10); };
            Vec3 r = f == "min_extent" ? lo : hi;
            if (!ok) r = Vec3(0, 0, 0);
            return Value(Num::vec(Vec3(clamp(r.x), clamp(r.y), clamp(r.z))));
        }
        p_.expect(",", "after the object in trace()");
        Vec3 from = p_.parse_vector();
        p_.expect(",", "after the start point in trace()");
        Vec3 dir = p_.parse_vector();
        std::string normal_var;
        FileLoc nloc;
        if (p_.accept(",")) {
            const Token& n = p_.next();
            if (n.kind != TokKind::Word)
                p_.fail("expected an identifier for the normal in trace(), got " + p_.got(n));
            normal_var = n.text;
            nloc = p_.loc();
        }
        p_.expect(")", "to close trace()");
        (void)fn_loc;
        bool hit = length(dir) > 0 && p_.options.object_query(one, kObjectTrace, from, dir, lo, hi);
        if (!hit) lo = hi = Vec3(0, 0, 0);
        if (!normal_var.empty()) p_.assign_existing_or_declare(normal_var, Num::vec(hi), nloc);
        return Value(Num::vec(lo));
    }

    Value function(const std::string& f) {
        // Errors in a call point at the function's name.
        const FileLoc fn_loc = p_.loc();
        if (f == "defined") {
            p_.expect("(", "after 'defined'");
            const Token& t = p_.next();
            bool d = t.kind == TokKind::Word && p_.lookup(t.text) != nullptr;
            p_.expect(")", "after the identifier in defined()");
            return Num::scalar(d ? 1 : 0);
        }
        if (f == "dimensions" || f == "dimension_size") {
            p_.expect("(", ("after '" + f + "'").c_str());
            const Token& t = p_.next();
            const Symbol* s = t.kind == TokKind::Word ? p_.lookup(t.text) : nullptr;
            auto arr = s ? std::get_if<std::shared_ptr<ArrayValue>>(&s->value) : nullptr;
            if (!arr) p_.fail_at(fn_loc, "expected an array identifier in " + f + "(), got " + p_.got(t));
            auto keep = *arr;
            double r = static_cast<double>(keep->sizes.size());
            if (f == "dimension_size") {
                p_.expect(",", "in dimension_size()");
                int d = to_int(p_.parse_float());
                if (d < 1 || d > static_cast<int>(keep->sizes.size()))
                    p_.fail_at(fn_loc, "dimension_size: the array has no dimension " + std::to_string(d));
                r = keep->sizes[d - 1];
            }
            p_.expect(")", ("to close " + f + "()").c_str());
            return Num::scalar(r);
        }
        std::vector<Value> a = args(f);
        auto need = [&](size_t n) {
            if (a.size() != n)
                p_.fail_at(fn_loc, "'" + f + "' takes " + std::to_string(n) + " argument(s), got " +
                        std::to_string(a.size()));
        };
        auto F = [&](size_t i) { return as_float(a[i], ("a float argument of " + f).c_str()); };
        auto V = [&](size_t i) {
            Num n = num(a[i], ("a vector argument of " + f).c_str());
            n.promote(3);
            return n.vec3();
        };
        auto S = [&](size_t i) -> std::string {
            if (auto s = std::get_if<std::string>(&a[i])) return *s;
            p_.fail_at(fn_loc, "expected a string argument of '" + f + "', got " + value_kind_name(a[i]));
        };
        auto R = [](double r) { return Value(Num::scalar(r)); };
        static const std::unordered_map<std::string, double (*)(double)> unary = {
            {"abs", [](double x) { return std::fabs(x); }},
            {"sin", [](double x) { return std::sin(x); }},
            {"cos", [](double x) { return std::cos(x); }},
            {"tan", [](double x) { return std::tan(x); }},
            {"asin", [](double x) { return std::asin(x); }},
            {"acos", [](double x) { return std::acos(x); }},
            {"sinh", [](double x) { return std::sinh(x); }},
            {"cosh", [](double x) { return std::cosh(x); }},
            {"tanh", [](double x) { return std::tanh(x); }},
            {"asinh", [](double x) { return std::asinh(x); }},
            {"acosh", [](double x) { return std::acosh(x); }},
            {"atanh", [](double x) { return std::atanh(x); }},
            {"exp", [](double x) { return std::exp(x); }},
            {"floor", [](double x) { return std::floor(x); }},
            {"ceil", [](double x) { return std::ceil(x); }},
            {"int", [](double x) { return std::trunc(x); }},
            {"degrees", [](double x) { return x * 180.0 / kPi; }},
            {"radians", [](double x) { return x * kPi / 180.0; }},
            {"sqr", [](double x) { return x * x; }},
            {"odd", [](double x) { return std::fmod(std::trunc(x), 2.0) != 0 ? 1.0 : 0.0; }},
            {"even", [](double x) { return std::fmod(std::trunc(x), 2.0) == 0 ? 1.0 : 0.0; }},
        };
        if (auto it = unary.find(f); it != unary.end()) {
            need(1);
            const double r = it->second(F(0));
            if (!std::isfinite(r))
                p_.fail_at(fn_loc, "the result of " + f + "() is not a finite number (overflow)");
            return R(r);
        }
        if (f == "atan") {
            if (a.size() == 2) return R(std::atan2(F(0), F(1)));
            need(1);
            return R(std::atan(F(0)));
        }
        if (f == "sqrt") {
            need(1);
            if (F(0) < 0) p_.fail_at(fn_loc, "sqrt of a negative number");
            return R(std::sqrt(F(0)));
        }
        if (f == "log" || f == "ln") {
            need(1);
            if (F(0) <= 0) p_.fail_at(fn_loc, f + " of a number that is not positive");
            return R(f == "log" ? std::log10(F(0)) : std::log(F(0)));
        }
        if (f == "atan2") { need(2); return R(std::atan2(F(0), F(1))); }
        if (f == "pow") { need(2); return R(std::pow(F(0), F(1))); }
        if (f == "mod") {
            need(2);
            if (F(1) == 0) p_.fail_at(fn_loc, "mod by zero");
            return R(std::fmod(F(0), F(1)));
        }
        if (f == "div") {
            need(2);
            if (F(1) == 0) p_.fail_at(fn_loc, "div by zero");
            return R(std::trunc(F(0) / F(1)));
        }
        if (f == "bitwise_and" || f == "bitwise_or" || f == "bitwise_xor") {
            need(2);
            long long x = to_long_long(F(0)), y = to_long_long(F(1));
            return R(static_cast<double>(f == "bitwise_and" ? (x & y)
                                         : f == "bitwise_or" ? (x | y) : (x ^ y)));
        }
        if (f == "min" || f == "max") {
            if (a.empty()) p_.fail_at(fn_loc, "'" + f + "' needs at least one argument");
            double r = F(0);
            for (size_t i = 1; i < a.size(); ++i) r = f == "min" ? std::min(r, F(i)) : std::max(r, F(i));
            return R(r);
        }
        if (f == "select") {
            if (a.size() != 3 && a.size() != 4) p_.fail_at(fn_loc, "'select' takes 3 or 4 arguments");
            double c = F(0);
            if (a.size() == 3) return c < 0 ? a[1] : a[2];
            return c < 0 ? a[1] : c == 0 ? a[2] : a[3];
        }
        if (f == "vturbulence") {
            // vturbulence(lambda, omega, octaves, point): POV-Ray's DTurbulence.
            need(4);
            TurbulenceParams turb;
            turb.lambda = F(0);
            turb.omega = F(1);
            turb.octaves = std::clamp(to_int(F(2)), 1, 10);
            return Value(Num::vec(dturbulence(V(3), turb)));
        }
        if (f == "vlength") { need(1); return R(length(V(0))); }
        if (f == "vdot") { need(2); return R(dot(V(0), V(1))); }
        if (f == "vcross") { need(2); return Value(Num::vec(cross(V(0), V(1)))); }
        if (f == "vnormalize") {
            need(1);
            Vec3 v = V(0);
            if (length(v) == 0) p_.fail_at(fn_loc, "vnormalize of a zero-length vector");
            return Value(Num::vec(normalize(v)));
        }
        if (f == "vrotate") {
            need(2);
            return Value(Num::vec(Transform::rotate_xyz_degrees(V(1)).vector(V(0))));
        }
        if (f == "vaxis_rotate") {
            need(3);
            return Value(Num::vec(Transform::rotate_axis(V(1), F(2)).vector(V(0))));
        }
        if (f == "seed") {
            // POV-Ray's random streams (express.cpp stream_seed / randomsequences.cpp).
            need(1);
            p_.rand_streams.push_back(static_cast<uint32_t>(to_int(F(0))));
            return R(static_cast<double>(p_.rand_streams.size() - 1));
        }
        if (f == "rand") {
            need(1);
            int i = to_int(F(0));
            if (i < 0 || i >= static_cast<int>(p_.rand_streams.size()))
                p_.fail_at(fn_loc, "rand(): no random stream " + std::to_string(i) + " (use seed())");
            uint32_t& n = p_.rand_streams[i];
            n = n * 1812433253u + 12345u;
            return R(static_cast<double>(n) / 4294967295.0);
        }
        if (f == "strlen") { need(1); return R(static_cast<double>(S(0).size())); }
        if (f == "val") { need(1); return R(std::strtod(S(0).c_str(), nullptr)); }
        if (f == "asc") { need(1); return R(S(0).empty() ? 0 : static_cast<unsigned char>(S(0)[0])); }
        if (f == "strcmp") { need(2); int c = S(0).compare(S(1)); return R(c < 0 ? -1 : c > 0 ? 1 : 0); }
        if (f == "file_exists") {
            need(1);
            std::FILE* fp = std::fopen(S(0).c_str(), "rb");
            if (fp) std::fclose(fp);
            return R(fp ? 1 : 0);
        }
        if (f == "str") {
            need(3);
            // The text is at most 511 bytes, so wider fields and longer fractions change
            // nothing but the time snprintf takes: both are bounded (2^31 wide would hang).
            int w = std::clamp(to_int(F(1)), -511, 511), prec = std::min(to_int(F(2)), 511);
            char buf[512];
            if (prec < 0) prec = 6;
            if (w < 0)
                std::snprintf(buf, sizeof buf, "%0*.*f", -w, prec, F(0));
            else
                std::snprintf(buf, sizeof buf, "%*.*f", w, prec, F(0));
            return std::string(buf);
        }
        if (f == "vstr") {
            // vstr(N, V, separator, width, precision): N components of V, each like str().
            need(5);
            Num n = num(a[1], "a vector argument of vstr");
            int count = std::clamp(to_int(F(0)), 2, 5);
            n.promote(count);
            int w = std::clamp(to_int(F(3)), -511, 511), prec = std::min(to_int(F(4)), 511);
            if (prec < 0) prec = 6;
            std::string sep = S(2), r;
            for (int i = 0; i < count; ++i) {
                char buf[512];
                if (w < 0)
                    std::snprintf(buf, sizeof buf, "%0*.*f", -w, prec, n.v[i]);
                else
                    std::snprintf(buf, sizeof buf, "%*.*f", w, prec, n.v[i]);
                if (i > 0) r += sep;
                r += buf;
            }
            return r;
        }
        if (f == "concat") {
            std::string r;
            for (size_t i = 0; i < a.size(); ++i) {
                const std::string& part = S(i);
                if (static_cast<long long>(r.size() + part.size()) > p_.options.max_string_length)
                    p_.fail_limit(fn_loc,
                                  "concat() would make a string longer than " +
                                      std::to_string(p_.options.max_string_length) + " bytes",
                                  "--max-string-length");
                r += part;
            }
            return r;
        }
        if (f == "chr") { need(1); return std::string(1, static_cast<char>(to_int(F(0)))); }
        if (f == "substr") {
            need(3);
            std::string s = S(0);
            int pos = to_int(F(1)), len = to_int(F(2));
            if (pos < 1 || len < 0 || pos - 1LL + len > static_cast<long long>(s.size()))
                p_.fail_at(fn_loc, "substr range is outside the string");
            return s.substr(pos - 1, len);
        }
        if (f == "strupr" || f == "strlwr") {
            need(1);
            std::string s = S(0);
            for (char& c : s) c = f == "strupr" ? std::toupper(c) : std::tolower(c);
            return s;
        }
        p_.fail_at(fn_loc, "function '" + f + "' is not supported");
    }

    // POV-Ray's Parse_Colour: keywords and expressions in any combination; `ft_terms` is 5
    // where filter/transmit count (pigments), 3 where only RGB does (lights, finishes).
    Num color(int ft_terms) {
        Num c{{0, 0, 0, 0, 0}, 5};
        p_.accept("color") || p_.accept("colour");
        bool started = false;
        for (;;) {
            const Token& t = p_.next();
            if (t.kind != TokKind::Word && !t.is_symbol('<') && !t.is_symbol('(') &&
                t.kind != TokKind::Number && !t.is("-") && !t.is("+")) {
                p_.unget();
                break;
            }
            std::string w = t.kind == TokKind::Word ? t.text : std::string();
            bool ident = t.kind == TokKind::Word && p_.lookup(w) != nullptr;
            int n = 0;
            bool srgb = false, swap_t = false;
            if (!ident && (w == "rgb" || w == "srgb")) n = 3, srgb = w == "srgb";
            else if (!ident && (w == "rgbf" || w == "srgbf")) n = 4, srgb = w == "srgbf";
            else if (!ident && (w == "rgbt" || w == "srgbt")) n = 4, srgb = w == "srgbt", swap_t = true;
            else if (!ident && (w == "rgbft" || w == "srgbft")) n = 5, srgb = w == "srgbft";
            if (n > 0) {
                if (started) { p_.unget(); break; }
                Num e = num(expr(), ("a color after '" + w + "'").c_str());
                e.promote(n);
                for (int i = 0; i < e.terms && i < 5; ++i) c.v[i] = e.v[i];
                if (swap_t) { c.v[4] = c.v[3]; c.v[3] = 0; }
                if (srgb) {
                    double g = p_.scene.global.assumed_gamma.value_or(1.0);
                    for (int i = 0; i < 3; ++i) c.v[i] = std::pow(srgb_decode(c.v[i]), 1.0 / g);
                }
                started = true;
                continue;
            }
            int key = ident ? -1 : w == "red" ? 0 : w == "green" ? 1 : w == "blue" ? 2
                                 : w == "filter" ? 3 : w == "transmit" ? 4 : -1;
            if (key >= 0) {
                c.v[key] = as_float(expr(), ("a float after '" + w + "'").c_str());
                started = true;
                continue;
            }
            bool starts_expr = t.kind != TokKind::Word || ident || constant_names().count(w) ||
                               function_names().count(w);
            if (!starts_expr || started) {
                p_.unget();
                break;
            }
            p_.unget();
            Num e = num(expr(), "a color expression");
            e.promote(ft_terms);
            for (int i = 0; i < e.terms && i < 5; ++i) c.v[i] = e.v[i];
            started = true;
        }
        if (!started) p_.fail("expected a color, got " + p_.got(*p_next_peek()));
        return c;
    }

    const Token* p_next_peek() { return &p_.peek(); }

private:
    Parser& p_;
    int vector_depth_ = 0;
};

Value Parser::parse_expression_value() { return ExprParser(*this).expr(); }

Num Parser::parse_num(int terms) {
    ExprParser e(*this);
    FileLoc at = e.start();
    Num n = e.num(e.expr(), terms == 1 ? "a float" : terms == 3 ? "a vector" : "a number", at);
    n.promote(terms);
    return n;
}

double Parser::parse_float() {
    ExprParser e(*this);
    FileLoc at = e.start();
    return e.as_float(e.expr(), "a float", at);
}

double Parser::parse_float_no_compare() {
    ExprParser e(*this);
    FileLoc at = e.start();
    return e.as_float(e.additive(), "a float", at);
}

double Parser::parse_float_in_angle_brackets() {
    ExprParser e(*this, 1);
    FileLoc at = e.start();
    return e.as_float(e.expr(), "a float", at);
}

// Meshes are long lists of literal vectors; reading `<n, n, n>` straight from the token array
// (when nothing can follow that would make it part of a larger expression) keeps a 100k-face
// mesh2 fast. Anything else takes the general path.
bool Parser::try_literal_vector(Vec3& out) {
    if (ungot_ || frames_.empty()) return false;
    Frame& f = frames_.back();
    const auto& t = files_[f.file]->tokens;
    size_t i = f.pos;
    if (!t[i].is_symbol('<')) return false;
    ++i;
    double v[3];
    for (int k = 0; k < 3; ++k) {
        double sign = 1;
        if (t[i].is_symbol('-')) {
            sign = -1;
            ++i;
        }
        if (t[i].kind != TokKind::Number) return false;
        v[k] = sign * t[i].number;
        ++i;
        if (k < 2) {
            if (!t[i].is_symbol(',')) return false;
            ++i;
        }
    }
    if (!t[i].is_symbol('>')) return false;
    const Token& n = t[i + 1];
    if (n.kind == TokKind::Symbol && !(n.is_symbol(',') || n.is_symbol('}') || n.is_symbol(')') ||
                                       n.is_symbol(']') || n.is_symbol(';')))
        return false;
    token_count_ += static_cast<long long>(i + 1 - f.pos);
    f.pos = i + 1;
    cur_ = &t[i];
    cur_file_ = f.file;
    out = Vec3(v[0], v[1], v[2]);
    return true;
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
    one.materials.resize(1);
    std::function<scene::Object(const PovObject&, bool)> conv = [&](const PovObject& p, bool top) {
        scene::Object o = p.obj;
        o.material = top ? 0 : -1;
        if (auto csg = std::get_if<scene::Csg>(&o.shape)) {
            csg->children.clear();
            for (const auto& c : p.children) csg->children.push_back(conv(c, false));
        }
        return o;
    };
    if (!po.is_light) one.objects.push_back(conv(po, true));
    return one;
}

void Parser::assign_existing_or_declare(const std::string& name, Value v, const FileLoc& at) {
    for (size_t k = scopes_.size(); k-- > 0;) {
        auto e = scopes_[k].find(name);
        if (e != scopes_[k].end()) {
            e->second.value = std::move(v);
            e->second.loc = at;
            return;
        }
    }
    declare(name, std::move(v), at, false);
}

}  // namespace glint::pov
