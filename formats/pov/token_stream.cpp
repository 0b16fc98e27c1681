// The token stream under the parser: tokens come from a stack of frames (the main file,
// #include files, macro bodies), and directives are executed as they are met, the way POV-Ray's
// tokenizer does (directives.cpp; the file directives in file_directives.cpp). Here: the
// frames, reading the next token, errors, and the symbol table.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/memory.h"
#include "formats/pov/token_stream.h"
#include "formats/pov/reserved_words.h"

namespace glint::pov {

namespace fs = std::filesystem;

// ---------------------------------------------------------------- shared with the directive files

bool opens_block(const std::string& d) {
    return d == "if" || d == "ifdef" || d == "ifndef" || d == "while" || d == "for" ||
           d == "switch" || d == "macro";
}

// Directives that start a new statement: while a #declare's right-hand side is being read,
// meeting one of these ends the value (see TokenStream::next).
bool starts_statement(const std::string& d) {
    return opens_block(d) || d == "declare" || d == "local" || d == "include" ||
           d == "undef" || d == "default" || d == "version" || d == "debug" ||
           d == "warning" || d == "error";
}

// POV-Ray 3.7 refuses its reserved words (reserved_words.h) as the name a #declare, #local,
// #macro (or its parameters), #for, #undef or #fopen defines.
void check_not_reserved(const std::string& name, const std::string& expected, const FileLoc& at) {
    if (is_reserved_word(name))
        throw Error(ErrorKind::Scene, at,
                    "expected " + expected + ", got the reserved word '" + name +
                        "' (a POV-Ray keyword cannot be redefined)");
}

TokenStream::TokenStream(const ParseOptions& opts, Diagnostics& d) : options(opts), diag(d) {
    stack_base_ = reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0));
    stack_budget_ = std::uintptr_t(std::max(opts.max_parse_stack_mib, 1)) << 20;
    scopes_.emplace_back();  // global
    end_token_.kind = TokKind::End;
    fake_end_.kind = TokKind::Symbol;
    fake_end_.text = ";";
}

int TokenStream::add_source(const std::string& text, const std::string& name, bool system) {
    auto sf = std::make_unique<SourceFile>();
    sf->name = std::make_shared<const std::string>(name);
    fs::path p(name);
    sf->dir = p.has_parent_path() ? p.parent_path().string() : std::string(".");
    sf->system = system;
    sf->tokens = scan(text, sf->name);
    files_.push_back(std::move(sf));
    return static_cast<int>(files_.size()) - 1;
}

int TokenStream::load_file(const std::string& path, bool system, const FileLoc& from) {
    auto it = file_cache_.find(path);
    if (it != file_cache_.end()) return it->second;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(ErrorKind::MissingFile, from, "cannot read '" + path + "'");
    std::stringstream ss;
    ss << in.rdbuf();
    int idx = add_source(ss.str(), path, system);
    file_cache_[path] = idx;
    file_read(path);
    return idx;
}

bool TokenStream::in_system_file() const { return !frames_.empty() && files_[cur_file_]->system; }

void TokenStream::fail(const std::string& message) const { fail_at(loc(), message); }

std::string TokenStream::got(const Token& t) const {
    if (t.kind == TokKind::Word && !lookup(t.text)) {
        for (char c : t.text)
            if (c >= 'A' && c <= 'Z') return "the unknown identifier '" + t.text + "'";
    }
    return describe(t);
}

void TokenStream::fail_at(const FileLoc& l, const std::string& message) const {
    throw Error(ErrorKind::Scene, l, message);
}

void TokenStream::fail_limit(const FileLoc& l, const std::string& message, const char* flag) const {
    throw Error(ErrorKind::Render, l, message + " (limit: " + flag + ")");
}

void TokenStream::unsupported(const std::string& what) const {
    throw Unsupported(loc(), what + " is not supported yet");
}

// ---------------------------------------------------------------- raw tokens

