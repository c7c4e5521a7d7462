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

// After the tile's first barrier, which orders it after tileFlagBegin.
void tileFlagAdd(bool perSample) {
    if (kShadingRate != 0u && perSample) atomicOr(sTileFlagged, 1u);
}

// After the tile's last barrier (every invocation's tileFlagAdd before it): one invocation lists
// the tile if any of its pixels was flagged.
void tileFlagEnd() {
    if (kShadingRate == 0u || gl_LocalInvocationIndex != 0u || sTileFlagged == 0u) return;
    uint slot = atomicAdd(flaggedDispatch[0], 1u);
    flaggedTiles[slot] = gl_WorkGroupID.x | (gl_WorkGroupID.y << 16u);
}

// The largest of the pixel's aggregates' estimates (0 outside the image or without a tolerance).
float pixelEstimate(bool inside) {
    float estimate = 0.0;
    if (kShadingRate == 0u || !inside) return estimate;
    for (uint a = 0u; a < kAggregates; ++a)
        if (walk.samplesIn[a] > 0u) estimate = max(estimate, prefilterEstimate(a, walk.samplesIn[a]));
    return estimate;
}

// Whether the pixel is shaded per sample before it is lit: its estimate reaches the tolerance and
// stays below the alias limit, above which its samples would alias the highlight the aggregate's
// lobe integrates (AggregateSettings::aliasLimit). At a tolerance of 0 the limit is the largest
// float, and every covered pixel is flagged: the reference at the same n.
bool shadePerSample(bool inside, float estimate) {
    return kShadingRate != 0u && inside && estimate >= agaa.shadingRate.x && estimate < agaa.shadingRate.y;
}

// Whether a pixel above the alias limit (and the tolerance) is shaded per sample after all, once
// lit: where its aggregates' exposed radiance is past the tone map's shoulder (agaa.shadingRate.z,
// kAliasedSaturation), an aliased highlight's samples clip one by one, which the aggregate's
// spread energy does not, and n samples come closer to the truth than the aggregate
// (docs/decisions/shading-rate-estimate.md, step 3).
bool shadeSaturatedAlias(bool inside, float estimate, vec3 exposedHdr) {
    bool aboveLimit = estimate >= agaa.shadingRate.y && estimate >= agaa.shadingRate.x;
    return kShadingRate != 0u && inside && aboveLimit &&
           max(exposedHdr.r, max(exposedHdr.g, exposedHdr.b)) >= agaa.shadingRate.z;
}

// --debug shading-rate: this pass draws its pixels in grey (shading_rate_view.glsl).
layout(constant_id = kSpecLightingShadingRateView) const uint kShadingRateView = 0u;
