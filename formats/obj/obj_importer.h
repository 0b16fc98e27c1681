// Wavefront OBJ/MTL import through tinyobjloader (Debian libtinyobjloader-dev, double
// precision build): meshes, normals, uvs, objects/groups and materials into the IR. What each
// MTL statement becomes is in formats/obj/MTL.md.
#pragma once

#include <string>

#include "core/log.h"
#include "core/transform.h"
#include "scene/scene.h"

namespace glint::obj {

struct ObjImport {
    // One scene object per OBJ object/group (`o`/`g`), in file order.
    int first_object = 0;
    int object_count = 0;
    int first_material = 0;
    int material_count = 0;
    long long triangles = 0;
    Bounds3 bounds;  // world-space bounds of what was added
};

// Appends the OBJ file's meshes and materials to `scene`. Every object is placed by
// `transform`. `material_override` >= 0 makes every face use that scene material (a POV-style
// texture override) instead of the MTL's. Faces without a material get a neutral gray default.
// Throws Error(MissingFile) when the OBJ cannot be read and Error(Scene) with file:line for
// broken input (bad face indices, unparsable statements tinyobjloader reports). A missing MTL
// or texture image is a warning naming the file; the material still renders without it.
ObjImport import_obj(const std::string& path, scene::Scene& scene, const Transform& transform,
                     int material_override, Diagnostics& diag);

// `glint render model.obj`: the model alone, like a model viewer. OBJ's right-handed, y-up
// axes become POV-Ray's left-handed ones by mirroring z, the camera (perspective, 40 degrees
// vertically, image aspect) looks at the bounds' centre from the front, above and to the
// right, far enough that the bounding sphere fits, and a key, a fill and a rim light light it.
scene::Scene viewer_scene(const std::string& path, int width, int height, Diagnostics& diag);

// The classic (Whitted) texture and the PBR half for one MTL material, as MTL.md documents.
// The has_ flags say which statements the material wrote (an absent one keeps the default
// here, Blender's default material). Exposed for tests.
struct MtlValues {
    Color Ka{0, 0, 0}, Kd{0.8, 0.8, 0.8}, Ks{0, 0, 0}, Ke{0, 0, 0}, Tf{0, 0, 0};
    double Ns = 0, Ni = 1.45, d = 1;
    int illum = 2;
    bool has_Ka = false, has_Ns = false, has_Ni = false, has_Tf = false;
    bool has_Pr = false, has_Pm = false;
    // Any of Pr Pm Ps Pc Pcr aniso anisor: the material is in the PBR extension's terms (what
    // Blender writes with export_pbr_extensions), so Tf is its transmission.
    bool pbr_extension = false;
    double Pr = 0.5, Pm = 0, Ps = 0, Pc = 0, Pcr = 0, aniso = 0, anisor = 0;
};
scene::Material material_from_mtl(const MtlValues& v);

}  // namespace glint::obj