void TokenStream::expand_number_list(const Token& list, int file) {
    auto it = number_list_files_.find(&list);
    int idx;
    if (it != number_list_files_.end()) {
        idx = it->second;
    } else {
        const SourceFile& from = *files_[file];
        auto sf = std::make_unique<SourceFile>();
        sf->name = from.name;
        sf->dir = from.dir;
        sf->system = from.system;
        sf->tokens = scan(list.text, from.name, list.line, list.column, false);
        files_.push_back(std::move(sf));
        idx = static_cast<int>(files_.size()) - 1;
        number_list_files_[&list] = idx;
    }
    frames_.push_back(Frame{idx, 0});
}

const Token* TokenStream::take_number_list() {
    if (ungot_ || frames_.empty()) return nullptr;
    Frame& f = frames_.back();
    const Token& t = files_[f.file]->tokens[f.pos];
    if (t.kind != TokKind::NumberList) return nullptr;
    ++f.pos;
    cur_ = &t;
    cur_file_ = f.file;
    return &t;
}

bool TokenStream::count_tokens(long long tokens, const FileLoc& at) {
    if (tokens > options.max_tokens - token_count_) return false;
    token_count_ += tokens;
    if (options.cancel && options.cancel->load(std::memory_order_relaxed))
        throw Error(ErrorKind::Cancelled, {}, "interrupted while parsing");
    if (options.max_memory_mib > 0 &&
        static_cast<long long>(resident_bytes() >> 20) > options.max_memory_mib)
        fail_limit(at,
                   "the scene holds more than " + std::to_string(options.max_memory_mib) +
                       " MiB of memory while it is parsed",
                   "--max-memory");
    return true;
}

const Token& TokenStream::raw() {
    for (;;) {
        Frame& f = frames_.back();
        const Token& t = files_[f.file]->tokens[f.pos];
        if (t.kind == TokKind::NumberList) {
            // Not taken by a fast path: its tokens, in place.
            ++f.pos;
            expand_number_list(t, f.file);
            continue;
        }
        if (t.kind != TokKind::End) {
            ++f.pos;
            cur_ = &t;
            cur_file_ = f.file;
            return t;
        }
        if (!f.conds.empty()) {
            const Cond& c = f.conds.back();
            fail_at(c.loc, "this directive has no matching #end before the end of the file");
        }
        if (f.is_macro) fail_at(f.call_loc, "the macro called here has no #end");
        if (frames_.size() == 1) {
            cur_ = &t;
            cur_file_ = f.file;
            return t;
        }
        if (f.pushed_scope) scopes_.pop_back();
        frames_.pop_back();
    }
}

