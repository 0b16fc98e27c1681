// The POV-Ray importer's token layer: tokens from a stack of frames (the main file, #include
// files, macro bodies, number lists), with the directives executed as they are met, the way
// POV-Ray's tokenizer does; the symbol table; errors with their locations. The grammar
// (Parser, parser_impl.h) reads tokens through this class and nothing else of it; the
// directives read their values (#if's condition, #declare's right-hand side) through the few
// grammar entry points declared pure virtual below.
//   token_stream.cpp     frames, reading the next token, errors, the symbol table
//   directives.cpp       #declare, #include, #macro and macro calls, #if/#while/#for/#switch/#end
//   file_directives.cpp  #fopen, #fclose, #read, #write
//   scanner.cpp, literal_list.cpp  text -> tokens; mesh2's literal lists read whole
#pragma once

#include <algorithm>
#include <climits>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/log.h"
#include "formats/pov/parser.h"
#include "formats/pov/scanner.h"
#include "formats/pov/value.h"

namespace glint::pov {

// One scope's symbols. A lookup walks every scope from the innermost out, and scenes whose
// macros recurse fifty deep make tens of millions of lookups (tracevines), so the name is
// hashed once (SymbolKey) and each scope first answers from a 64-bit summary of the hashes it
// holds, probing its buckets only when the name may be there.
struct SymbolKey {
    std::string_view name;
    size_t hash;
    explicit SymbolKey(std::string_view n) : name(n), hash(std::hash<std::string_view>{}(n)) {}
};
struct SymbolHash {
    using is_transparent = void;
    size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
    size_t operator()(const std::string& s) const { return (*this)(std::string_view(s)); }
    size_t operator()(const SymbolKey& k) const { return k.hash; }
};
struct SymbolEq {
    using is_transparent = void;
    static std::string_view view(std::string_view s) { return s; }
    static std::string_view view(const SymbolKey& k) { return k.name; }
    template <class A, class B>
    bool operator()(const A& a, const B& b) const { return view(a) == view(b); }
};
class SymbolTable : public std::unordered_map<std::string, Symbol, SymbolHash, SymbolEq> {
public:
    // The one way names enter a scope.
    Symbol& operator[](const std::string& name) {
        const size_t h = SymbolHash{}(name);
        for (int k = 0; k < 2; ++k) summary_[word(h, k)] |= bit(h, k);
        return unordered_map::operator[](name);
    }
    const Symbol* lookup(const SymbolKey& key) const {
        for (int k = 0; k < 2; ++k)
            if (!(summary_[word(key.hash, k)] & bit(key.hash, k))) return nullptr;
        auto it = find(key);
        return it == end() ? nullptr : &it->second;
    }

private:
    // A 256-bit Bloom filter of the names, two bits each from the hash's top 16 bits (the
    // buckets use the low ones); erased names keep their bits. A recursive macro stacks a
    // scope per call, and a global's lookup passes every one of them (tracevines.pov): with a
    // 64-bit, one-bit summary a scope of 20 locals answered "maybe" a quarter of the time.
    static int byte(size_t hash, int k) {
        return static_cast<int>((hash >> (sizeof(size_t) * 8 - 8 * (k + 1))) & 0xff);
    }
    static int word(size_t hash, int k) { return byte(hash, k) >> 6; }
    static uint64_t bit(size_t hash, int k) { return uint64_t{1} << (byte(hash, k) & 63); }
    uint64_t summary_[4] = {0, 0, 0, 0};
};

// A float read where the language wants an integer, truncated toward zero like POV-Ray's
// (int) cast. Casting a value outside int's range (or NaN) is undefined behaviour, so it is
// clamped first: a count or an index of 1e20 then meets the same range check as one of 1e9.
inline int to_int(double v) {
    if (!(v == v)) return 0;
    return static_cast<int>(std::clamp(v, double(INT_MIN), double(INT_MAX)));
}
inline long long to_long_long(double v) {
    if (!(v == v)) return 0;
    constexpr double kMax = 9.2e18;  // below 2^63, which is itself out of range
    return static_cast<long long>(std::clamp(v, -kMax, kMax));
}

// Directives that open a block closed by #end (#if, #ifdef, #ifndef, #while, #for, #switch,
// #macro), and those that start a new statement (which end a #declare's value).
bool opens_block(const std::string& d);
bool starts_statement(const std::string& d);
// Throws where `name`, about to be defined, is one of POV-Ray's reserved words.
void check_not_reserved(const std::string& name, const std::string& expected, const FileLoc& at);
// Thrown for a feature glint does not implement yet. Inside the standard include files a
// declaration that throws this is skipped and its identifier marked unusable.
class Unsupported : public Error {
public:
    Unsupported(FileLoc loc, const std::string& message)
        : Error(ErrorKind::Scene, std::move(loc), message) {}
};

struct SourceFile {
    std::shared_ptr<const std::string> name;
    std::string dir;  // folder of the file, for #include and image_map lookups
    std::vector<Token> tokens;
    bool system = false;  // a standard include (outside the scene's folder)
};

enum class CondKind { If, While, For, Switch };

struct Cond {
    Cond() = default;
    Cond(CondKind k, FileLoc l) : kind(k), loc(std::move(l)) {}
    CondKind kind = CondKind::If;
    FileLoc loc;
    size_t restart = 0;  // While: token index of the condition; For: first body token
    long long iterations = 0;
    std::string var;      // For: loop variable
    double end = 0, step = 1;
    double switch_value = 0;
};

struct Frame {
    Frame() = default;
    Frame(int f, size_t p) : file(f), pos(p) {}
    int file = 0;
    size_t pos = 0;
    bool is_macro = false;
    bool pushed_scope = false;
    std::vector<Cond> conds;
    FileLoc call_loc;  // macro call or #include
    std::string macro_name;  // is_macro: for the "in macro 'Name' called here" note
};

class TokenStream {
public:
    TokenStream(const ParseOptions& options, Diagnostics& diag);
    virtual ~TokenStream() = default;

