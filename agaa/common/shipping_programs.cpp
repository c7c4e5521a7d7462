#include "agaa/common/shipping_programs.h"

#include "shaders/agaa_shaders_programs.h"

#include <stdexcept>

namespace agaa {

NamedProgram shippingProgram(const std::string& name) {
    for (const EmbeddedProgram& p : kAgaaShadersPrograms)
        if (p.name == name) return {p.name, p.code};
    throw std::logic_error("agaa: the shader table (shaders/CMakeLists.txt) has no program " + name);
}

} // namespace agaa
