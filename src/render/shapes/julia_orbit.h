// The orbit arithmetic of julia_fractal (POV-Ray 3.7 quatern.cpp, hcmplx.cpp): iterating
// z -> f(z) + c from a point of the 4D slice, the step estimate the ray march takes outside
// the set, and the surface normal from the orbit. Used by julia_fractal.cpp.
#pragma once

#include <vector>

#include "core/math.h"
#include "scene/shape.h"

namespace glint::render::julia {

struct Quad {
    double x = 0, y = 0, z = 0, w = 0;
};
struct Complex {
    double x = 0, y = 0;
};

// POV-Ray's complex functions as hcmplx.cpp evaluates them (branch cuts and the cases it
// leaves `out` as it was included). `exponent`: pwr's only.
void complex_function(scene::JuliaFunction f, const Complex& z, const Complex& exponent,
                      Complex* out);

// The orbit of one point: entries 0 ... max_iteration, kept on the stack for small counts.
class OrbitStack {
public:
    explicit OrbitStack(int iterations) {
        if (iterations + 1 > kInline) {
            heap_.resize(static_cast<size_t>(iterations) + 1);
            data_ = heap_.data();
        }
    }
    OrbitStack(const OrbitStack&) = delete;
    OrbitStack& operator=(const OrbitStack&) = delete;
    Quad* data() { return data_; }

private:
    static constexpr int kInline = 33;
    Quad inline_[kInline];
    std::vector<Quad> heap_;
    Quad* data_ = inline_;
};

class Orbit {
public:
    explicit Orbit(const scene::JuliaFractal& s);

    // Radius of the bounding sphere about the origin.
    double radius() const { return radius_; }
    int iterations() const { return s_.max_iteration; }
    // The march's smallest step (1 / precision).
    double min_step() const { return min_step_; }

    // Whether p's orbit stays within the escape radius for every iteration (POV-Ray's
    // Iteration_*); the orbit is left in `stack`.
    bool stays(const Vec3& p, Quad* stack) const;
    // stays(), and the distance the march may step along unit `dir` (POV-Ray's
    // D_Iteration_*): an estimate of the distance to the set outside it, min_step() inside.
    bool stays_with_step(const Vec3& p, const Vec3& dir, double* step, Quad* stack) const;
    // The (unnormalized) normal from an orbit of `n` iterations (POV-Ray's Normal_Calc_*).
    Vec3 normal(int n, const Quad* stack) const;

private:
    Quad start(const Vec3& p) const;
    Quad map(const Quad& q) const;  // hypercomplex f(q), without c
    double escape_step(double f_value, int n, const Vec3& dir, const Quad* stack) const;

    scene::JuliaFractal s_;
    Complex exponent_;
    double radius_ = 2;
    double exit_value_ = 4;
    double min_step_ = 0.05;
};

}  // namespace glint::render::julia
