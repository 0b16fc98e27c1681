#pragma once
// Keeps libraries' own lines off stderr while glint calls them: libpng, under OpenImageIO,
// prints "libpng error: ..." and "libpng warning: ..." itself before OpenImageIO reports a
// broken image, and glint's stderr must hold glint's diagnostics alone (file:line:col, the
// source line, a caret). While at least one QuietStderr lives, file descriptor 2 goes to
// /dev/null; the last one to end puts it back. Safe to nest and to use from several threads
// (a counter under a mutex), but anything else written to stderr meanwhile is lost too: keep
// the scope to the library call.
#include <string>

namespace glint {

class QuietStderr {
public:
    QuietStderr();
    ~QuietStderr();
    QuietStderr(const QuietStderr&) = delete;
    QuietStderr& operator=(const QuietStderr&) = delete;
};

// The first line of a library's error text, without trailing spaces or full stop
// ("unknown error" when empty): OpenImageIO's texts run over several lines, which would split
// glint's error line from its source line.
std::string first_line_of(std::string text);

}  // namespace glint
