// The POV-Ray importer's grammar, over the token layer (token_stream.h: tokens, directives,
// symbols, errors), shared by the files that implement it:
//   expressions.cpp   float/vector/color/string expressions: Parser's entry points, with
//                     the grammar in expr_parser.h and the built-in functions in
//                     builtin_functions.cpp
//   materials.cpp     texture, pigment, finish, normal, interior, color maps
//   patterns.cpp      pigment, normal and texture bodies and their pattern keywords
//   pattern_grammar.cpp  pattern arguments and modifiers, warps, maps
//   objects.cpp       object statements: a declared object to start from, light bodies,
//                     object modifiers; the keyword -> body table in object_bodies.h, the
//                     bodies in object_bodies.cpp, meshes.cpp and solids.cpp
//   extensions.cpp    glint's own: blender_light and obj_file
//   camera.cpp        camera resolution, global_settings, background, sky_sphere
//   parser.cpp        the top-level loop and placement of objects into the scene
// Internal to formats/pov; the public entry points are in parser.h.
#pragma once

#include <algorithm>
#include <climits>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/log.h"
#include "formats/pov/parser.h"
#include "formats/pov/scanner.h"
#include "formats/pov/token_stream.h"
#include "formats/pov/unsupported.h"
#include "formats/pov/value.h"
#include "scene/scene.h"

namespace glint::pov {

// Entries of a block pattern (checker 2, brick 2, hexagon 3, square 4, triangular and cubic 6;
// 0 for the others).
int block_count(scene::PatternKind k);

// Pattern transforms map pattern space to world, so later transforms compose after them;
// sub-pigments (checker entries) move with their parent as in POV-Ray's Transform_Pigment.
void transform_pigment(scene::Pigment& p, const Transform& t);
// media.cpp: the densities of media follow the transforms of their media and objects.
void transform_media(scene::Media& m, const Transform& t);
void transform_interior(scene::Interior& in, const Transform& t);
void transform_texture(scene::Texture& tex, const Transform& t);
// No pattern anywhere in it (pigment, normal and every layer plain): the same at every point,
// whatever its transforms.
bool texture_is_uniform(const scene::Texture& tex);
// An object as an IR object with no materials (clipped_by, bounded_by, object patterns).
scene::Object object_without_materials(const PovObject& p);
// POV-Ray's Link_Textures: `top` (with its own layers) is drawn over `base`.
void layer_texture(scene::Texture& base, const scene::Texture& top, const FileLoc& at);

class Parser final : public TokenStream {
public:
    Parser(const ParseOptions& options, Diagnostics& diag);

    scene::Scene parse_main_file(const std::string& path);
    scene::Scene parse_main_string(const std::string& text, const std::string& name);

    // ---- expressions (expressions.cpp)
    Num parse_num(int terms);  // an expression promoted to `terms` components
    // An additive expression, as POV-Ray's Parse_Float reads it (expressions.cpp).
    double parse_float() override;
    double parse_condition() override;
    double parse_float_in_angle_brackets();  // where '>' closes instead of comparing
    Vec3 parse_vector();
    std::string parse_string() override;
    Value parse_expression_value() override;  // a number or a string
    // Color after an optional `color`/`colour` keyword: rgb/rgbf/.../red/... or expression.
    scene::ColorFT parse_color();
    Color parse_rgb();
    bool next_is_expression_start();
    // A float-valued keyword constant (pi, clock, true, image_width, ...) by name.
    bool float_constant(const std::string& name, double& out) const;
    double allow_float(double fallback);  // an optional float (POV-Ray's Allow_Float)

    // ---- functions and splines (functions.cpp)
    // After `function`: parameters and body; returns the index into scene.functions.
    int parse_function_definition();
    scene::Spline parse_spline_body();  // after spline {
    // Parse-time calls `F(1, 2, 3)` / `S(t [, type])`, after the name.
    Value call_function_now(int index, const std::string& name, const FileLoc& at);
    Value call_spline_now(const scene::Spline& s, const std::string& name);
    scene::FunctionEnv function_env() const;
    void warn_unimplemented_internal(int id, const FileLoc& at);
    // `sky_sphere { SkyIdent ...}` (parser.cpp): true when the raw tokens ahead are '{' and an
    // identifier holding a declared sky_sphere.
    bool declared_sky_sphere_follows() const {
        const Symbol* s = symbol_after_raw_brace();
        return s && (s->unusable || std::holds_alternative<scene::SkySphere>(s->value));
    }
    // trace/inside/min_extent/max_extent (expressions.cpp): the object alone in a scene,
    // prepared by options.prepare_object once per declared object.
    scene::Scene one_object_scene(const PovObject& po) const;
    const scene::PreparedObject& prepared_object(const std::shared_ptr<const PovObject>& po);

