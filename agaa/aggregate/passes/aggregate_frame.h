#pragma once
// One frame of AggregateAA as its passes hand it on (agaa/aggregate/aggregate.cpp addPasses): the
// host's inputs, the frame's AGAA constants, and each pass's outputs as they are added. A pass
// reads the fields its inputs are in and AggregateAA stores what it returns.

#include "agaa/aggregate/aggregate_plan.h"
#include "agaa/common/sample_gbuffer.h"
#include "agaa/common/shadow_map.h"
#include "agaa/common/technique.h"

#include <cstdint>

namespace agaa {

// The clustering's outputs (agaa.cluster): the bit-packed metadata and each pixel's aggregate count.
struct Clusters {
    eng::rg::Buffer metadata;
    eng::rg::Texture count; // R8_UINT
};

// The accumulate path's generation outputs (agaa.clear, agaa.generation).
struct Accumulation {
    eng::rg::Buffer agBuffer;
    eng::rg::Buffer sampleMaterial; // with a tolerance: each covered sample's; a 16-byte stand-in otherwise
    eng::rg::Texture depth;         // the visibility depth after generation wrote its stencil
    eng::rg::Texture emissive;      // per sample, where the scene emits
};

struct AggregateFrame {
    const FrameInputs& in;
    const AggregatePlan& plan;
    eng::rg::Buffer constants;       // shared::AgaaConstants of in.frameSlot
    EnvironmentBindings environment; // what the lighting passes bind (frameEnvironment)
    // What the clustering reads: the samples path's G-buffer, or the visibility prepass's depth and
    // face normals. `depth` is then the lighting's: after generation, the version with its stencil.
    SampleGBuffer gbuffer; // samples path
    eng::rg::Texture depth, normal;
    Clusters clusters;
    ShadowMaps shadow;         // where the scene has a shadowed light
    Accumulation accumulation; // accumulate path

    // An image of one value per sample: 4x, one layer per 4 samples.
    eng::rg::TextureDesc sampleDesc(VkFormat format) const {
        return {format, in.width, in.height, plan.layers(), VK_SAMPLE_COUNT_4_BIT};
    }
    // A per-pixel image, as the lighting's targets.
    eng::rg::TextureDesc pixelDesc(VkFormat format) const {
        return {format, in.width, in.height, 1, VK_SAMPLE_COUNT_1_BIT};
    }
};

// Workgroups of `group` invocations that cover `size`.
inline uint32_t groupCount(uint32_t size, uint32_t group) {
    return (size + group - 1) / group;
}

} // namespace agaa