    // ---- tokens
    const Token& next();   // the next grammar token; directives and macro calls are handled
    const Token& peek() { next(); unget(); return *cur_; }
    void unget() { ungot_ = true; }
    // Looks at the next token without running directives (safe right after a value).
    bool raw_next_is(const char* word) const {
        if (ungot_) return cur_->is(word);
        const Frame& f = frames_.back();
        return files_[f.file]->tokens[f.pos].is(word);
    }
    FileLoc loc() const { return loc_of(cur_file_, *cur_); }  // of the last token
    FileLoc loc_of(int file, const Token& t) const {
        return FileLoc{files_[file]->name, t.line, t.column};
    }
    bool accept(const char* word);        // consumes the token if it is `word`
    void expect(const char* word, const char* context);
    void expect_open(const char* what);   // '{'; remembers where for the matching '}'
    void expect_close(const char* what, const FileLoc& opened);
    void skip_comma() { accept(","); }
    // Meshes are long lists of literal vectors: `<n, n, n>` read straight from the tokens when
    // nothing that follows could make it part of a larger expression; false (nothing read)
    // otherwise.
    bool try_literal_vector(Vec3& out);
    // The NumberList token next in the raw stream, consumed, or null (then nothing changes).
    const Token* take_number_list();
    // A taken NumberList the fast path refused: its tokens come next.
    void give_back_number_list(const Token& list) { expand_number_list(list, cur_file_); }
    // Counts `tokens` read by a fast path against --max-tokens and the checks next() makes
    // (interruption, --max-memory); false, with nothing counted, when they would exceed the
    // token limit (the caller then reads them token by token, which reports it).
    bool count_tokens(long long tokens, const FileLoc& at);
    // The symbol named right after a raw '{' ahead (`sky_sphere { S ...`), or null; an
    // unusable one too (use_symbol then says why its declaration was skipped).
    const Symbol* symbol_after_raw_brace() const;