    // ---- materials (materials.cpp)
    scene::Texture parse_texture_body();      // after texture {
    // After pigment {, finish {, normal {; `one_item`: read a single item only (POV-Ray 1.0's
    // items written straight in a texture, parse_old_texture_item).
    void parse_pigment_body(scene::Pigment& p, bool one_item = false);
    void parse_finish_body(scene::Finish& f, bool one_item = false);
    void parse_normal_body(scene::Normal& n, bool one_item = false);
    // Under `#version` below 3.0: a pigment, normal or finish item written straight in a
    // texture (POV-Ray's Parse_Vers1_Texture), read into `top`; false if `t` is none.
    bool parse_old_texture_item(const Token& t, scene::Texture& top);
    void parse_interior_body(scene::Interior& in);
    MaterialValue parse_material_body();
    // `finish { F_Shiny ... }`: when `t` names a symbol, copies it into `out` and returns
    // true; throws if it holds another type ("expected a finish, got ...") or is not the
    // body's first item.
    template <class T>
    bool take_body_identifier(const Token& t, bool first, const char* article, const char* noun,
                              T& out);
    std::vector<scene::ColorMapEntry> parse_color_map_body();
    // bump_size is read into *bump_size when given (bump_map).
    // `material_map`: the body of a material_map, whose image items stop at its first texture.
    // `image_pattern`: the items of Parse_Image_Pattern (use_alpha too).
    void parse_image_map_body(scene::ImageMap& im, double* bump_size = nullptr,
                              bool material_map = false, bool image_pattern = false);
    // ---- patterns and maps (patterns.cpp, pattern_grammar.cpp)
    void parse_pattern_arguments(scene::PatternKind kind, scene::PatternParams& pp, bool normal);
    // A pattern modifier (turbulence, frequency, warp, brick_size, ...) if `w` is one; `head`
    // is the pattern's own transform, which a warp block moves into the warp list.
    void parse_slope(scene::SlopeParams& s);  // after slope (pattern_grammar.cpp)
    bool parse_pattern_modifier(const std::string& w, scene::PatternKind kind,
                                scene::PatternParams& pp, Transform& head);
    scene::Warp parse_warp_body(const FileLoc& at);
    template <class F>
    void parse_map_entries(const char* what, bool average, F item);
    const BlendMapValue* declared_map(const char* keyword);
    std::vector<scene::PigmentMapEntry> parse_pigment_map_body(bool average);
    std::vector<scene::PigmentMapEntry> parse_density_map_body();
    std::vector<scene::NormalMapEntry> parse_normal_map_body(bool average);
    std::vector<scene::SlopeMapEntry> parse_slope_map_body();
    std::vector<scene::TextureMapEntry> parse_texture_map_body(bool average);
    std::vector<scene::Pigment> parse_pigment_entries(scene::PatternKind kind, int count);
    std::vector<scene::Normal> parse_normal_entries(int count);
    std::vector<scene::Texture> parse_texture_entries(int count);
    // material_map { IMAGE ITEMS texture {..} ... } (after the keyword) into `tex`.
    void parse_material_map(scene::Texture& tex);
    void parse_tiles(scene::Texture& tex);  // after `tiles` in a texture
    // `#declare M = color_map { ... }` (and the other maps) after the keyword `w`.
    Value parse_map_rvalue(const std::string& w);
    // A transform keyword (translate/rotate/scale/matrix/transform) if the next token is one.
    bool parse_transform_item(Transform& t);
    Transform parse_transform_body();

    // ---- objects (objects.cpp)
    bool is_object_keyword(const Token& t) const;
    // Parses an object statement whose keyword was just read; false if `kw` is not one.
    bool parse_object(const Token& kw, PovObject& out);
    void parse_object_mods(PovObject& o, const char* what, const FileLoc& opened);
    // glint's extension obj_file (extensions.cpp), after its opening brace.
    void parse_obj_file(PovObject& po, const FileLoc& opened);
    void apply_transform(PovObject& o, const Transform& t);
    // `looks_like`, when given, receives the light's looks_like object (placed at the light).
    void parse_light_body(scene::Light& l, std::optional<PovObject>* looks_like = nullptr);
    // Fails (--max-triangles) at `at` when `pending` more mesh triangles would pass the limit;
    // count_triangles() adds them once the mesh is read.
    void check_triangle_budget(size_t pending, const FileLoc& at) const;
    void count_triangles(size_t n) { triangles_ += static_cast<long long>(n); }

