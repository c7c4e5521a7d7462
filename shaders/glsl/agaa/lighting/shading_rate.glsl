// The error-driven shading rate's decision (docs/decisions/shading-rate-estimate.md): a pixel one
// of whose aggregates the estimate distrusts (prefilter_estimate.glsl) is flagged. The lighting
// pass then drops its aggregates and writes only the flag (FrameTargets::perSampleShaded), and
// lists its tile; the pass after it (agaa/lighting_per_sample.comp) runs one workgroup per listed
// tile, an indirect dispatch, and lights and resolves each flagged pixel's samples as the reference
// does. Samples path only: the accumulate path keeps no per-sample material (AggregateAA refuses
// --agaa-tolerance there).

// The tiles with a flagged pixel: the per-sample pass's VkDispatchIndirectCommand (x counts the
// tiles; y and z are 1, set by the frame's clear), then each tile's x | y << 16. Bound only with a
// tolerance (a 16-byte stand-in otherwise, which kShadingRate 0 never touches).
layout(set = 0, binding = 19, std430) buffer FlaggedTiles {
    uint flaggedDispatch[3];
    uint flaggedTiles[];
};
shared uint sTileFlagged;

// Before the tile's first barrier (tileBoundsBegin), which orders it before tileFlagAdd.
void tileFlagBegin() {
    if (kShadingRate != 0u && gl_LocalInvocationIndex == 0u) sTileFlagged = 0u;
}

// Between the tile's two barriers.
void tileFlagAdd(bool perSample) {
    if (kShadingRate != 0u && perSample) atomicOr(sTileFlagged, 1u);
}

// After the second barrier: one invocation lists the tile if any of its pixels was flagged.
void tileFlagEnd() {
    if (kShadingRate == 0u || gl_LocalInvocationIndex != 0u || sTileFlagged == 0u) return;
    uint slot = atomicAdd(flaggedDispatch[0], 1u);
    flaggedTiles[slot] = gl_WorkGroupID.x | (gl_WorkGroupID.y << 16u);
}

// Whether the pixel is shaded per sample: one of its aggregates' estimates reaches the tolerance
// (at 0, every covered pixel: the reference at the same n).
bool shadePerSample(bool inside) {
    if (kShadingRate == 0u || !inside) return false;
    for (uint a = 0u; a < kAggregates; ++a)
        if (walk.samplesIn[a] > 0u && prefilterEstimate(a, walk.samplesIn[a]) >= agaa.shadingRate.x)
            return true;
    return false;
}

// --debug shading-rate: this pass draws its pixels in grey (shading_rate_view.glsl).
layout(constant_id = kSpecLightingShadingRateView) const uint kShadingRateView = 0u;
