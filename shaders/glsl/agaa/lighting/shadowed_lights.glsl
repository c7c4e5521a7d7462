// The tile's shadowed lights (AGAA_SHADOWS 1): shadow maps (agaa/common/shadow_map.h) filtered
// inside each aggregate's footprint (paper section 3.5.3, common/shadow.glsl). Without shadows the
// variant has no shadow bindings (agaa/lighting.comp) and addShadowedLights adds nothing.
#if AGAA_SHADOWS

// agaa/common/effects.h ShadowFootprint: 0 the statistical footprint
// (common/shadow.glsl shadowVisibilityAggregate), 1 taps at the aggregate's own sample positions,
// 2 adaptive: the statistical taps, refined at every sample where they disagree (every sample
// outright at n <= 9, shadowVisibilityFootprint). The taps' count,
// not their placement, leaves one-surface pixels at twice per-sample shading's error, and a
// shadow edge is where the count matters; elsewhere 4 taps agree and are exact.
layout(constant_id = kSpecShadowFootprint) const uint kShadowFootprint = 0u;

// The paper's "more precise" footprint (section 3.5.3): min(taps, k) of the aggregate's k samples,
// evenly spread in sample order (ranks (2j + 1) k / (2 taps)), each tapped at its own position.
float shadowVisibilityAggregateSamples(uint light, Aggregate ag) {
    int layer = shadowLayer(light);
    uint k = ag.samples;
    if (layer < 0 || k == 0u) return 1.0;
    uint taps = min(kShadowTaps, k);
    uint rank = 0u, j = 0u;
    float sum = 0.0;
    for (uint s = 0u; s < kSamples && j < taps; ++s) {
        float d = sampleDepth(ag.pixel, s);
        if (isSky(d) || sampleAggregate(s, ag.pixelIndex) != ag.id) continue;
        if (rank == ((2u * j + 1u) * k) / (2u * taps)) {
            vec3 Ps = sampleViewPosition(ag.pixel, s, d);
            sum += shadowTap(layer, shadowReceiver(layer, Ps, ag.surface.normal));
            ++j;
        }
        ++rank;
    }
    return sum / float(max(j, 1u));
}

// The penumbra refinement of the adaptive footprint: every one of the aggregate's samples,
// tapped at its own position, which is the visibility per-sample shading gives those samples.
float shadowVisibilityAggregateEverySample(uint light, Aggregate ag) {
    int layer = shadowLayer(light);
    if (layer < 0) return 1.0;
    uint count = 0u;
    float sum = 0.0;
    for (uint s = 0u; s < kSamples; ++s) {
        float d = sampleDepth(ag.pixel, s);
        if (isSky(d) || sampleAggregate(s, ag.pixelIndex) != ag.id) continue;
        vec3 Ps = sampleViewPosition(ag.pixel, s, d);
        sum += shadowTap(layer, shadowReceiver(layer, Ps, ag.surface.normal));
        ++count;
    }
    return count == 0u ? 1.0 : sum / float(count);
}

// Light `light`'s visibility over the aggregate's footprint: defined after the pass
// (agaa/lighting/shadow_footprint.glsl; agaa-timings --breakdown's build without it lights every
// footprint fully).
float shadowVisibilityFootprint(uint light, Aggregate ag, float pixelSize);

void addShadowedLights(Aggregate ag, AggregateLobe lobe, OffLayer off, vec3 V, float viewWeight,
                       inout Shading shading, inout OffLayerShading offShading) {
    // The aggregate's footprint: depth standard deviation along the ray, one pixel across.
    float pixelSize = pixelFootprint(-ag.position.z, frame.extent, frame.projParams);
    for (uint i = nextTileShadowedLight(0u); i < kMaxLights; i = nextTileShadowedLight(i + 1u)) {
        // c = 1: the off-layer samples' own shadow, one tap at their mean position (not the
        // aggregate's: the wall behind a leaf is not in the leaf's shadow).
        vec3 offLayerE, offLayerS;
        if (offLayerLight(i, off, offLayerE, offLayerS) && offLayerE + offLayerS != vec3(0.0)) {
            float offLayerVisibility = shadowVisibilityPoint(i, off.position.xyz, off.lobe.xyz);
            offShading.irradiance += offLayerE * offLayerVisibility;
            offShading.specular += offLayerS * offLayerVisibility;
            offShading.specularSquares += offLayerS * offLayerS * (offLayerVisibility * offLayerVisibility);
        }
        vec3 L, irradiance;
        if (!lightIncidence(lights[i], ag.position, L, irradiance)) continue;
        irradiance *= shadowVisibilityFootprint(i, ag, pixelSize);
        addAggregateLight(ag, lobe, V, viewWeight, L, irradiance, shading);
    }
}
#else
void addShadowedLights(Aggregate ag, AggregateLobe lobe, OffLayer off, vec3 V, float viewWeight,
                       inout Shading shading, inout OffLayerShading offShading) {}
#endif
