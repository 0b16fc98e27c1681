// The directives that steer the token stream (token_stream.cpp), executed as they are met: a
// false #if skips raw tokens to its #else/#end, #while jumps back to its condition at #end, a
// macro call pushes a frame at the macro body and #end pops it; #declare, #include, #macro.
#include <cmath>
#include <filesystem>

#include "formats/pov/token_stream.h"

namespace glint::pov {

namespace fs = std::filesystem;

bool TokenStream::handle_directive(const Token& d, int file) {
    FileLoc dloc = loc_of(file, d);
    // A view: each comparison below checks the length first (a std::string against a literal
    // costs a strlen and a memcmp each, a tenth of a bare #while iteration's time).
    const std::string_view k = d.text;
    if (k == "declare" || k == "local") {
        handle_declare(k == "local", dloc);
    } else if (k == "include") {
        handle_include(dloc);
    } else if (k == "if") {
        handle_if(dloc, Conditional::If);
    } else if (k == "ifdef") {
        handle_if(dloc, Conditional::Ifdef);
    } else if (k == "ifndef") {
        handle_if(dloc, Conditional::Ifndef);
    } else if (k == "else" || k == "elseif") {
        handle_else(d);
    } else if (k == "end") {
        handle_end(dloc);
    } else if (k == "while") {
        handle_while(dloc);
    } else if (k == "for") {
        handle_for(dloc);
    } else if (k == "switch") {
        handle_switch(dloc);
    } else if (k == "case") {
        // Reached by falling through from the previous case: POV-Ray runs on.
        parse_cond_paren();
    } else if (k == "range") {
        expect("(", "after #range");
        parse_float();
        skip_comma();
        parse_float();
        expect(")", "to close #range");
    } else if (k == "break") {
        handle_break(dloc);
    } else if (k == "macro") {
        handle_macro_def(dloc);
    } else if (k == "undef") {
        std::string name = read_name("#undef");
        for (size_t i = scopes_.size(); i-- > 0;)
            if (scopes_[i].erase(name)) break;
    } else if (k == "debug" || k == "warning" || k == "error") {
        handle_message(d.text, dloc);
    } else if (k == "version") {
        size_t saved = declare_frame_;
        declare_frame_ = frames_.size();
        double v = parse_float();
        accept(";");
        declare_frame_ = saved;
        version_ = v;
        version_set_ = true;
    } else if (k == "default") {
        parse_default();
    } else if (k == "fopen") {
        handle_fopen(dloc);
    } else if (k == "fclose") {
        handle_fclose(dloc);
    } else if (k == "read") {
        handle_read(dloc);
    } else if (k == "write") {
        handle_write(dloc);
    } else if (k == "statistics" || k == "render") {
        // Messages to POV-Ray's statistics/render streams: shown like #debug.
        handle_message("debug", dloc);
    } else {
        fail_at(dloc, "unknown directive '#" + d.text + "'");
    }
    return true;
}

void TokenStream::handle_declare(bool local, const FileLoc& dloc) {
    std::string name = read_name(local ? "#local" : "#declare");
    std::string deprecated;
    bool deprecated_once = false;
    if (name == "deprecated") {
        // #declare deprecated [once] "message" Name = ...: POV-Ray warns when Name is used
        // (once: only the first time).
        Frame& f = frames_.back();
        const auto& toks = files_[f.file]->tokens;
        if (toks[f.pos].is("once")) {
            ++f.pos;
            deprecated_once = true;
        }
        if (toks[f.pos].kind == TokKind::String) deprecated = toks[f.pos++].text;
        name = read_name("#declare deprecated");
        if (deprecated.empty()) deprecated = "Identifier '" + name + "' was declared deprecated.";
    }
    FileLoc nloc = loc();
    if (deprecated.empty())
        check_not_reserved(name, std::string("an identifier after ") + (local ? "#local" : "#declare"),
                           nloc);
    if (raw_next_is("[")) {
        // #declare A[i] = value
        const Symbol* s = lookup(name);
        auto arr = s ? std::get_if<std::shared_ptr<ArrayValue>>(&s->value) : nullptr;
        if (!arr) fail("'" + name + "' is not an array");
        auto keep = *arr;
        std::string display;
        size_t idx = parse_array_index(*keep, name, display);
        // #declare A[i][j] = value, where A[i] is an array of its own.
        while (keep->items[idx] && raw_next_is("[")) {
            auto inner = std::get_if<std::shared_ptr<ArrayValue>>(keep->items[idx].get());
            if (!inner) break;
            keep = *inner;
            const std::string outer = display;
            idx = parse_array_index(*keep, outer, display);
        }
        expect("=", ("after '" + display + "'").c_str());
        size_t saved = declare_frame_;
        declare_frame_ = size_t(-1);
        pending_declare_frame_ = frames_.size();
        Value v = parse_rvalue();
        declare_frame_ = saved;
        pending_declare_frame_ = size_t(-1);
        keep->items[idx] = std::make_shared<Value>(std::move(v));
        accept(";");
        return;
    }
    const Token& eq = next();
    if (!eq.is_symbol('=')) fail("expected '=' after '" + name + "', got " + got(eq));
    Frame& f = frames_.back();
    size_t nframes = frames_.size(), start = f.pos, nscopes = scopes_.size();
    size_t nconds = f.conds.size();
    bool tolerant = files_[f.file]->system && !f.is_macro;
    size_t saved = declare_frame_;
    declare_frame_ = size_t(-1);
    pending_declare_frame_ = frames_.size();
    try {
        Value v = parse_rvalue();
        declare_frame_ = saved;
        pending_declare_frame_ = size_t(-1);
        declared(name, v);
        declare(name, std::move(v), nloc, local, nscopes - 1);
        if (!deprecated.empty()) {
            auto& scope = local ? scopes_[std::min(nscopes, scopes_.size()) - 1] : scopes_.front();
            auto it = scope.find(name);
            if (it != scope.end()) {
                it->second.deprecated = deprecated;
                it->second.deprecated_once = deprecated_once;
            }
        }
    } catch (const Unsupported& e) {
        declare_frame_ = saved;
        pending_declare_frame_ = size_t(-1);
        if (!tolerant) throw;
        // A standard include may declare things glint cannot read yet; the scene fails only
        // if it uses them (POV-Ray's includes are large, most scenes use a few names).
        skip_declaration(nframes, start, nscopes, nconds);
        Symbol s;
        s.value = Num::scalar(0);
        s.loc = e.loc();
        s.unusable = true;
        s.unusable_reason = e.what();
        (local ? scopes_.back() : scopes_.front())[name] = std::move(s);
        diag.warning(nloc, "skipped the declaration of '" + name + "': " + e.what());
    }
    (void)dloc;
    accept(";");
}

void TokenStream::skip_declaration(size_t nframes, size_t start, size_t nscopes, size_t nconds) {
    while (frames_.size() > nframes) frames_.pop_back();
    while (scopes_.size() > nscopes) scopes_.pop_back();
    Frame& f = frames_.back();
    f.conds.resize(nconds);
    f.pos = start;
    ungot_ = false;
    const auto& toks = files_[f.file]->tokens;
    int depth = 0;
    bool opened = false;
    while (toks[f.pos].kind != TokKind::End) {
        const Token& t = toks[f.pos];
        if (depth == 0 && t.kind == TokKind::Directive) return;
        ++f.pos;
        if (t.kind != TokKind::Symbol) continue;
        char c = t.text[0];
        if (t.text.size() != 1) continue;
        if (c == '{' || c == '(' || c == '[') {
            ++depth;
            opened = opened || c == '{';
        } else if (c == '}' || c == ')' || c == ']') {
            --depth;
            if (depth <= 0 && c == '}' && opened) {
                // Layered textures: `texture {..} texture {..}` is one declaration.
                if (toks[f.pos].is("texture") && toks[f.pos + 1].is_symbol('{')) {
                    depth = 0;
                    continue;
                }
                return;
            }
        } else if (c == ';' && depth == 0) {
            --f.pos;  // leave the ';' for the caller
            return;
        }
    }
}

void TokenStream::handle_include(const FileLoc& dloc) {
    std::string name = parse_string();
    FileLoc sloc = loc();
    int non_macro = 0;
    for (const auto& f : frames_) non_macro += f.is_macro ? 0 : 1;
    if (non_macro >= options.max_include_depth)
        fail_limit(dloc,
                   "#include nested deeper than " + std::to_string(options.max_include_depth) +
                       " files",
                   "--max-include-depth");
    std::vector<std::pair<std::string, bool>> dirs;
    dirs.push_back({files_[cur_file_]->dir, files_[cur_file_]->system});
    dirs.push_back({scene_dir_, false});
    for (const auto& d : options.include_dirs) dirs.push_back({d, true});
    std::string found;
    bool system = false;
    // A folder with the include's name is remembered so the error can say so: "cannot find"
    // would send the user looking for a file that is, in a sense, right there.
    bool saw_folder = false;
    // error_code overloads: a name the system refuses (too long, ...) is "cannot find", not a
    // std::filesystem_error escaping the parser.
    std::error_code ec;
    if (fs::path(name).is_absolute()) {
        if (fs::is_regular_file(name, ec)) found = name;
        saw_folder = fs::is_directory(name, ec);
    } else {
        for (const auto& [dir, sys] : dirs) {
            fs::path p = fs::path(dir) / name;
            saw_folder = saw_folder || fs::is_directory(p, ec);
            if (fs::is_regular_file(p, ec)) {
                found = p.lexically_normal().string();
                // A folder the user lists that is the scene's own folder is not "system".
                system = sys &&
                         fs::weakly_canonical(dir, ec) != fs::weakly_canonical(scene_dir_, ec);
                break;
            }
        }
    }
    if (found.empty() && saw_folder)
        throw Error(ErrorKind::MissingFile, sloc, "'" + name + "' is a folder, not a file");
    if (found.empty())
        throw Error(ErrorKind::MissingFile, sloc, "cannot find include file '" + name + "'");
    int idx = load_file(found, system, sloc);
    files_[idx]->system = files_[idx]->system || system;
    Frame f;
    f.file = idx;
    f.pos = 0;
    f.pushed_scope = true;
    f.call_loc = dloc;
    scopes_.emplace_back();
    frames_.push_back(std::move(f));
}

void TokenStream::handle_macro_def(const FileLoc& dloc) {
    auto m = std::make_shared<Macro>();
    m->name = read_name("#macro");
    m->loc = dloc;
    const Token& p = raw();
    if (!p.is_symbol('(')) fail("expected '(' after the macro name, got " + got(p));
    for (;;) {
        const Token& t = raw();
        if (t.is_symbol(')')) break;
        if (t.is_symbol(',')) continue;
        if (t.kind != TokKind::Word) fail("expected a parameter name, got " + got(t));
        if (t.text != "optional") check_not_reserved(t.text, "a parameter name", loc());
        bool opt = false;
        if (t.text == "optional") {
            // POV-Ray 3.8's optional parameters: the argument may be left out (empty or
            // missing at the end); the parameter is then undefined in the body.
            const Token& n = raw();
            if (n.kind != TokKind::Word)
                fail("expected a parameter name after 'optional', got " + got(n));
            check_not_reserved(n.text, "a parameter name", loc());
            opt = true;
            m->params.push_back(n.text);
        } else {
            m->params.push_back(t.text);
        }
        m->optional.push_back(opt);
    }
    m->file = frames_.back().file;
    m->body = frames_.back().pos;
    skip_block(false, false, dloc, 0);
    Symbol& s = scopes_.front()[m->name];
    s.value = std::shared_ptr<const Macro>(m);
    s.loc = dloc;
    s.unusable = false;
}

void TokenStream::call_macro(const Macro& m, const FileLoc& cloc) {
    if (macro_depth_ >= options.max_macro_depth)
        fail_limit(cloc,
                   "macro calls nested deeper than " + std::to_string(options.max_macro_depth) +
                      ": runaway recursion?",
                   "--max-recursion");
    expect("(", ("after the macro name '" + m.name + "'").c_str());
    SymbolTable args;
    size_t saved = declare_frame_, saved_pending = pending_declare_frame_;
    declare_frame_ = size_t(-1);
    pending_declare_frame_ = size_t(-1);
    for (size_t i = 0; i < m.params.size(); ++i) {
        bool opt = i < m.optional.size() && m.optional[i];
        if (raw_next_is(")") && (i > 0 || !opt)) {
            if (opt) continue;  // left out at the end: undefined in the body
            size_t need = 0;
            for (size_t k = 0; k < m.params.size(); ++k)
                need += (k < m.optional.size() && m.optional[k]) ? 0 : 1;
            next();
            fail("macro '" + m.name + "' expects " + std::to_string(need) +
                 " argument(s), but only " + std::to_string(i) + " were given");
        }
        if (i > 0) accept(",");  // POV-Ray's Parse_Comma: the comma is optional
        if (opt && (raw_next_is(",") || raw_next_is(")"))) continue;  // left out: undefined
        Symbol s;
        {
            // A lone identifier argument is passed by reference (POV-Ray semantics).
            const Frame& f = frames_.back();
            const auto& toks = files_[f.file]->tokens;
            const Token& a = toks[f.pos];
            if (!ungot_ && a.kind == TokKind::Word &&
                (toks[f.pos + 1].is_symbol(',') || toks[f.pos + 1].is_symbol(')'))) {
                for (size_t k = scopes_.size(); k-- > 0;) {
                    if (scopes_[k].count(a.text)) {
                        s.ref_name = a.text;
                        s.ref_scope = k;
                        break;
                    }
                }
            }
        }
        s.value = parse_rvalue();
        s.loc = loc();
        args[m.params[i]] = std::move(s);
    }
    declare_frame_ = saved;
    pending_declare_frame_ = saved_pending;
    const Token& t = next();
    if (!t.is_symbol(')'))
        fail("expected ')' after the " + std::to_string(m.params.size()) + " argument(s) of macro '" +
             m.name + "', got " + got(t));
    scopes_.push_back(std::move(args));
    Frame f;
    f.file = m.file;
    f.pos = m.body;
    f.is_macro = true;
    f.pushed_scope = true;
    f.call_loc = cloc;
    f.macro_name = m.name;
    frames_.push_back(std::move(f));
    ++macro_depth_;
}

double TokenStream::parse_cond_paren() {
    expect("(", "before the condition");
    double v = parse_condition();
    expect(")", "after the condition");
    return v;
}

std::string TokenStream::skip_block(bool stop_at_else, bool stop_at_case, const FileLoc& opened,
                               int depth) {
    Frame& f = frames_.back();
    const auto& toks = files_[f.file]->tokens;
    for (;;) {
        const Token& t = toks[f.pos];
        if (t.kind == TokKind::End)
            fail_at(opened, "this directive has no matching #end before the end of the file");
        ++f.pos;
        if (t.kind != TokKind::Directive) continue;
        const std::string& d = t.text;
        if (opens_block(d)) {
            ++depth;
        } else if (d == "end") {
            if (depth == 0) return d;
            --depth;
        } else if (depth == 0) {
            if (stop_at_else && (d == "else" || d == "elseif")) return d;
            if (stop_at_case && (d == "case" || d == "range" || d == "else")) return d;
        }
    }
}

void TokenStream::handle_if(const FileLoc& dloc, Conditional kind) {
    bool c;
    if (kind == Conditional::If) {
        c = parse_cond_paren() != 0;
    } else {
        const Token& p = raw();
        if (!p.is_symbol('(')) fail("expected '(' after #ifdef/#ifndef, got " + got(p));
        std::string name = read_name("#ifdef");
        const Symbol* s = lookup(name);
        auto arr = s ? std::get_if<std::shared_ptr<ArrayValue>>(&s->value) : nullptr;
        if (arr && raw_next_is("[")) {
            auto keep = *arr;
            std::string display;
            size_t idx = parse_array_index(*keep, name, display);
            expect(")", "after the array element");
            c = keep->items[idx] != nullptr;
        } else {
            const Token& q = raw();
            if (!q.is_symbol(')')) fail("expected ')' after the identifier, got " + got(q));
            c = s != nullptr;
        }
        if (kind == Conditional::Ifndef) c = !c;
    }
    for (;;) {
        if (c) {
            frames_.back().conds.push_back(Cond{CondKind::If, dloc});
            return;
        }
        std::string s = skip_block(true, false, dloc);
        if (s == "end") return;
        if (s == "else") {
            frames_.back().conds.push_back(Cond{CondKind::If, dloc});
            return;
        }
        c = parse_cond_paren() != 0;  // #elseif
    }
}

void TokenStream::handle_else(const Token& d) {
    auto& conds = frames_.back().conds;
    FileLoc dloc = loc();
    if (!conds.empty() && conds.back().kind == CondKind::Switch && d.text == "else") return;
    if (conds.empty() || conds.back().kind != CondKind::If)
        fail_at(dloc, "#" + d.text + " without a matching #if");
    FileLoc opened = conds.back().loc;
    skip_block(false, false, opened);
    frames_.back().conds.pop_back();
}

void TokenStream::handle_end(const FileLoc& dloc) {
    Frame& f = frames_.back();
    if (f.conds.empty()) {
        if (!f.is_macro) fail_at(dloc, "#end without a matching #if, #while, #for, #switch or #macro");
        if (f.pushed_scope) scopes_.pop_back();
        frames_.pop_back();
        --macro_depth_;
        return;
    }
    Cond& c = f.conds.back();
    switch (c.kind) {
        case CondKind::If:
        case CondKind::Switch:
            f.conds.pop_back();
            return;
        case CondKind::While: {
            if (++c.iterations >= options.max_loop_iterations)
                fail_limit(c.loc,
                           "#while loop ran more than " +
                               std::to_string(options.max_loop_iterations) + " iterations",
                           "--max-loop-iterations");
            size_t after = f.pos;
            f.pos = c.restart;
            if (parse_cond_paren() == 0) {
                frames_.back().conds.pop_back();
                frames_.back().pos = after;
            }
            return;
        }
        case CondKind::For: {
            if (++c.iterations >= options.max_loop_iterations)
                fail_limit(c.loc,
                           "#for loop ran more than " +
                               std::to_string(options.max_loop_iterations) + " iterations",
                           "--max-loop-iterations");
            const Symbol* s = lookup(c.var);
            const Num* n = s ? std::get_if<Num>(&s->value) : nullptr;
            if (!n) fail_at(c.loc, "the #for loop variable '" + c.var + "' is no longer a float");
            double v = n->v[0] + c.step;
            declare(c.var, Num::scalar(v), c.loc, true);
            bool more = c.step > 0 ? v <= c.end + 1e-10 : v >= c.end - 1e-10;
            if (more)
                f.pos = c.restart;
            else
                f.conds.pop_back();
            return;
        }
    }
}

void TokenStream::handle_while(const FileLoc& dloc) {
    size_t restart = frames_.back().pos;
    if (parse_cond_paren() != 0) {
        Cond c{CondKind::While, dloc};
        c.restart = restart;
        frames_.back().conds.push_back(c);
    } else {
        skip_block(false, false, dloc);
    }
}

void TokenStream::handle_for(const FileLoc& dloc) {
    expect("(", "after #for");
    const Token& t = next();
    if (t.kind != TokKind::Word) fail("expected the loop variable after '#for (', got " + got(t));
    check_not_reserved(t.text, "the loop variable after '#for ('", loc());
    std::string var = t.text;
    expect(",", "after the #for variable");
    double start = parse_float();
    expect(",", "after the #for start value");
    double end = parse_float();
    double step = 1;
    if (accept(",")) step = parse_float();
    expect(")", "to close #for");
    if (step == 0) fail_at(dloc, "#for step must not be zero");
    declare(var, Num::scalar(start), dloc, true);
    bool run = step > 0 ? start <= end + 1e-10 : start >= end - 1e-10;
    if (!run) {
        skip_block(false, false, dloc);
        return;
    }
    Cond c{CondKind::For, dloc};
    c.restart = frames_.back().pos;
    c.var = var;
    c.end = end;
    c.step = step;
    frames_.back().conds.push_back(c);
}

void TokenStream::handle_switch(const FileLoc& dloc) {
    double v = parse_cond_paren();
    Cond c{CondKind::Switch, dloc};
    c.switch_value = v;
    frames_.back().conds.push_back(c);
    for (;;) {
        std::string s = skip_block(false, true, dloc);
        if (s == "end") {
            frames_.back().conds.pop_back();
            return;
        }
        if (s == "else") return;
        if (s == "case") {
            // POV-Ray compares with a small tolerance (EPSILON in tokenize.cpp).
            if (std::fabs(parse_cond_paren() - v) < 1e-10) return;
        } else {
            expect("(", "after #range");
            double lo = parse_float();  // POV-Ray's Parse_Float_Param2: no comparisons
            skip_comma();
            double hi = parse_float();
            expect(")", "to close #range");
            if (v >= lo && v <= hi) return;
        }
    }
}

void TokenStream::handle_break(const FileLoc& dloc) {
    auto& conds = frames_.back().conds;
    int above = 0;
    for (size_t i = conds.size(); i-- > 0; ++above) {
        if (conds[i].kind == CondKind::Switch) {
            FileLoc opened = conds[i].loc;
            conds.resize(i + 1);
            skip_block(false, false, opened, above);
            frames_.back().conds.pop_back();
            return;
        }
    }
    fail_at(dloc, "#break outside a #switch");
}

void TokenStream::handle_message(const std::string& kind, const FileLoc& dloc) {
    std::string text = parse_string();
    if (kind == "error") throw Error(ErrorKind::Scene, dloc, "#error: " + text);
    if (kind == "warning")
        diag.warning(dloc, text);
    else
        diag.info(text);
}

}  // namespace glint::pov