const Token& TokenStream::next() {
    // Every level of nesting reads a token, so the stack used so far is checked here.
    const auto here = reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0));
    if (stack_base_ > here && stack_base_ - here > stack_budget_)
        fail_limit(loc(),
                   "the scene nests expressions, objects, blocks or macro calls too deeply "
                   "for the parser (over " + std::to_string(stack_budget_ >> 20) +
                       " MiB of stack): runaway recursion?",
                   "--max-parse-stack");
    for (;;) {
        if (ungot_) {
            ungot_ = false;
            return *cur_;
        }
        // A #declare value ends where the next statement-opening directive begins.
        if (declare_frame_ == frames_.size()) {
            const Frame& f = frames_.back();
            const Token& t = files_[f.file]->tokens[f.pos];
            if (t.kind == TokKind::Directive && starts_statement(t.text)) {
                fake_end_.line = t.line;
                fake_end_.column = t.column;
                cur_ = &fake_end_;
                cur_file_ = f.file;
                return fake_end_;
            }
        }
        const Token& t = raw();
        if (++token_count_ > options.max_tokens)
            fail("the scene exceeds the token limit (" + std::to_string(options.max_tokens) + ")");
        if ((token_count_ & 0xfff) == 0 && options.cancel &&
            options.cancel->load(std::memory_order_relaxed))
            throw Error(ErrorKind::Cancelled, {}, "interrupted while parsing");
        if ((token_count_ & 0x3fff) == 0 && options.max_memory_mib > 0 &&
            static_cast<long long>(resident_bytes() >> 20) > options.max_memory_mib)
            fail_limit(loc_of(cur_file_, t),
                       "the scene holds more than " + std::to_string(options.max_memory_mib) +
                           " MiB of memory while it is parsed",
                       "--max-memory");
        if (t.kind == TokKind::Directive) {
            handle_directive(t, cur_file_);
            continue;
        }
        if (t.kind == TokKind::Word) {
            const Symbol* s = lookup(t.text);
            if (s && !s->unusable) {
                if (auto m = std::get_if<std::shared_ptr<const Macro>>(&s->value)) {
                    auto keep = *m;
                    call_macro(*keep, loc());
                    continue;
                }
                auto arr = std::get_if<std::shared_ptr<ArrayValue>>(&s->value);
                if (arr && raw_next_is("[")) {
                    auto keep = *arr;
                    Token at = t;
                    FileLoc aloc = loc();
                    int file = cur_file_;
                    std::string display;
                    size_t idx = parse_array_index(*keep, at.text, display);
                    // An element that is an array itself (POV-Ray 3.7's arrays of arrays,
                    // `array[2] { array[2] {..}, .. }`) is indexed on: A[i][j].
                    for (;;) {
                        if (!keep->items[idx])
                            fail_at(aloc, "array element " + display + " is not initialized");
                        auto inner =
                            std::get_if<std::shared_ptr<ArrayValue>>(keep->items[idx].get());
                        if (!inner || !raw_next_is("[")) break;
                        keep = *inner;
                        const std::string outer = display;
                        idx = parse_array_index(*keep, outer, display);
                    }
                    Symbol& es = element_syms_[display];
                    es.value = *keep->items[idx];
                    es.loc = aloc;
                    Token& st = synth_[synth_next_++ % synth_.size()];
                    st = at;
                    st.text = display;
                    cur_ = &st;
                    cur_file_ = file;
                    return st;
                }
            }
        }
        return t;
    }
}

bool TokenStream::accept(const char* word) {
    const Token& t = next();
    if (t.is(word)) return true;
    unget();
    return false;
}

void TokenStream::expect(const char* word, const char* context) {
    const Token& t = next();
    if (!t.is(word))
        fail(std::string("expected '") + word + "' " + context + ", got " + got(t));
}

void TokenStream::expect_open(const char* what) {
    const Token& t = next();
    if (!t.is_symbol('{'))
        fail(std::string("expected '{' after '") + what + "', got " + got(t));
}

void TokenStream::expect_close(const char* what, const FileLoc& opened) {
    const Token& t = next();
    if (!t.is_symbol('}'))
        fail(std::string("expected '}' to close the ") + what + " opened at " +
             std::to_string(opened.line) + ":" + std::to_string(opened.column) + ", got " +
             got(t));
}

// Meshes are long lists of literal vectors; reading `<n, n, n>` straight from the token array
// (when nothing can follow that would make it part of a larger expression) keeps a 100k-face
// mesh2 fast. Anything else takes the general path.
bool TokenStream::try_literal_vector(Vec3& out) {
    if (ungot_ || frames_.empty()) return false;
    Frame& f = frames_.back();
    const auto& t = files_[f.file]->tokens;
    size_t i = f.pos;
    if (!t[i].is_symbol('<')) return false;
    ++i;
    double v[3];
    for (int k = 0; k < 3; ++k) {
        double sign = 1;
        if (t[i].is_symbol('-')) {
            sign = -1;
            ++i;
        }
        if (t[i].kind != TokKind::Number) return false;
        v[k] = sign * t[i].number;
        ++i;
        if (k < 2) {
            if (!t[i].is_symbol(',')) return false;
            ++i;
        }
    }
    if (!t[i].is_symbol('>')) return false;
    const Token& n = t[i + 1];
    if (n.kind == TokKind::Symbol && !(n.is_symbol(',') || n.is_symbol('}') || n.is_symbol(')') ||
                                       n.is_symbol(']') || n.is_symbol(';')))
        return false;
    token_count_ += static_cast<long long>(i + 1 - f.pos);
    f.pos = i + 1;
    cur_ = &t[i];
    cur_file_ = f.file;
    out = Vec3(v[0], v[1], v[2]);
    return true;
}


