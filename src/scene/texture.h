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

// POV-Ray's pattern set. A renderer that meets a kind it does not implement must say so
// (analyze() lists it), never shade it as something else. Pattern values are in [0, 1]
// (block patterns: an entry index); see render/textures/pattern.h for the evaluation.
enum class PatternKind {
    Plain,     // a single color (pigment) or no perturbation (normal)
    Checker,   // block pattern: entries[0], entries[1]
    Gradient,  // continuous: fractional part of dot(p, vector)
    // image_map (pigment), bump_map (normal), material_map (texture: the pixel's palette index
    // picks an entry)
    ImageMap,
    // continuous patterns
    Agate, Boxed, Bozo, Bumps, Cells, Crackle, Cylindrical, Dents, Facets, Granite, Leopard,
    Marble, Onion, Planar, Quilted, Radial, Ripples, Spherical, Spiral1, Spiral2, Spotted,
    Waves, Wood, Wrinkles, Mandel, Julia, Function,
    DensityFile,  // density_file df3 "file": a voxel grid over the unit cube
    // magnet 1|2 mandel I | magnet 1|2 julia <c>, I: PatternParams::magnet_*
    Magnet,
    Tiling,  // tiling N: PatternParams::tiling_type
    // image_pattern { "file" ... }: the image's grey (or alpha) at the point
    // (PatternParams::image, mapped as an image_map)
    ImagePattern,
    // block patterns: entries (or map entries) chosen by the pattern value
    Brick, Hexagon, Square, Triangular, Cubic,
    // object { OBJECT A, B }: entries[1] inside the object (PatternParams::object), else [0]
    Object,
    // pigment_pattern { PIGMENT }: the pigment's grey value (PatternParams::pigment)
    PigmentPattern,
    // slope { [point_at] <v> [, lo, hi] [altitude <a> [, lo, hi]] }: the surface normal's
    // slope against v, mixed with the height along a (PatternParams::slope)
    Slope,
    // aoi: the angle between the surface normal facing the ray and the ray, / pi
    Aoi,
    // pigment { average pigment_map { [w P] ... } }, normal { average normal_map {...} }
    Average,
};

enum class WaveType { Ramp, Triangle, Sine, Scallop, Cubic, Poly };

// The keyword of a pattern kind ("plain" for Plain), for messages and `glint ir`.
const char* pattern_name(PatternKind kind);

struct Turbulence {
    Vec3 amount{0, 0, 0};
    int octaves = 6;
    double omega = 0.5;
    double lambda = 2.0;
};

// POV-Ray's warps (backend/pattern/warps.h), applied in list order to the pattern-space point
// (after the pattern's own `transform`) before the pattern function. A `warp { }` block goes in
// front (POV-Ray prepends it, so the pattern's transform so far becomes a Transform warp behind
// it); `turbulence`/`octaves`/`omega`/`lambda` written directly in a pattern make (or modify) a
// ClassicTurbulence warp at the end of the list, as POV-Ray's Check_Turb does; agate, marble, spiral1/2 and wood apply classic turbulence inside the
// pattern function instead, the others through the warp.
enum class WarpKind {
    ClassicTurbulence,  // turbulence written in the pattern
    Turbulence,         // warp { turbulence ... }
    Repeat,             // warp { repeat <dir> offset <v> flip <v> }
    BlackHole,          // warp { black_hole <center>, radius ... }
    Cylindrical,        // warp { cylindrical orientation <v> dist_exp d }
    Spherical,
    Toroidal,           // also major_radius
    Planar,             // warp { planar <v>, offset }
    Cubic,              // warp { cubic }
    Transform,          // warp { transforms }: Transform applied to the point
};

struct Warp {
    WarpKind kind = WarpKind::ClassicTurbulence;
    Turbulence turbulence;  // ClassicTurbulence, Turbulence, BlackHole (its `turbulence`)
    // Repeat: the axis-aligned direction vector as written (width = its non-zero component).
    Vec3 direction{0, 0, 0};
    Vec3 offset{0, 0, 0};
    Vec3 flip{0, 0, 0};
    // BlackHole
    Vec3 center{0, 0, 0};
    double radius = 1;
    double strength = 1;
    double falloff = 2;
    bool inverse = false;
    Vec3 repeat{0, 0, 0};  // black_hole repeat <v>
    // Cylindrical/Spherical/Toroidal/Planar
    Vec3 orientation{0, 0, 1};
    double dist_exp = 0;
    double major_radius = 1;
    double planar_offset = 0;
    Transform transform;  // Transform
    FileLoc loc;
};

