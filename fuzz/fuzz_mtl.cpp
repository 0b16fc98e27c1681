// libFuzzer target: the MTL importer. The input is written to fuzz.mtl; a fixed OBJ names it
// with mtllib and uses a few material names, so tinyobjloader's MTL reader, glint's own MTL
// statement scan and material_from_mtl all see it.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.h"
#include "formats/obj/obj_importer.h"
#include "fuzz_common.h"

namespace {
const char kObj[] =
    "mtllib fuzz.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
    "usemtl Material\nf 1/1/1 2/2/1 3/3/1\n"
    "usemtl Material.001\nf 1/1/1 2/2/1 3/3/1\n"
    "usemtl a\nf 1/1/1 2/2/1 3/3/1\n";
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    const std::string dir = glint::fuzz::work_dir();
    glint::fuzz::write_file(dir + "/fuzz.obj", reinterpret_cast<const uint8_t*>(kObj),
                            sizeof(kObj) - 1);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string dir = glint::fuzz::work_dir();
    glint::fuzz::write_file(dir + "/fuzz.mtl", data, size);
    glint::Diagnostics diag;
    try {
        glint::scene::Scene scene;
        (void)glint::obj::import_obj(dir + "/fuzz.obj", scene, glint::Transform(), -1, diag);
    } catch (const glint::Error&) {
    }
    return 0;
}