    // ---- errors
    [[noreturn]] void fail(const std::string& message) const;
    // describe(t), but an undeclared name that cannot be a keyword (POV-Ray keywords are
    // lower case) is called what it most likely is: an unknown identifier.
    std::string got(const Token& t) const;
    [[noreturn]] void fail_at(const FileLoc& loc, const std::string& message) const;
    // A resource limit of ParseOptions was passed: ErrorKind::Render (exit 4), naming the flag.
    [[noreturn]] void fail_limit(const FileLoc& loc, const std::string& message,
                                 const char* flag) const;
    [[noreturn]] void unsupported(const std::string& what) const;
    bool in_system_file() const;
    // True the first time `key` is asked about (one-time warnings).
    bool first_time(const std::string& key) { return warned_once_.insert(key).second; }

    // ---- identifiers
    const Symbol* lookup(const std::string& name) const;
    // Finds `name` or fails (unknown identifier / unusable declaration).
    const Symbol& use_symbol(const Token& t);
    // `local_scope`: the scope a #local writes to, fixed before its value is parsed (a macro
    // called in the value has its own scope on the stack until its #end); default innermost.
    void declare(const std::string& name, Value v, const FileLoc& loc, bool local,
                 size_t local_scope = size_t(-1));
    // `#read` and trace()'s normal: assigns where the name lives, else declares it globally.
    void assign_existing_or_declare(const std::string& name, Value v, const FileLoc& at);

    // ---- files
    // A file the scene names (image_map, ttf, #fopen, obj_file): as given when absolute, else
    // in the current file's folder, the scene's, then options.include_dirs; MissingFile if
    // none has it.
    std::string resolve_file(const std::string& name, const FileLoc& loc) const;
    // The language version set by #version (3.7 until then), and whether any was.
    double version() const { return version_; }
    bool version_set() const { return version_set_; }

    const ParseOptions& options;
    Diagnostics& diag;

    // Below the budget, for what runs under one next() (an image load, a function compile).
    static constexpr std::size_t kParseStackMargin = std::size_t(64) << 20;

protected:
    // What the directives read with the grammar.
    virtual double parse_float() = 0;
    virtual double parse_condition() = 0;  // the full expression grammar, comparisons and all
    virtual std::string parse_string() = 0;
    virtual Value parse_rvalue() = 0;            // #declare's right-hand side
    virtual Value parse_expression_value() = 0;  // #write's items
    virtual void parse_default() = 0;            // #default { ... }
    // A file read (the main file or an #include), for the scene's list of sources.
    virtual void file_read(const std::string& path) = 0;
    // `name` was just declared to `v` (the grammar names functions after it).
    virtual void declared(const std::string& name, const Value& v) = 0;

