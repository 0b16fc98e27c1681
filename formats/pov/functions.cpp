// User-defined functions and splines (reference manual 3.3.1.8-9; fnsyntax.cpp and
// function.cpp in POV-Ray). A function body is compiled into scene::Function's expression tree
// with POV-Ray's function grammar, which differs from ordinary expressions: all comparisons
// share one precedence level between '&' and '+', there is no '!' and no '?:', declared floats
// become constants, and anything else that is not a parameter must be a declared function.
#include <cmath>
#include <unordered_map>

#include "formats/pov/parser_impl.h"

namespace glint::pov {

namespace {

using scene::FnMath1;
using scene::FnNode;
using scene::FnOp;

const std::unordered_map<std::string, FnMath1>& math1_names() {
    static const std::unordered_map<std::string, FnMath1> k = {
        {"sin", FnMath1::Sin},     {"cos", FnMath1::Cos},         {"tan", FnMath1::Tan},
        {"asin", FnMath1::Asin},   {"acos", FnMath1::Acos},       {"atan", FnMath1::Atan},
        {"sinh", FnMath1::Sinh},   {"cosh", FnMath1::Cosh},       {"tanh", FnMath1::Tanh},
        {"asinh", FnMath1::Asinh}, {"acosh", FnMath1::Acosh},     {"atanh", FnMath1::Atanh},
        {"abs", FnMath1::Abs},     {"radians", FnMath1::Radians}, {"degrees", FnMath1::Degrees},
        {"int", FnMath1::Int},     {"floor", FnMath1::Floor},     {"ceil", FnMath1::Ceil},
        {"sqrt", FnMath1::Sqrt},   {"exp", FnMath1::Exp},         {"ln", FnMath1::Ln},
        {"log", FnMath1::Log},     {"sqr", FnMath1::Sqr},
    };
    return k;
}

int member_index(const std::string& s) {
    if (s == "x" || s == "u" || s == "red") return 0;
    if (s == "y" || s == "v" || s == "green") return 1;
    if (s == "z" || s == "blue") return 2;
    if (s == "t" || s == "filter") return 3;
    if (s == "transmit") return 4;
    if (s == "gray" || s == "grey") return 5;
    return -1;
}

bool is_const(const FnNode& n) { return n.op == FnOp::Const; }

// Compiles one function body (POV-Ray's parse_expr + optimise_expr, as a recursive descent
// over the same precedence table).
class FnCompiler {
public:
    FnCompiler(Parser& p, scene::Function& f) : p_(p), f_(f) {
        for (const auto& name : f.params) locals_.push_back(name);
        f_.slots = static_cast<int>(locals_.size());
    }

    int expr() { return or_expr(); }

private:
    int add(FnNode n, std::initializer_list<int> ops) {
        n.first = static_cast<int>(f_.operands.size());
        n.count = static_cast<int>(ops.size());
        for (int o : ops) f_.operands.push_back(o);
        f_.nodes.push_back(n);
        return static_cast<int>(f_.nodes.size()) - 1;
    }
    int add_list(FnNode n, const std::vector<int>& ops) {
        n.first = static_cast<int>(f_.operands.size());
        n.count = static_cast<int>(ops.size());
        for (int o : ops) f_.operands.push_back(o);
        f_.nodes.push_back(n);
        return static_cast<int>(f_.nodes.size()) - 1;
    }
    int constant(double v) {
        FnNode n;
        n.op = FnOp::Const;
        n.value = v;
        return add(n, {});
    }
    // a op b, folded when both are constants (POV-Ray's optimise_expr folds the same way).
    int binary(FnOp op, int a, int b) {
        const FnNode& l = f_.nodes[a];
        const FnNode& r = f_.nodes[b];
        if (is_const(l) && is_const(r)) {
            double x = l.value, y = r.value, v = 0;
            switch (op) {
                case FnOp::Add: v = x + y; break;
                case FnOp::Sub: v = x - y; break;
                case FnOp::Mul: v = x * y; break;
                case FnOp::Div: v = x / y; break;
                case FnOp::Lt: v = x < y; break;
                case FnOp::Le: v = x <= y; break;
                case FnOp::Gt: v = x > y; break;
                case FnOp::Ge: v = x >= y; break;
                case FnOp::Eq: v = x == y; break;
                case FnOp::Ne: v = x != y; break;
                case FnOp::And: v = (x != 0) && (y != 0); break;
                case FnOp::Or: v = (x != 0) || (y != 0); break;
                default: goto no_fold;
            }
            return constant(v);
        }
    no_fold:
        FnNode n;
        n.op = op;
        return add(n, {a, b});
    }

