// The shadowed lights' visibility over each aggregate's footprint (paper section 3.5.3), for
// agaa/lighting/shadowed_lights.glsl addShadowedLights: the footprint kShadowFootprint names.
// Included after agaa/lighting/lighting_pass.glsl by the builds that light; agaa-timings
// --breakdown's build without it (breakdown/lighting_no_shadow_filter.comp) times what the
// footprint's taps cost.
#if AGAA_SHADOWS
// The adaptive footprint's penumbra test: the corner taps and the kShadowTaps statistical ones.
const uint kAdaptiveTestTaps = kAdaptiveCornerTaps + kShadowTaps;

float shadowVisibilityFootprint(uint light, Aggregate ag, float pixelSize) {
    vec3 P = ag.position, N = ag.surface.normal;
    if (kShadowFootprint == 1u) return shadowVisibilityAggregateSamples(light, ag);
    if (kShadowFootprint == 0u)
        return shadowVisibilityAggregate(light, P, N, ag.depthSigma, pixelSize, ag.screenSpread);
    // Adaptive, where no aggregate has more samples than the test has taps (n <= 9 at 4 taps):
    // every sample's own tap, the answer the test refines to, for fewer taps than the test and
    // none of its refinements. A constant branch (n is a specialisation constant). Measured at
    // n = 8 on lavapipe: 2 to 10 ms less of the lighting pass on foliage, furball, default and
    // metal, where the refinement, run by most SIMD groups for one aggregate on a shadow edge,
    // cost them more than the test (docs/decisions/shadow-footprint.md).
    if (kSamples <= kAdaptiveTestTaps) return shadowVisibilityAggregateEverySample(light, ag);
    // Above: where the footprint's corners disagree a shadow edge crosses the aggregate and its
    // own samples decide (up to n taps, paid by the few aggregates on a penumbra); where they
    // agree, that is the answer.
    float visibility =
        shadowVisibilityAggregateCorners(light, P, N, ag.depthSigma, pixelSize, ag.screenSpread);
    float rooks = shadowVisibilityAggregate(light, P, N, ag.depthSigma, pixelSize, ag.screenSpread);
    if (visibility != rooks || (visibility > 0.0 && visibility < 1.0))
        visibility = shadowVisibilityAggregateEverySample(light, ag);
    return visibility;
}
#endif
