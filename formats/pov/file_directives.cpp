// #fopen, #fclose, #read and #write: a scene's own data files. Files a scene writes are kept in
// memory, never on disk (handle_fopen says why).
#include <cstdio>
#include <fstream>
#include <sstream>

#include "formats/pov/token_stream.h"

namespace glint::pov {

// Files a scene writes are kept in memory, never written to disk: a scene file must not be
// able to write anywhere on the user's machine, and scenes that write a file mostly read it back
// in the same parse (caches of computed data), which the memory copy serves.
void TokenStream::handle_fopen(const FileLoc& dloc) {
    std::string handle = read_name("#fopen");
    FileLoc hloc = loc();
    std::string name = parse_string();
    FileLoc sloc = loc();
    const Token& mode = next();
    OpenFile f;
    f.name = std::make_shared<const std::string>(name);
    if (mode.is("read")) {
        auto w = written_files_.find(name);
        std::string text;
        if (w != written_files_.end()) {
            text = w->second;
            f.path = name;
        } else {
            f.path = resolve_file(name, sloc);
            std::ifstream in(f.path, std::ios::binary);
            if (!in)
                throw Error(ErrorKind::MissingFile, sloc, "cannot read the file '" + name + "'");
            std::stringstream ss;
            ss << in.rdbuf();
            text = ss.str();
            f.name = std::make_shared<const std::string>(f.path);
        }
        f.tokens = scan(text, f.name);
    } else if (mode.is("write") || mode.is("append")) {
        if (!warned_writes_) {
            diag.warning(dloc, "#fopen for " + mode.text + ": glint keeps written files in memory "
                               "(a later #fopen ... read of the same name sees them); nothing "
                               "is written to disk");
            warned_writes_ = true;
        }
        f.writing = true;
        f.path = name;
        if (mode.is("write")) written_files_[name].clear();
        else written_files_[name];
    } else {
        fail("expected read, write or append after the file name in #fopen, got " + got(mode));
    }
    Symbol sym;
    sym.value = FileHandle{handle};
    sym.loc = hloc;
    scopes_.front()[handle] = std::move(sym);
    open_files_[handle] = std::move(f);
}

void TokenStream::handle_fclose(const FileLoc& dloc) {
    (void)dloc;
    std::string handle = read_name("#fclose");
    // POV-Ray ignores #fclose of a name that is not an open file (e.g. after the end of the
    // file was read, which closes it).
    if (!open_files_.erase(handle)) return;
    for (size_t i = scopes_.size(); i-- > 0;)
        if (scopes_[i].erase(handle)) break;
}

namespace {

// A float in a data file: an optionally signed number.
bool read_number(const std::vector<Token>& toks, size_t& i, double& out) {
    double sign = 1;
    size_t k = i;
    while (toks[k].is("-") || toks[k].is("+")) {
        if (toks[k].is("-")) sign = -sign;
        ++k;
    }
    if (toks[k].kind != TokKind::Number) return false;
    out = sign * toks[k].number;
    i = k + 1;
    return true;
}

}  // namespace

void TokenStream::handle_read(const FileLoc& dloc) {
    expect("(", "after #read");
    const Token& h = raw();
    if (h.kind != TokKind::Word) fail("expected a file handle after '#read (', got " + got(h));
    std::string handle = h.text;
    auto it = open_files_.find(handle);
    if (it == open_files_.end()) fail("'" + handle + "' is not a file opened with #fopen");
    if (it->second.writing)
        fail("cannot read from '" + handle + "': the file is open for writing");
    OpenFile& f = it->second;
    bool at_end = false;
    for (;;) {
        const Token& t = raw();
        if (t.is_symbol(')')) break;
        if (t.is_symbol(',')) continue;
        std::string var;
        if (t.kind == TokKind::Word) {
            var = t.text;
        } else {
            fail("expected an identifier to read into, got " + got(t));
        }
        if (at_end) continue;
        const auto& toks = f.tokens;
        size_t& i = f.pos;
        FileLoc vloc{f.name, toks[i].line, toks[i].column};
        Value v;
        double d;
        if (toks[i].kind == TokKind::End) {
            at_end = true;
            continue;
        }
        if (read_number(toks, i, d)) {
            v = Num::scalar(d);
        } else if (toks[i].is_symbol('<')) {
            ++i;
            Num n;
            n.terms = 0;
            for (;;) {
                if (toks[i].is_symbol('>')) {
                    ++i;
                    break;
                }
                if (toks[i].is_symbol(',')) {
                    ++i;
                    continue;
                }
                if (n.terms == 5 || !read_number(toks, i, n.v[n.terms]))
                    fail_at(vloc, "bad vector in the data file read by #read");
                ++n.terms;
            }
            if (n.terms < 2) fail_at(vloc, "bad vector in the data file read by #read");
            v = n;
        } else if (toks[i].kind == TokKind::String) {
            v = toks[i++].text;
        } else {
            fail_at(vloc, "expected a float, vector or string in the data file, got " +
                              describe(toks[i]));
        }
        if (toks[i].is_symbol(',')) ++i;
        if (toks[i].kind == TokKind::End) at_end = true;  // as POV-Ray: the last value closes
        // #read assigns where the identifier lives, else declares it globally (POV-Ray's
        // Add_Symbol at the current table; a fresh name in a macro would vanish with it).
        bool done = false;
        for (size_t k = scopes_.size(); k-- > 0 && !done;) {
            auto e = scopes_[k].find(var);
            if (e != scopes_[k].end()) {
                e->second.value = v;
                e->second.loc = dloc;
                done = true;
            }
        }
        if (!done) declare(var, v, dloc, false);
    }
    if (at_end) {
        open_files_.erase(handle);
        for (size_t i = scopes_.size(); i-- > 0;)
            if (scopes_[i].erase(handle)) break;
    }
}

void TokenStream::handle_write(const FileLoc& dloc) {
    (void)dloc;
    expect("(", "after #write");
    const Token& h = raw();
    if (h.kind != TokKind::Word) fail("expected a file handle after '#write (', got " + got(h));
    std::string handle = h.text;
    auto it = open_files_.find(handle);
    if (it == open_files_.end()) fail("'" + handle + "' is not a file opened with #fopen");
    if (!it->second.writing)
        fail("cannot write to '" + handle + "': the file is open for reading");
    std::string path = it->second.path;
    std::string out;
    for (;;) {
        const Token& t = next();
        if (t.is_symbol(')')) break;
        if (t.is_symbol(',')) continue;
        unget();
        Value v = parse_expression_value();
        if (auto str = std::get_if<std::string>(&v)) {
            out += *str;
            continue;
        }
        const Num& n = std::get<Num>(v);
        char buf[64];
        if (n.terms == 1) {
            std::snprintf(buf, sizeof buf, "%g", n.v[0]);
            out += buf;
        } else {
            out += '<';
            for (int k = 0; k < n.terms; ++k) {
                std::snprintf(buf, sizeof buf, k == 0 ? "%g" : ",%g", n.v[k]);
                out += buf;
            }
            out += "> ";
        }
    }
    written_files_[path] += out;
}

}  // namespace glint::pov