    int or_expr() {
        int a = and_expr();
        while (p_.accept("|")) a = binary(FnOp::Or, a, and_expr());
        return a;
    }
    int and_expr() {
        int a = cmp_expr();
        while (p_.accept("&")) a = binary(FnOp::And, a, cmp_expr());
        return a;
    }
    int cmp_expr() {
        int a = add_expr();
        for (;;) {
            const Token& t = p_.next();
            FnOp op;
            if (t.is("<")) op = FnOp::Lt;
            else if (t.is("<=")) op = FnOp::Le;
            else if (t.is(">")) op = FnOp::Gt;
            else if (t.is(">=")) op = FnOp::Ge;
            else if (t.is("=")) op = FnOp::Eq;
            else if (t.is("!=")) op = FnOp::Ne;
            else {
                p_.unget();
                return a;
            }
            a = binary(op, a, add_expr());
        }
    }
    int add_expr() {
        int a = mul_expr();
        for (;;) {
            if (p_.accept("+")) a = binary(FnOp::Add, a, mul_expr());
            else if (p_.accept("-")) a = binary(FnOp::Sub, a, mul_expr());
            else return a;
        }
    }
    int mul_expr() {
        int a = unary();
        for (;;) {
            if (p_.accept("*")) a = binary(FnOp::Mul, a, unary());
            else if (p_.accept("/")) a = binary(FnOp::Div, a, unary());
            else return a;
        }
    }
    int unary() {
        const Token& t = p_.next();
        if (t.is("+")) return unary();
        if (t.is("-")) {
            int a = unary();
            if (is_const(f_.nodes[a])) return constant(-f_.nodes[a].value);
            FnNode n;
            n.op = FnOp::Neg;
            return add(n, {a});
        }
        if (t.is("!"))
            p_.fail("'!' cannot be used in a function (POV-Ray functions have no logical not; "
                    "write 1 - (a) or select)");
        p_.unget();
        return primary();
    }

    std::vector<int> call_args(const std::string& name) {
        p_.expect("(", ("after '" + name + "' in the function").c_str());
        std::vector<int> args;
        if (p_.accept(")")) return args;
        for (;;) {
            args.push_back(expr());
            const Token& t = p_.next();
            if (t.is(")")) return args;
            if (!t.is(","))
                p_.fail("expected ',' or ')' in the arguments of '" + name + "', got " +
                        p_.got(t));
        }
    }

    int param_slot(const std::string& name) const {
        for (size_t i = locals_.size(); i-- > 0;)
            if (locals_[i] == name) return static_cast<int>(i);
        return -1;
    }

    // x/u and y/v share POV-Ray's registers: `u` reads the parameter named x or u.
    int register_slot(const std::string& name) const {
        if (name == "x" || name == "u") {
            int s = param_slot("x");
            return s >= 0 ? s : param_slot("u");
        }
        if (name == "y" || name == "v") {
            int s = param_slot("y");
            return s >= 0 ? s : param_slot("v");
        }
        if (name == "z") return param_slot("z");
        return -1;
    }

