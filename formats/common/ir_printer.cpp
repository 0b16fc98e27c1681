#include "formats/common/ir_printer.h"

namespace glint::formats {
std::string print_ir(const scene::Scene&) { return "(ir printer not written yet)\n"; }
}  // namespace glint::formats
