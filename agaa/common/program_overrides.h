#pragma once
// Builds of a technique's programs that run in place of its shipping ones, keyed by the program's
// name in the shader table (shaders/CMakeLists.txt, e.g. "agaa/lighting_gbuffer.comp"). They are
// the same sources built with other macros: agaa-timings' part-removed builds (--breakdown,
// tools/agaa_timings/CMakeLists.txt), a test's or a host's own. A replacement declares the
// bindings of the program it replaces; its layout is reflected from it like the shipping one's.

#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <string_view>

namespace agaa {

using ProgramOverrides = std::map<std::string, std::span<const uint32_t>, std::less<>>;

// One of a technique's shipping programs, by its table name.
struct NamedProgram {
    std::string_view name;
    std::span<const uint32_t> code;
};

// The code that runs for `shipping`: its replacement in `overrides`, or its own.
inline std::span<const uint32_t> programCode(const ProgramOverrides& overrides,
                                             const NamedProgram& shipping) {
    auto it = overrides.find(shipping.name);
    return it == overrides.end() ? shipping.code : it->second;
}

} // namespace agaa