    int primary() {
        const Token& t = p_.next();
        if (t.kind == TokKind::Number) return constant(t.number);
        if (t.is_symbol('(')) {
            int a = expr();
            p_.expect(")", "to close the parenthesis in the function");
            return a;
        }
        if (t.kind != TokKind::Word) p_.fail("expected an operand in the function, got " + p_.got(t));
        const std::string name = t.text;
        FileLoc at = p_.loc();
        // Parameters (and sum/prod variables) come first: they shadow declared names.
        int slot = param_slot(name);
        if (slot < 0 && name.size() == 1) slot = register_slot(name);
        if (slot >= 0 || (name.size() == 1 && std::string("xyzuv").find(name[0]) !=
                                                  std::string::npos)) {
            if (slot < 0) return constant(0);  // an unset register, as in POV-Ray
            FnNode n;
            n.op = FnOp::Param;
            n.index = slot;
            return add(n, {});
        }
        if (p_.lookup(name)) {
            const Symbol& s = p_.use_symbol(t);
            if (auto fr = std::get_if<FunctionRef>(&s.value)) return call(fr->index, name, at);
            if (auto n = std::get_if<Num>(&s.value)) {
                if (n->terms == 1) return constant(n->v[0]);
                // A vector identifier with a component: a constant too.
                Num v = *n;
                if (p_.accept(".")) {
                    const Token& m = p_.next();
                    int k = m.kind == TokKind::Word ? member_index(m.text) : -1;
                    if (k < 0 || k == 5 || k >= v.terms)
                        p_.fail("expected a component of '" + name + "' after '.', got " +
                                p_.got(m));
                    return constant(v.v[k]);
                }
                p_.fail_at(at, "expected a float in the function, got " + value_kind_name(s.value) +
                                   " '" + name + "' (use " + name + ".x etc.)");
            }
            p_.fail_at(at, "expected a float or a function in the function, got " +
                               value_kind_name(s.value) + " '" + name + "'");
        }
        if (auto it = math1_names().find(name); it != math1_names().end()) {
            std::vector<int> a = call_args(name);
            if (a.size() != 1)
                p_.fail_at(at, "'" + name + "' takes 1 argument, got " + std::to_string(a.size()));
            if (is_const(f_.nodes[a[0]]) && it->second != FnMath1::Ln && it->second != FnMath1::Log)
                return fold_math1(it->second, a[0]);
            FnNode n;
            n.op = FnOp::Math1;
            n.index = static_cast<int>(it->second);
            return add(n, {a[0]});
        }
        static const std::unordered_map<std::string, FnOp> kBinary = {
            {"atan2", FnOp::Atan2}, {"mod", FnOp::Mod}, {"div", FnOp::IntDiv}, {"pow", FnOp::Pow}};
        if (auto it = kBinary.find(name); it != kBinary.end()) {
            std::vector<int> a = call_args(name);
            if (a.size() != 2)
                p_.fail_at(at, "'" + name + "' takes 2 arguments, got " + std::to_string(a.size()));
            FnNode n;
            n.op = it->second;
            return add(n, {a[0], a[1]});
        }
        if (name == "min" || name == "max") {
            std::vector<int> a = call_args(name);
            if (a.empty()) p_.fail_at(at, "'" + name + "' needs at least one argument");
            FnNode n;
            n.op = name == "min" ? FnOp::Min : FnOp::Max;
            return add_list(n, a);
        }
        if (name == "select") {
            std::vector<int> a = call_args(name);
            if (a.size() != 3 && a.size() != 4)
                p_.fail_at(at, "'select' takes 3 or 4 arguments, got " + std::to_string(a.size()));
            FnNode n;
            n.op = FnOp::Select;
            return add_list(n, a);
        }
        if (name == "sum" || name == "prod") return sum_prod(name, at);
        double c;
        if (p_.float_constant(name, c)) return constant(c);
        if (name == "internal")
            p_.fail_at(at, "internal(N) must be the whole function body: function { internal(N) }");
        p_.fail_at(at, "unknown identifier '" + name + "' in the function (a function must be "
                       "declared before it is called; the f_ functions need "
                       "#include \"functions.inc\")");
    }

