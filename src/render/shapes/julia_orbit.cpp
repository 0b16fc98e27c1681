// julia_fractal's orbits, after POV-Ray 3.7 quatern.cpp and hcmplx.cpp. The evaluation order
// of each sum follows POV-Ray's so that points near the surface fall on the same side; where
// 3.7 has a quirk that shows in its images it is kept, and named:
//  - hypercomplex `cube` iterates z^2 + c, as 3.7 does;
//  - the inside test of the hypercomplex functions (exp ... pwr) starts the orbit with z = y;
//  - their normal multiplies by f(z) rather than f'(z).
#include "render/shapes/julia_orbit.h"

#include <algorithm>
#include <cmath>

namespace glint::render::julia {
namespace {

using scene::JuliaAlgebra;
using scene::JuliaFunction;

constexpr double kFractalTolerance = 1e-7;  // fractal.cpp
constexpr double kStepTolerance = 1e-8;     // hcmplx.cpp

// Hypercomplex product (commutative).
Quad hmul(const Quad& a, const Quad& b) {
    return {a.x * b.x - a.y * b.y - a.z * b.z + a.w * b.w,
            a.y * b.x + a.x * b.y - a.w * b.z - a.z * b.w,
            a.z * b.x - a.w * b.y + a.x * b.z - a.y * b.w,
            a.w * b.x + a.z * b.y + a.y * b.z + a.x * b.w};
}

Quad hsqr(const Quad& a) {
    return {a.x * a.x - a.y * a.y - a.z * a.z + a.w * a.w, 2.0 * (a.x * a.y - a.z * a.w),
            2.0 * (a.z * a.x - a.w * a.y), 2.0 * (a.w * a.x + a.z * a.y)};
}

// 1 / a; zero where a has no inverse (POV-Ray leaves the result unset there).
Quad hreciprocal(const Quad& a) {
    const double x = a.x, y = a.y, z = a.z, w = a.w;
    const double det = ((x - w) * (x - w) + (y + z) * (y + z)) *
                       ((x + w) * (x + w) + (y - z) * (y - z));
    if (det == 0.0) return {};
    const double mod = x * x + y * y + z * z + w * w;
    const double xw_yz = x * w - y * z;
    return {(x * mod - 2 * w * xw_yz) / det, (-y * mod - 2 * z * xw_yz) / det,
            (-z * mod - 2 * y * xw_yz) / det, (w * mod - 2 * x * xw_yz) / det};
}

double norm2(const Quad& q) { return q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w; }

Quad plus(const Quad& a, const double c[4]) {
    return {a.x + c[0], a.y + c[1], a.z + c[2], a.w + c[3]};
}

// The projection of hypercomplex orbit derivative q onto the last orbit point n.
Vec3 hnormal(const Quad& q, const Quad& n) {
    return {q.x * n.x + q.y * n.y + q.z * n.z + q.w * n.w,
            -q.y * n.x + q.x * n.y - q.w * n.z + q.z * n.w,
            -q.z * n.x - q.w * n.y + q.x * n.z + q.y * n.w};
}

// Quaternion product of the running derivative and an orbit point, in the two term orders
// of POV-Ray's sqr and cube estimators.
Quad qmul_sqr(const Quad& a, const Quad& b) {
    return {a.x * b.x - a.y * b.y - a.z * b.z - a.w * b.w,
            a.x * b.y + a.y * b.x + a.w * b.z - a.z * b.w,
            a.x * b.z + a.z * b.x + a.y * b.w - a.w * b.y,
            a.x * b.w + a.w * b.x + a.z * b.y - a.y * b.z};
}
Quad qmul_cube(const Quad& a, const Quad& b) {
    return {a.x * b.x - a.y * b.y - a.z * b.z - a.w * b.w,
            a.x * b.y + a.y * b.x - a.z * b.w + a.w * b.z,
            a.x * b.z + a.y * b.w + a.z * b.x - a.w * b.y,
            a.x * b.w - a.y * b.z + a.z * b.y + a.w * b.x};
}

Complex cmul(const Complex& a, const Complex& b) {
    return {a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x};
}
// a / b; a as it was where b is zero.
Complex cdiv(const Complex& a, const Complex& b) {
    const double mod = b.x * b.x + b.y * b.y;
    if (mod == 0) return a;
    const double re = b.x / mod, im = -b.y / mod;
    return {a.x * re - a.y * im, a.x * im + a.y * re};
}
Complex cln(const Complex& a) {
    return {std::log(std::sqrt(a.x * a.x + a.y * a.y)), std::atan2(a.y, a.x)};
}
Complex csqrt(const Complex& a) {
    if (a.x == 0.0 && a.y == 0.0) return {};
    const double mag = std::sqrt(std::sqrt(a.x * a.x + a.y * a.y));
    const double theta = std::atan2(a.y, a.x) / 2;
    return {mag * std::cos(theta), mag * std::sin(theta)};
}

void catanh(const Complex& z, Complex* out) {
    if (z.x == 0.0) {
        *out = {0, std::atan(z.y)};
    } else if (std::fabs(z.x) == 1.0 && z.y == 0.0) {
        return;  // a pole: left as it was
    } else if (std::fabs(z.x) < 1.0 && z.y == 0.0) {
        *out = {std::log((1 + z.x) / (1 - z.x)) / 2, 0};
    } else {
        Complex l = cln(cdiv({1 + z.x, z.y}, {1 - z.x, -z.y}));
        *out = {0.5 * l.x, 0.5 * l.y};
    }
}

}  // namespace

void complex_function(JuliaFunction f, const Complex& z, const Complex& exponent, Complex* out) {
    switch (f) {
        case JuliaFunction::Exp: {
            const double e = std::exp(z.x);
            *out = {e * std::cos(z.y), e * std::sin(z.y)};
            return;
        }
        case JuliaFunction::Ln: *out = cln(z); return;
        case JuliaFunction::Sin:
            *out = {std::sin(z.x) * std::cosh(z.y), std::cos(z.x) * std::sinh(z.y)};
            return;
        case JuliaFunction::Sinh:
            *out = {std::sinh(z.x) * std::cos(z.y), std::cosh(z.x) * std::sin(z.y)};
            return;
        case JuliaFunction::Cos:
            *out = {std::cos(z.x) * std::cosh(z.y), -std::sin(z.x) * std::sinh(z.y)};
            return;
        case JuliaFunction::Cosh:
            *out = {std::cosh(z.x) * std::cos(z.y), std::sinh(z.x) * std::sin(z.y)};
            return;
        case JuliaFunction::Asin: {  // -i ln(iz + sqrt(1 - z^2))
            Complex s = cmul(z, z);
            s = csqrt({1 - s.x, -s.y});
            Complex l = cln({s.x - z.y, s.y + z.x});
            *out = {l.y, -l.x};
            return;
        }
        case JuliaFunction::Acos: {  // -i ln(z + sqrt(z^2 - 1))
            Complex s = cmul(z, z);
            s = csqrt({s.x - 1, s.y});
            Complex l = cln({s.x + z.x, s.y + z.y});
            *out = {l.y, -l.x};
            return;
        }
        case JuliaFunction::Asinh: {  // ln(z + sqrt(z^2 + 1))
            Complex s = cmul(z, z);
            s = csqrt({s.x + 1, s.y});
            *out = cln({s.x + z.x, s.y + z.y});
            return;
        }
        case JuliaFunction::Acosh: {  // ln(z + sqrt(z^2 - 1))
            Complex s = cmul(z, z);
            s = csqrt({s.x - 1, s.y});
            *out = cln({z.x + s.x, z.y + s.y});
            return;
        }
        case JuliaFunction::Atanh: catanh(z, out); return;
        case JuliaFunction::Atan:
            if (z.x == 0.0 && z.y == 0.0) {
                *out = {};
            } else if (z.y == 0.0) {
                *out = {std::atan(z.x), 0};
            } else if (z.x == 0.0) {
                Complex t{z.y, 0};
                catanh(t, &t);
                *out = {-t.y, t.x};
            } else {
                const Complex iz{-z.y, z.x};
                Complex l = cln(cdiv({1 - iz.x, -iz.y}, {1 + iz.x, iz.y}));
                *out = {-l.y * 0.5, 0.5 * l.x};
            }
            return;
        case JuliaFunction::Tan: {
            const double x = 2 * z.x, y = 2 * z.y;
            const double d = std::cos(x) + std::cosh(y);
            if (d == 0) return;
            *out = {std::sin(x) / d, std::sinh(y) / d};
            return;
        }
        case JuliaFunction::Tanh: {
            const double x = 2 * z.x, y = 2 * z.y;
            const double d = std::cosh(x) + std::cos(y);
            if (d == 0) return;
            *out = {std::sinh(x) / d, std::sin(y) / d};
            return;
        }
        case JuliaFunction::Pwr: {
            if (z.x == 0 && z.y == 0) {
                *out = {};
                return;
            }
            Complex t = cmul(cln(z), exponent);
            const double e = t.x < -690 ? 0 : std::exp(t.x);
            *out = {e * std::cos(t.y), e * std::sin(t.y)};
            return;
        }
        default: return;  // sqr, cube, reciprocal are not complex functions
    }
}

Orbit::Orbit(const scene::JuliaFractal& s) : s_(s), exponent_{s.exponent.x, s.exponent.y} {
    if (s.algebra == JuliaAlgebra::Quaternion) {
        double r = 1.0 + std::sqrt(s.c[0] * s.c[0] + s.c[1] * s.c[1] + s.c[2] * s.c[2] +
                                   s.c[3] * s.c[3]);
        r += kFractalTolerance;  // c = 0 would put the set's surface on the bound
        radius_ = std::min(r, 2.0);
        exit_value_ = radius_ * radius_ + kFractalTolerance;
    } else {
        radius_ = 4;
        exit_value_ = 16;
    }
    min_step_ = 1.0 / s.precision;
}

Quad Orbit::start(const Vec3& p) const {
    const double* n = s_.slice;
    return {p.x, p.y, p.z, (s_.slice_distance - n[0] * p.x - n[1] * p.y - n[2] * p.z) / n[3]};
}

// Duplex form: the hypercomplex number as two complex ones, f applied to each.
Quad Orbit::map(const Quad& q) const {
    const Complex a{q.x - q.w, q.y + q.z}, b{q.x + q.w, q.y - q.z};
    Complex ra, rb;
    complex_function(s_.function, a, exponent_, &ra);
    complex_function(s_.function, b, exponent_, &rb);
    return {.5 * (ra.x + rb.x), .5 * (ra.y + rb.y), .5 * (ra.y - rb.y), .5 * (rb.x - ra.x)};
}

bool Orbit::stays(const Vec3& p, Quad* stack) const {
    const double* c = s_.c;
    const int n = s_.max_iteration;
    if (s_.algebra == JuliaAlgebra::Quaternion) {
        double x = p.x, y = p.y, z = p.z, w = start(p).w;
        stack[0] = {x, y, z, w};
        const bool cube = s_.function == JuliaFunction::Cube;
        for (int i = 1; i <= n; ++i) {
            const double d = y * y + z * z + w * w, x2 = x * x;
            if (d + x2 > exit_value_) return false;
            if (cube) {
                const double tmp = 3.0 * x2 - d;
                x = x * (x2 - 3.0 * d) + c[0];
                y = y * tmp + c[1];
                z = z * tmp + c[2];
                w = w * tmp + c[3];
            } else {
                x *= 2.0;
                y = x * y + c[1];
                z = x * z + c[2];
                w = x * w + c[3];
                x = x2 - d + c[0];
            }
            stack[i] = {x, y, z, w};
        }
        return true;
    }
    Quad q;
    switch (s_.function) {
        case JuliaFunction::Sqr:
            q = start(p);
            stack[0] = q;
            for (int i = 1; i <= n; ++i) {
                const double yz = q.y * q.y + q.z * q.z, xw = q.x * q.x + q.w * q.w;
                if (xw + yz > exit_value_) return false;
                q = {xw - yz + c[0], 2.0 * (q.x * q.y - q.z * q.w) + c[1],
                     2.0 * (q.x * q.z - q.w * q.y) + c[2], 2.0 * (q.x * q.w + q.y * q.z) + c[3]};
                stack[i] = q;
            }
            return true;
        case JuliaFunction::Cube:
        case JuliaFunction::Reciprocal:
            q = start(p);
            stack[0] = q;
            for (int i = 1; i <= n; ++i) {
                if (norm2(q) > exit_value_) return false;
                q = plus(s_.function == JuliaFunction::Cube ? hsqr(q) : hreciprocal(q), c);
                stack[i] = q;
            }
            return true;
        default:
            q = start({p.x, p.y, p.y});  // 3.7's inside test reads y for z
            stack[0] = q;
            for (int i = 1; i <= n; ++i) {
                if (norm2(q) > exit_value_) return false;
                q = plus(map(q), c);
                stack[i] = q;
            }
            return true;
    }
}

// Outside a hypercomplex set: f / (2 |grad f . dir|) where it is neither tiny nor huge
// against the precision step, else the precision step.
double Orbit::escape_step(double f_value, int n, const Vec3& dir, const Quad* stack) const {
    double step = dot(normal(n, stack), dir);
    if (step < -kStepTolerance) {
        step = -2.0 * step;
        if (f_value > min_step_ * step && f_value < 30 * min_step_ * step) return f_value / step;
    }
    return min_step_;
}

bool Orbit::stays_with_step(const Vec3& p, const Vec3& dir, double* step, Quad* stack) const {
    const double* c = s_.c;
    const int n = s_.max_iteration;
    if (s_.algebra == JuliaAlgebra::Quaternion) {
        const bool cube = s_.function == JuliaFunction::Cube;
        double x = p.x, y = p.y, z = p.z, w = start(p).w;
        stack[0] = {x, y, z, w};
        for (int i = 1; i <= n; ++i) {
            const double d = y * y + z * z + w * w, x2 = x * x;
            const double norm = d + x2;
            if (norm > exit_value_) {
                // Distance estimate |z| log|z| / |z'| from the orbit's derivative.
                Quad q = stack[0];
                double pw = cube ? 1.0 / 3.0 : 1.0 / 2.0;
                for (int j = 1; j < i; ++j) {
                    q = cube ? qmul_cube(q, stack[j]) : qmul_sqr(q, stack[j]);
                    pw /= cube ? 3.0 : 2.0;
                }
                *step = pw * std::sqrt(norm / norm2(q)) * std::log(norm);
                return false;
            }
            if (cube) {
                const double tmp = 3.0 * x2 - d;
                x = x * (x2 - 3.0 * d) + c[0];
                y = y * tmp + c[1];
                z = z * tmp + c[2];
                w = w * tmp + c[3];
            } else {
                x *= 2.0;
                y = x * y + c[1];
                z = x * z + c[2];
                w = x * w + c[3];
                x = x2 - d + c[0];
            }
            stack[i] = {x, y, z, w};
        }
        *step = min_step_;
        return true;
    }
    Quad q = start(p);
    stack[0] = q;
    for (int i = 1; i <= n; ++i) {
        double f_value;
        if (s_.function == JuliaFunction::Sqr)
            f_value = (q.x * q.x + q.w * q.w) + (q.y * q.y + q.z * q.z);
        else
            f_value = norm2(q);
        if (f_value > exit_value_) {
            *step = escape_step(f_value, i - 1, dir, stack);
            return false;
        }
        switch (s_.function) {
            case JuliaFunction::Sqr: {
                const double yz = q.y * q.y + q.z * q.z, xw = q.x * q.x + q.w * q.w;
                q = {xw - yz + c[0], 2.0 * (q.x * q.y - q.z * q.w) + c[1],
                     2.0 * (q.x * q.z - q.w * q.y) + c[2], 2.0 * (q.x * q.w + q.y * q.z) + c[3]};
                break;
            }
            case JuliaFunction::Cube: q = plus(hsqr(q), c); break;
            case JuliaFunction::Reciprocal: q = plus(hreciprocal(q), c); break;
            default: q = plus(map(q), c); break;
        }
        stack[i] = q;
    }
    *step = min_step_;
    return true;
}

Vec3 Orbit::normal(int n, const Quad* stack) const {
    if (s_.algebra == JuliaAlgebra::Quaternion) {
        // Rows of the Jacobian of the orbit map, carried through the iterations.
        double m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
        const bool cube = s_.function == JuliaFunction::Cube;
        for (int i = 1; i <= n; ++i) {
            const double x = stack[i - 1].x, y = stack[i - 1].y, z = stack[i - 1].z,
                         w = stack[i - 1].w;
            for (auto& r : m) {
                if (cube) {
                    const double t = y * y + z * z + w * w, x2 = x * x;
                    const double x3 = x2 - t, x4 = 3.0 * x2 - t;
                    const double dt = 2.0 * (r[1] * y + r[2] * z + r[3] * w);
                    const double dt2 = 6.0 * x * r[0] - dt;
                    r[0] = (r[0] * x3 - x * dt) * 3.0;
                    r[1] = r[1] * x4 + y * dt2;
                    r[2] = r[2] * x4 + z * dt2;
                    r[3] = r[3] * x4 + w * dt2;
                } else {
                    const double t = r[0] * x - r[1] * y - r[2] * z - r[3] * w;
                    r[1] = r[0] * y + x * r[1];
                    r[2] = r[0] * z + x * r[2];
                    r[3] = r[0] * w + x * r[3];
                    r[0] = t;
                }
            }
        }
        const Quad& e = stack[n];
        Vec3 out;
        for (int k = 0; k < 3; ++k)
            out[k] = m[k][0] * e.x + m[k][1] * e.y + m[k][2] * e.z + m[k][3] * e.w;
        return out;
    }
    Quad q = stack[0];
    double scale = 2.0;
    for (int i = 1; i < n; ++i) {
        switch (s_.function) {
            case JuliaFunction::Sqr:
                q = hmul(stack[i], q);
                scale *= 2.0;
                break;
            case JuliaFunction::Cube: q = hmul(stack[i], q); break;
            case JuliaFunction::Reciprocal: {
                const Quad s = hsqr(hreciprocal(stack[i]));
                q = hmul(q, {-s.x, -s.y, -s.z, -s.w});
                break;
            }
            default: q = hmul(map(stack[i]), q); break;
        }
    }
    Quad e = stack[n];
    if (s_.function == JuliaFunction::Sqr) e = {e.x * scale, e.y * scale, e.z * scale, e.w * scale};
    return hnormal(q, e);
}

}  // namespace glint::render::julia
