#pragma once
// The host's programs (tests/node/host_content.h) as the node tests embed them.

#include "shaders/tests/host_accumulation_frag.h"
#include "shaders/tests/host_gbuffer_frag.h"
#include "shaders/tests/host_gbuffer_sample_rate_frag.h"
#include "shaders/tests/host_gbuffer_vert.h"
#include "shaders/tests/host_shadow_vert.h"
#include "shaders/tests/host_visibility_frag.h"
#include "tests/node/host_content.h"

namespace agaa::test {

inline HostPrograms embeddedHostPrograms() {
    return {kTestsHostGbufferVert,           kTestsHostShadowVert,     kTestsHostGbufferFrag,
            kTestsHostGbufferSampleRateFrag, kTestsHostVisibilityFrag, kTestsHostAccumulationFrag};
}

} // namespace agaa::test
