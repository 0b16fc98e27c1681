// Evaluation of user-defined functions and splines. The expression tree is walked recursively;
// arguments live in a small array on the stack of each call (POV-Ray functions cannot recurse:
// a function can only call functions declared before it).
#include "scene/function.h"

#include <algorithm>
#include <climits>
#include <cmath>

#include "core/noise.h"

namespace glint::scene {

// ---------------------------------------------------------------- splines

void Spline::insert(double t, const std::array<double, 5>& v) {
    auto it = std::lower_bound(par.begin(), par.end(), t);
    size_t i = static_cast<size_t>(it - par.begin());
    if (it != par.end() && *it == t) {
        vec[i] = v;
        return;
    }
    par.insert(it, t);
    vec.insert(vec.begin() + static_cast<std::ptrdiff_t>(i), v);
}

namespace {

// POV-Ray's findt: the index of the first entry whose parameter is >= t (0 before the first,
// n at or after the last).
size_t find_segment(const std::vector<double>& par, double t) {
    size_t n = par.size();
    if (n == 0 || t <= par[0]) return 0;
    if (t >= par[n - 1]) return n;
    return static_cast<size_t>(std::lower_bound(par.begin(), par.end(), t) - par.begin());
}

double linear_at(const Spline& s, size_t i, int k, double t) {
    double p1 = s.par[i], p2 = s.par[i + 1], v1 = s.vec[i][k], v2 = s.vec[i + 1][k];
    return (t - p1) * (v2 - v1) / (p2 - p1) + v1;
}

// The parabola through entries i-1, i, i+1.
double quadratic_at(const Spline& s, size_t i, int k, double t) {
    double p1 = s.par[i - 1], p2 = s.par[i], p3 = s.par[i + 1];
    double v1 = s.vec[i - 1][k], v2 = s.vec[i][k], v3 = s.vec[i + 1][k];
    double n = (p2 - p1) * (p3 - p1) * (p3 - p2);
    double a = (-p2 * v1 + p3 * v1 + p1 * v2 - p3 * v2 - p1 * v3 + p2 * v3) / n;
    double b = (p2 * p2 * v1 - p3 * p3 * v1 - p1 * p1 * v2 + p3 * p3 * v2 + p1 * p1 * v3 -
                p2 * p2 * v3) / n;
    double c = (-p2 * p2 * p3 * v1 + p2 * p3 * p3 * v1 + p1 * p1 * p3 * v2 - p1 * p3 * p3 * v2 -
                p1 * p1 * p2 * v3 + p1 * p2 * p2 * v3) / n;
    return (a * t + b) * t + c;
}

// Catmull-Rom between entries i and i+1 with tangents from the neighbours (POV-Ray's
// cubic_spline).
double catmull_rom_at(const Spline& s, size_t i, int k, double t) {
    const auto& P = s.par;
    const auto& V = s.vec;
    double dt = P[i + 1] - P[i];
    double u = (t - P[i]) / dt;
    double d_mid = (V[i + 1][k] - V[i][k]) / dt;
    double dp0 = ((V[i][k] - V[i - 1][k]) / (P[i] - P[i - 1]) + d_mid) / 2.0 * dt;
    double dp1 = ((V[i + 2][k] - V[i + 1][k]) / (P[i + 2] - P[i + 1]) + d_mid) / 2.0 * dt;
    double u2 = u * u, u3 = u2 * u;
    return V[i][k] * (2 * u3 - 3 * u2 + 1) + V[i + 1][k] * (3 * u2 - 2 * u3) +
           dp0 * (u3 - 2 * u2 + u) + dp1 * (u3 - u2);
}

// Second derivatives of the natural cubic spline through the entries (zero at both ends),
// POV-Ray's Precompute_Cubic_Coeffs (tridiagonal elimination).
std::vector<std::array<double, 5>> natural_coeffs(const Spline& s) {
    size_t n = s.par.size();
    std::vector<std::array<double, 5>> c(n, std::array<double, 5>{});
    if (n < 3) return c;
    std::vector<double> h(n), b(n), u(n), v(n);
    for (int k = 0; k < 5; ++k) {
        for (size_t i = 0; i + 1 < n; ++i) {
            h[i] = s.par[i + 1] - s.par[i];
            b[i] = (s.vec[i + 1][k] - s.vec[i][k]) / h[i];
        }
        u[1] = 2 * (h[0] + h[1]);
        v[1] = 6 * (b[1] - b[0]);
        for (size_t i = 2; i + 1 < n; ++i) {
            u[i] = 2 * (h[i] + h[i - 1]) - h[i - 1] * h[i - 1] / u[i - 1];
            v[i] = 6 * (b[i] - b[i - 1]) - h[i - 1] * v[i - 1] / u[i - 1];
        }
        c[n - 1][k] = 0;
        for (size_t i = n - 2; i > 0; --i) c[i][k] = (v[i] - h[i] * c[i + 1][k]) / u[i];
        c[0][k] = 0;
    }
    return c;
}

double natural_at(const Spline& s, const std::vector<std::array<double, 5>>& c, size_t i, int k,
                  double t) {
    double h = s.par[i + 1] - s.par[i];
    double d = t - s.par[i];
    double tmp = c[i][k] / 2.0 + d * (c[i + 1][k] - c[i][k]) / (6.0 * h);
    tmp = -(h / 6.0) * (c[i + 1][k] + 2.0 * c[i][k]) + (s.vec[i + 1][k] - s.vec[i][k]) / h +
          d * tmp;
    return s.vec[i][k] + d * tmp;
}

}  // namespace

void Spline::evaluate(double t, double out[5]) const {
    for (int k = 0; k < 5; ++k) out[k] = 0;
    if (par.empty()) return;
    size_t last = par.size() - 1;
    if (last == 0) {
        for (int k = 0; k < 5; ++k) out[k] = vec[0][k];
        return;
    }
    size_t i = find_segment(par, t);
    std::vector<std::array<double, 5>> coeffs;
    if (type == Type::Natural) coeffs = natural_coeffs(*this);
    for (int k = 0; k < 5; ++k) {
        if (type == Type::Cubic) {
            if (last == 1)
                out[k] = (vec[0][k] + vec[1][k]) / 2.0;
            else if (i < 2)
                out[k] = vec[1][k];
            else if (i >= last)
                out[k] = vec[last - 1][k];
            else
                out[k] = catmull_rom_at(*this, i - 1, k, t);
            continue;
        }
        if (i == 0) {
            out[k] = vec[0][k];
        } else if (i > last) {
            out[k] = vec[last][k];
        } else if (type == Type::Linear || (type == Type::Quadratic && last == 1)) {
            out[k] = linear_at(*this, i - 1, k, t);
        } else if (type == Type::Quadratic) {
            out[k] = quadratic_at(*this, i > 1 ? i - 1 : i, k, t);
        } else {
            out[k] = natural_at(*this, coeffs, i - 1, k, t);
        }
    }
}

// ---------------------------------------------------------------- internal functions

namespace {

struct InternalInfo {
    const char* name;
    int params;  // besides x, y, z
    bool implemented;
};

// functions.inc's internal(N) table (POV-Ray fnintern.cpp POVFPU_TrapTable).
constexpr InternalInfo kInternals[kInternalFunctionCount] = {
    {"f_algbr_cyl1", 5, false}, {"f_algbr_cyl2", 5, false}, {"f_algbr_cyl3", 5, false},
    {"f_algbr_cyl4", 5, false}, {"f_bicorn", 2, false}, {"f_bifolia", 2, false},
    {"f_blob", 5, false}, {"f_blob2", 4, false}, {"f_boy_surface", 2, false},
    {"f_comma", 1, false}, {"f_cross_ellipsoids", 4, false}, {"f_crossed_trough", 1, false},
    {"f_cubic_saddle", 1, false}, {"f_cushion", 1, false}, {"f_devils_curve", 1, false},
    {"f_devils_curve_2d", 6, false}, {"f_dupin_cyclid", 6, false}, {"f_ellipsoid", 3, true},
    {"f_enneper", 1, false}, {"f_flange_cover", 4, false}, {"f_folium_surface", 3, false},
    {"f_folium_surface_2d", 6, false}, {"f_glob", 1, false}, {"f_heart", 1, false},
    {"f_helical_torus", 10, false}, {"f_helix1", 7, true}, {"f_helix2", 7, false},
    {"f_hex_x", 1, false}, {"f_hex_y", 1, false}, {"f_hetero_mf", 6, true},
    {"f_hunt_surface", 1, false}, {"f_hyperbolic_torus", 3, false},
    {"f_isect_ellipsoids", 4, false}, {"f_kampyle_of_eudoxus", 3, false},
    {"f_kampyle_of_eudoxus_2d", 6, false}, {"f_klein_bottle", 1, false},
    {"f_kummer_surface_v1", 1, false}, {"f_kummer_surface_v2", 4, false},
    {"f_lemniscate_of_gerono", 1, false}, {"f_lemniscate_of_gerono_2d", 6, false},
    {"f_mesh1", 5, false}, {"f_mitre", 1, false}, {"f_nodal_cubic", 1, false},
    {"f_odd", 1, false}, {"f_ovals_of_cassini", 4, false}, {"f_paraboloid", 1, true},
    {"f_parabolic_torus", 3, false}, {"f_ph", 0, true}, {"f_pillow", 1, false},
    {"f_piriform", 1, false}, {"f_piriform_2d", 7, false}, {"f_poly4", 5, false},
    {"f_polytubes", 6, false}, {"f_quantum", 1, false}, {"f_quartic_paraboloid", 1, false},
    {"f_quartic_saddle", 1, false}, {"f_quartic_cylinder", 3, false}, {"f_r", 0, true},
    {"f_ridge", 6, true}, {"f_ridged_mf", 6, true}, {"f_rounded_box", 4, true},
    {"f_sphere", 1, true}, {"f_spikes", 5, false}, {"f_spikes_2d", 4, false},
    {"f_spiral", 6, false}, {"f_steiners_roman", 1, false}, {"f_strophoid", 4, false},
    {"f_strophoid_2d", 7, false}, {"f_superellipsoid", 2, true}, {"f_th", 0, true},
    {"f_torus", 2, true}, {"f_torus2", 3, true}, {"f_torus_gumdrop", 1, false},
    {"f_umbrella", 1, false}, {"f_witch_of_agnesi", 2, false},
    {"f_witch_of_agnesi_2d", 6, false}, {"f_noise3d", 0, true}, {"f_pattern", 0, false},
    {"f_noise_generator", 1, true},
};

double noise_at(const FunctionEnv& env, const Vec3& p, int generator) {
    return env.noise ? env.noise(p, generator) : glint::noise(p, generator);
}

// A parameter used as a count or a selector: truncated like POV-Ray's (int) cast, but clamped
// first, since casting 1e20 or NaN to int is undefined behaviour.
int int_param(double v, int lo, int hi) {
    if (!(v == v)) return lo;
    return static_cast<int>(std::clamp(v, double(lo), double(hi)));
}
// Octave counts past this add nothing visible (the amplitude is below a double's precision
// long before) and would only let one function call run for minutes.
constexpr int kMaxOctaves = 64;

// The formulas of POV-Ray's fnintern.cpp for the internal functions example scenes use.
// a[0..2] = x, y, z; a[3 + i] = P(i).
double eval_internal(const FunctionEnv& env, int id, const double* a) {
    double x = a[0], y = a[1], z = a[2];
    const double* P = a + 3;
    auto clamp10 = [](double r) { return std::min(10.0, std::max(r, -10.0)); };
    switch (id) {
        case 17:  // f_ellipsoid
            return std::sqrt(x * x * P[0] * P[0] + y * y * P[1] * P[1] + z * z * P[2] * P[2]);
        case 25: {  // f_helix1
            double r = std::sqrt(x * x + z * z);
            if (x == 0 && z == 0) x = 0.000001;
            double th = std::atan2(z, x);
            th = std::fmod(th * P[0] + y * P[1] * P[0], 2 * kPi);
            if (th < 0) th += 2 * kPi;
            z = (th - kPi) / P[4] / (P[1] * P[0]);
            x = r - P[3];
            double r2;
            if (P[5] == 1) {
                r2 = std::sqrt(x * x + z * z);
            } else {
                if (P[6] != 0) {
                    double c = std::cos(P[6] * kPi / 180), s = std::sin(P[6] * kPi / 180);
                    double x2 = x * c - z * s;
                    z = x * s + z * c;
                    x = x2;
                }
                if (P[5] != 0) {
                    double e = 2.0 / P[5];
                    r2 = std::pow(std::pow(std::fabs(x), e) + std::pow(std::fabs(z), e),
                                  P[5] * 0.5);
                } else {
                    r2 = std::max(std::fabs(x), std::fabs(z));
                }
            }
            return -P[2] + std::min(P[3] + r, r2);
        }
        case 29: {  // f_hetero_mf
            Vec3 v(x, y, z);
            int gen = int_param(P[5], INT_MIN, INT_MAX) & 3;
            double signal = (noise_at(env, v, gen) * 2.0 - 1.0) + P[3];
            v *= P[1];
            double step = std::pow(P[1], -P[0]), ea = step;
            const double octaves = std::min(P[2], double(kMaxOctaves));
            for (int i = 1; i < octaves; ++i) {
                double inc = ((noise_at(env, v, gen) * 2.0 - 1.0) + P[3]) * ea;
                for (int k = int_param(P[4], 0, kMaxOctaves); k > 0; --k) inc *= signal;
                signal += inc;
                v *= P[1];
                ea *= step;
            }
            double rem = octaves - std::trunc(octaves);
            if (rem != 0.0) {
                double inc = ((noise_at(env, v, gen) * 2.0 - 1.0) + P[3]) * ea;
                signal += rem * inc * signal;
            }
            return signal;
        }
        case 45:  // f_paraboloid
            return clamp10(P[0] * -(x * x - y + z * z));
        case 47:  // f_ph
            return std::atan2(std::sqrt(x * x + z * z), y);
        case 57:  // f_r
            return std::sqrt(x * x + y * y + z * z);
        case 58: {  // f_ridge
            Vec3 p(x, y, z);
            int gen = int_param(P[5], INT_MIN, INT_MAX) & 3;
            double lambda = P[0], omega = P[2], l = lambda, o = omega;
            const double oct = std::clamp(P[1], -double(kMaxOctaves), double(kMaxOctaves));
            int octaves = int_param(oct, -kMaxOctaves, kMaxOctaves);
            double off = P[3], ridge = P[4], tot = 1.0;
            double rscale = 1.0 / std::max(ridge, 1.0 - ridge);
            double scale = 1.0 / std::max(off, 1.0 - off);
            double resid = oct - octaves;
            double value = std::fabs(noise_at(env, p, gen) - ridge) * rscale - off;
            for (int i = 2; i <= octaves; ++i) {
                double v = std::fabs(noise_at(env, p * l, gen) - ridge) * rscale;
                value += o * (v - off);
                tot += o;
                l *= lambda;
                o *= omega;
            }
            if (resid != 0.0) {
                double v = std::fabs(noise_at(env, p * l, gen) - ridge) * rscale;
                value += o * (v - off) * resid;
                tot += o * resid;
            }
            return value * scale / tot;
        }
        case 59: {  // f_ridged_mf
            Vec3 v(x, y, z);
            int gen = int_param(P[5], INT_MIN, INT_MAX) & 3;
            auto ridged = [&](const Vec3& q) {
                double s = noise_at(env, q, gen) * 2.0 - 1.0;
                s = P[3] - std::fabs(s);
                return s * s;
            };
            double signal = ridged(v), result = signal, freq = 1.0;
            const double octaves = std::min(P[2], double(kMaxOctaves));
            for (int i = 1; i < octaves; ++i) {
                freq *= P[1];
                v *= P[1];
                double weight = std::clamp(signal * P[4], 0.0, 1.0);
                signal = ridged(v) * weight;
                result += signal * std::pow(freq, -P[0]);
            }
            return result;
        }
        case 60: {  // f_rounded_box
            double r = P[0];
            double hx = P[1] - r, hy = P[2] - r, hz = P[3] - r;
            double ox = x < hx ? 0 : x - hx, oy = y < hy ? 0 : y - hy, oz = z < hz ? 0 : z - hz;
            double ix = x > -hx ? 0 : -hx - x, iy = y > -hy ? 0 : -hy - y,
                   iz = z > -hz ? 0 : -hz - z;
            double dx = std::max(ix, ox), dy = std::max(iy, oy), dz = std::max(iz, oz);
            return -r + std::sqrt(dx * dx + dy * dy + dz * dz) - 1e-6;
        }
        case 61:  // f_sphere
            return -P[0] + std::sqrt(x * x + y * y + z * z);
        case 68: {  // f_superellipsoid
            double e = 2 / P[0], n = 1 / P[1];
            return 1 - std::pow(std::pow(std::pow(std::fabs(x), e) + std::pow(std::fabs(y), e),
                                         P[0] * n) +
                                    std::pow(std::fabs(z), 2 * n),
                                P[1] * 0.5);
        }
        case 69:  // f_th
            return std::atan2(x, z);
        case 70: {  // f_torus
            double d = std::sqrt(x * x + z * z) - P[0];
            return -P[1] + std::sqrt(d * d + y * y);
        }
        case 71: {  // f_torus2
            double x2 = x * x, y2 = y * y, z2 = z * z;
            double ph = P[1] * P[1], th = P[2] * P[2];
            double r = -(x2 * x2 + y2 * y2 + z2 * z2 + 2 * x2 * y2 + 2 * x2 * z2 + 2 * y2 * z2 -
                         2 * (ph + th) * x2 + 2 * (ph - th) * y2 - 2 * (ph + th) * z2 +
                         (ph - th) * (ph - th));
            return clamp10(P[0] * r);
        }
        case 76:  // f_noise3d
            return noise_at(env, Vec3(x, y, z), env.noise_generator);
        case 78:  // f_noise_generator
            return noise_at(env, Vec3(x, y, z), int_param(P[0], INT_MIN, INT_MAX) & 3);
        default:
            return 0.0;
    }
}

// ---------------------------------------------------------------- expressions

constexpr int kMaxSlots = 64;

double eval_math1(FnMath1 m, double a) {
    switch (m) {
        case FnMath1::Sin: return std::sin(a);
        case FnMath1::Cos: return std::cos(a);
        case FnMath1::Tan: return std::tan(a);
        case FnMath1::Asin: return std::asin(a);
        case FnMath1::Acos: return std::acos(a);
        case FnMath1::Atan: return std::atan(a);
        case FnMath1::Sinh: return std::sinh(a);
        case FnMath1::Cosh: return std::cosh(a);
        case FnMath1::Tanh: return std::tanh(a);
        case FnMath1::Asinh: return std::asinh(a);
        case FnMath1::Acosh: return std::acosh(a);
        case FnMath1::Atanh: return std::atanh(a);
        case FnMath1::Abs: return std::fabs(a);
        case FnMath1::Radians: return a * kPi / 180.0;
        case FnMath1::Degrees: return a * 180.0 / kPi;
        case FnMath1::Int: return std::trunc(a);
        case FnMath1::Floor: return std::floor(a);
        case FnMath1::Ceil: return std::ceil(a);
        case FnMath1::Sqrt: return std::sqrt(a);
        case FnMath1::Exp: return std::exp(a);
        case FnMath1::Ln: return std::log(a);
        case FnMath1::Log: return std::log10(a);
        case FnMath1::Sqr: return a * a;
    }
    return 0;
}

class Evaluator {
public:
    Evaluator(const FunctionEnv& env, const Function& f, double* slots)
        : env_(env), f_(f), slots_(slots) {}

