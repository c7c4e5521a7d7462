#pragma once
// The host sample's programs (samples/host_engine/programs.cmake) as the node tests embed them.

#include "shaders/agaa_host_shaders_programs.h"
#include "tests/node/host_mesh.h"

#include <string_view>

namespace agaa::test {

using host_engine::HostPrograms;

inline HostPrograms embeddedHostPrograms() {
    constexpr std::string_view folder = "host_engine/shaders/";
    HostPrograms programs;
    for (const EmbeddedProgram& p : kAgaaHostShadersPrograms)
        programs.emplace(std::string(p.name.substr(folder.size())), p.code);
    return programs;
}

} // namespace agaa::test
