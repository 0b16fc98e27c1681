// Blender's Python enum identifiers -> the node functions' enums, through a constant table.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <utility>

namespace glint::render::shader {

template <typename E, std::size_t N>
bool parse_enum(std::string_view id, const std::array<std::pair<std::string_view, E>, N>& table,
                E* out) {
    for (const auto& [name, value] : table)
        if (name == id) {
            *out = value;
            return true;
        }
    return false;
}

}  // namespace glint::render::shader
