// The expression parser of the POV-Ray importer (reference manual 3.2.1 "Language Basics",
// express.cpp in POV-Ray): one ExprParser per top-level expression, over the Parser's tokens.
// The grammar is in this class; the built-in functions (sin ... vturbulence) are in
// builtin_functions.cpp; Parser's entry points (parse_float, parse_vector, ...) in
// expressions.cpp.
#pragma once

#include <ctime>
#include <string>
#include <unordered_set>
#include <vector>

#include "formats/pov/parser_impl.h"

namespace glint::pov {

// The words that start a colour, name a built-in function or a built-in constant.
const std::unordered_set<std::string>& color_keywords();
const std::unordered_set<std::string>& function_names();
const std::unordered_set<std::string>& constant_names();
// x/u/red -> 0, y/v/green -> 1, z/blue -> 2, t/filter -> 3, transmit -> 4, gray -> -2, else -1.
int component_index(const std::string& s);
// sRGB transfer function (IEC 61966-2-1), to linear.
double srgb_decode(double c);

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
        if ((w == "trace" || w == "inside" || w == "min_extent" || w == "max_extent") &&
            p_.options.prepare_object)
            return object_function(w);
        if (w == "eval_pigment") return eval_pigment();
        if (w == "inside") {
            // inside(Obj, P) with no renderer to ask: read, warned about once, and 0.
            warn_unsupported(p_, w + "()", p_.loc(), "it gives 0");
            p_.expect("(", ("after '" + w + "'").c_str());
            p_.next();  // the object identifier
            p_.expect(",", ("after the first argument of " + w + "()").c_str());
            p_.parse_vector();
            p_.expect(")", ("to close " + w + "()").c_str());
            return Value(Num::scalar(0));
        }
        if (w == "now") {
            // POV-Ray's now: days since 2000-01-01 00:00 UTC.
            const double secs = static_cast<double>(std::time(nullptr));
            return Value(Num::scalar((secs - 946684800.0) / 86400.0));
        }
        static const std::unordered_set<std::string> kUnsupportedFns = {
            "trace", "min_extent", "max_extent"};
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
        return Num::scalar(p_.version());  // version
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

    // trace(Obj, start, dir [, NormalVar]), inside(Obj, P), min_extent(Obj), max_extent(Obj):
    // answered by the application's geometry for the object alone (Parser::prepared_object).
    Value object_function(const std::string& f) {
        p_.expect("(", ("after '" + f + "'").c_str());
        const Token& t = p_.next();
        const Symbol* s = t.kind == TokKind::Word ? p_.lookup(t.text) : nullptr;
        if (s) s = &p_.use_symbol(t);
        auto obj = s ? std::get_if<std::shared_ptr<const PovObject>>(&s->value) : nullptr;
        if (!obj) p_.fail("expected an object identifier in " + f + "(), got " + p_.got(t));
        auto keep = *obj;
        const scene::PreparedObject& one = p_.prepared_object(keep);
        if (f == "inside") {
            p_.expect(",", "after the object in inside()");
            Vec3 at = p_.parse_vector();
            p_.expect(")", "to close inside()");
            return Value(Num::scalar(one.inside(at) ? 1 : 0));
        }
        if (f != "trace") {
            p_.expect(")", ("to close " + f + "()").c_str());
            const scene::ObjectAnswer box = one.bounds();
            // POV-Ray's bounding boxes of unbounded objects are large, not infinite.
            auto clamp = [](double v) { return std::clamp(v, -1e10, 1e10); };
            Vec3 r = f == "min_extent" ? box.lo : box.hi;
            if (!box.found) r = Vec3(0, 0, 0);
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
        scene::ObjectAnswer hit;
        if (length(dir) > 0) hit = one.trace(from, dir);
        if (!hit.found) hit.point = hit.normal = Vec3(0, 0, 0);
        if (!normal_var.empty())
            p_.assign_existing_or_declare(normal_var, Num::vec(hit.normal), nloc);
        return Value(Num::vec(hit.point));
    }

    Value function(const std::string& f);  // builtin_functions.cpp

    // eval_pigment(Pig, P) (functions.inc's macro, also read without it): the pigment's color
    // at P, through the application's pattern hook.
    Value eval_pigment() {
        const FileLoc at = p_.loc();
        p_.expect("(", "after 'eval_pigment'");
        const Token& t = p_.next();
        const Symbol* s = t.kind == TokKind::Word ? p_.lookup(t.text) : nullptr;
        if (s) s = &p_.use_symbol(t);
        auto pig = s ? std::get_if<scene::Pigment>(&s->value) : nullptr;
        if (!pig) p_.fail("expected a pigment identifier in eval_pigment(), got " + p_.got(t));
        scene::Function f;
        f.kind = scene::FunctionKind::Pigment;
        f.pigment = {*pig};
        p_.expect(",", "after the pigment in eval_pigment()");
        Vec3 q = p_.parse_vector();
        p_.expect(")", "to close eval_pigment()");
        if (!p_.options.pattern_hook)
            throw Unsupported(at, "eval_pigment() while parsing is not supported here");
        Num n{{0, 0, 0, 0, 0}, 5};
        const scene::FunctionEnv env = p_.function_env();
        p_.options.pattern_hook(&env, f, q, n.v);
        return Value(n);
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

}  // namespace glint::pov
