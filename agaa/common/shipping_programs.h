#pragma once
// The shipping programs of the shader table (shaders/CMakeLists.txt) by name, from its generated
// index: how a pass or this project's scene drawer names the program it runs, so that
// ProgramOverrides (agaa/common/program_overrides.h) can replace it by the same name.

#include "agaa/common/program_overrides.h"

#include <string>

namespace agaa {

// Throws std::logic_error for a name the table lacks (the caller's mistake, not the user's).
NamedProgram shippingProgram(const std::string& name);

} // namespace agaa
