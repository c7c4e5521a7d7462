#include "tools/agaa_timings/breakdown_builds.h"

#include "shaders/agaa_breakdown_shaders_programs.h"

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace agaa::timings {

namespace {

// Every breakdown build named "breakdown/<pass><variant><part>.<stage>" (its part the one it leaves
// out) as the replacement of "agaa/<pass><variant><suffix>.<stage>" for each of `suffixes`: the
// shipping variants it stands for (shaders/CMakeLists.txt, tools/agaa_timings/CMakeLists.txt).
void replace(ProgramOverrides& o, std::string_view pass, std::string_view part,
             const std::vector<std::string_view>& suffixes) {
    const std::string prefix = "breakdown/" + std::string(pass);
    bool found = false;
    for (const EmbeddedProgram& p : kAgaaBreakdownShadersPrograms) {
        const std::string_view name = p.name;
        const size_t dot = name.rfind('.');
        if (name.substr(0, prefix.size()) != prefix || dot < part.size() ||
            name.substr(dot - part.size(), part.size()) != part)
            continue;
        const std::string_view variant = name.substr(prefix.size(), dot - part.size() - prefix.size());
        for (std::string_view suffix : suffixes)
            o["agaa/" + std::string(pass) + std::string(variant) + std::string(suffix) +
              std::string(name.substr(dot))] = p.code;
        found = true;
    }
    if (!found)
        throw std::logic_error("agaa-timings: no breakdown build of " + prefix + "*" + std::string(part));
}

// Without atomics, 64-bit atomics and subgroup pre-reduction change nothing: one build stands for
// every generation variant of its output.
const std::vector<std::string_view> kEveryAtomics = {"", "_subgroup", "_int64", "_int64_subgroup"};

} // namespace

ProgramOverrides lightingWithoutShading() {
    ProgramOverrides o;
    replace(o, "lighting", "_no_shading", {""});
    return o;
}

ProgramOverrides lightingWithoutShadowFilter() {
    ProgramOverrides o;
    replace(o, "lighting", "_no_shadow_filter", {""});
    return o;
}

ProgramOverrides generationWithoutAtomicsVisibilityWithoutNormals() {
    ProgramOverrides o;
    replace(o, "generation", "_material_only", kEveryAtomics);
    replace(o, "visibility", "_no_normals", {""});
    return o;
}

ProgramOverrides generationEmpty() {
    ProgramOverrides o;
    replace(o, "generation", "_empty", kEveryAtomics);
    return o;
}

} // namespace agaa::timings
