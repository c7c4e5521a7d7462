// The error-driven shading rate's decision (docs/decisions/shading-rate-estimate.md): a pixel one
// of whose aggregates the estimate distrusts (prefilter_estimate.glsl) is flagged. The lighting
// pass then drops its aggregates and writes only the flag (FrameTargets::perSampleShaded), and
// lists its tile; the pass after it (agaa/lighting_per_sample.comp) runs one workgroup per listed
// tile, an indirect dispatch, and lights and resolves each flagged pixel's samples as the reference
// does, from the per-sample G-buffer (samples path) or the per-sample material the accumulation
// kernel kept (accumulate path, shared/sample_material.h).

// The tiles with a flagged pixel: the per-sample pass's VkDispatchIndirectCommand (x counts the
// tiles; y and z are 1, set by the frame's clear), then each tile's x | y << 16. Bound only with a
// tolerance (a 16-byte stand-in otherwise, which kShadingRate 0 never touches).
layout(set = 0, binding = 19, std430) buffer FlaggedTiles {
    uint flaggedDispatch[3];
    uint flaggedTiles[];
};
shared uint sTileListed; // 1 once an invocation of this tile has listed it

// Before the tile's first barrier (tileBoundsBegin), which orders it before tileFlagAdd.
void tileFlagBegin() {
    if (kShadingRate != 0u && gl_LocalInvocationIndex == 0u) sTileListed = 0u;
}

// After the tile's first barrier, which orders it after tileFlagBegin: the first invocation of the
// tile to flag its pixel lists the tile, early (before lighting) or late (after its resolve). The
// shared exchange, not a last barrier and one lister, decides which: a barrier costs lavapipe a
// switch through all 256 invocations (docs/decisions/shading-rate-estimate.md, step 5).
void tileFlagAdd(bool perSample) {
    if (kShadingRate == 0u || !perSample || atomicExchange(sTileListed, 1u) != 0u) return;
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

// An aggregate needs this many members before the gap below says anything: one or two members
// are always as far from their mean as each other (the ratio is 1), and three often are.
// Measured at c = 2: with two members it flags 28 % of spikes and takes 22 points of its energy.
const uint kGapMembers = 4u;

// Above the alias limit: whether one of the pixel's aggregates (kGapMembers or more members) has
// its mean normal in a gap between its members' normals, where the filtered lobe then stands for
// a facing no sample has (docs/decisions/shading-rate-estimate.md, step 4). Two chrome walls of a
// V-groove in one aggregate put the mean between them, and the sun along the view axis lights the
// lobe there, which the truth never shows; samples along one curved rod have one near the mean.
// With S the sum of the members' m unit normals and N = S / |S|, the gap is
//   g = min_s (1 - N_s . N) / mean_s (1 - N_s . N),   and mean_s (1 - N_s . N) = 1 - |S| / m,
// 1 where every member is equally far from the mean (two symmetric walls) and small on one
// continuous spread. Tested as m min_s (|S| - N_s . S) >= G |S| (m - |S|), which needs no guard:
// normals that cancel (|S| = 0) have no mean and are in a gap (0 >= 0). A second read of the
// members' normals, for pixels above the limit only.
bool meanNormalInGap(ivec2 pixel, uint pixelIndex) {
    // min_s (|S| - N_s . S): at most its mean over s, |S| - |S|^2 / m <= m / 4, so n bounds it.
    float nearest[kMaxAggregates] =
        float[](float(kSamples), float(kSamples), float(kSamples), float(kSamples));
    for (uint s = 0u; s < kSamples; ++s) {
        if (isSky(sampleDepth(pixel, s))) continue;
        uint a = sampleAggregate(s, pixelIndex);
        if (a >= kAggregates || walk.samplesIn[a] < kGapMembers) continue; // c = 1's off-layer samples
        vec3 S = spreadSums.normalSum[a];
        nearest[a] = min(nearest[a], length(S) - dot(loadSampleMaterial(pixel, s).normal, S));
    }
    bool gap = false;
    for (uint a = 0u; a < kAggregates; ++a) {
        float m = float(walk.samplesIn[a]);
        float length_ = length(spreadSums.normalSum[a]);
        // A flat aggregate (kNormalSpreadFloor) has no gap: both sides are then rounding.
        gap = gap || (walk.samplesIn[a] >= kGapMembers && m - length_ > kNormalSpreadFloor * m &&
                      m * nearest[a] >= agaa.shadingRate.w * length_ * (m - length_));
    }
    return gap;
}

// Whether the pixel is shaded per sample before it is lit: its estimate reaches the tolerance and
// stays below the alias limit, above which its samples would alias the highlight the aggregate's
// lobe integrates (AggregateSettings::aliasLimit), unless, at c = 1, its aggregate's mean normal
// lies in a gap between its members' (meanNormalInGap, kMeanNormalGap). At a tolerance of 0 the
// limit is the largest float, and every covered pixel is flagged: the reference at the same n.
// The gap rule only at c = 1 (a constant): from c = 2 the clustering gives each wall of a groove
// its own aggregate, and on the gold rods of spikes and glints, where it still found gaps, it
// flagged 6.5 % of the pixels at 320x180 for no accuracy their truths can see
// (docs/decisions/shading-rate-estimate.md, step 8); its second read of the members' normals,
// in a branch, is paid by every pixel on lavapipe.
bool shadePerSample(bool inside, float estimate, ivec2 pixel, uint pixelIndex) {
    if (kShadingRate == 0u || !inside || estimate < agaa.shadingRate.x) return false;
    return estimate < agaa.shadingRate.y || (kAggregates == 1u && meanNormalInGap(pixel, pixelIndex));
}

// Which of a flagged pixel's samples the next pass shades (FrameTargets::perSampleShaded holds the
// mask): the members of the aggregates the estimate distrusts, whose own estimate reaches the
// tolerance; the others keep their one shading event. On the chain-link a flagged pixel is a rod's
// curved aggregate beside a flat wall's, whose pre-filter is exact (issue 49: shading the wall's
// samples too took most of the per-sample pass). Every sample (kPerSampleWholePixel, the sky's too,
// resolved as the reference resolves) where every aggregate is distrusted, as a tolerance of 0
// makes every pixel; at c = 1, whose off-layer samples are resolved with aggregate 0's shading;
// and with fragment routing, whose aggregates stand for the samples they received, not the ones
// the metadata assigns them.
const uint kPerSampleWholePixel = 0xFFFFFFFFu >> (32u - kSamples);
// Set for the resolve (resolve.glsl): the samples the next pass shades, whose aggregates are then
// not present here. 0 for a pixel that keeps every aggregate.
uint perSampleMembers = 0u;

uint perSampleSamples(ivec2 pixel, uint pixelIndex) {
    if (kAggregates == 1u || kRouteFragment != 0u) return kPerSampleWholePixel;
    uint distrusted = 0u;
    bool every = true;
    for (uint a = 0u; a < kAggregates; ++a) {
        if (walk.samplesIn[a] == 0u) continue;
        bool flagged = prefilterEstimate(a, walk.samplesIn[a]) >= agaa.shadingRate.x;
        distrusted |= flagged ? 1u << a : 0u;
        every = every && flagged;
    }
    if (every) return kPerSampleWholePixel;
    uint members = 0u;
    for (uint s = 0u; s < kSamples; ++s) {
        if (isSky(sampleDepth(pixel, s))) continue;
        uint a = sampleAggregate(s, pixelIndex);
        members |= a < kAggregates && ((distrusted >> a) & 1u) != 0u ? 1u << s : 0u;
    }
    return members;
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
