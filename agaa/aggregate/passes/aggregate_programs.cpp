// AGAA's program table (agaa/aggregate/passes/aggregate_programs.h).

#include "agaa/aggregate/passes/aggregate_programs.h"

#include "shaders/agaa/cluster_comp.h"
#include "shaders/agaa/cluster_gbuffer_comp.h"
#include "shaders/agaa/debug_aggregates_comp.h"
#include "shaders/agaa/generation_emissive_frag.h"
#include "shaders/agaa/generation_emissive_int64_frag.h"
#include "shaders/agaa/generation_emissive_int64_subgroup_frag.h"
#include "shaders/agaa/generation_emissive_subgroup_frag.h"
#include "shaders/agaa/generation_frag.h"
#include "shaders/agaa/generation_int64_frag.h"
#include "shaders/agaa/generation_int64_subgroup_frag.h"
#include "shaders/agaa/generation_subgroup_frag.h"
#include "shaders/agaa/lighting_comp.h"
#include "shaders/agaa/lighting_emissive_comp.h"
#include "shaders/agaa/lighting_emissive_shadow_comp.h"
#include "shaders/agaa/lighting_gbuffer_comp.h"
#include "shaders/agaa/lighting_gbuffer_emissive_comp.h"
#include "shaders/agaa/lighting_gbuffer_emissive_shadow_comp.h"
#include "shaders/agaa/lighting_gbuffer_shadow_comp.h"
#include "shaders/agaa/lighting_per_sample_accumulate_comp.h"
#include "shaders/agaa/lighting_per_sample_accumulate_emissive_comp.h"
#include "shaders/agaa/lighting_per_sample_accumulate_emissive_shadow_comp.h"
#include "shaders/agaa/lighting_per_sample_accumulate_shadow_comp.h"
#include "shaders/agaa/lighting_per_sample_comp.h"
#include "shaders/agaa/lighting_per_sample_shadow_comp.h"
#include "shaders/agaa/lighting_shadow_comp.h"
#include "shaders/agaa/visibility_frag.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace agaa {
namespace {

const NamedProgram kVisibilityProgram{"agaa/visibility.frag", kAgaaVisibilityFrag};
const NamedProgram kClusterPrograms[2] = {{"agaa/cluster.comp", kAgaaClusterComp},
                                          {"agaa/cluster_gbuffer.comp", kAgaaClusterGbufferComp}};
// [emissive][int64][subgroup]
const NamedProgram kGenerationPrograms[2][2][2] = {
    {{{"agaa/generation.frag", kAgaaGenerationFrag},
      {"agaa/generation_subgroup.frag", kAgaaGenerationSubgroupFrag}},
     {{"agaa/generation_int64.frag", kAgaaGenerationInt64Frag},
      {"agaa/generation_int64_subgroup.frag", kAgaaGenerationInt64SubgroupFrag}}},
    {{{"agaa/generation_emissive.frag", kAgaaGenerationEmissiveFrag},
      {"agaa/generation_emissive_subgroup.frag", kAgaaGenerationEmissiveSubgroupFrag}},
     {{"agaa/generation_emissive_int64.frag", kAgaaGenerationEmissiveInt64Frag},
      {"agaa/generation_emissive_int64_subgroup.frag", kAgaaGenerationEmissiveInt64SubgroupFrag}}}};
// [gbuffer][emissive][shadows]
const NamedProgram kLightingPrograms[2][2][2] = {
    {{{"agaa/lighting.comp", kAgaaLightingComp}, {"agaa/lighting_shadow.comp", kAgaaLightingShadowComp}},
     {{"agaa/lighting_emissive.comp", kAgaaLightingEmissiveComp},
      {"agaa/lighting_emissive_shadow.comp", kAgaaLightingEmissiveShadowComp}}},
    {{{"agaa/lighting_gbuffer.comp", kAgaaLightingGbufferComp},
      {"agaa/lighting_gbuffer_shadow.comp", kAgaaLightingGbufferShadowComp}},
     {{"agaa/lighting_gbuffer_emissive.comp", kAgaaLightingGbufferEmissiveComp},
      {"agaa/lighting_gbuffer_emissive_shadow.comp", kAgaaLightingGbufferEmissiveShadowComp}}}};
// [path][emissive][shadows]: the flagged pixels' per-sample shading (--agaa-tolerance), path 0 the
// samples path's G-buffer (whose emissive it holds), 1 the accumulate path's per-sample material.
const NamedProgram kPerSamplePrograms[2][2][2] = {
    {{{"agaa/lighting_per_sample.comp", kAgaaLightingPerSampleComp},
      {"agaa/lighting_per_sample_shadow.comp", kAgaaLightingPerSampleShadowComp}},
     {{"agaa/lighting_per_sample.comp", kAgaaLightingPerSampleComp},
      {"agaa/lighting_per_sample_shadow.comp", kAgaaLightingPerSampleShadowComp}}},
    {{{"agaa/lighting_per_sample_accumulate.comp", kAgaaLightingPerSampleAccumulateComp},
      {"agaa/lighting_per_sample_accumulate_shadow.comp", kAgaaLightingPerSampleAccumulateShadowComp}},
     {{"agaa/lighting_per_sample_accumulate_emissive.comp", kAgaaLightingPerSampleAccumulateEmissiveComp},
      {"agaa/lighting_per_sample_accumulate_emissive_shadow.comp",
       kAgaaLightingPerSampleAccumulateEmissiveShadowComp}}}};
const NamedProgram kDebugProgram{"agaa/debug_aggregates.comp", kAgaaDebugAggregatesComp};

} // namespace

const NamedProgram& visibilityProgram() {
    return kVisibilityProgram;
}

const NamedProgram& clusterProgram(bool gbuffer) {
    return kClusterPrograms[gbuffer ? 1 : 0];
}

const NamedProgram& generationProgram(bool emissive, bool int64, bool subgroup) {
    return kGenerationPrograms[emissive ? 1 : 0][int64 ? 1 : 0][subgroup ? 1 : 0];
}

const NamedProgram& lightingProgram(bool gbuffer, bool emissive, bool shadows) {
    return kLightingPrograms[gbuffer ? 1 : 0][emissive ? 1 : 0][shadows ? 1 : 0];
}

const NamedProgram& perSampleProgram(bool accumulate, bool emissive, bool shadows) {
    return kPerSamplePrograms[accumulate ? 1 : 0][accumulate && emissive ? 1 : 0][shadows ? 1 : 0];
}

const NamedProgram& aggregatesViewProgram() {
    return kDebugProgram;
}

std::vector<NamedProgram> aggregatePrograms() {
    std::vector<NamedProgram> all = {kVisibilityProgram, kClusterPrograms[0], kClusterPrograms[1],
                                     kDebugProgram};
    for (const auto& table : {kGenerationPrograms, kLightingPrograms, kPerSamplePrograms})
        for (int i = 0; i < 8; ++i)
            all.push_back(table[i / 4][i / 2 % 2][i % 2]);
    return all;
}

void checkProgramOverrides(const ProgramOverrides& overrides) {
    std::vector<std::string_view> known;
    for (const NamedProgram& p : aggregatePrograms())
        if (std::find(known.begin(), known.end(), p.name) == known.end()) known.push_back(p.name);
    for (const auto& [name, code] : overrides) {
        if (std::find(known.begin(), known.end(), name) != known.end()) continue;
        std::string list;
        for (std::string_view k : known)
            list += (list.empty() ? "" : ", ") + std::string(k);
        throw std::invalid_argument("agaa: a replacement for program '" + name +
                                    "', which AGAA does not run (its programs: " + list + ")");
    }
}

} // namespace agaa
