// libFuzzer target: the OBJ importer (tinyobjloader, compiled here with the same sanitizers,
// plus glint's conversion to the IR). The input is written to fuzz.obj in a private folder.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.h"
#include "formats/obj/obj_importer.h"
#include "fuzz_common.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    glint::fuzz::work_dir();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string path = glint::fuzz::work_dir() + "/fuzz.obj";
    glint::fuzz::write_file(path, data, size);
    glint::Diagnostics diag;
    try {
        glint::scene::Scene scene;
        (void)glint::obj::import_obj(path, scene, glint::Transform(), -1, diag);
    } catch (const glint::Error&) {
    }
    return 0;
}
