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

PovObject skip_unsupported_object(Parser& p, const std::string& keyword, const FileLoc& at) {
    warn_unsupported(p, keyword, at, "the object is left out");
    skip_braced_block(p, keyword);
    PovObject o;
    o.obj.loc = at;
    o.left_out = keyword;
    return o;
}

}  // namespace glint::pov
