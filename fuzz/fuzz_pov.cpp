// libFuzzer target: a whole POV-Ray scene text through the scanner and the parser into the IR.
// A glint::Error is the expected outcome of broken input; anything else (another exception,
// a sanitizer report, a hang past -timeout) is a finding.
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
    const std::string text(reinterpret_cast<const char*>(data), size);
    glint::Diagnostics diag;
    try {
        (void)glint::pov::parse_string(text, glint::fuzz::work_dir() + "/fuzz.pov",
                                       glint::fuzz::fuzz_options(), diag);
    } catch (const glint::Error&) {
    }
    return 0;
}
