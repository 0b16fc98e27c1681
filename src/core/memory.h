// What the process holds in memory and what the machine has, for the resource limits that keep
// a scene from taking the machine's memory (pov::ParseOptions::max_memory_mib, --max-memory).
#pragma once

#include <cstddef>

namespace glint {

// Resident set size of this process in bytes (Linux /proc/self/statm); 0 if unknown.
std::size_t resident_bytes();

// Physical memory of the machine in bytes; 0 if unknown.
std::size_t physical_memory_bytes();

}  // namespace glint