// A POV-Ray df3 density file: nx * ny * nz voxels (x fastest) over the unit cube, as read
// (8, 16 or 32 bits, big-endian) and scaled to [0, 1].
struct DensityGrid {
    int nx = 0, ny = 0, nz = 0;
    std::vector<float> values;
    std::string path;
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
    // `filter N, V` / `transmit N, V` (index N) and `filter all` / `transmit all` (index -1),
    // in the order written: on a palette image they set the entries' values, later edits
    // winning (filter_all/transmit_all, added to every texel, are for other images).
    struct PaletteEdit {
        int index = -1;
        bool filter = true;  // or transmit
        double value = 0;
        FileLoc loc;
    };
    std::vector<PaletteEdit> palette_edits;
    // `gamma G` on the image; 0 = POV-Ray's default for the file type and #version.
    double gamma = 0;
    bool premultiplied = false;
    // `use_index` (POV-Ray's USE_NONE): a bump_map on a palette image takes the texels'
    // palette indices as heights instead of their colours' grey (`use_color`, the default).
    bool use_index = false;
    // image_pattern's `use_alpha`: the pattern is the texels' transmit (1 - alpha), or their
    // red on an image without alpha, instead of their grey.
    bool use_alpha = false;
    // Read as data, not colour (Parse_Image without GammaCorrect: bump_map, image_pattern):
    // the values as stored, or decoded by the map's own `gamma`, never by the working gamma.
    bool data = false;
    FileLoc loc;
};

struct Pigment;

// POV-Ray's slope pattern as its parser leaves it (parstxtr.cpp): unit vectors, the spans
// already hi - lo (0: no range given), the two weights summing to 1, and the axis shortcuts
// (1..3 = +x..+z, -1..-3 = -x..-z, 0 none) that change rounding, so they are kept.
struct SlopeParams {
    Vec3 vector{0, 1, 0};
    double lo = 0, span = 0;
    Vec3 altitude{0, 0, 0};
    double altitude_lo = 0, altitude_span = 0;
    double weight = 1, altitude_weight = 0;
    bool point_at = false;  // vector is a point: the slope towards it
    int base = 0, altitude_base = 0;
};

struct PatternParams {
    Vec3 vector{0, 1, 0};  // gradient direction
    double frequency = 1;
    double phase = 0;
    WaveType wave = WaveType::Ramp;
    double wave_exponent = 1;
    std::vector<Warp> warps;  // in order; see WarpKind
    // noise_generator given in the pattern; 0 = the scene's global_settings value.
    int noise_generator = 0;
    ImageMap image;  // PatternKind::ImageMap and ImagePattern
    // PatternKind::DensityFile: the grid (shared by copies) and `interpolate` (0 nearest,
    // 1 trilinear, 2 tricubic).
    std::shared_ptr<const DensityGrid> density_file;
    int density_interpolate = 0;
    // Per-pattern parameters (POV-Ray's defaults).
    double agate_turb = 1.0;        // agate_turb
    Vec3 brick_size{8, 3, 4.5};     // brick: brick_size
    double mortar = 0.5;            // brick: mortar
    int arms = 0;                   // spiral1/spiral2: number of arms (required)
    double control0 = 1, control1 = 1;  // quilted
    // crackle: metric, offset, solid, form
    double crackle_metric = 2;
    double crackle_offset = 0;
    bool crackle_solid = false;
    Vec3 crackle_form{-1, 1, 0};
    // facets (normal only): coords or size, metric
    double facets_coords = 0;
    double facets_size = 0.1;
    double facets_metric = 2;
    // mandel/julia
    int iterations = 0;
    double fractal_exponent = 2;
    Vec2 julia_param{0, 0};
    int exterior_type = 1, interior_type = 0;
    double exterior_factor = 1, interior_factor = 1;
    // magnet: formula 1 or 2, and julia (julia_param is the constant) or mandel
    int magnet_type = 1;
    bool magnet_julia = false;
    int tiling_type = 1;  // tiling: 1..27
    int function = -1;  // PatternKind::Function: index into Scene::functions
    int object = -1;    // PatternKind::Object: index into Scene::pattern_objects
    // PatternKind::PigmentPattern: the pigment, its transform relative to this pattern's space
    // (shared by copies).
    std::shared_ptr<const Pigment> pigment;
    SlopeParams slope;  // PatternKind::Slope
};

struct ColorMapEntry {
    double value = 0;
    ColorFT color;
};

struct Pigment;
struct Normal;
struct Texture;