    // ---- camera and scene settings (camera.cpp)
    void parse_camera_body(scene::Camera& cam);
    void parse_mesh_camera(scene::MeshCamera& m);
    void parse_focal_blur_item(const std::string& w, scene::FocalBlur& fb);
    // The object pattern's closing brace, after its entries (parse_pattern_arguments opens).
    void close_object_pattern();
    std::vector<FileLoc> object_pattern_open_;
    // A mesh's texture_list textures follow its transforms (scene::MeshRef::face_materials):
    // transformed copies of the materials its faces name.
    void transform_face_materials(scene::MeshRef& ref, const Transform& t);
    // Mesh::Determine_Textures: a hit from inside shows the mesh's interior_texture whatever
    // the face's own texture, so the faces' materials get copies that carry it.
    void give_faces_interior_texture(scene::MeshRef& ref, const scene::Texture& inside);
    // The mesh object's own uv_mapping reaches its faces' textures too (copies that carry it).
    void give_faces_uv_points(scene::MeshRef& ref);
    // Fills ref.face_materials (identity) if empty; false if the mesh's faces name none.
    bool own_face_materials(scene::MeshRef& ref);
    std::unordered_map<int, std::vector<int>> face_material_ids_;  // per mesh, distinct
    void parse_global_settings();
    void parse_radiosity_settings();  // after `radiosity` in global_settings
    void parse_photon_settings();     // after `photons` in global_settings
    // An object's or a light's `photons { ... }` block (objects.cpp), after the keyword.
    void parse_object_photons(scene::Object& o);
    void parse_light_photons(scene::Light& l);
    // `radiosity { importance F }` (an object's, or #default's), after the keyword.
    void parse_radiosity_importance(double* importance);
    // accept(w), and the place of the keyword taken in *at (loc() names the last token).
    bool accept_at(const char* w, FileLoc* at) {
        if (!accept(w)) return false;
        *at = loc();
        return true;
    }
    void parse_background();
    void parse_sky_sphere();
    // ---- atmosphere (atmosphere.cpp): fog { ... } and rainbow { ... } statements
    void parse_fog();
    void parse_rainbow();
    // ---- media (media.cpp): media { } and density { } bodies, after the brace
    scene::Media new_media() const;  // the defaults of the #version in force
    void parse_media_body(scene::Media& m);
    scene::Pigment parse_density_body();
    // density_file df3: the grid of `path` (found for `name`), shared by every use of it.
    std::shared_ptr<const scene::DensityGrid> load_df3(const std::string& name,
                                                       const std::string& path, const FileLoc& at);
    std::map<std::string, std::shared_ptr<const scene::DensityGrid>> df3_cache_;
    bool in_density_ = false;  // parsing a density: density_map is allowed

    // ---- top level (parser.cpp)
    void place_object(PovObject o);
    // `interior_id`: scene::Material::interior_id (-1 for mesh face textures); `inside`:
    // the interior_texture, or null for none.
    int add_material(const scene::Texture& t, const scene::Interior& in, const FileLoc& loc,
                     int interior_id = -1, const scene::Texture* inside = nullptr,
                     bool uv_points = false);
    // What a #declare right-hand side can be: object, texture, expression, ...
    Value parse_rvalue() override;
    void parse_default() override;
    void finish_version();
    // Runs the statements of the main file; an error raised inside a macro body gets a note
    // at the innermost macro's call site, since the body's text alone does not say which of
    // several calls (with which arguments) went wrong.
    void run_statements();

    UnsupportedLog unsupported_log;  // features already warned about (unsupported.h)
    std::vector<uint32_t> rand_streams;  // seed()/rand() state, POV-Ray's LCG
    scene::Scene scene;
    scene::Texture default_texture_;
    int next_interior_id_ = 0;  // scene::Material::interior_id of the next declaration
    // The materials made for uniform textures (texture_is_uniform) of the object being placed,
    // keyed by the address of the texture they came from, in a child that the copies of a
    // declared object share (PovChildren), and by the rest of what a material holds: such
    // copies differ only by transforms, which cannot change a uniform texture, so they share
    // one material. place_object() empties it: the addresses are the placed object's.
    std::map<std::vector<uint64_t>, int> uniform_materials_;
    // A fresh scene::Light::group id (light_group.cpp), of a group that is a copy or not.
    int new_light_group(bool copy) {
        copied_light_groups_.push_back(copy);
        return next_light_group_++;
    }
    bool is_copied_light_group(int id) const {
        return id >= 0 && id < next_light_group_ && copied_light_groups_[static_cast<size_t>(id)];
    }

private:
    int next_light_group_ = 0;
    std::vector<bool> copied_light_groups_;
    // The token layer's questions (token_stream.h).
    void file_read(const std::string& path) override;
    void declared(const std::string& name, const Value& v) override;
    // Values of arrays (parser.cpp).
    void parse_array_init(ArrayValue& a, size_t dim, size_t& k);
    Value parse_array();
    std::set<int> warned_internals_;
    bool warned_old_texture_ = false;  // POV-Ray 1.0 texture syntax, said once
    // Objects asked about while parsing, with the object kept alive so its address stays its.
    std::map<const PovObject*, std::pair<std::shared_ptr<const PovObject>,
                                         std::shared_ptr<const scene::PreparedObject>>>
        prepared_objects_;
    long long triangles_ = 0;  // mesh triangles so far, against options.max_triangles
};

}  // namespace glint::pov
