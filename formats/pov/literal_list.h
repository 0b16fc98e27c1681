// The fast path for mesh2's long lists (vertex_vectors, face_indices, ...): a NumberList token's
// text (scanner.h) read straight into numbers, for the one shape the grammar gives a single
// meaning without evaluating anything: `N, <a, b, c>, <a, b, c>, ...` with literal numbers,
// optional minus signs and a comma after each vector but perhaps the last. Any other text
// (a missing comma, a plus sign, vectors of another size, fewer or more vectors than N) is
// refused, and the parser reads it token by token instead, with its usual messages.
#pragma once

#include <string_view>
#include <vector>

namespace glint::pov {

struct LiteralList {
    double count = 0;            // N as written
    std::vector<double> values;  // dims per vector
    long long tokens = 0;        // the tokens the text amounts to (for --max-tokens)
};

// Reads `text` as N vectors of `dims` components. Returns false when it is not exactly that.
bool read_literal_list(std::string_view text, int dims, LiteralList* out);

}  // namespace glint::pov
