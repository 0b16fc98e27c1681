// Entry points of the POV-Ray importer and the top level of a scene file: statements,
// #declare values, #default, and the placement of finished objects into scene::Scene
// (where POV-Ray's default texture and the material ids are settled).
#include "formats/pov/parser.h"

#include <pthread.h>

#include <cstring>
#include <exception>
#include <filesystem>
#include <functional>
#include <optional>
#include <unordered_set>

#include "formats/pov/parser_impl.h"

namespace glint::pov {

namespace fs = std::filesystem;

int Parser::add_material(const scene::Texture& t, const scene::Interior& in, const FileLoc& l,
                         int interior_id, const scene::Texture* inside, bool uv_points) {
    scene::Material m;
    m.texture = t;
    m.uv_points = uv_points;
    if (inside) m.interior_texture.push_back(*inside);
    m.interior = in;
    if (t.kind == scene::PatternKind::Plain) {
        // POV-Ray 3.0's `finish { ior caustics refraction }` (Post_Process promotes them).
        const scene::Finish& f = t.finish;
        if (f.old_ior >= 0) m.interior.ior = f.old_ior;
        if (f.old_caustics >= 0) m.interior.caustics = f.old_caustics;
        m.interior.old_refraction = f.old_refraction;
    }
    m.interior_id = interior_id;
    m.loc = l;
    scene.materials.push_back(std::move(m));
    return static_cast<int>(scene.materials.size()) - 1;
}

// A uniform texture's material where the object's copies can share it (Parser::
// uniform_materials_): its key, or an empty one where they cannot.
static std::vector<uint64_t> shared_material_key(const scene::Texture* source,
                                                 const scene::Texture& tex,
                                                 const scene::Texture* inside,
                                                 const scene::Interior& in, int id, bool uv) {
    if (!source || inside || !in.media.empty() || !texture_is_uniform(tex)) return {};
    std::vector<uint64_t> key{reinterpret_cast<uintptr_t>(source), static_cast<uint64_t>(id),
                              uv};
    for (double v : {in.ior, in.dispersion, in.caustics, in.fade_distance, in.fade_power,
                     in.fade_color.r, in.fade_color.g, in.fade_color.b, in.old_refraction}) {
        uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        key.push_back(bits);
    }
    return key;
}

// Children without a texture, interior_texture or interior of their own inherit (material
// -1); those with one get a material completed from what they inherit. POV-Ray's
// Post_Process hands each of the three down on its own, and the parent's uv_mapping with
// an inherited texture. An object that declares an interior (and each top-level object)
// starts a new interior id; the others share their parent's.
// `source`: the texture po's own texture was copied from, in a child shared by copies of a
// declared object (null for the object placed).
static scene::Object to_ir(Parser& p, const PovObject& po, const scene::Texture* source,
                           const scene::Texture& inh_tex, const scene::Texture* inh_inside,
                           const scene::Interior& inh_in, int inh_id, bool inh_uv, bool top,
                           int* next_id) {
    scene::Object o = po.obj;
    const scene::Texture& tex = po.texture ? *po.texture : inh_tex;
    const scene::Texture* inside = po.interior_texture ? &*po.interior_texture : inh_inside;
    const scene::Interior& in = po.interior ? *po.interior : inh_in;
    const int id = top || po.interior ? (*next_id)++ : inh_id;
    const bool uv = po.uv_mapping || (!po.texture && inh_uv);
    if (top || po.texture || po.interior || po.interior_texture || uv != inh_uv) {
        const std::vector<uint64_t> key =
            shared_material_key(po.texture ? source : nullptr, tex, inside, in, id, uv);
        auto shared = key.empty() ? p.uniform_materials_.end() : p.uniform_materials_.find(key);
        if (shared != p.uniform_materials_.end()) {
            o.material = shared->second;
        } else {
            o.material = p.add_material(tex, in, po.texture ? po.texture->loc : po.obj.loc, id,
                                        inside, uv);
            if (!key.empty()) p.uniform_materials_.emplace(key, o.material);
        }
    } else {
        o.material = -1;
    }
    if (auto* ref = std::get_if<scene::MeshRef>(&o.shape); ref && inside)
        p.give_faces_interior_texture(*ref, *inside);
    if (auto* ref = std::get_if<scene::MeshRef>(&o.shape); ref && uv) p.give_faces_uv_points(*ref);
    if (auto csg = std::get_if<scene::Csg>(&o.shape)) {
        csg->children.clear();
        csg->children.reserve(po.children.given().size());
        for (const PovObject& given : po.children.given()) {
            std::optional<PovObject> moved;
            const PovObject& c = with_owed_transforms(po.children, given, &moved);
            const scene::Texture* c_source = given.texture ? &*given.texture : nullptr;
            csg->children.push_back(
                to_ir(p, c, c_source, tex, inside, in, id, uv, false, next_id));
        }
    }
    return o;
}

// POV-Ray's Post_Process hands these flags down to CSG children.
static void propagate_flags(scene::Object& o) {
    auto csg = std::get_if<scene::Csg>(&o.shape);
    if (!csg) return;
    for (auto& c : csg->children) {
        c.no_shadow = c.no_shadow || o.no_shadow;
        c.no_image = c.no_image || o.no_image;
        c.no_reflection = c.no_reflection || o.no_reflection;
        c.no_radiosity = c.no_radiosity || o.no_radiosity;
        if (c.radiosity_importance < 0) c.radiosity_importance = o.radiosity_importance;
        propagate_flags(c);
    }
}

void Parser::place_object(PovObject o) {
    for (auto& l : o.lights) scene.lights.push_back(l);
    if (o.is_light || !o.left_out.empty()) return;
    scene::Texture def = default_texture_;
    def.loc = o.obj.loc;
    if (static_cast<long long>(scene.objects.size()) >= options.max_objects)
        fail_limit(o.obj.loc,
                   "the scene has more than " + std::to_string(options.max_objects) + " objects",
                   "--max-objects");
    uniform_materials_.clear();
    scene.objects.push_back(to_ir(*this, o, nullptr, def, nullptr, scene::Interior{}, -1, false,
                                  true, &next_interior_id_));
    uniform_materials_.clear();
    propagate_flags(scene.objects.back());
}

static void parse_declared_sky_sphere(Parser& p);

Value Parser::parse_rvalue() {
    const Token& t = next();
    value_begins();
    if (t.kind == TokKind::Word) {
        if (lookup(t.text)) {
            const Symbol& s = use_symbol(t);
            if (auto arr = std::get_if<std::shared_ptr<ArrayValue>>(&s.value))
                return std::make_shared<ArrayValue>(**arr);  // arrays are copied
            bool callable = std::holds_alternative<FunctionRef>(s.value) ||
                            std::holds_alternative<std::shared_ptr<const scene::Spline>>(s.value);
            if (!std::holds_alternative<Num>(s.value) &&
                !std::holds_alternative<std::string>(s.value) && !(callable && raw_next_is("(")))
                return s.value;
            unget();
            return parse_expression_value();
        }
        const std::string w = t.text;
        // Inside a braced value, directives are ordinary content: only an expression value
        // ends at a following directive (see Parser::next).
        BracedValue braced_value(*this);
        PovObject po;
        if (parse_object(t, po)) return std::make_shared<const PovObject>(std::move(po));
        auto braced = [&](auto body) {
            expect_open(w.c_str());
            FileLoc o = loc();
            auto v = body();
            expect_close(w.c_str(), o);
            return v;
        };
        if (w == "texture") {
            scene::Texture tex = braced([&] { return parse_texture_body(); });
            while (raw_next_is("texture")) {  // layered: each one over the ones before
                next();
                FileLoc at = loc();
                layer_texture(tex, braced([&] { return parse_texture_body(); }), at);
            }
            return tex;
        }
        if (w == "pigment")
            return braced([&] {
                scene::Pigment p = default_texture_.pigment;
                p.loc = loc();
                parse_pigment_body(p);
                return p;
            });
        if (w == "finish")
            return braced([&] {
                scene::Finish f = default_texture_.finish;
                f.loc = loc();
                parse_finish_body(f);
                return f;
            });
        if (w == "normal")
            return braced([&] {
                scene::Normal n = default_texture_.normal;
                n.loc = loc();
                parse_normal_body(n);
                return n;
            });
        if (w == "interior")
            return braced([&] {
                scene::Interior in;
                parse_interior_body(in);
                return in;
            });
        if (w == "material") return braced([&] { return parse_material_body(); });
        if (w == "camera")
            return braced([&] {
                scene::Camera c;
                parse_camera_body(c);
                return c;
            });
        if (w == "transform") return braced([&] { return parse_transform_body(); });
        if (w == "array") return parse_array();
        if (w == "color_map" || w == "colour_map" || w == "pigment_map" || w == "normal_map" ||
            w == "texture_map" || w == "slope_map")
            return parse_map_rvalue(w);
        if (w == "function") return FunctionRef{parse_function_definition()};
        if (w == "sky_sphere") {
            // parse_sky_sphere sets the scene's sky; a declaration keeps it instead.
            std::optional<scene::SkySphere> saved = scene.sky_sphere;
            if (declared_sky_sphere_follows())
                parse_declared_sky_sphere(*this);
            else
                parse_sky_sphere();
            scene::SkySphere sky = std::move(*scene.sky_sphere);
            scene.sky_sphere = std::move(saved);
            return sky;
        }
        if (w == "spline")
            return braced([&] { return std::make_shared<const scene::Spline>(parse_spline_body()); });
        static const std::unordered_set<std::string> kUnsupported = {
            "fog", "rainbow", "material_map", "background"};
        if (w == "media")
            return braced([&] {
                scene::Media m = new_media();
                parse_media_body(m);
                return m;
            });
        if (w == "density") return braced([&] { return parse_density_body(); });
        if (w == "density_map") {
            const bool outer = in_density_;
            in_density_ = true;
            Value v = parse_map_rvalue(w);
            in_density_ = outer;
            return v;
        }
        if (kUnsupported.count(w)) unsupported("declaring '" + w + "'");
    }
    unget();
    return parse_expression_value();
}

// array[n][m] [{ {..}, {..} }]
Value Parser::parse_array() {
    auto a = std::make_shared<ArrayValue>();
    size_t total = 1;
    while (raw_next_is("[")) {
        expect("[", "after 'array'");
        FileLoc l = loc();
        double n = parse_float();
        expect("]", "after the array size");
        if (!(n >= 1)) fail_at(l, "array size must be at least 1");
        const double limit = static_cast<double>(options.max_array_elements);
        if (n * static_cast<double>(total) > limit)
            fail_limit(l, "array of more than " + std::to_string(options.max_array_elements) +
                              " elements", "--max-array-size");
        a->sizes.push_back(static_cast<int>(n));
        total *= static_cast<size_t>(n);
    }
    if (a->sizes.empty()) fail("expected '[' and a size after 'array'");
    a->items.resize(total);
    if (raw_next_is("{")) {
        size_t k = 0;
        parse_array_init(*a, 0, k);
    }
    return a;
}

void Parser::parse_array_init(ArrayValue& a, size_t dim, size_t& k) {
    expect_open("array");
    FileLoc o = loc();
    for (int i = 0; i < a.sizes[dim]; ++i) {
        if (i > 0) skip_comma();  // optional, as POV-Ray's Parse_Comma
        if (dim + 1 < a.sizes.size())
            parse_array_init(a, dim + 1, k);
        else
            a.items[k++] = std::make_shared<Value>(parse_rvalue());
    }
    accept(",");
    const Token& t = next();
    if (!t.is_symbol('}'))
        fail("expected '}' after the " + std::to_string(a.sizes[dim]) +
             " elements of the array opened at " + std::to_string(o.line) + ":" +
             std::to_string(o.column) + ", got " + got(t));
}

void Parser::parse_default() {
    expect_open("#default");
    FileLoc o = loc();
    for (;;) {
        const Token& t = next();
        if (t.is_symbol('}') || t.kind == TokKind::End) {
            unget();
            break;
        }
        const std::string w = t.text;
        if (w == "texture") {
            expect_open("texture");
            FileLoc lo = loc();
            default_texture_ = parse_texture_body();
            expect_close("texture", lo);
        } else if (w == "pigment") {
            expect_open("pigment");
            FileLoc lo = loc();
            parse_pigment_body(default_texture_.pigment);
            expect_close("pigment", lo);
        } else if (w == "finish") {
            expect_open("finish");
            FileLoc lo = loc();
            parse_finish_body(default_texture_.finish);
            expect_close("finish", lo);
        } else if (w == "normal") {
            expect_open("normal");
            FileLoc lo = loc();
            parse_normal_body(default_texture_.normal);
            expect_close("normal", lo);
        } else if (w == "radiosity") {
            parse_radiosity_importance(&scene.global.radiosity_importance);
        } else {
            fail("expected texture, pigment, finish, normal or radiosity in #default, got " +
                 got(t));
        }
    }
    expect_close("#default", o);
}

// sky_sphere { SkyIdent [pigment {..}] [emission c] [transforms] }: a copy of the declared
// sky, with more pigment layers and transforms (camera.cpp reads the literal form).
static void parse_declared_sky_sphere(Parser& p) {
    p.expect_open("sky_sphere");
    FileLoc o = p.loc();
    scene::SkySphere sky = std::get<scene::SkySphere>(p.use_symbol(p.next()).value);
    for (;;) {
        const Token& t = p.next();
        if (t.is_symbol('}')) break;
        if (t.kind == TokKind::End) p.expect_close("sky_sphere", o);
        if (t.is("pigment")) {
            p.expect_open("pigment");
            FileLoc po = p.loc();
            scene::Pigment pg;
            pg.loc = po;
            p.parse_pigment_body(pg);
            p.expect_close("pigment", po);
            sky.pigments.push_back(pg);
        } else if (t.is("emission")) {
            sky.emission = p.parse_rgb();
        } else {
            p.unget();
            Transform delta;
            if (!p.parse_transform_item(delta))
                p.fail("expected pigment, emission or a transform in sky_sphere, got " +
                       p.got(p.next()));
            sky.transform = sky.transform.then(delta);
        }
    }
    p.scene.sky_sphere = std::move(sky);
}

static void parse_statements(Parser& p) {
    for (;;) {
        const Token& t = p.next();
        if (t.kind == TokKind::End) return;
        if (t.kind == TokKind::Word && !p.lookup(t.text)) {
            const std::string& w = t.text;
            if (w == "camera") {
                p.expect_open("camera");
                FileLoc o = p.loc();
                scene::Camera cam;
                p.parse_camera_body(cam);
                p.expect_close("camera", o);
                p.scene.camera = cam;
                continue;
            }
            if (w == "global_settings") { p.parse_global_settings(); continue; }
            if (w == "default") { p.parse_default(); continue; }  // old form of #default
            if (w == "background") { p.parse_background(); continue; }
            if (w == "sky_sphere" && p.declared_sky_sphere_follows()) {
                parse_declared_sky_sphere(p);
                continue;
            }
            if (w == "sky_sphere") { p.parse_sky_sphere(); continue; }
            if (w == "fog") { p.parse_fog(); continue; }
            if (w == "rainbow") { p.parse_rainbow(); continue; }
            if (w == "media") {
                p.expect_open("media");
                FileLoc o = p.loc();
                scene::Media m = p.new_media();
                p.parse_media_body(m);
                p.expect_close("media", o);
                p.scene.media.push_back(std::move(m));
                continue;
            }
        }
        PovObject o;
        if (p.parse_object(t, o)) {  // a shape keyword, or a declared object's name alone
            p.place_object(std::move(o));
            continue;
        }
        if (t.kind == TokKind::Word && p.lookup(t.text))
            p.fail("expected an object, light_source, camera or directive, got " +
                   value_kind_name(p.lookup(t.text)->value) + " '" + t.text + "'");
        if (t.kind == TokKind::Word)
            p.fail("unknown keyword or identifier '" + t.text + "'");
        p.fail("expected an object, light_source, camera or directive, got " + p.got(t));
    }
}

// A scene that never ran #version is taken as pre-3.7 (3.62), as POV-Ray 3.7's
// EffectiveLanguageVersion does (scene.h); this decides e.g. the gamma handling.
void Parser::finish_version() {
    scene.version = version_set() ? version() : 3.62;
    if (!version_set())
        diag.warning(FileLoc{}, "the scene has no #version directive: treated as version 3.62 "
                                "(POV-Ray 3.7 does the same)");
}

void Parser::run_statements() {
    // Declare=Name=Value from POV-Ray's command line: as if declared before the first line.
    for (const auto& [name, value] : options.declares)
        declare(name, Num::scalar(value), FileLoc{}, false);
    try {
        parse_statements(*this);
    } catch (Error& e) {
        note_macro_call(e);
        throw;
    }
}

Parser::Parser(const ParseOptions& opts, Diagnostics& d) : TokenStream(opts, d) {}

void Parser::file_read(const std::string& path) {
    for (const auto& s : scene.source_files)
        if (s == path) return;
    scene.source_files.push_back(path);
}

void Parser::declared(const std::string& name, const Value& v) {
    if (auto fr = std::get_if<FunctionRef>(&v)) {
        auto& fn = scene.functions[static_cast<size_t>(fr->index)];
        if (fn.name.empty()) fn.name = name;
    }
}

scene::Scene Parser::parse_main_file(const std::string& path) {
    if (!fs::is_regular_file(path))
        throw Error(ErrorKind::MissingFile, FileLoc{std::make_shared<const std::string>(path), 0, 0},
                    "cannot read the scene file '" + path + "'");
    open_main_file(path);
    run_statements();
    finish_version();
    return std::move(scene);
}

scene::Scene Parser::parse_main_string(const std::string& text, const std::string& name) {
    open_main_string(text, name);
    run_statements();
    finish_version();
    return std::move(scene);
}

namespace {

// Runs `parse` on a thread whose stack is the parser's budget plus a margin (reserved, not
// touched: only the pages a deep scene reaches are ever used), so that the parser's own stack
// check, not the 8 MiB of a main thread or the smaller stacks of worker threads, is what stops
// deep nesting. The caller waits; an exception crosses back to it.
scene::Scene on_parse_stack(const ParseOptions& options,
                            const std::function<scene::Scene()>& parse) {
    if (options.parse_on_calling_thread) return parse();
    const std::size_t stack =
        (std::size_t(std::max(options.max_parse_stack_mib, 1)) << 20) + Parser::kParseStackMargin;
    struct Job {
        const std::function<scene::Scene()>* parse;
        std::optional<scene::Scene> result;
        std::exception_ptr error;
    } job{&parse, std::nullopt, nullptr};
    auto body = [](void* arg) -> void* {
        auto* j = static_cast<Job*>(arg);
        try {
            j->result.emplace((*j->parse)());
        } catch (...) {
            j->error = std::current_exception();
        }
        return nullptr;
    };
    pthread_attr_t attr;
    pthread_t thread;
    bool started = pthread_attr_init(&attr) == 0 &&
                   pthread_attr_setstacksize(&attr, stack) == 0 &&
                   pthread_create(&thread, &attr, body, &job) == 0;
    pthread_attr_destroy(&attr);
    if (!started)
        throw Error(ErrorKind::Render, FileLoc{},
                    "cannot start the parser's thread (" +
                        std::to_string(stack >> 20) + " MiB of stack)");
    pthread_join(thread, nullptr);
    if (job.error) std::rethrow_exception(job.error);
    return std::move(*job.result);
}

}  // namespace

scene::Scene parse_file(const std::string& path, const ParseOptions& options, Diagnostics& diag) {
    return on_parse_stack(options, [&] {
        Parser p(options, diag);
        return p.parse_main_file(path);
    });
}

scene::Scene parse_string(const std::string& text, const std::string& name,
                          const ParseOptions& options, Diagnostics& diag) {
    return on_parse_stack(options, [&] {
        Parser p(options, diag);
        return p.parse_main_string(text, name);
    });
}

}  // namespace glint::pov
