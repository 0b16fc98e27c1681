// The first stage of the POV-Ray importer: characters -> tokens with line/column. Comments
// (// and nested /* */) vanish here; `#word` becomes one Directive token so the directive layer
// (token_stream.cpp, directives.cpp) can recognise it without looking at whitespace.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/error.h"

namespace glint::pov {

enum class TokKind : unsigned char {
    Word,       // keyword or identifier: text
    Number,     // number
    String,     // text (escapes resolved)
    Symbol,     // text: one of { } ( ) [ ] < > , ; = + - * / . ? : ! & | <= >= !=
    Directive,  // text: the word after '#'
    // text: the body of a mesh2 list (vertex_vectors { ... } and the like) that holds nothing
    // but numbers, '<', '>', ',', '+', '-' and white space, read as a whole by the parser's
    // fast path (literal_list.h) or scanned into tokens where it is met otherwise. line and
    // column: where the body begins. A million-triangle mesh is one token instead of
    // sixteen million.
    NumberList,
    End,        // end of the file
};

struct Token {
    TokKind kind = TokKind::End;
    std::string text;
    double number = 0;
    int line = 0;
    int column = 0;

    bool is(const char* s) const {
        // The parser asks this of nearly every token, against many words in turn: the first
        // character settles most of them without a strlen and memcmp (half of a bare #while
        // iteration's time went to those).
        return (kind == TokKind::Word || kind == TokKind::Symbol) && !text.empty() &&
               text[0] == s[0] && text == s;
    }
    bool is_symbol(char c) const {
        return kind == TokKind::Symbol && text.size() == 1 && text[0] == c;
    }
};

// Throws glint::Error (ErrorKind::Scene) for an unterminated comment or string or a stray
// character, at its location in `file`.
// `line` and `column` say where `text` begins in the file (a NumberList's body scanned on its
// own); `lists`: whether to make NumberList tokens at all.
std::vector<Token> scan(const std::string& text, const std::shared_ptr<const std::string>& file,
                        int line = 1, int column = 1, bool lists = true);

// A human-readable description of a token for messages: "'sphere'", "the number 3", ...
std::string describe(const Token& t);

}  // namespace glint::pov
