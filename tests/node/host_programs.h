#pragma once
// The host sample's programs (samples/host_engine/shaders) as the node tests embed them.

#include "shaders/host_engine/shaders/host_accumulation_frag.h"
#include "shaders/host_engine/shaders/host_gbuffer_frag.h"
#include "shaders/host_engine/shaders/host_gbuffer_sample_rate_frag.h"
#include "shaders/host_engine/shaders/host_gbuffer_vert.h"
#include "shaders/host_engine/shaders/host_shadow_vert.h"
#include "shaders/host_engine/shaders/host_visibility_frag.h"
#include "tests/node/host_mesh.h"

namespace agaa::test {

using host_engine::HostPrograms;

inline HostPrograms embeddedHostPrograms() {
    return {kHostEngineShadersHostGbufferVert,    kHostEngineShadersHostShadowVert,
            kHostEngineShadersHostGbufferFrag,    kHostEngineShadersHostGbufferSampleRateFrag,
            kHostEngineShadersHostVisibilityFrag, kHostEngineShadersHostAccumulationFrag};
}

} // namespace agaa::test