    // Starts reading the main file or text.
    void open_main_file(const std::string& path);
    void open_main_string(const std::string& text, const std::string& name);
    // An error raised inside a macro body gets a note at the innermost macro's call site.
    void note_macro_call(Error& e) const;
    // The grammar's side of a #declare's value: value_begins() after its first token;
    // while a braced value (object, texture, ...) is read, directives are ordinary content,
    // and only an expression value ends at a following statement directive.
    void value_begins() {
        if (pending_declare_frame_ != size_t(-1)) {
            declare_frame_ = pending_declare_frame_;
            pending_declare_frame_ = size_t(-1);
        }
    }
    struct BracedValue {
        explicit BracedValue(TokenStream& t) : ts(t), saved(t.declare_frame_) {
            t.declare_frame_ = size_t(-1);
        }
        ~BracedValue() { ts.declare_frame_ = saved; }
        TokenStream& ts;
        size_t saved;
    };
    // Frame depth of the #declare whose expression value is being read (-1: none).
    size_t declare_frame_ = size_t(-1);

private:
    int load_file(const std::string& path, bool system, const FileLoc& from);
    int add_source(const std::string& text, const std::string& name, bool system);
    const Token& raw();        // next token of the top frame, no processing
    // A NumberList met by raw(): its body scanned into tokens (cached per token) and read as
    // a frame of its own, as though written in place.
    void expand_number_list(const Token& list, int file);
    std::unordered_map<const Token*, int> number_list_files_;
    bool handle_directive(const Token& d, int file);
    void handle_declare(bool local, const FileLoc& dloc);
    void handle_include(const FileLoc& dloc);
    void handle_macro_def(const FileLoc& dloc);
    void call_macro(const Macro& m, const FileLoc& loc);
    enum class Conditional { If, Ifdef, Ifndef };
    void handle_if(const FileLoc& dloc, Conditional kind);
    void handle_else(const Token& d);
    void handle_end(const FileLoc& dloc);
    void handle_while(const FileLoc& dloc);
    void handle_for(const FileLoc& dloc);
    void handle_switch(const FileLoc& dloc);
    void handle_break(const FileLoc& dloc);
    void handle_message(const std::string& kind, const FileLoc& dloc);
    double parse_cond_paren();
    // Skips raw tokens to the #else/#elseif/#end (etc.) that closes the current level.
    std::string skip_block(bool stop_at_else, bool stop_at_case, const FileLoc& opened,
                           int depth = 0);
    void skip_declaration(size_t frames, size_t pos, size_t scopes, size_t conds);
    std::string read_name(const char* context);
    // Reads `[i][j]...` after an array name; returns the flat index, sets `display` to
    // "A[i][j]".
    size_t parse_array_index(const ArrayValue& a, const std::string& name, std::string& display);
    void warn_deprecated(const std::string& name, const Symbol& s, const FileLoc& at);

    std::vector<std::unique_ptr<SourceFile>> files_;
    std::unordered_map<std::string, int> file_cache_;
    std::vector<Frame> frames_;
    std::vector<SymbolTable> scopes_;
    const Token* cur_ = nullptr;
    int cur_file_ = 0;
    bool ungot_ = false;
    long long token_count_ = 0;
    int macro_depth_ = 0;
    // Set by #declare; becomes declare_frame_ once the value's first token is read (a value
    // may start with a directive, e.g. `#declare S = #if (..) sphere {..} #else .. #end`).
    size_t pending_declare_frame_ = size_t(-1);
    double version_ = 3.7;
    bool version_set_ = false;
    // The grammar is recursive descent, and directives, macro calls and #while bodies can be
    // reached from inside any value, so nesting has no fixed bound in the grammar. The parser
    // runs on a thread of its own with options.max_parse_stack_mib plus kParseStackMargin of
    // stack (parser.cpp), and next() stops the scene once the budget is used: where the stack
    // was when the parser was made is stack_base_.
    std::uintptr_t stack_base_ = 0;
    std::uintptr_t stack_budget_ = 0;
    std::string scene_dir_;
    Token end_token_;
    // An array element read in the grammar becomes a token "A[3]" whose symbol lives here, so
    // every place that takes an identifier takes an element too. Tokens rotate through a ring
    // (callers hold a token only briefly).
    std::unordered_map<std::string, Symbol> element_syms_;
    std::vector<Token> synth_ = std::vector<Token>(256);
    size_t synth_next_ = 0;
    Token fake_end_;  // ends a #declare value at the next statement directive
    std::set<std::string> warned_once_;  // deprecated-once names, one-time warnings
    // #fopen: open files by handle name; written files are kept in memory (see GRAMMAR.md).
    struct OpenFile {
        std::string path;  // as resolved (read) or as written (write/append)
        bool writing = false;
        std::vector<Token> tokens;  // read: the file's tokens
        size_t pos = 0;
        std::shared_ptr<const std::string> name;
    };
    std::map<std::string, OpenFile> open_files_;
    std::map<std::string, std::string> written_files_;  // name -> contents written
    bool warned_writes_ = false;
    void handle_fopen(const FileLoc& dloc);
    void handle_fclose(const FileLoc& dloc);
    void handle_read(const FileLoc& dloc);
    void handle_write(const FileLoc& dloc);
};

}  // namespace glint::pov