const Symbol* TokenStream::symbol_after_raw_brace() const {
    if (ungot_ || frames_.empty()) return nullptr;
    const Frame& f = frames_.back();
    const auto& toks = files_[f.file]->tokens;
    if (!toks[f.pos].is_symbol('{') || toks[f.pos + 1].kind != TokKind::Word) return nullptr;
    return lookup(toks[f.pos + 1].text);
}

void TokenStream::open_main_file(const std::string& path) {
    fs::path p(path);
    scene_dir_ = p.has_parent_path() ? p.parent_path().string() : std::string(".");
    int idx = load_file(path, false, FileLoc{});
    frames_.push_back(Frame{idx, 0});
    cur_file_ = idx;
}

void TokenStream::open_main_string(const std::string& text, const std::string& name) {
    fs::path p(name);
    scene_dir_ = p.has_parent_path() ? p.parent_path().string() : std::string(".");
    int idx = add_source(text, name, false);
    file_read(name);
    frames_.push_back(Frame{idx, 0});
    cur_file_ = idx;
}

void TokenStream::note_macro_call(Error& e) const {
    // The frames are still those of the moment of the throw. An error that already has a
    // note (raised deeper, e.g. a "declared here") keeps it: the innermost note is the more
    // specific one.
    if (!e.note().empty()) return;
    for (size_t k = frames_.size(); k-- > 0;) {
        const Frame& f = frames_[k];
        if (!f.is_macro) continue;
        const FileLoc& c = f.call_loc;
        // "the macro called here has no #end" already points at the call.
        bool same = c.filename() == e.loc().filename() && c.line == e.loc().line &&
                    c.column == e.loc().column;
        if (!same) e.with_note(c, "in macro '" + f.macro_name + "' called here");
        return;
    }
}

std::string TokenStream::resolve_file(const std::string& name, const FileLoc& l) const {
    std::error_code ec;  // a name the system refuses (too long, ...) is "cannot find" too
    if (fs::path(name).is_absolute()) {
        if (fs::is_regular_file(name, ec)) return name;
    } else {
        std::vector<std::string> dirs = {files_[cur_file_]->dir, scene_dir_};
        for (const auto& d : options.include_dirs) dirs.push_back(d);
        for (const auto& d : dirs) {
            fs::path p = fs::path(d) / name;
            if (fs::is_regular_file(p, ec)) return p.lexically_normal().string();
        }
    }
    throw Error(ErrorKind::MissingFile, l, "cannot find the file '" + name + "'");
}

// ---------------------------------------------------------------- identifiers

size_t TokenStream::parse_array_index(const ArrayValue& a, const std::string& name,
                                      std::string& display) {
    display = name;
    size_t flat = 0;
    for (size_t d = 0; d < a.sizes.size(); ++d) {
        expect("[", ("to index the array '" + name + "'").c_str());
        peek();
        FileLoc l = loc();
        double v = parse_float();
        expect("]", "after the array index");
        int i = to_int(v);
        if (i < 0 || i >= a.sizes[d])
            fail_at(l, "index " + std::to_string(i) + " is outside the array '" + name + "' (size " +
                           std::to_string(a.sizes[d]) + ")");
        display += '[';
        display += std::to_string(i);
        display += ']';
        flat = flat * a.sizes[d] + i;
    }
    return flat;
}

const Symbol* TokenStream::lookup(const std::string& name) const {
    if (name.find('[') != std::string::npos) {
        auto it = element_syms_.find(name);
        return it == element_syms_.end() ? nullptr : &it->second;
    }
    const SymbolKey key(name);
    for (size_t i = scopes_.size(); i-- > 0;)
        if (const Symbol* s = scopes_[i].lookup(key)) return s;
    return nullptr;
}