    int fold_math1(FnMath1 m, int a) {
        FnNode n;
        n.op = FnOp::Math1;
        n.index = static_cast<int>(m);
        int node = add(n, {a});
        // Evaluate the one-node function now.
        scene::Function tmp;
        tmp.nodes = {f_.nodes[a], f_.nodes[node]};
        tmp.nodes[1].first = 0;
        tmp.operands = {0};
        tmp.root = 1;
        std::vector<scene::Function> one{tmp};
        scene::FunctionEnv env;
        env.functions = &one;
        return constant(scene::evaluate_function(env, 0, nullptr, 0));
    }

    // sum(i, from, to, expr) / prod(...): `i` is a new variable inside expr.
    int sum_prod(const std::string& name, const FileLoc& at) {
        p_.expect("(", ("after '" + name + "'").c_str());
        const Token& v = p_.next();
        if (v.kind != TokKind::Word)
            p_.fail("expected the variable of '" + name + "', got " + p_.got(v));
        std::string var = v.text;
        p_.expect(",", ("after the variable of '" + name + "'").c_str());
        int from = expr();
        p_.expect(",", ("in '" + name + "'").c_str());
        int to = expr();
        p_.expect(",", ("in '" + name + "'").c_str());
        locals_.push_back(var);
        int slot = static_cast<int>(locals_.size()) - 1;
        f_.slots = std::max(f_.slots, slot + 1);
        int body = expr();
        locals_.pop_back();
        p_.expect(")", ("to close '" + name + "'").c_str());
        (void)at;
        FnNode n;
        n.op = name == "sum" ? FnOp::Sum : FnOp::Prod;
        n.index = slot;
        return add(n, {from, to, body});
    }

    int call(int index, const std::string& name, const FileLoc& at) {
        const scene::Function& callee = p_.scene.functions[static_cast<size_t>(index)];
        std::vector<int> a = call_args(name);
        size_t want = callee.kind == scene::FunctionKind::Internal
                          ? static_cast<size_t>(scene::internal_function_arity(callee.internal))
                          : callee.params.size();
        if (a.size() != want)
            p_.fail_at(at, "the function '" + name + "' takes " + std::to_string(want) +
                               " argument(s), got " + std::to_string(a.size()));
        FnNode n;
        if (callee.kind == scene::FunctionKind::Internal) {
            if (!scene::internal_function_implemented(callee.internal))
                p_.warn_unimplemented_internal(callee.internal, at);
            n.op = FnOp::Internal;
            n.index = callee.internal;
            return add_list(n, a);
        }
        n.op = FnOp::Call;
        n.index = index;
        if (callee.is_vector()) {
            // POV-Ray requires a component after a vector function call in a function.
            p_.expect(".", ("after the call of the vector function '" + name +
                            "' (a function needs one component: .x, .red, .gray, ...)")
                               .c_str());
            const Token& m = p_.next();
            int k = m.kind == TokKind::Word ? member_index(m.text) : -1;
            if (k < 0) p_.fail("expected a component (x, y, z, red, ..., gray), got " + p_.got(m));
            n.member = k;
        }
        return add_list(n, a);
    }

