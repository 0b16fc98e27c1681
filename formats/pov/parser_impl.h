// The POV-Ray importer's parser state, shared by the files that implement its layers:
//   token_stream.cpp  tokens from the #include stack and macro frames; errors; symbols
//   directives.cpp    #declare, #include, #macro and macro calls, #if/#while/#for/#switch/#end
//   file_directives.cpp  #fopen, #fclose, #read, #write
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
#include "formats/pov/unsupported.h"
#include "formats/pov/value.h"
#include "scene/scene.h"

namespace glint::pov {

// A float read where the language wants an integer, truncated toward zero like POV-Ray's
// (int) cast. Casting a value outside int's range (or NaN) is undefined behaviour, so it is
// clamped first: a count or an index of 1e20 then meets the same range check as one of 1e9.
inline int to_int(double v) {
    if (!(v == v)) return 0;
    return static_cast<int>(std::clamp(v, double(INT_MIN), double(INT_MAX)));
}
inline long long to_long_long(double v) {
    if (!(v == v)) return 0;
    constexpr double kMax = 9.2e18;  // below 2^63, which is itself out of range
    return static_cast<long long>(std::clamp(v, -kMax, kMax));
}

// Directives that open a block closed by #end (#if, #ifdef, #ifndef, #while, #for, #switch,
// #macro), and those that start a new statement (which end a #declare's value).
bool opens_block(const std::string& d);
bool starts_statement(const std::string& d);
// Throws where `name`, about to be defined, is one of POV-Ray's reserved words.
void check_not_reserved(const std::string& name, const std::string& expected, const FileLoc& at);
// Entries of a block pattern (checker 2, brick 2, hexagon 3, square 4, triangular and cubic 6;
// 0 for the others).
int block_count(scene::PatternKind k);

// Thrown for a feature glint does not implement yet. Inside the standard include files a
// declaration that throws this is skipped and its identifier marked unusable.
class Unsupported : public Error {
public:
    Unsupported(FileLoc loc, const std::string& message)
        : Error(ErrorKind::Scene, std::move(loc), message) {}
};

struct SourceFile {
    std::shared_ptr<const std::string> name;
    std::string dir;  // folder of the file, for #include and image_map lookups
    std::vector<Token> tokens;
    bool system = false;  // a standard include (outside the scene's folder)
};

enum class CondKind { If, While, For, Switch };

struct Cond {
    Cond() = default;
    Cond(CondKind k, FileLoc l) : kind(k), loc(std::move(l)) {}
    CondKind kind = CondKind::If;
    FileLoc loc;
    size_t restart = 0;  // While: token index of the condition; For: first body token
    long long iterations = 0;
    std::string var;      // For: loop variable
    double end = 0, step = 1;
    double switch_value = 0;
};

struct Frame {
    Frame() = default;
    Frame(int f, size_t p) : file(f), pos(p) {}
    int file = 0;
    size_t pos = 0;
    bool is_macro = false;
    bool pushed_scope = false;
    std::vector<Cond> conds;
    FileLoc call_loc;  // macro call or #include
    std::string macro_name;  // is_macro: for the "in macro 'Name' called here" note
};

// Pattern transforms map pattern space to world, so later transforms compose after them;
// sub-pigments (checker entries) move with their parent as in POV-Ray's Transform_Pigment.
void transform_pigment(scene::Pigment& p, const Transform& t);
void transform_texture(scene::Texture& tex, const Transform& t);
// POV-Ray's Link_Textures: `top` (with its own layers) is drawn over `base`.
void layer_texture(scene::Texture& base, const scene::Texture& top, const FileLoc& at);

class Parser {
public:
    Parser(const ParseOptions& options, Diagnostics& diag);

    scene::Scene parse_main_file(const std::string& path);
    scene::Scene parse_main_string(const std::string& text, const std::string& name);

