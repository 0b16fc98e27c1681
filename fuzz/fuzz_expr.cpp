// libFuzzer target: the expression evaluator, through `#declare X = <input>;` so that every
// float, vector, colour, string and function expression form is reachable without a scene
// around it.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.h"
#include "fuzz_common.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    glint::fuzz::work_dir();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string text = "#declare X = ";
    text.append(reinterpret_cast<const char*>(data), size);
    text += ";\n";
    glint::Diagnostics diag;
    try {
        (void)glint::pov::parse_string(text, glint::fuzz::work_dir() + "/fuzz.pov",
                                       glint::fuzz::fuzz_options(), diag);
    } catch (const glint::Error&) {
    }
    return 0;
}
