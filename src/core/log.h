// Warnings and verbose messages from the library. There is no global logger: whoever runs a
// stage passes a Diagnostics sink; the CLI prints it to stderr, tests collect it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/error.h"

namespace glint {

struct Diagnostic {
    enum class Level { Info, Warning } level;
    FileLoc loc;
    std::string message;
};

class Diagnostics {
public:
    using Sink = std::function<void(const Diagnostic&)>;
    Diagnostics() = default;
    explicit Diagnostics(Sink sink) : sink_(std::move(sink)) {}

    void warning(const FileLoc& loc, const std::string& message) {
        emit({Diagnostic::Level::Warning, loc, message});
    }
    void info(const std::string& message) { emit({Diagnostic::Level::Info, {}, message}); }
    const std::vector<Diagnostic>& all() const { return all_; }
    int warning_count() const { return warnings_; }

private:
    void emit(Diagnostic d) {
        if (d.level == Diagnostic::Level::Warning) ++warnings_;
        if (sink_) sink_(d);
        all_.push_back(std::move(d));
    }
    Sink sink_;
    std::vector<Diagnostic> all_;
    int warnings_ = 0;
};

}  // namespace glint