    // ---- token layer (token_stream.cpp; directives in directives.cpp, file_directives.cpp)
    const Token& next();   // the next grammar token; directives and macro calls are handled
    const Token& peek() { next(); unget(); return *cur_; }
    void unget() { ungot_ = true; }
    // Looks at the next token without running directives (safe right after a value).
    bool raw_next_is(const char* word) const {
        if (ungot_) return cur_->is(word);
        const Frame& f = frames_.back();
        return files_[f.file]->tokens[f.pos].is(word);
    }
    FileLoc loc() const { return loc_of(cur_file_, *cur_); }  // of the last token
    FileLoc loc_of(int file, const Token& t) const {
        return FileLoc{files_[file]->name, t.line, t.column};
    }
    bool accept(const char* word);        // consumes the token if it is `word`
    void expect(const char* word, const char* context);
    void expect_open(const char* what);   // '{'; remembers where for the matching '}'
    void expect_close(const char* what, const FileLoc& opened);
    [[noreturn]] void fail(const std::string& message) const;
    // describe(t), but an undeclared name that cannot be a keyword (POV-Ray keywords are
    // lower case) is called what it most likely is: an unknown identifier.
    std::string got(const Token& t) const;
    [[noreturn]] void fail_at(const FileLoc& loc, const std::string& message) const;
    // A resource limit of ParseOptions was passed: ErrorKind::Render (exit 4), naming the flag.
    [[noreturn]] void fail_limit(const FileLoc& loc, const std::string& message,
                                 const char* flag) const;
    [[noreturn]] void unsupported(const std::string& what) const;
    bool in_system_file() const;

    // Identifiers.
    const Symbol* lookup(const std::string& name) const;
    // Finds `name` or fails (unknown identifier / unusable declaration).
    const Symbol& use_symbol(const Token& t);
    // `local_scope`: the scope a #local writes to, fixed before its value is parsed (a macro
    // called in the value has its own scope on the stack until its #end); default innermost.
    void declare(const std::string& name, Value v, const FileLoc& loc, bool local,
                 size_t local_scope = size_t(-1));

    // ---- expressions (expressions.cpp)
    Num parse_num(int terms);  // an expression promoted to `terms` components
    double parse_float();
    // An additive expression only, as POV-Ray's Parse_Float reads it: a comparison needs
    // parentheses there. For counts before point lists (`N <x, y>`).
    double parse_float_no_compare();
    double parse_float_in_angle_brackets();  // where '>' closes instead of comparing
    Vec3 parse_vector();
    bool try_literal_vector(Vec3& out);
    std::string parse_string();
    Value parse_expression_value();  // a number or a string
    // Color after an optional `color`/`colour` keyword: rgb/rgbf/.../red/... or expression.
    scene::ColorFT parse_color();
    Color parse_rgb();
    bool next_is_expression_start();
    // A float-valued keyword constant (pi, clock, true, image_width, ...) by name.
    bool float_constant(const std::string& name, double& out) const;
    double allow_float(double fallback);  // an optional float (POV-Ray's Allow_Float)
    void skip_comma() { accept(","); }
    // The NumberList token next in the raw stream, consumed, or null (then nothing changes).
    const Token* take_number_list();
    // A taken NumberList the fast path refused: its tokens come next.
    void give_back_number_list(const Token& list) { expand_number_list(list, cur_file_); }
    // Counts `tokens` read by a fast path against --max-tokens and the checks next() makes
    // (interruption, --max-memory); false, with nothing counted, when they would exceed the
    // token limit (the caller then reads them token by token, which reports it).
    bool count_tokens(long long tokens, const FileLoc& at);

    // ---- functions and splines (functions.cpp)
    // After `function`: parameters and body; returns the index into scene.functions.
    int parse_function_definition();
    scene::Spline parse_spline_body();  // after spline {
    // Parse-time calls `F(1, 2, 3)` / `S(t [, type])`, after the name.
    Value call_function_now(int index, const std::string& name, const FileLoc& at);
    Value call_spline_now(const scene::Spline& s, const std::string& name);
    scene::FunctionEnv function_env() const;
    void warn_unimplemented_internal(int id, const FileLoc& at);
    bool warned_pigment_call() { return warned_once_.insert(" pigment call").second; }
    // `sky_sphere { SkyIdent ...}` (parser.cpp): true when the raw tokens ahead are '{' and an
    // identifier holding a declared sky_sphere.
    bool declared_sky_sphere_follows() const {
        if (ungot_ || frames_.empty()) return false;
        const Frame& f = frames_.back();
        const auto& toks = files_[f.file]->tokens;
        if (!toks[f.pos].is_symbol('{') || toks[f.pos + 1].kind != TokKind::Word) return false;
        const Symbol* s = lookup(toks[f.pos + 1].text);
        // An unusable one too: use_symbol then says why its declaration was skipped.
        return s && (s->unusable || std::holds_alternative<scene::SkySphere>(s->value));
    }
    // trace/min_extent/max_extent (expressions.cpp): the object alone in a scene.
    scene::Scene one_object_scene(const PovObject& po) const;
    // `#read` and trace()'s normal: assigns where the name lives, else declares it globally.
    void assign_existing_or_declare(const std::string& name, Value v, const FileLoc& at);

