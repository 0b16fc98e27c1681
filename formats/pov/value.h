// Values held by POV-Ray identifiers (#declare/#local) and produced by expressions: numbers
// with 1 to 5 components (float, uv, vector, 4d, color), strings, and the scene entities an
// identifier can name. Objects are kept in an importer-side form (PovObject) until they are
// placed in the scene, because their textures still change with later modifiers.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/error.h"
#include "core/transform.h"
#include "scene/camera.h"
#include "scene/function.h"
#include "scene/scene.h"
#include "scene/light.h"
#include "scene/shape.h"
#include "scene/texture.h"

namespace glint::pov {

// POV-Ray's EXPRESS: up to five components; `terms` says how many are meaningful
// (1 float, 2 uv, 3 vector, 4 4-d vector, 5 color rgbft).
struct Num {
    double v[5] = {0, 0, 0, 0, 0};
    int terms = 1;

    static Num scalar(double f) { return Num{{f, f, f, f, f}, 1}; }
    static Num vec(const Vec3& p) { return Num{{p.x, p.y, p.z, 0, 0}, 3}; }
    Vec3 vec3() const { return {v[0], v[1], v[2]}; }
    // POV-Ray's Promote_Express: a float fills every component, a vector pads with zeros.
    void promote(int n) {
        if (terms >= n) return;
        for (int i = terms; i < n; ++i) v[i] = terms == 1 ? v[0] : 0.0;
        terms = n;
    }
};

// An optional value kept on the heap. A PovObject's textures are mostly absent (CSG nodes,
// children that inherit) yet std::optional would hold 3.4 KB each inline, and a scene's copies
// of declared objects multiply every node (issue 33: nested copies peaked at 2.4 GB).
template <class T>
class HeapOptional {
public:
    HeapOptional() = default;
    HeapOptional(const HeapOptional& o) : p_(o.p_ ? std::make_unique<T>(*o.p_) : nullptr) {}
    HeapOptional(HeapOptional&&) noexcept = default;
    HeapOptional& operator=(const HeapOptional& o) {
        if (this != &o) p_ = o.p_ ? std::make_unique<T>(*o.p_) : nullptr;
        return *this;
    }
    HeapOptional& operator=(HeapOptional&&) noexcept = default;
    HeapOptional& operator=(const T& v) {
        p_ = std::make_unique<T>(v);
        return *this;
    }
    HeapOptional& operator=(T&& v) {
        p_ = std::make_unique<T>(std::move(v));
        return *this;
    }
    HeapOptional& operator=(const std::optional<T>& v) {
        p_ = v ? std::make_unique<T>(*v) : nullptr;
        return *this;
    }
    explicit operator bool() const { return p_ != nullptr; }
    bool has_value() const { return p_ != nullptr; }
    T& operator*() { return *p_; }
    const T& operator*() const { return *p_; }
    T* operator->() { return p_.get(); }
    const T* operator->() const { return p_.get(); }
    void reset() { p_.reset(); }

private:
    std::unique_ptr<T> p_;
};

struct PovObject;

// A CSG object's children, shared by its copies until one of them is changed (copy on write),
// with the texture transforms the CSG's own transformations still owe them. A copy of a
// declared union is one node however large the union; `object { U translate x }` records the
// translation here instead of moving every texture below (issue 33: a scene of nested copies
// of one declared object took 2.9 GB where POV-Ray takes 0.6). The owed transforms are applied,
// in order, to each child's textures and interior (transform_child_textures) when the children
// are edited, and by whoever reads them for their textures (placement: with_owed_transforms).
class PovChildren {
public:
    bool empty() const { return !items_ || items_->empty(); }
    // The children as they were given, without the owed transforms: for what transforms
    // leave alone (shapes, flags, lights, groups).
    const std::vector<PovObject>& given() const;
    // Texture transforms owed to every child, oldest first.
    const std::vector<Transform>& owed() const { return owed_; }
    // The children to change in place: an own copy once they are shared, the owed transforms
    // applied first (objects.cpp).
    std::vector<PovObject>& edit();
    void push_back(PovObject child);
    // A transform of the parent that its children's textures follow.
    void transform_textures(const Transform& t) {
        if (!empty()) owed_.push_back(t);
    }

private:
    std::shared_ptr<std::vector<PovObject>> items_;
    std::vector<Transform> owed_;
};

// An object as the importer holds it: the IR object (shape, transform, flags; for CSG the
// children live in `children` until placement) plus its optional texture and interior and the
// lights it contains (light_source inside a union moves with the union).
struct PovObject {
    scene::Object obj;
    PovChildren children;
    HeapOptional<scene::Texture> texture;
    HeapOptional<scene::Texture> interior_texture;  // the inside's texture, when given
    std::optional<scene::Interior> interior;
    std::vector<scene::Light> lights;
    bool is_light = false;  // a bare light_source: only lights[0] matters
    // The object's own `uv_mapping` (scene::Material::uv_points); its transforms then leave
    // its textures alone (POV-Ray's UV_FLAG).
    bool uv_mapping = false;
    // Non-empty for an object glint cannot render (the keyword, e.g. "isosurface"): it was
    // read over with a warning and is dropped where it would be placed (unsupported.h).
    std::string left_out;
};

inline const std::vector<PovObject>& PovChildren::given() const {
    static const std::vector<PovObject> kNone;
    return items_ ? *items_ : kNone;
}

// Child `c` of `parent` (one of parent.children.given()) as it is once the owed texture
// transforms are applied: `c` itself when none are owed, else a copy (one node; its own
// children stay shared and owe the transforms in turn) in *storage.
const PovObject& with_owed_transforms(const PovChildren& parent, const PovObject& c,
                                      std::optional<PovObject>* storage);

struct MaterialValue {
    std::optional<scene::Texture> texture;
    std::optional<scene::Texture> interior_texture;
    std::optional<scene::Interior> interior;
};

struct Macro {
    std::string name;
    std::vector<std::string> params;
    std::vector<bool> optional;  // per parameter: `optional` (may be left out at the call)
    int file = -1;      // index into the parser's source files
    size_t body = 0;    // token index of the first body token
    FileLoc loc;
};

struct ArrayValue;

// A declared function: an index into the scene's functions (Scene::functions), which only grow
// during a parse, so the index stays valid.
struct FunctionRef {
    int index = -1;
};

// #fopen handle: the name of the open file in the parser's file table.
struct FileHandle {
    std::string name;
};

// A declared map: `#declare M = color_map { ... }` (or pigment_map, normal_map, slope_map,
// texture_map), used as `color_map { M }`. `keyword` says which one is filled.
struct BlendMapValue {
    std::string keyword;
    std::vector<scene::ColorMapEntry> colors;
    std::vector<scene::PigmentMapEntry> pigments;
    std::vector<scene::NormalMapEntry> normals;
    std::vector<scene::SlopeMapEntry> slopes;
    std::vector<scene::TextureMapEntry> textures;
};

using Value = std::variant<Num, std::string, std::shared_ptr<const PovObject>, scene::Texture,
                           scene::Pigment, scene::Finish, scene::Normal, scene::Interior,
                           MaterialValue, scene::Camera, Transform, std::shared_ptr<const Macro>,
                           std::shared_ptr<ArrayValue>, FunctionRef,
                           std::shared_ptr<const scene::Spline>, FileHandle, BlendMapValue,
                           scene::SkySphere, scene::Media>;

// POV-Ray `array[n][m]...`: row-major elements, null until assigned. Held by shared_ptr so
// that `#declare A[i] = v` can fill it in place; `#declare B = A` copies (Parser::declare).
struct ArrayValue {
    std::vector<int> sizes;
    std::vector<std::shared_ptr<Value>> items;
};

// "a float", "a texture", ... for messages like "expected a float, got a texture".
std::string value_kind_name(const Value& v);

struct Symbol {
    Value value;
    FileLoc loc;
    // Set when a declaration in a standard include used an unsupported feature: the name
    // exists, but using it is an error that points at both places.
    bool unusable = false;
    std::string unusable_reason;
    // A macro parameter whose argument was a plain identifier: POV-Ray passes it by reference,
    // so `#declare Param = ...` in the body assigns the caller's identifier (scope index).
    std::string ref_name;
    size_t ref_scope = 0;
    // #declare deprecated [once] "message" Name = ...: warned about on use.
    std::string deprecated;
    bool deprecated_once = false;
};

}  // namespace glint::pov
