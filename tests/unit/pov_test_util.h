// Helpers for the POV-Ray importer tests: parse a string, expect an error at a place.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/error.h"
#include "core/log.h"
#include "formats/pov/parser.h"

namespace glint::pov::testing {

inline scene::Scene parse(const std::string& text, ParseOptions opts = {}) {
    Diagnostics diag;
    return parse_string(text, "test.pov", opts, diag);
}

// The error's "line:col: message" so tests can check the place and the wording at once.
inline std::string error_of(const std::string& text, ParseOptions opts = {}) {
    try {
        parse(text, opts);
    } catch (const Error& e) {
        return std::to_string(e.loc().line) + ":" + std::to_string(e.loc().column) + ": " +
               e.what();
    }
    return "(no error)";
}

inline std::string povray_include_dir() {
    const char* dir = "/usr/share/povray-3.7/include";
    return std::filesystem::is_directory(dir) ? dir : "";
}

}  // namespace glint::pov::testing
