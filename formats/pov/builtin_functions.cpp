// POV-Ray's built-in float, vector and string functions (reference manual 3.2.1.5-3.2.1.8),
// called from ExprParser::word once a function name was read.
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>

#include "core/noise.h"
#include "formats/pov/expr_parser.h"

namespace glint::pov {

Value ExprParser::function(const std::string& f) {
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
    if (f == "datetime") {
        // datetime(days since 2000-01-01 UTC [, strftime format]), as POV-Ray 3.7 formats it.
        if (a.empty() || a.size() > 2)
            p_.fail_at(fn_loc, "datetime() takes 1 or 2 arguments, got " + std::to_string(a.size()));
        const double secs = F(0) * 86400.0 + 946684800.0;
        if (!(std::fabs(secs) < 1e15)) p_.fail_at(fn_loc, "datetime(): the time is out of range");
        const std::time_t tt = static_cast<std::time_t>(std::floor(secs));
        std::tm tm{};
        gmtime_r(&tt, &tm);
        const std::string fmt = a.size() == 2 ? S(1) : std::string("%Y-%m-%d %H:%M:%SZ");
        char buf[512];
        size_t n = fmt.empty() ? 0 : std::strftime(buf, sizeof buf, fmt.c_str(), &tm);
        return std::string(buf, n);
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

}  // namespace glint::pov
