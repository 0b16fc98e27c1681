#include "formats/pov/literal_list.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace glint::pov {
namespace {

class Reader {
public:
    explicit Reader(std::string_view s) : s_(s) {}

    void skip_space() {
        while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r'))
            ++i_;
    }
    bool at_end() {
        skip_space();
        return i_ >= s_.size();
    }
    bool symbol(char c) {
        skip_space();
        if (i_ < s_.size() && s_[i_] == c) {
            ++i_;
            ++tokens;
            return true;
        }
        return false;
    }
    // A number as the scanner reads one (digits, optional fraction, optional exponent; or a
    // fraction alone), converted as it converts them; false for anything else or out of range.
    bool number(double* out) {
        skip_space();
        const size_t b = i_;
        auto digit = [&](size_t k) { return k < s_.size() && s_[k] >= '0' && s_[k] <= '9'; };
        if (!digit(i_) && !(i_ < s_.size() && s_[i_] == '.' && digit(i_ + 1))) return false;
        while (digit(i_)) ++i_;
        if (i_ < s_.size() && s_[i_] == '.') {
            ++i_;
            while (digit(i_)) ++i_;
        }
        if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
            size_t j = i_ + 1;
            if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
            if (digit(j)) {
                i_ = j;
                while (digit(i_)) ++i_;
            }
        }
        const char* first = s_.data() + b;
        const char* last = s_.data() + i_;
        const auto r = std::from_chars(first, last, *out);
        if (r.ec != std::errc() || r.ptr != last) *out = std::strtod(std::string(first, last).c_str(), nullptr);
        ++tokens;
        // Out of range: the token path reports it where it is written.
        return std::isfinite(*out);
    }
    // An optionally negated number, as the literal-vector path reads one.
    bool signed_number(double* out) {
        const bool negative = symbol('-');
        if (!number(out)) return false;
        if (negative) *out = -1 * *out;
        return true;
    }

    long long tokens = 0;

private:
    std::string_view s_;
    size_t i_ = 0;
};

}  // namespace

bool read_literal_list(std::string_view text, int dims, LiteralList* out) {
    Reader r(text);
    out->values.clear();
    if (!r.number(&out->count) || !(out->count >= 0) || !(out->count < 1e9)) return false;
    const long long n = static_cast<long long>(out->count);
    // Each vector takes at least 2 dims + 1 characters ("<1,1>"): a count the text cannot hold
    // is refused before anything is reserved for it.
    if (n > static_cast<long long>(text.size() / (2 * dims + 1))) return false;
    out->values.reserve(static_cast<size_t>(n) * static_cast<size_t>(dims));
    for (long long i = 0; i < n; ++i) {
        // A comma between items (the token path skips one before each item; none is also
        // accepted there before the first, and a '<' after a vector without one is read
        // differently, so only these two forms are taken here).
        if (!r.symbol(',') && i > 0) return false;
        if (!r.symbol('<')) return false;
        for (int k = 0; k < dims; ++k) {
            double v;
            if (k > 0 && !r.symbol(',')) return false;
            if (!r.signed_number(&v)) return false;
            out->values.push_back(v);
        }
        if (!r.symbol('>')) return false;
    }
    r.symbol(',');  // after the last item
    if (!r.at_end()) return false;
    out->tokens = r.tokens;
    return true;
}

}  // namespace glint::pov
