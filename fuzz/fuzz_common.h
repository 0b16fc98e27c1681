// Shared set-up for the libFuzzer targets: a private, empty folder that holds the input (so that
// relative #include and mtllib names resolve there, never in the repository), and the parser's
// resource limits set low so that a runaway #while or a macro recursion is a quick error.
#pragma once

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "formats/pov/parser.h"

namespace glint::fuzz {

// Creates (once) an empty folder under TMPDIR. The working folder stays as it is: libFuzzer
// reads its corpus paths relative to it.
inline const std::string& work_dir() {
    static const std::string dir = [] {
        const char* t = std::getenv("TMPDIR");
        std::string tmpl = std::string(t && *t ? t : "/tmp") + "/glint-fuzz-XXXXXX";
        if (!mkdtemp(tmpl.data())) std::abort();
        return tmpl;
    }();
    return dir;
}

inline void write_file(const std::string& path, const uint8_t* data, size_t size) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

inline pov::ParseOptions fuzz_options() {
    pov::ParseOptions o;
    o.max_loop_iterations = 1'000;
    o.max_include_depth = 8;
    o.max_macro_depth = 64;
    // About 30 ms of CPU with the sanitizers. The inputs that run into it (loops) decide
    // the throughput: on the same loaded 2-core machine fuzz_pov made ~730 executions a
    // second at 100 000 tokens and ~1200 at 10 000.
    o.max_tokens = 10'000;
    // Strings and arrays low too: `S = concat(S, S)` in a loop reaches the default 100 MB
    // in 23 passes, which took 1.3 s of page faults under ASan (0.5 s in a release build)
    // and ran past -timeout on a loaded machine. glint's own limit is tested by the error
    // case limit_string_length.
    o.max_string_length = 1'000'000;
    o.max_array_elements = 100'000;
    // On libFuzzer's thread (8 MiB of stack): half of it for the parser's nesting.
    o.parse_on_calling_thread = true;
    o.max_parse_stack_mib = 4;
    o.image_width = 64;
    o.image_height = 48;
    return o;
}

}  // namespace glint::fuzz