const Symbol& TokenStream::use_symbol(const Token& t) {
    const Symbol* s = lookup(t.text);
    if (!s) fail("unknown identifier '" + t.text + "'");
    if (s->unusable) {
        // Unsupported, so that a standard include's declaration built on a skipped one is
        // skipped in turn instead of failing the scene.
        Unsupported e(loc(), "'" + t.text + "' cannot be used: its declaration was skipped (" +
                                 s->unusable_reason + ")");
        e.with_note(s->loc, "the unsupported feature in the declaration of '" + t.text + "'");
        throw e;
    }
    if (!s->deprecated.empty()) warn_deprecated(t.text, *s, loc());
    return *s;
}

void TokenStream::warn_deprecated(const std::string& name, const Symbol& s, const FileLoc& at) {
    if (s.deprecated_once && !warned_once_.insert(name).second) return;
    diag.warning(at, s.deprecated);
}

void TokenStream::declare(const std::string& name, Value v, const FileLoc& l, bool local,
                     size_t local_scope) {
    if (local_scope >= scopes_.size()) local_scope = scopes_.size() - 1;
    {
        // A macro parameter passed by reference: #declare, and #local in the macro's own
        // scope, write through to the caller's variable (POV-Ray assigns through the
        // parameter; tracevines.pov's Grow moves its caller's root with `#local Start`).
        SymbolTable& own = local ? scopes_[local_scope] : scopes_.back();
        auto it = own.find(name);
        if (it != own.end() && !it->second.ref_name.empty()) {
            std::string ref = it->second.ref_name;
            size_t k = it->second.ref_scope;
            it->second.value = v;  // the parameter sees the new value too
            if (k < scopes_.size()) {
                // Through a chain of parameters (a macro passing its parameter on), each
                // link keeps the value, down to the variable itself.
                for (int hops = 0; hops < 4096; ++hops) {
                    Symbol& target = scopes_[k][ref];
                    target.value = v;
                    target.loc = l;
                    target.unusable = false;
                    if (target.ref_name.empty() || target.ref_scope >= scopes_.size() ||
                        target.ref_scope >= k)
                        break;
                    ref = target.ref_name;
                    k = target.ref_scope;
                }
                return;
            }
        }
    }
    if (!local) {
        // POV-Ray's #declare of a name that exists modifies it where it is found, local
        // scopes included (shapes.inc's HF macros count `#local K` up with `#declare K`).
        for (size_t k = scopes_.size(); k-- > 1;) {
            auto it = scopes_[k].find(name);
            if (it == scopes_[k].end() || !it->second.ref_name.empty()) continue;
            it->second.value = std::move(v);
            it->second.loc = l;
            it->second.unusable = false;
            it->second.unusable_reason.clear();
            return;
        }
    }
    auto& scope = local ? scopes_[local_scope] : scopes_.front();
    Symbol& s = scope[name];
    s.value = std::move(v);
    s.loc = l;
    s.unusable = false;
    s.unusable_reason.clear();
}

std::string TokenStream::read_name(const char* context) {
    const Token& t = raw();
    if (t.kind != TokKind::Word)
        fail(std::string("expected an identifier after ") + context + ", got " + got(t));
    if (std::string_view(context) != "#declare" && std::string_view(context) != "#local" &&
        std::string_view(context) != "#ifdef")  // #declare deprecated: see handle_declare
        check_not_reserved(t.text, std::string("an identifier after ") + context, loc());
    return t.text;
}


void TokenStream::assign_existing_or_declare(const std::string& name, Value v, const FileLoc& at) {
    for (size_t k = scopes_.size(); k-- > 0;) {
        auto e = scopes_[k].find(name);
        if (e != scopes_[k].end()) {
            e->second.value = std::move(v);
            e->second.loc = at;
            return;
        }
    }
    declare(name, std::move(v), at, false);
}

}  // namespace glint::pov
