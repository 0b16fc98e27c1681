// What a scene uses. The renderer sets up only what is listed here (a scene pays only for what
// it uses), and `glint render -v` prints the set and what was skipped.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace glint::scene {

struct Features {
    // Shape kinds in Shape variant order (see shape_name()).
    std::vector<bool> shapes = std::vector<bool>(std::variant_size_v<Shape>, false);
    bool csg = false;
    bool clipping = false;        // clipped_by or bounded_by anywhere
    bool lights = false;          // at least one light
    bool shadows = false;         // some light casts shadows
    bool spot_lights = false;
    bool parallel_lights = false;
    bool area_lights = false;
    bool light_fading = false;
    bool reflection = false;      // some finish reflects
    bool refraction = false;      // some transparent material bends light (ior != 1)
    bool transparency = false;    // some pigment has filter or transmit
    bool interior_fading = false;
    bool highlights = false;      // phong or specular
    bool image_textures = false;  // image_map anywhere: opens the texture system
    bool uv_mapping = false;
    bool checker = false;
    bool gradient = false;
    bool normals = false;         // normal perturbation
    bool bump_maps = false;       // bump_map normals (not rendered yet)
    bool patterns = false;        // procedural patterns other than checker and gradient
    bool texture_maps = false;    // texture_map, block patterns of textures, layered textures
    bool sky_sphere = false;
    bool media = false;  // participating media: in a hollow object's interior or everywhere
    bool radiosity = false;  // global_settings radiosity: the classic renderer's irradiance cache
    bool photons = false;    // global_settings photons: the classic renderer's caustic photons

    // Whether rays other than primary and shadow rays can be spawned.
    bool secondary_rays() const { return reflection || refraction || transparency; }
    // Human-readable: each entry "name" for used features.
    std::vector<std::string> used() const;
    // Setup stages skipped because the scene does not need them.
    std::vector<std::string> skipped() const;
};

Features analyze(const Scene& scene);

// The first bump_map normal of a texture (its layers and map entries included), or null.
const Normal* find_bump_map(const Texture& t);

}  // namespace glint::scene
