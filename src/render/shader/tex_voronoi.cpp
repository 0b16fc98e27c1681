#include "render/shader/tex_voronoi.h"

#include <cmath>

#include "render/shader/cycles_hash.h"

namespace glint::render::shader {
namespace {

// An N-component point; x is c[0] .. w is c[3].
template <int N>
struct Pt {
    float c[N] = {};
};

template <int N>
Pt<N> operator+(Pt<N> a, Pt<N> b) {
    for (int i = 0; i < N; ++i) a.c[i] += b.c[i];
    return a;
}
template <int N>
Pt<N> operator-(Pt<N> a, Pt<N> b) {
    for (int i = 0; i < N; ++i) a.c[i] -= b.c[i];
    return a;
}
template <int N>
Pt<N> operator*(Pt<N> a, float s) {
    for (int i = 0; i < N; ++i) a.c[i] *= s;
    return a;
}
// Cycles divides its float2 and float4 by a scalar through the reciprocal, its float3 (and
// plain floats) directly.
template <int N>
Pt<N> operator/(Pt<N> a, float s) {
    if constexpr (N == 2 || N == 4) {
        const float r = 1.0f / s;
        for (int i = 0; i < N; ++i) a.c[i] *= r;
    } else {
        for (int i = 0; i < N; ++i) a.c[i] /= s;
    }
    return a;
}
template <int N>
Pt<N> floor_of(Pt<N> a) {
    for (int i = 0; i < N; ++i) a.c[i] = std::floor(a.c[i]);
    return a;
}

// Cycles' float min/max (the comparison decides, NaN or not).
float min_c(float a, float b) { return a < b ? a : b; }
float max_c(float a, float b) { return a > b ? a : b; }
float clamp_c(float a, float lo, float hi) { return min_c(max_c(a, lo), hi); }

// a * b + c rounded once. Blender's x86-64 CPU kernel (AVX2, built with floating-point
// contraction) fuses these multiply-adds; fusing the same ones here gives its values bit for
// bit (checked against Blender 3.4.1 renders).
float madd(float a, float b, float c) { return std::fma(a, b, c); }

// Dot products as Cycles computes them: float2's scalar sum (fused), float3's and float4's
// SSE4.1 dpps, which adds the products pairwise.
template <int N>
float dot(Pt<N> a, Pt<N> b) {
    if constexpr (N == 1) return a.c[0] * b.c[0];
    if constexpr (N == 2) return madd(a.c[0], b.c[0], a.c[1] * b.c[1]);
    if constexpr (N == 3) return (a.c[0] * b.c[0] + a.c[1] * b.c[1]) + a.c[2] * b.c[2];
    if constexpr (N == 4)
        return (a.c[0] * b.c[0] + a.c[1] * b.c[1]) + (a.c[2] * b.c[2] + a.c[3] * b.c[3]);
}

template <int N>
float length(Pt<N> a) {
    return std::sqrt(dot(a, a));
}

template <int N>
Pt<N> normalized(Pt<N> a) {
    return a / length(a);
}

// The feature point's jitter in [0, 1]^N, hashed from its cell's coordinates.
Pt<1> jitter(Pt<1> k) { return {{hash_float_to_float(k.c[0])}}; }
Pt<2> jitter(Pt<2> k) {
    const float3 h = hash_float2_to_float2(k.c[0], k.c[1]);
    return {{h.x, h.y}};
}
Pt<3> jitter(Pt<3> k) {
    const float3 h = hash_float3_to_float3({k.c[0], k.c[1], k.c[2]});
    return {{h.x, h.y, h.z}};
}
Pt<4> jitter(Pt<4> k) {
    const float4 h = hash_float4_to_float4({k.c[0], k.c[1], k.c[2], k.c[3]});
    return {{h.x, h.y, h.z, h.w}};
}

// The cell's colour output.
float3 cell_color(Pt<1> k) { return hash_float_to_float3(k.c[0]); }
float3 cell_color(Pt<2> k) { return hash_float2_to_float3(k.c[0], k.c[1]); }
float3 cell_color(Pt<3> k) { return hash_float3_to_float3({k.c[0], k.c[1], k.c[2]}); }
float3 cell_color(Pt<4> k) { return hash_float4_to_float3({k.c[0], k.c[1], k.c[2], k.c[3]}); }

// The feature point of the cell at `offset` from the sample's cell, relative to that cell.
template <int N>
Pt<N> feature_point(Pt<N> cell, Pt<N> offset, float randomness) {
    const Pt<N> j = jitter(cell + offset);
    Pt<N> r;
    for (int i = 0; i < N; ++i) r.c[i] = madd(j.c[i], randomness, offset.c[i]);
    return r;
}

template <int N>
float metric_distance(Pt<N> a, Pt<N> b, VoronoiMetric metric, float exponent) {
    const Pt<N> d = a - b;
    if constexpr (N == 1) return std::fabs(d.c[0]);
    switch (metric) {
        case VoronoiMetric::EUCLIDEAN:
            return length(d);
        case VoronoiMetric::MANHATTAN: {
            float s = std::fabs(d.c[0]);
            for (int i = 1; i < N; ++i) s += std::fabs(d.c[i]);
            return s;
        }
        case VoronoiMetric::CHEBYCHEV: {
            float m = std::fabs(d.c[N - 1]);
            for (int i = N - 2; i >= 0; --i) m = max_c(std::fabs(d.c[i]), m);
            return m;
        }
        case VoronoiMetric::MINKOWSKI: {
            float s = std::pow(std::fabs(d.c[0]), exponent);
            for (int i = 1; i < N; ++i) s += std::pow(std::fabs(d.c[i]), exponent);
            return std::pow(s, 1.0f / exponent);
        }
    }
    return 0.0f;
}

// Calls f(offset) for every offset in [-r, r]^N, x fastest and w slowest, as Cycles' loops.
template <int N, class F>
void for_each_offset(int r, F&& f) {
    int idx[N];
    for (int i = 0; i < N; ++i) idx[i] = -r;
    for (;;) {
        Pt<N> o;
        for (int i = 0; i < N; ++i) o.c[i] = static_cast<float>(idx[i]);
        f(o);
        int i = 0;
        while (i < N && idx[i] == r) idx[i++] = -r;
        if (i == N) return;
        ++idx[i];
    }
}

// What one feature search gives, before scaling back: distance, colour, position (cell
// space), radius.
template <int N>
struct Found {
    float distance = 0.0f;
    float3 color;
    Pt<N> position;
    float radius = 0.0f;
};

template <int N>
Found<N> search_f1(Pt<N> coord, float exponent, float randomness, VoronoiMetric metric) {
    const Pt<N> cell = floor_of(coord);
    const Pt<N> local = coord - cell;
    float best = 8.0f;
    Pt<N> best_offset, best_point;
    for_each_offset<N>(1, [&](Pt<N> offset) {
        const Pt<N> point = feature_point(cell, offset, randomness);
        const float d = metric_distance(point, local, metric, exponent);
        if (d < best) {
            best_offset = offset;
            best = d;
            best_point = point;
        }
    });
    return {best, cell_color(cell + best_offset), best_point + cell, 0.0f};
}

template <int N>
Found<N> search_f2(Pt<N> coord, float exponent, float randomness, VoronoiMetric metric) {
    const Pt<N> cell = floor_of(coord);
    const Pt<N> local = coord - cell;
    float d1 = 8.0f, d2 = 8.0f;
    Pt<N> offset1, point1, offset2, point2;
    for_each_offset<N>(1, [&](Pt<N> offset) {
        const Pt<N> point = feature_point(cell, offset, randomness);
        const float d = metric_distance(point, local, metric, exponent);
        if (d < d1) {
            d2 = d1;
            d1 = d;
            offset2 = offset1;
            offset1 = offset;
            point2 = point1;
            point1 = point;
        } else if (d < d2) {
            d2 = d;
            offset2 = offset;
            point2 = point;
        }
    });
    return {d2, cell_color(cell + offset2), point2 + cell, 0.0f};
}

// Cycles' mix(a, b, t) = a + t (b - a), fused.
float mix1(float a, float b, float t) { return madd(t, b - a, a); }
float3 mix3(float3 a, float3 b, float t) {
    return {mix1(a.x, b.x, t), mix1(a.y, b.y, t), mix1(a.z, b.z, t)};
}

template <int N>
Found<N> search_smooth_f1(Pt<N> coord, float smoothness, float exponent, float randomness,
                          VoronoiMetric metric) {
    const Pt<N> cell = floor_of(coord);
    const Pt<N> local = coord - cell;
    float dist = 8.0f;
    float3 color;
    Pt<N> position;
    for_each_offset<N>(2, [&](Pt<N> offset) {
        const Pt<N> point = feature_point(cell, offset, randomness);
        const float d = metric_distance(point, local, metric, exponent);
        // Cycles' smoothstep(0, 1, x).
        const float x = 0.5f + 0.5f * (dist - d) / smoothness;
        const float h = x < 0.0f ? 0.0f : (x >= 1.0f ? 1.0f : (3.0f - 2.0f * x) * (x * x));
        float correction = smoothness * h * (1.0f - h);
        dist = mix1(dist, d, h) - correction;
        correction /= 1.0f + 3.0f * smoothness;
        color = mix3(color, cell_color(cell + offset), h) - float3(correction);
        for (int i = 0; i < N; ++i) position.c[i] = mix1(position.c[i], point.c[i], h) - correction;
    });
    return {dist, color, cell + position, 0.0f};
}

template <int N>
float search_edge(Pt<N> coord, float randomness) {
    const Pt<N> cell = floor_of(coord);
    const Pt<N> local = coord - cell;
    Pt<N> to_closest;
    float best = 8.0f;
    for_each_offset<N>(1, [&](Pt<N> offset) {
        const Pt<N> to_point = feature_point(cell, offset, randomness) - local;
        const float d = dot(to_point, to_point);
        if (d < best) {
            best = d;
            to_closest = to_point;
        }
    });
    best = 8.0f;
    for_each_offset<N>(1, [&](Pt<N> offset) {
        const Pt<N> to_point = feature_point(cell, offset, randomness) - local;
        const Pt<N> perpendicular = to_point - to_closest;
        if (dot(perpendicular, perpendicular) > 0.0001f) {
            const float d = dot((to_closest + to_point) / 2.0f, normalized(perpendicular));
            best = min_c(best, d);
        }
    });
    return best;
}

float search_edge_1d(float w, float randomness) {
    const float cell = std::floor(w);
    const float local = w - cell;
    const float mid = hash_float_to_float(cell) * randomness;
    const float left = -1.0f + hash_float_to_float(cell - 1.0f) * randomness;
    const float right = 1.0f + hash_float_to_float(cell + 1.0f) * randomness;
    const float to_left = std::fabs((mid + left) / 2.0f - local);
    const float to_right = std::fabs((mid + right) / 2.0f - local);
    return min_c(to_left, to_right);
}

template <int N>
float search_radius(Pt<N> coord, float randomness) {
    const Pt<N> cell = floor_of(coord);
    const Pt<N> local = coord - cell;
    Pt<N> closest, closest_offset;
    float best = 8.0f;
    for_each_offset<N>(1, [&](Pt<N> offset) {
        const Pt<N> point = feature_point(cell, offset, randomness);
        const float d = metric_distance(point, local, VoronoiMetric::EUCLIDEAN, 0.0f);
        if (d < best) {
            best = d;
            closest = point;
            closest_offset = offset;
        }
    });
    best = 8.0f;
    Pt<N> nearest_to_closest;
    for_each_offset<N>(1, [&](Pt<N> offset) {
        bool centre = true;
        for (int i = 0; i < N; ++i) centre = centre && offset.c[i] == 0.0f;
        if (centre) return;
        const Pt<N> neighbour = offset + closest_offset;
        const Pt<N> point = feature_point(cell, neighbour, randomness);
        const float d = metric_distance(closest, point, VoronoiMetric::EUCLIDEAN, 0.0f);
        if (d < best) {
            best = d;
            nearest_to_closest = point;
        }
    });
    return metric_distance(nearest_to_closest, closest, VoronoiMetric::EUCLIDEAN, 0.0f) / 2.0f;
}

template <int N>
Found<N> evaluate(Pt<N> coord, const VoronoiTextureParams& params, float smoothness, float exponent,
                  float randomness) {
    switch (params.feature) {
        case VoronoiFeature::F1:
            return search_f1(coord, exponent, randomness, params.metric);
        case VoronoiFeature::F2:
            return search_f2(coord, exponent, randomness, params.metric);
        case VoronoiFeature::SMOOTH_F1:
            return search_smooth_f1(coord, smoothness, exponent, randomness, params.metric);
        case VoronoiFeature::DISTANCE_TO_EDGE: {
            Found<N> f;
            if constexpr (N == 1)
                f.distance = search_edge_1d(coord.c[0], randomness);
            else
                f.distance = search_edge(coord, randomness);
            return f;
        }
        case VoronoiFeature::N_SPHERE_RADIUS: {
            Found<N> f;
            f.radius = search_radius(coord, randomness);
            return f;
        }
    }
    return {};
}

float safe_div(float a, float b) { return b != 0.0f ? a / b : 0.0f; }

}  // namespace

VoronoiTextureOutput voronoi_texture(const VoronoiTextureInputs& in,
                                     const VoronoiTextureParams& params) {
    const float randomness = clamp_c(in.randomness, 0.0f, 1.0f);
    const float smoothness = clamp_c(in.smoothness / 2.0f, 0.0f, 0.5f);
    const float scale = in.scale;
    const float w = in.w * scale;
    const float3 co = in.vector * scale;
    const float e = in.exponent;
    VoronoiTextureOutput out;
    switch (params.dimensions) {
        case NoiseDimensions::D1: {
            const Found<1> f = evaluate(Pt<1>{{w}}, params, smoothness, e, randomness);
            out.distance = f.distance;
            out.color = f.color;
            out.radius = f.radius;
            out.w = safe_div(f.position.c[0], scale);
            break;
        }
        case NoiseDimensions::D2: {
            const Found<2> f = evaluate(Pt<2>{{co.x, co.y}}, params, smoothness, e, randomness);
            out.distance = f.distance;
            out.color = f.color;
            out.radius = f.radius;
            if (scale != 0.0f) {
                const Pt<2> p = f.position / scale;
                out.position = {p.c[0], p.c[1], 0.0f};
            }
            break;
        }
        case NoiseDimensions::D3: {
            const Found<3> f =
                evaluate(Pt<3>{{co.x, co.y, co.z}}, params, smoothness, e, randomness);
            out.distance = f.distance;
            out.color = f.color;
            out.radius = f.radius;
            if (scale != 0.0f)
                out.position = float3(f.position.c[0], f.position.c[1], f.position.c[2]) / scale;
            break;
        }
        case NoiseDimensions::D4: {
            const Found<4> f =
                evaluate(Pt<4>{{co.x, co.y, co.z, w}}, params, smoothness, e, randomness);
            out.distance = f.distance;
            out.color = f.color;
            out.radius = f.radius;
            if (scale != 0.0f) {
                const Pt<4> p = f.position / scale;
                out.position = {p.c[0], p.c[1], p.c[2]};
                out.w = p.c[3];
            }
            break;
        }
    }
    return out;
}

}  // namespace glint::render::shader
