// POV-Ray features glint lacks, met in a scene: one warning per feature and run, naming it and
// where it was first met, then the parser reads over it so the render goes on without it
// (an object is left out, a modifier or effect is dropped). The keywords listed in the
// parser's "unsupported" sets come here; giving one real support takes it out of those sets.
// Used by objects.cpp, parser.cpp, camera.cpp and materials.cpp.
#pragma once

#include <set>
#include <string>

#include "core/error.h"

namespace glint::pov {

class Parser;

// Which features were already reported. The standard include files count apart from the
// scene's own: the CLI hides the includes' warnings, so a feature first met in an include
// must still be reported where the scene itself uses it.
class UnsupportedLog {
  public:
    // True the first time `feature` is met in a scene file (system = false) or an include.
    bool first(const std::string& feature, bool system) {
        return seen_[system ? 1 : 0].insert(feature).second;
    }

  private:
    std::set<std::string> seen_[2];
};

// `file:line:col: warning: '<feature>' is not supported: <consequence>`, the first time only.
void warn_unsupported(Parser& p, const std::string& feature, const FileLoc& at,
                      const std::string& consequence);

// Reads the `{ ... }` that comes next up to its matching '}' (directives and macros inside
// still run, as they would in POV-Ray). `what` names the block in an "unterminated" error.
void skip_braced_block(Parser& p, const std::string& what);

}  // namespace glint::pov
