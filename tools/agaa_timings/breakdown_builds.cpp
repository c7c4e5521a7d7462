#include "tools/agaa_timings/breakdown_builds.h"

#include "shaders/breakdown/generation_emissive_empty_frag.h"
#include "shaders/breakdown/generation_emissive_material_only_frag.h"
#include "shaders/breakdown/generation_empty_frag.h"
#include "shaders/breakdown/generation_material_only_frag.h"
#include "shaders/breakdown/lighting_emissive_no_shading_comp.h"
#include "shaders/breakdown/lighting_emissive_shadow_no_shading_comp.h"
#include "shaders/breakdown/lighting_gbuffer_emissive_no_shading_comp.h"
#include "shaders/breakdown/lighting_gbuffer_emissive_shadow_no_shading_comp.h"
#include "shaders/breakdown/lighting_gbuffer_no_shading_comp.h"
#include "shaders/breakdown/lighting_gbuffer_shadow_no_shading_comp.h"
#include "shaders/breakdown/lighting_no_shading_comp.h"
#include "shaders/breakdown/lighting_shadow_no_shading_comp.h"
#include "shaders/breakdown/visibility_no_normals_frag.h"

#include <string>

namespace agaa::timings {

ProgramOverrides lightingWithoutShading() {
    return {
        {"agaa/lighting.comp", kBreakdownLightingNoShadingComp},
        {"agaa/lighting_emissive.comp", kBreakdownLightingEmissiveNoShadingComp},
        {"agaa/lighting_shadow.comp", kBreakdownLightingShadowNoShadingComp},
        {"agaa/lighting_emissive_shadow.comp", kBreakdownLightingEmissiveShadowNoShadingComp},
        {"agaa/lighting_gbuffer.comp", kBreakdownLightingGbufferNoShadingComp},
        {"agaa/lighting_gbuffer_emissive.comp", kBreakdownLightingGbufferEmissiveNoShadingComp},
        {"agaa/lighting_gbuffer_shadow.comp", kBreakdownLightingGbufferShadowNoShadingComp},
        {"agaa/lighting_gbuffer_emissive_shadow.comp", kBreakdownLightingGbufferEmissiveShadowNoShadingComp}};
}

namespace {

// Every generation variant's name ([emissive] [int64] [subgroup]) to the build for its output.
ProgramOverrides everyGeneration(std::span<const uint32_t> plain, std::span<const uint32_t> emissive) {
    ProgramOverrides o;
    for (const char* atomics : {"", "_int64"})
        for (const char* subgroup : {"", "_subgroup"}) {
            const std::string suffix = std::string(atomics) + subgroup + ".frag";
            o["agaa/generation" + suffix] = plain;
            o["agaa/generation_emissive" + suffix] = emissive;
        }
    return o;
}

} // namespace

ProgramOverrides generationWithoutAtomicsVisibilityWithoutNormals() {
    ProgramOverrides o =
        everyGeneration(kBreakdownGenerationMaterialOnlyFrag, kBreakdownGenerationEmissiveMaterialOnlyFrag);
    o["agaa/visibility.frag"] = kBreakdownVisibilityNoNormalsFrag;
    return o;
}

ProgramOverrides generationEmpty() {
    return everyGeneration(kBreakdownGenerationEmptyFrag, kBreakdownGenerationEmissiveEmptyFrag);
}

} // namespace agaa::timings