// pigment_map { [v pigment] ... } (also the entries of `average`, value = weight).
struct PigmentMapEntry {
    double value = 0;
    std::vector<Pigment> pigment;  // exactly one (a vector because Pigment is incomplete here)
};

struct Pigment {
    PatternKind kind = PatternKind::Plain;
    ColorFT color{Color(0, 0, 0)};  // Plain; POV-Ray's default pigment is black
    PatternParams params;
    // Continuous patterns use color_map, or pigment_map when that is non-empty; both empty =
    // POV-Ray's default map. Block patterns use `entries` (checker: two, hexagon: three, ...).
    std::vector<ColorMapEntry> color_map;
    std::vector<PigmentMapEntry> pigment_map;
    std::vector<Pigment> entries;
    bool uv_mapping = false;  // evaluate at (u, v, 0) instead of the hit point
    Transform transform;      // pattern space -> world space
    FileLoc loc;
};

// slope_map { [v <height, slope>] ... }
struct SlopeMapEntry {
    double value = 0;
    double height = 0;
    double slope = 0;
};

struct NormalMapEntry {
    double value = 0;
    std::vector<Normal> normal;  // exactly one
};

struct Normal {
    PatternKind kind = PatternKind::Plain;  // Plain = unperturbed
    double amount = 0;     // bump_size / the float after the pattern (POV-Ray default 0.5 for
                           // most patterns; the importer stores the effective value)
    PatternParams params;
    std::vector<SlopeMapEntry> slope_map;
    std::vector<NormalMapEntry> normal_map;  // normal_map, or `average` entries
    std::vector<Normal> entries;             // block patterns of normals
    double accuracy = 0.02;                  // numeric gradient step (POV-Ray `accuracy`)
    bool uv_mapping = false;
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
    // `diffuse A, B`: B lights the surface from lights on its far side (POV-Ray 3.7's diffuse
    // backside illumination, for thin things such as leaves and paper); no highlights there.
    double diffuse_back = 0;
    double brilliance = 1;
    double phong = 0;
    double phong_size = 40;
    double specular = 0;
    double roughness = 0.05;
    double metallic = 0;  // tints phong/specular highlights by the surface color
    Reflection reflection;
    bool conserve_energy = false;
    double crand = 0;
    // `subsurface { translucency C }`: POV-Ray's subsurface light transport (with the global
    // settings' subsurface block) replaces the diffuse term; C is the mean free path in mm
    // (its inverse the reduced scattering coefficient).
    bool subsurface = false;
    Color translucency{0, 0, 0};
    // irid { amount [thickness t] [turbulence u] }: thin-film interference tinting each
    // light's contribution and the reflection (POV-Ray's ComputeIridColour); 0 = none.
    double irid = 0;
    double irid_thickness = 0;
    double irid_turbulence = 0;
    // POV-Ray 3.0's interior items written in a finish (`ior`, `caustics`, `refraction`):
    // an object whose plain texture has them takes them into its interior (POV-Ray 3.7's
    // Post_Process still does). -1: not given; refraction scales the refracted light.
    double old_ior = -1;
    double old_caustics = -1;
    double old_refraction = 1;
    FileLoc loc;
};

struct TextureMapEntry {
    double value = 0;
    std::vector<Texture> texture;  // exactly one
};

struct Texture {
    // A plain texture: pigment, normal, finish.
    Pigment pigment;
    Normal normal;
    Finish finish;
    // A patterned texture (texture_map, or a block pattern of textures such as
    // `texture { checker texture{..} texture{..} }`) when kind != Plain; the plain members
    // above are then unused. `material_map { png "f" texture{..} ... }` is kind ImageMap
    // with params.image and one entry per texture, chosen by the image's pixel.
    PatternKind kind = PatternKind::Plain;
    PatternParams params;
    std::vector<TextureMapEntry> texture_map;
    std::vector<Texture> entries;
    bool uv_mapping = false;
    Transform transform;  // pattern space -> world, for the patterned texture
    // POV-Ray layered textures: `texture {A} texture {B}` draws B over A. `layers` holds the
    // textures drawn over this one, bottom to top.
    std::vector<Texture> layers;
    FileLoc loc;
};

// POV-Ray's participating media (3.7 manual 3.4.4.2 / 3.5.7 "Media"), stored as Parse_Media
// leaves it. A medium fills the inside of a hollow object (Interior::media) or all of space
// (Scene::media). Coefficients are per unit of distance, scaled by the density.
enum class ScatteringType {
    Isotropic = 1,
    MieHazy = 2,
    MieMurky = 3,
    Rayleigh = 4,
    HenyeyGreenstein = 5
};

