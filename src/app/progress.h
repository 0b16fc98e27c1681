// Progress reporting for the CLI: a bar on a terminal, or machine-readable `progress 0.42`
// lines on stderr (the contract the Blender add-on reads), or nothing. The renderer calls
// update() from any thread; output is serialized and only printed when it changes.
#pragma once

#include <cstdio>
#include <mutex>

namespace glint::app {

enum class ProgressStyle { None, Bar, Lines };

class ProgressReporter {
  public:
    // `out` is usually stderr; the reporter does not own it.
    ProgressReporter(ProgressStyle style, std::FILE* out) : style_(style), out_(out) {}
    ProgressReporter(const ProgressReporter&) = delete;
    ProgressReporter& operator=(const ProgressReporter&) = delete;

    // fraction in [0, 1]; thread-safe; values below the last one shown are ignored.
    void update(double fraction);
    // Shows 1.0 and ends the bar's line. Idempotent.
    void finish();
    // Ends the bar's line without claiming completion (before an error message).
    void abandon();

  private:
    void draw_bar(int percent);

    ProgressStyle style_;
    std::FILE* out_;
    std::mutex mutex_;
    int shown_ = -1;  // last shown value in hundredths (Lines) or percent (Bar)
    bool done_ = false;
};

}  // namespace glint::app
