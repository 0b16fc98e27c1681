// Where things come from and how failures are reported. Every IR entity carries the FileLoc
// of the text that made it; library code throws glint::Error and only the CLI turns errors
// into messages (file:line:col, the source line, a caret) and exit codes.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

namespace glint {

struct FileLoc {
    // Shared so that a million mesh faces do not copy the file name a million times.
    std::shared_ptr<const std::string> file;
    int line = 0;  // 1-based; 0 = unknown
    int column = 0;  // 1-based; 0 = unknown

    bool valid() const { return file && line > 0; }
    std::string filename() const { return file ? *file : std::string(); }
    // "file:line:col" (or as much of it as is known).
    std::string to_string() const;
};

// What kind of failure: decides the CLI's exit code (docs/usage.md "Exit codes" lists them).
enum class ErrorKind {
    Usage,        // bad command line
    Scene,        // the scene text is wrong (syntax, types, values)
    MissingFile,  // an input, include or image file could not be found or read
    Render,       // the renderer failed (resource limits, internal errors)
    Output,       // the image could not be written
    Cancelled,    // interrupted by the user
};

class Error : public std::runtime_error {
public:
    Error(ErrorKind kind, FileLoc loc, const std::string& message)
        : std::runtime_error(message), kind_(kind), loc_(std::move(loc)) {}

    ErrorKind kind() const { return kind_; }
    const FileLoc& loc() const { return loc_; }
    // A second location the message refers to ("declared here"); optional.
    const FileLoc& note_loc() const { return note_loc_; }
    const std::string& note() const { return note_; }
    Error& with_note(FileLoc loc, std::string note) {
        note_loc_ = std::move(loc);
        note_ = std::move(note);
        return *this;
    }

private:
    ErrorKind kind_;
    FileLoc loc_;
    FileLoc note_loc_;
    std::string note_;
};

// Formats `file:line:col: <severity>: message`, then the source line and a caret under the
// column when the file can be read. Used for errors and warnings alike.
std::string format_diagnostic(const FileLoc& loc, const std::string& severity,
                              const std::string& message);
std::string format_error(const Error& e);

}  // namespace glint
