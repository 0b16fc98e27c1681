#include "formats/pov/unsupported.h"

#include "formats/pov/parser_impl.h"

namespace glint::pov {

void warn_unsupported(Parser& p, const std::string& feature, const FileLoc& at,
                      const std::string& consequence) {
    if (!p.unsupported_log.first(feature, p.in_system_file())) return;
    p.diag.warning(at, "'" + feature + "' is not supported: " + consequence);
}

void skip_braced_block(Parser& p, const std::string& what) {
    p.expect_open(what.c_str());
    FileLoc opened = p.loc();
    int depth = 1;
    while (depth > 0) {
        const Token& t = p.next();
        if (t.kind == TokKind::End) {
            p.unget();
            p.expect_close(what.c_str(), opened);
        }
        if (t.is_symbol('{')) ++depth;
        if (t.is_symbol('}')) --depth;
    }
}

}  // namespace glint::pov