    // ---- materials (materials.cpp)
    scene::Texture parse_texture_body();      // after texture {
    void parse_pigment_body(scene::Pigment& p);  // after pigment {
    void parse_finish_body(scene::Finish& f);    // after finish {
    void parse_normal_body(scene::Normal& n);    // after normal {
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
    void parse_image_map_body(scene::ImageMap& im, double* bump_size = nullptr);
    // ---- patterns and maps (patterns.cpp, pattern_grammar.cpp)
    void parse_pattern_arguments(scene::PatternKind kind, scene::PatternParams& pp, bool normal);
    // A pattern modifier (turbulence, frequency, warp, brick_size, ...) if `w` is one; `head`
    // is the pattern's own transform, which a warp block moves into the warp list.
    bool parse_pattern_modifier(const std::string& w, scene::PatternKind kind,
                                scene::PatternParams& pp, Transform& head);
    scene::Warp parse_warp_body(const FileLoc& at);
    template <class F>
    void parse_map_entries(const char* what, bool average, F item);
    const BlendMapValue* declared_map(const char* keyword);
    std::vector<scene::PigmentMapEntry> parse_pigment_map_body(bool average);
    std::vector<scene::NormalMapEntry> parse_normal_map_body(bool average);
    std::vector<scene::SlopeMapEntry> parse_slope_map_body();
    std::vector<scene::TextureMapEntry> parse_texture_map_body(bool average);
    std::vector<scene::Pigment> parse_pigment_entries(scene::PatternKind kind, int count);
    std::vector<scene::Normal> parse_normal_entries(int count);
    std::vector<scene::Texture> parse_texture_entries(int count);
    // `#declare M = color_map { ... }` (and the other maps) after the keyword `w`.
    Value parse_map_rvalue(const std::string& w);
    // A transform keyword (translate/rotate/scale/matrix/transform) if the next token is one.
    bool parse_transform_item(Transform& t);
    Transform parse_transform_body();
    std::string resolve_file(const std::string& name, const FileLoc& loc) const;

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
    void parse_global_settings();
    void parse_background();
    void parse_sky_sphere();
    // ---- atmosphere (atmosphere.cpp): fog { ... } and rainbow { ... } statements
    void parse_fog();
    void parse_rainbow();

    // ---- top level (parser.cpp)
    void place_object(PovObject o);
    int add_material(const scene::Texture& t, const scene::Interior& in, const FileLoc& loc);
    // What a #declare right-hand side can be: object, texture, expression, ...
    Value parse_rvalue();
    void parse_default();
    void finish_version();
    // Runs the statements of the main file; an error raised inside a macro body gets a note
    // at the innermost macro's call site, since the body's text alone does not say which of
    // several calls (with which arguments) went wrong.
    void run_statements();