    double node(int i) {
        const FnNode& n = f_.nodes[i];
        const int* a = f_.operands.data() + n.first;
        switch (n.op) {
            case FnOp::Const: return n.value;
            case FnOp::Param: return slots_[n.index];
            case FnOp::Neg: return -node(a[0]);
            case FnOp::Add: return node(a[0]) + node(a[1]);
            case FnOp::Sub: return node(a[0]) - node(a[1]);
            case FnOp::Mul: return node(a[0]) * node(a[1]);
            case FnOp::Div: return node(a[0]) / node(a[1]);
            case FnOp::Pow: return std::pow(node(a[0]), node(a[1]));
            case FnOp::Lt: return node(a[0]) < node(a[1]) ? 1 : 0;
            case FnOp::Le: return node(a[0]) <= node(a[1]) ? 1 : 0;
            case FnOp::Gt: return node(a[0]) > node(a[1]) ? 1 : 0;
            case FnOp::Ge: return node(a[0]) >= node(a[1]) ? 1 : 0;
            case FnOp::Eq: return node(a[0]) == node(a[1]) ? 1 : 0;
            case FnOp::Ne: return node(a[0]) != node(a[1]) ? 1 : 0;
            case FnOp::And: {
                double l = node(a[0]), r = node(a[1]);
                return (l != 0) && (r != 0) ? 1 : 0;
            }
            case FnOp::Or: {
                double l = node(a[0]), r = node(a[1]);
                return (l != 0) || (r != 0) ? 1 : 0;
            }
            case FnOp::Math1: return eval_math1(static_cast<FnMath1>(n.index), node(a[0]));
            case FnOp::Atan2: return std::atan2(node(a[0]), node(a[1]));
            case FnOp::Mod: return std::fmod(node(a[0]), node(a[1]));
            case FnOp::IntDiv: return std::trunc(node(a[0]) / node(a[1]));
            case FnOp::Min:
            case FnOp::Max: {
                double r = node(a[0]);
                for (int k = 1; k < n.count; ++k) {
                    double v = node(a[k]);
                    r = n.op == FnOp::Min ? std::min(r, v) : std::max(r, v);
                }
                return r;
            }
            case FnOp::Select: {
                double c = node(a[0]);
                if (n.count == 3) return c < 0 ? node(a[1]) : node(a[2]);
                return c < 0 ? node(a[1]) : c == 0 ? node(a[2]) : node(a[3]);
            }
            case FnOp::Sum:
            case FnOp::Prod: {
                double from = node(a[0]), to = node(a[1]);
                double r = n.op == FnOp::Sum ? 0.0 : 1.0;
                for (double k = from; k <= to; k += 1.0) {
                    slots_[n.index] = k;
                    double v = node(a[2]);
                    r = n.op == FnOp::Sum ? r + v : r * v;
                }
                return r;
            }
            case FnOp::Call:
            case FnOp::Internal: {
                double args[kMaxSlots];
                int na = std::min(n.count, kMaxSlots);
                for (int k = 0; k < na; ++k) args[k] = node(a[k]);
                if (n.op == FnOp::Internal) {
                    for (int k = na; k < 3 + 10; ++k) args[k] = 0;
                    return eval_internal(env_, n.index, args);
                }
                if (n.member < 0) return evaluate_function(env_, n.index, args, na);
                double out[5];
                evaluate_function_vector(env_, n.index, args, na, out);
                if (n.member == 5) return 0.297 * out[0] + 0.589 * out[1] + 0.114 * out[2];
                return out[n.member];
            }
        }
        return 0;
    }

private:
    const FunctionEnv& env_;
    const Function& f_;
    double* slots_;
};

}  // namespace

const char* internal_function_name(int id) {
    return id >= 0 && id < kInternalFunctionCount ? kInternals[id].name : "?";
}
int internal_function_arity(int id) {
    return id >= 0 && id < kInternalFunctionCount ? 3 + kInternals[id].params : 3;
}
bool internal_function_implemented(int id) {
    return id >= 0 && id < kInternalFunctionCount && kInternals[id].implemented;
}

void evaluate_function_vector(const FunctionEnv& env, int fn, const double* args, int nargs,
                              double out[5]) {
    const Function& f = (*env.functions)[static_cast<size_t>(fn)];
    auto arg = [&](int i) { return i < nargs ? args[i] : 0.0; };
    switch (f.kind) {
        case FunctionKind::Expression: {
            double slots[kMaxSlots] = {};
            for (int i = 0; i < nargs && i < kMaxSlots; ++i) slots[i] = args[i];
            double v = f.root >= 0 ? Evaluator(env, f, slots).node(f.root) : 0.0;
            for (int k = 0; k < 5; ++k) out[k] = v;
            return;
        }
        case FunctionKind::Internal: {
            double a[3 + 16] = {};
            for (int i = 0; i < nargs && i < 3 + 16; ++i) a[i] = args[i];
            double v = eval_internal(env, f.internal, a);
            for (int k = 0; k < 5; ++k) out[k] = v;
            return;
        }
        case FunctionKind::Pattern:
        case FunctionKind::Pigment: {
            for (int k = 0; k < 5; ++k) out[k] = 0;
            if (env.pattern) env.pattern(env.user, f, Vec3(arg(0), arg(1), arg(2)), out);
            if (f.kind == FunctionKind::Pattern)
                for (int k = 1; k < 5; ++k) out[k] = out[0];
            return;
        }
        case FunctionKind::Transform: {
            Vec3 p = f.transform.point(Vec3(arg(0), arg(1), arg(2)));
            out[0] = p.x;
            out[1] = p.y;
            out[2] = p.z;
            out[3] = out[4] = 0;
            return;
        }
        case FunctionKind::Spline:
            f.spline.evaluate(arg(0), out);
            return;
    }
}

double evaluate_function(const FunctionEnv& env, int fn, const double* args, int nargs) {
    const Function& f = (*env.functions)[static_cast<size_t>(fn)];
    if (f.kind == FunctionKind::Expression) {
        double slots[kMaxSlots] = {};
        for (int i = 0; i < nargs && i < kMaxSlots; ++i) slots[i] = args[i];
        return f.root >= 0 ? Evaluator(env, f, slots).node(f.root) : 0.0;
    }
    double out[5];
    evaluate_function_vector(env, fn, args, nargs, out);
    return out[0];
}

}  // namespace glint::scene
