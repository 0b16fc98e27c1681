// POV-Ray user-defined functions (`#declare F = function(a, b) { expr }`, reference manual
// 3.3.1.8 "User-Defined Functions") and splines (3.3.1.9), as plain data: the importer compiles
// a function body into a flat expression tree, the renderer evaluates it (function patterns)
// and so does the importer (`#declare V = F(1, 2, 3);`). Patterns and pigments used as functions
// (`function { pattern { agate } }`) are evaluated through a hook the renderer installs, since
// the pattern code lives above this layer.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/math.h"
#include "core/transform.h"
#include "scene/texture.h"

namespace glint::scene {

// spline { linear_spline | quadratic_spline | cubic_spline | natural_spline  t, <v> ... }
// (POV-Ray's splines.cpp: entries sorted by t, a repeated t replaces the entry).
struct Spline {
    enum class Type { Linear, Quadratic, Cubic, Natural };
    Type type = Type::Linear;
    std::vector<double> par;                  // sorted ascending
    std::vector<std::array<double, 5>> vec;   // the value at each par
    int terms = 2;                            // components the calls return (2..5)

    void insert(double t, const std::array<double, 5>& v);
    // POV-Ray's Get_Spline_Val: out[0..4]; outside the range the end value (cubic: the
    // second / next-to-last point, as POV-Ray).
    void evaluate(double t, double out[5]) const;
};

enum class FnOp : unsigned char {
    Const,     // value
    Param,     // index: argument slot
    Neg,       // a[0]
    Add, Sub, Mul, Div, Pow,      // a[0] op a[1]
    Lt, Le, Gt, Ge, Eq, Ne, And, Or,
    Math1,     // index: FnMath1, a[0]
    Atan2, Mod, IntDiv,           // atan2(a, b), mod(a, b) (fmod), div(a, b)
    Min, Max,  // a[0..count)
    Select,    // select(c, neg, zero_or_pos) or select(c, neg, zero, pos)
    Sum, Prod, // index: loop slot; a[0] from, a[1] to, a[2] body
    Call,      // index: function; a[0..count) arguments; member: component for vector fns
    Internal,  // index: internal function id (functions.inc); a[0..count) arguments
};

enum class FnMath1 : unsigned char {
    Sin, Cos, Tan, Asin, Acos, Atan, Sinh, Cosh, Tanh, Asinh, Acosh, Atanh, Abs, Radians,
    Degrees, Int, Floor, Ceil, Sqrt, Exp, Ln, Log, Sqr,
};

struct FnNode {
    FnOp op = FnOp::Const;
    int index = 0;
    int member = -1;  // Call of a vector function: 0..4 (x/red ... transmit), 5 = gray
    int first = 0;    // operands are Function::operands[first, first + count)
    int count = 0;
    double value = 0;
};

enum class FunctionKind {
    Expression,  // nodes/root
    Internal,    // function { internal(N) }: POV-Ray's built-in functions (functions.inc)
    Pattern,     // function { pattern { ... } }: the pattern value
    Pigment,     // function { pigment { ... } }: a color (vector function)
    Transform,   // function { transform { ... } }: a point (vector function)
    Spline,      // function { spline { ... } }: the spline's value (vector function)
};

struct Function {
    FunctionKind kind = FunctionKind::Expression;
    std::string name;                 // the identifier it was declared as, if any
    std::vector<std::string> params;  // x, y, z when none were written
    int slots = 0;                    // params + sum/prod loop variables
    std::vector<FnNode> nodes;
    std::vector<int> operands;
    int root = -1;
    int internal = -1;               // Internal
    std::vector<Pigment> pigment;    // Pattern / Pigment: exactly one
    Transform transform;             // Transform
    Spline spline;                   // Spline
    FileLoc loc;

    bool is_vector() const {
        return kind == FunctionKind::Pigment || kind == FunctionKind::Transform ||
               kind == FunctionKind::Spline;
    }
};

// What evaluation needs besides the function: the other functions (calls by index) and hooks
// for what lives above the scene layer. A null hook evaluates to 0.
struct FunctionEnv {
    const std::vector<Function>* functions = nullptr;
    // Pattern: out[0] = pattern value; Pigment: out = rgbft. p is the point passed in.
    void (*pattern)(const void* user, const Function& f, const Vec3& p, double out[5]) = nullptr;
    const void* user = nullptr;
    // Replaces POV-Ray's Noise(p, generator) (core/noise.h) when set (tests).
    double (*noise)(const Vec3& p, int generator) = nullptr;
    int noise_generator = 2;  // global_settings { noise_generator }
};

// Calls function `fn` with `nargs` arguments; a vector function returns its first component.
double evaluate_function(const FunctionEnv& env, int fn, const double* args, int nargs);
// Vector functions: all five components (scalar functions fill out[0..4] with the value).
void evaluate_function_vector(const FunctionEnv& env, int fn, const double* args, int nargs,
                              double out[5]);

// functions.inc's `internal(N)`: the name POV-Ray gives N, its number of arguments (x, y, z
// plus parameters), and whether glint implements it (others evaluate to 0).
constexpr int kInternalFunctionCount = 79;
const char* internal_function_name(int id);
int internal_function_arity(int id);
bool internal_function_implemented(int id);

}  // namespace glint::scene