struct Media {
    // Sampling along each ray (defaults of #version 3.5 and later; older scenes get
    // intervals 10, samples 1,1, method 1, as POV-Ray gives them).
    int method = 3;  // 1: random, 2: stratified, 3: adaptive
    int intervals = 1;
    int min_samples = 10;
    int max_samples = 10;
    double jitter = 0;
    double aa_threshold = 0.1;
    int aa_level = 3;
    double confidence = 0.9;  // method 1/2: extra samples until the variance is below this
    double variance = 1.0 / 128.0;
    double ratio = 0.9;  // share of the intervals given to the lit parts of a ray
    bool collect = true;  // `collect off`: ignore photons
    Color absorption{0, 0, 0};
    Color emission{0, 0, 0};
    Color scattering{0, 0, 0};
    ScatteringType type = ScatteringType::Isotropic;
    double eccentricity = 0;  // Henyey-Greenstein g
    double extinction = 1;    // scales the scattering's share of the extinction
    // density { } blocks, multiplied together (Evaluate_Density_Pigment); none = 1. Each is a
    // pigment pattern whose colour is the density per channel, in world space.
    std::vector<Pigment> density;
    FileLoc loc;
};

struct Interior {
    std::vector<Media> media;
    double ior = 1;
    double dispersion = 1;
    double caustics = 0;
    double fade_distance = 0;  // 0 = no attenuation
    double fade_power = 0;
    Color fade_color{0, 0, 0};
    double old_refraction = 1;  // from a finish's `refraction` (Finish::old_refraction)
};

// Physically based half of the material (Blender Principled BSDF / MTL PBR extension).
// `derived` = filled by the documented mapping from the POV finish, not by the importer.
// A texture image driving one PBR parameter (MTL `map_Kd -o u v w -s u v w -bm b file`),
// looked up at the surface's uv coordinates (offset and scale applied as MTL defines).
struct PbrMap {
    std::string file;           // as written
    std::string resolved_path;  // empty when the file was not found (the importer warned)
    Vec3 offset{0, 0, 0};       // -o
    Vec3 scale{1, 1, 1};        // -s
    double bump_multiplier = 1;  // -bm (bump maps)
    FileLoc loc;
    bool present() const { return !resolved_path.empty(); }
};

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
    double sheen = 0;
    double clearcoat = 0;
    double clearcoat_roughness = 0;
    double anisotropy = 0;
    double anisotropy_rotation = 0;
    // Texture maps (OBJ/MTL); absent ones have an empty resolved_path.
    PbrMap base_color_map;     // map_Kd
    PbrMap specular_map;       // map_Ks
    PbrMap emission_map;       // map_Ke
    PbrMap roughness_map;      // map_Pr
    PbrMap metallic_map;       // map_Pm
    PbrMap exponent_map;       // map_Ns (specular exponent, converted like Ns)
    PbrMap alpha_map;          // map_d
    PbrMap bump_map;           // map_Bump / bump (-bm)
    bool derived = true;
    // The material came from Blender's Principled BSDF: its MTL carried statements only the
    // Principled export writes (Ps, Pc, Pcr, aniso, anisor). The path tracer then uses
    // Principled's Burley diffuse; other materials keep a Lambert diffuse (docs/pbr-mapping.md).
    bool principled = false;
};

struct Material {
    Texture texture;
    // POV-Ray's interior_texture: shown where a ray meets the surface from inside (the
    // outward normal facing away from the ray); empty = `texture` on both sides. Zero or
    // one entry (a vector keeps materials without one small).
    std::vector<Texture> interior_texture;
    Interior interior;
    // Which interior declaration this is, for POV-Ray's interior bookkeeping: CSG children
    // without an interior of their own share their parent's (Post_Process copies the pointer),
    // so a ray that met the parent's interior meets the same one at such a child, but a
    // different one at a child that declares its own. -1: one interior per object (other
    // importers).
    int interior_id = -1;
    // POV-Ray's object-level `uv_mapping` (the object's UV_FLAG): every texture of the object
    // is evaluated at the surface's (u, v, 0) instead of the point, and the object's
    // transforms leave its textures alone.
    bool uv_points = false;
    Pbr pbr;
    // A shader node graph (Scene::shader_graphs) that the path tracer evaluates instead of
    // `pbr`; -1: none.
    int graph = -1;
    // Cycles' material Settings > Volume: the step rate of ray marching a volume that varies
    // in space, and Homogeneous (evaluate it once per segment, at its start).
    double volume_step_rate = 1.0;
    bool volume_homogeneous = false;
    FileLoc loc;
};

}  // namespace glint::scene