    Parser& p_;
    scene::Function& f_;
    std::vector<std::string> locals_;
};

}  // namespace

void Parser::warn_unimplemented_internal(int id, const FileLoc& at) {
    if (!warned_internals_.insert(id).second) return;
    diag.warning(at, std::string("the internal function ") + scene::internal_function_name(id) +
                         " is not implemented: it evaluates to 0");
}

scene::FunctionEnv Parser::function_env() const {
    scene::FunctionEnv env;
    env.functions = &scene.functions;
    env.noise_generator = scene.global.noise_generator;
    return env;
}

// After `function`: [ (a, b, ...) ] { body }.
int Parser::parse_function_definition() {
    FileLoc at = loc();
    scene::Function f;
    f.loc = at;
    if (accept("(")) {
        for (;;) {
            const Token& t = next();
            if (t.is_symbol(')')) break;
            if (t.is_symbol(',')) continue;
            if (t.kind != TokKind::Word)
                fail("expected a parameter name in the function's parameter list, got " + got(t));
            f.params.push_back(t.text);
        }
        if (f.params.empty()) fail_at(at, "a function needs at least one parameter");
    } else {
        f.params = {"x", "y", "z"};
    }
    if (f.params.size() > 56) fail_at(at, "a function has at most 56 parameters");
    expect_open("function");
    FileLoc opened = loc();
    const Token& t = next();
    bool has_params = f.params != std::vector<std::string>{"x", "y", "z"};
    auto no_params = [&](const char* what) {
        if (has_params)
            fail(std::string("function parameters are not allowed for ") + what + " functions");
    };
    if (t.is("internal")) {
        expect("(", "after 'internal'");
        FileLoc nl = loc();
        double n = parse_float();
        expect(")", "after the internal function number");
        int id = to_int(n);
        if (id < 0 || id >= scene::kInternalFunctionCount)
            fail_at(nl, "there is no internal function " + std::to_string(id) + " (0 to " +
                            std::to_string(scene::kInternalFunctionCount - 1) + ")");
        f.kind = scene::FunctionKind::Internal;
        f.internal = id;
        f.params.clear();
        for (int i = 0; i < scene::internal_function_arity(id); ++i)
            f.params.push_back(i < 3 ? std::string(1, "xyz"[i]) : "P" + std::to_string(i - 3));
    } else if (t.is("pattern") || t.is("pigment")) {
        bool pigment = t.is("pigment");
        no_params(pigment ? "pigment" : "pattern");
        std::string kw = t.text;
        expect_open(kw.c_str());
        FileLoc po = loc();
        scene::Pigment pg;
        if (pigment) pg = default_texture_.pigment;
        pg.loc = po;
        parse_pigment_body(pg);
        expect_close(kw.c_str(), po);
        f.kind = pigment ? scene::FunctionKind::Pigment : scene::FunctionKind::Pattern;
        f.pigment.push_back(std::move(pg));
    } else if (t.is("transform")) {
        no_params("transform");
        const Token& b = next();
        if (b.is_symbol('{')) {
            FileLoc to = loc();
            f.transform = parse_transform_body();
            expect_close("transform", to);
        } else if (b.kind == TokKind::Word && lookup(b.text)) {
            const Symbol& s = use_symbol(b);
            auto tr = std::get_if<Transform>(&s.value);
            if (!tr) fail("expected a transform, got " + value_kind_name(s.value));
            f.transform = *tr;
        } else {
            fail("expected '{' after 'transform', got " + got(b));
        }
        f.kind = scene::FunctionKind::Transform;
    } else if (t.is("spline")) {
        no_params("spline");
        expect_open("spline");
        FileLoc so = loc();
        f.spline = parse_spline_body();
        expect_close("spline", so);
        f.kind = scene::FunctionKind::Spline;
        f.params = {"t"};
    } else {
        unget();
        f.kind = scene::FunctionKind::Expression;
        FnCompiler c(*this, f);
        f.root = c.expr();
    }
    expect_close("function", opened);
    scene.functions.push_back(std::move(f));
    return static_cast<int>(scene.functions.size()) - 1;
}

// spline { [Ident] [linear_spline | quadratic_spline | cubic_spline | natural_spline]
//          t, <v> [,] ... } (POV-Ray's Parse_Spline).
scene::Spline Parser::parse_spline_body() {
    scene::Spline s;
    bool copied = false;
    const Token& first = next();
    if (first.kind == TokKind::Word && lookup(first.text)) {
        const Symbol& sym = use_symbol(first);
        if (auto sp = std::get_if<std::shared_ptr<const scene::Spline>>(&sym.value)) {
            s = **sp;
            copied = true;
        } else {
            unget();
        }
    } else {
        unget();
    }
    for (;;) {
        const Token& t = next();
        if (t.is("linear_spline")) s.type = scene::Spline::Type::Linear;
        else if (t.is("quadratic_spline")) s.type = scene::Spline::Type::Quadratic;
        else if (t.is("cubic_spline")) s.type = scene::Spline::Type::Cubic;
        else if (t.is("natural_spline")) s.type = scene::Spline::Type::Natural;
        else {
            unget();
            break;
        }
    }
    int max_terms = copied ? s.terms : 2;
    while (next_is_expression_start()) {
        double t = parse_float();
        accept(",");
        peek();
        FileLoc vl = loc();
        Num v = parse_num(0);
        if (v.terms > 5) fail_at(vl, "too many components in the spline's vector");
        max_terms = std::max(max_terms, v.terms);
        v.promote(2);
        std::array<double, 5> a{};
        for (int k = 0; k < 5; ++k) a[static_cast<size_t>(k)] = v.v[k];
        s.insert(t, a);
        accept(",");
    }
    if (s.par.empty()) fail("a spline needs at least one entry (t, <vector>)");
    s.terms = max_terms;
    return s;
}

Value Parser::call_function_now(int index, const std::string& name, const FileLoc& at) {
    const scene::Function& f = scene.functions[static_cast<size_t>(index)];
    expect("(", ("after the function '" + name + "'").c_str());
    std::vector<double> args;
    if (!accept(")")) {
        for (;;) {
            args.push_back(parse_float());
            const Token& t = next();
            if (t.is(")")) break;
            if (!t.is(","))
                fail("expected ',' or ')' in the arguments of '" + name + "', got " + got(t));
        }
    }
    size_t want = f.params.size();
    if (args.size() != want)
        fail_at(at, "the function '" + name + "' takes " + std::to_string(want) +
                        " argument(s), got " + std::to_string(args.size()));
    if (f.kind == scene::FunctionKind::Internal && !scene::internal_function_implemented(f.internal))
        warn_unimplemented_internal(f.internal, at);
    if ((f.kind == scene::FunctionKind::Pattern || f.kind == scene::FunctionKind::Pigment) &&
        !options.pattern_hook)
        throw Unsupported(at, "calling the pattern or pigment function '" + name +
                                  "' while parsing is not supported yet");
    scene::FunctionEnv env = function_env();
    env.pattern = options.pattern_hook;
    env.user = options.hook_user;
    if (!f.is_vector())
        return Num::scalar(scene::evaluate_function(env, index, args.data(),
                                                    static_cast<int>(args.size())));
    Num n;
    scene::evaluate_function_vector(env, index, args.data(), static_cast<int>(args.size()), n.v);
    n.terms = f.kind == scene::FunctionKind::Pigment ? 5
              : f.kind == scene::FunctionKind::Spline ? f.spline.terms
                                                       : 3;
    return n;
}

// S(t) or S(t, linear_spline): the spline's value, with its number of components.
Value Parser::call_spline_now(const scene::Spline& s, const std::string& name) {
    expect("(", ("after the spline '" + name + "'").c_str());
    double t = parse_float();
    scene::Spline::Type type = s.type;
    if (accept(",")) {
        const Token& k = next();
        if (k.is("linear_spline")) type = scene::Spline::Type::Linear;
        else if (k.is("quadratic_spline")) type = scene::Spline::Type::Quadratic;
        else if (k.is("cubic_spline")) type = scene::Spline::Type::Cubic;
        else if (k.is("natural_spline")) type = scene::Spline::Type::Natural;
        else fail("expected linear_spline, quadratic_spline, cubic_spline or natural_spline, got " +
                  got(k));
    }
    expect(")", ("to close the call of the spline '" + name + "'").c_str());
    Num n;
    if (type == s.type) {
        s.evaluate(t, n.v);
    } else {
        scene::Spline copy = s;
        copy.type = type;
        copy.evaluate(t, n.v);
    }
    n.terms = s.terms;
    return n;
}

}  // namespace glint::pov