    const ParseOptions& options;
    Diagnostics& diag;
    UnsupportedLog unsupported_log;  // features already warned about (unsupported.h)
    std::vector<uint32_t> rand_streams;  // seed()/rand() state, POV-Ray's LCG
    // Frame depth of the #declare whose expression value is being read (-1: none).
    size_t declare_frame_ = size_t(-1);
    // Set by #declare; becomes declare_frame_ once the value's first token is read (a value
    // may start with a directive, e.g. `#declare S = #if (..) sphere {..} #else .. #end`).
    size_t pending_declare_frame_ = size_t(-1);
    scene::Scene scene;
    double version = 3.7;        // the `version` value expressions see
    bool version_set_ = false;   // any #version seen
    scene::Texture default_texture_;

private:
    // token_stream.cpp and directives.cpp internals
    int load_file(const std::string& path, bool system, const FileLoc& from);
    int add_source(const std::string& text, const std::string& name, bool system);
    const Token& raw();        // next token of the top frame, no processing
    // A NumberList met by raw(): its body scanned into tokens (cached per token) and read as
    // a frame of its own, as though written in place.
    void expand_number_list(const Token& list, int file);
    std::unordered_map<const Token*, int> number_list_files_;
    bool handle_directive(const Token& d, int file);
    void handle_declare(bool local, const FileLoc& dloc);
    void handle_include(const FileLoc& dloc);
    void handle_macro_def(const FileLoc& dloc);
    void call_macro(const Macro& m, const FileLoc& loc);
    enum class Conditional { If, Ifdef, Ifndef };
    void handle_if(const FileLoc& dloc, Conditional kind);
    void handle_else(const Token& d);
    void handle_end(const FileLoc& dloc);
    void handle_while(const FileLoc& dloc);
    void handle_for(const FileLoc& dloc);
    void handle_switch(const FileLoc& dloc);
    void handle_break(const FileLoc& dloc);
    void handle_message(const std::string& kind, const FileLoc& dloc);
    double parse_cond_paren();
    // Skips raw tokens to the #else/#elseif/#end (etc.) that closes the current level.
    std::string skip_block(bool stop_at_else, bool stop_at_case, const FileLoc& opened,
                           int depth = 0);
    void skip_declaration(size_t frames, size_t pos, size_t scopes, size_t conds);
    std::string read_name(const char* context);
    // Reads `[i][j]...` after an array name; returns the flat index, sets `display` to
    // "A[i][j]".
    size_t parse_array_index(const ArrayValue& a, const std::string& name, std::string& display);
    void parse_array_init(ArrayValue& a, size_t dim, size_t& k);
    Value parse_array();

    std::vector<std::unique_ptr<SourceFile>> files_;
    std::unordered_map<std::string, int> file_cache_;
    std::vector<Frame> frames_;
    std::vector<std::unordered_map<std::string, Symbol>> scopes_;
    const Token* cur_ = nullptr;
    int cur_file_ = 0;
    bool ungot_ = false;
    long long token_count_ = 0;
    int macro_depth_ = 0;
    long long triangles_ = 0;  // mesh triangles so far, against options.max_triangles
    // The grammar is recursive descent, and directives, macro calls and #while bodies can be
    // reached from inside any value, so nesting has no fixed bound in the grammar. The parser
    // runs on a thread of its own with options.max_parse_stack_mib plus kParseStackMargin of
    // stack (parser.cpp), and next() stops the scene once the budget is used: where the stack
    // was when the parser was made is stack_base_.
    std::uintptr_t stack_base_ = 0;
    std::uintptr_t stack_budget_ = 0;

public:
    // Below the budget, for what runs under one next() (an image load, a function compile).
    static constexpr std::size_t kParseStackMargin = std::size_t(64) << 20;

private:
    std::string scene_dir_;
    Token end_token_;
    // An array element read in the grammar becomes a token "A[3]" whose symbol lives here, so
    // every place that takes an identifier takes an element too. Tokens rotate through a ring
    // (callers hold a token only briefly).
    std::unordered_map<std::string, Symbol> element_syms_;
    std::vector<Token> synth_ = std::vector<Token>(256);
    size_t synth_next_ = 0;
    Token fake_end_;  // ends a #declare value at the next statement directive
    std::set<int> warned_internals_;
    std::set<std::string> warned_once_;  // deprecated-once names, one-time warnings
    // #fopen: open files by handle name; written files are kept in memory (see GRAMMAR.md).
    struct OpenFile {
        std::string path;  // as resolved (read) or as written (write/append)
        bool writing = false;
        std::vector<Token> tokens;  // read: the file's tokens
        size_t pos = 0;
        std::shared_ptr<const std::string> name;
    };
    std::map<std::string, OpenFile> open_files_;
    std::map<std::string, std::string> written_files_;  // name -> contents written
    bool warned_writes_ = false;
    void handle_fopen(const FileLoc& dloc);
    void handle_fclose(const FileLoc& dloc);
    void handle_read(const FileLoc& dloc);
    void handle_write(const FileLoc& dloc);
    void warn_deprecated(const std::string& name, const Symbol& s, const FileLoc& at);
};

}  // namespace glint::pov
