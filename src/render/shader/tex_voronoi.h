// Blender's Voronoi Texture node (ShaderNodeTexVoronoi) evaluated as Cycles 3.4 evaluates it
// (kernel/svm/voronoi.h): one jittered feature point per unit cell, placed by Cycles' lookup3
// hashes of the cell's coordinates, searched over the neighbouring cells (5^N for Smooth F1).
// Every feature, metric and dimension count; 1D always measures |a - b|, whatever the metric,
// and Distance to Edge and N-Sphere Radius always use the Euclidean distance, as in Cycles.
#pragma once

#include "render/shader/float3.h"
#include "render/shader/tex_noise.h"

namespace glint::render::shader {

enum class VoronoiFeature { F1, F2, SMOOTH_F1, DISTANCE_TO_EDGE, N_SPHERE_RADIUS };
enum class VoronoiMetric { EUCLIDEAN, MANHATTAN, CHEBYCHEV, MINKOWSKI };

struct VoronoiTextureParams {
    NoiseDimensions dimensions = NoiseDimensions::D3;  // voronoi_dimensions
    VoronoiFeature feature = VoronoiFeature::F1;       // feature
    VoronoiMetric metric = VoronoiMetric::EUCLIDEAN;   // distance
};

// The node's input sockets, with Blender's defaults. Smoothness is the socket's value (the
// node halves it and clamps it to [0, 0.5]); randomness is clamped to [0, 1].
struct VoronoiTextureInputs {
    float3 vector;
    float w = 0.0f;
    float scale = 5.0f;
    float smoothness = 1.0f;
    float exponent = 0.5f;  // Minkowski's exponent
    float randomness = 1.0f;
};

// Outputs a feature does not produce stay zero: Distance to Edge gives distance only,
// N-Sphere Radius radius only. Position is in the input's space (divided by scale; 2D leaves
// z 0, 1D leaves it all 0); W is the feature point's w for 1D and 4D.
struct VoronoiTextureOutput {
    float distance = 0.0f;
    float3 color;
    float3 position;
    float w = 0.0f;
    float radius = 0.0f;
};

VoronoiTextureOutput voronoi_texture(const VoronoiTextureInputs& in,
                                     const VoronoiTextureParams& params);

}  // namespace glint::render::shader
