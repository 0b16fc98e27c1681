// Surface appearance: POV-Ray's texture { pigment normal finish } plus interior, and the
// physically based parameters the path tracer and OBJ/MTL use. Defaults are POV-Ray 3.7's
// (reference manual 3.6 "Textures"). Patterns are shared by pigments and normals.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/math.h"
#include "core/transform.h"
#include "scene/color.h"

namespace glint::scene {

// The pattern set grows with the POV-Ray compatibility work; a renderer that meets a kind it
// does not implement must say so (analyze() lists it), never shade it as something else.
enum class PatternKind {
    Plain,     // a single color (pigment) or no perturbation (normal)
    Checker,   // block pattern: entries[0], entries[1]
    Gradient,  // continuous: fractional part of dot(p, vector)
    ImageMap,  // image_map: color from an image file
    // Room for the rest of POV-Ray's pattern set (agate, bozo, brick, ...).
};

enum class WaveType { Ramp, Triangle, Sine, Scallop, Cubic, Poly };

struct Turbulence {
    Vec3 amount{0, 0, 0};
    int octaves = 6;
    double omega = 0.5;
    double lambda = 2.0;
};

// image_map { TYPE "file" map_type N once interpolate N filter/transmit ... }
struct ImageMap {
    std::string file;           // as written in the scene
    std::string resolved_path;  // found through the include search path
    std::string type;           // png, jpeg, tga, ... as written (informational)
    int map_type = 0;           // 0 planar, 1 spherical, 2 cylindrical, 5 torus
    bool once = false;
    int interpolate = 0;        // 0 none, 2 bilinear, 4 normalized distance
    double filter_all = 0;
    double transmit_all = 0;
    // `gamma G` on the image; 0 = POV-Ray's default for the file type and #version.
    double gamma = 0;
    bool premultiplied = false;
    FileLoc loc;
};

struct PatternParams {
    Vec3 vector{0, 1, 0};  // gradient direction
    double frequency = 1;
    double phase = 0;
    WaveType wave = WaveType::Ramp;
    double wave_exponent = 1;
    std::optional<Turbulence> turbulence;
    ImageMap image;  // PatternKind::ImageMap
};

struct ColorMapEntry {
    double value = 0;
    ColorFT color;
};

struct Pigment {
    PatternKind kind = PatternKind::Plain;
    ColorFT color{Color(0, 0, 0)};  // Plain; POV-Ray's default pigment is black
    PatternParams params;
    std::vector<ColorMapEntry> color_map;  // continuous patterns; empty = POV-Ray's default map
    std::vector<Pigment> entries;          // block patterns (checker: two)
    bool uv_mapping = false;               // evaluate at (u, v, 0) instead of the hit point
    Transform transform;                   // pattern space -> world space
    FileLoc loc;
};

struct Normal {
    PatternKind kind = PatternKind::Plain;  // Plain = unperturbed
    double amount = 0;
    PatternParams params;
    Transform transform;
    FileLoc loc;
};

struct Reflection {
    Color min{0, 0, 0};
    Color max{0, 0, 0};
    double falloff = 1;  // reflection { ... falloff F }
    bool fresnel = false;
    double metallic = 0;  // reflection { ... metallic M }: tint reflection by the surface color
    double exponent = 1;  // reflection_exponent
};

struct Finish {
    Color ambient{0.1, 0.1, 0.1};
    Color emission{0, 0, 0};
    double diffuse = 0.6;
    double brilliance = 1;
    double phong = 0;
    double phong_size = 40;
    double specular = 0;
    double roughness = 0.05;
    double metallic = 0;  // tints phong/specular highlights by the surface color
    Reflection reflection;
    bool conserve_energy = false;
    double crand = 0;
    FileLoc loc;
};

struct Texture {
    Pigment pigment;
    Normal normal;
    Finish finish;
    FileLoc loc;
};

struct Interior {
    double ior = 1;
    double dispersion = 1;
    double caustics = 0;
    double fade_distance = 0;  // 0 = no attenuation
    double fade_power = 0;
    Color fade_color{0, 0, 0};
};

// Physically based half of the material (Blender Principled BSDF / MTL PBR extension).
// `derived` = filled by the documented mapping from the POV finish, not by the importer.
struct Pbr {
    Color base_color{0.8, 0.8, 0.8};
    double metallic = 0;
    double roughness = 0.5;
    double specular = 0.5;
    double ior = 1.45;
    double transmission = 0;
    Color emission{0, 0, 0};
    double emission_strength = 0;
    double alpha = 1;
    bool derived = true;
};

struct Material {
    Texture texture;
    Interior interior;
    Pbr pbr;
    FileLoc loc;
};

}  // namespace glint::scene
