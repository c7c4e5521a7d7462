// AGAA's programs (agaa/aggregate/passes/aggregate_programs.h), selected by name from the shader
// table's generated index (shaders/CMakeLists.txt; tools/cmake/embed_spirv.cmake).

#include "agaa/aggregate/passes/aggregate_programs.h"

#include "agaa/common/shipping_programs.h"

#include "shaders/agaa_shaders_programs.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace agaa {

namespace {

NamedProgram shipping(const std::string& name) {
    return shippingProgram(name);
}

const char* suffix(bool on, const char* text) {
    return on ? text : "";
}

} // namespace

NamedProgram visibilityProgram() {
    return shipping("agaa/visibility.frag");
}

NamedProgram clusterProgram(bool gbuffer) {
    return shipping(std::string("agaa/cluster") + suffix(gbuffer, "_gbuffer") + ".comp");
}

NamedProgram generationProgram(bool emissive, bool int64, bool subgroup) {
    return shipping(std::string("agaa/generation") + suffix(emissive, "_emissive") + suffix(int64, "_int64") +
                    suffix(subgroup, "_subgroup") + ".frag");
}

NamedProgram lightingProgram(bool gbuffer, bool emissive, bool shadows) {
    return shipping(std::string("agaa/lighting") + suffix(gbuffer, "_gbuffer") +
                    suffix(emissive, "_emissive") + suffix(shadows, "_shadow") + ".comp");
}

NamedProgram perSampleProgram(bool accumulate, bool emissive, bool shadows) {
    // The samples path's G-buffer holds its emissive: no emissive variant there.
    return shipping(std::string("agaa/lighting_per_sample") + suffix(accumulate, "_accumulate") +
                    suffix(accumulate && emissive, "_emissive") + suffix(shadows, "_shadow") + ".comp");
}

NamedProgram aggregatesViewProgram() {
    return shipping("agaa/debug_aggregates.comp");
}

std::vector<NamedProgram> aggregatePrograms() {
    std::vector<NamedProgram> all;
    for (const EmbeddedProgram& p : kAgaaShadersPrograms)
        if (p.name.starts_with("agaa/")) all.push_back({p.name, p.code});
    return all;
}

void checkProgramOverrides(const ProgramOverrides& overrides) {
    const std::vector<NamedProgram> known = aggregatePrograms();
    for (const auto& [name, code] : overrides) {
        if (std::any_of(known.begin(), known.end(), [&](const NamedProgram& p) { return p.name == name; }))
            continue;
        std::string list;
        for (const NamedProgram& k : known)
            list += (list.empty() ? "" : ", ") + std::string(k.name);
        throw std::invalid_argument("agaa: a replacement for program '" + name +
                                    "', which AGAA does not run (its programs: " + list + ")");
    }
}

} // namespace agaa
