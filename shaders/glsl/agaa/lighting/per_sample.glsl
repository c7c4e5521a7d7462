// A pixel the shading rate flags (prefilter_estimate.glsl) skips its aggregates: each covered
// sample is lit on its own, with its own G-buffer material and position, and tone-mapped on its
// own, as the reference shades and resolves it. On the compacted schedule its samples join the
// tile's list (schedule.glsl), so that a flagged pixel's n events spread over the tile's lanes;
// on the per-pixel schedule its invocation shades them in turn. Samples path only: the accumulate
// path keeps no per-sample material (AggregateAA refuses --agaa-tolerance there).

// Whether the pixel is shaded per sample: one of its aggregates' estimates reaches the tolerance
// (at 0, every covered pixel: the reference at the same n).
bool shadePerSample(bool inside) {
    if (kShadingRate == 0u || !inside) return false;
    for (uint a = 0u; a < kAggregates; ++a)
        if (walk.samplesIn[a] > 0u && prefilterEstimate(a, walk.samplesIn[a]) >= agaa.shadingRate.x)
            return true;
    return false;
}

// The flagged pixel's resolve, summed as its samples' shadings arrive (module state).
struct SampleResolve {
    vec3 display; // tone-mapped per sample, weighted 1/n
    vec3 hdr;     // exposed linear radiance, weighted 1/n
};
SampleResolve sampleResolve;

// The sky's share of the resolve, before any sample's shading is added.
void beginSampleResolve(ivec2 pixel) {
    float weight = float(walk.skySamples) / float(kSamples);
    vec3 sky = skyRadiance(pixel) * frame.depthParams.z;
    sampleResolve.display = weight * toneMapAces(sky);
    sampleResolve.hdr = weight * sky;
}

// Sample s's radiance (before exposure): its emission added, exposed, tone-mapped, summed.
void addSampleShading(ivec2 pixel, uint s, vec3 radiance) {
#if AGAA_EMISSIVE
    radiance += texelFetch(emissiveSamples, ivec3(pixel, s / 4u), int(s % 4u)).rgb;
#endif
    vec3 L = min(radiance * frame.depthParams.z, vec3(kMaxRadiance));
    float weight = 1.0 / float(kSamples);
    sampleResolve.display += weight * toneMapAces(L);
    sampleResolve.hdr += weight * L;
}

#if AGAA_GBUFFER
// Sample s as an aggregate of one: its own GGX lobe, set directly rather than filtered back from
// moments (an SGGX matrix's eigen-decomposition would only round it), no spread, no footprint.
Aggregate oneSampleAggregate(ivec2 pixel, uint pixelIndex, uint s, vec3 P) {
    SampleMaterial sm = loadSampleMaterial(pixel, s);
    float rawAlpha = sm.roughness * sm.roughness;
    float alpha = clamp(rawAlpha, kMinGgxAlpha, kMaxGgxAlpha);
    Aggregate ag;
    ag.pixel = pixel;
    ag.pixelIndex = pixelIndex;
    ag.id = 0u;
    ag.samples = 1u;
    ag.accumulated = 1u;
    ag.present = true;
    ag.oneSample = true;
    ag.surface.normal = sm.normal;
    ag.surface.roughness = sqrt(alpha); // the BRDF squares it back
    ag.surface.albedo = sm.albedoMetal.rgb;
    ag.surface.metallic = sm.albedoMetal.a;
    // SGGX's anisotropic BRDF reads a frame: any around N, both alphas equal.
    hemisphereBasis(sm.normal.x, sm.normal.y, sm.normal.z, ag.tangent.x, ag.tangent.y, ag.tangent.z,
                    ag.bitangent.x, ag.bitangent.y, ag.bitangent.z);
    ag.alphas = vec2(alpha);
    ag.spread = 1.0;
    ag.environmentRoughness = environmentAggregateRoughness(alpha, min(rawAlpha, kMaxGgxAlpha));
    ag.position = P;
    ag.depthSigma = 0.0;
    ag.screenSpread = vec3(0.0);
    return ag;
}
#else
Aggregate oneSampleAggregate(ivec2 pixel, uint pixelIndex, uint s, vec3 P) {
    return aggregates[0]; // never called: the accumulate path never flags a pixel
}
#endif

// --debug shading-rate (AggregateDebugView::ShadingRate): the lit image's luminance, in red where the
// pixel was shaded per sample and in grey elsewhere.
layout(constant_id = kSpecLightingShadingRateView) const uint kShadingRateView = 0u;

vec3 shadingRateView(vec3 display, bool perSample) {
    float luminance = dot(display, vec3(0.2126, 0.7152, 0.0722));
    float shade = 0.25 + 0.75 * luminance; // flagged dark pixels stay visible
    return perSample ? shade * vec3(1.0, 0.15, 0.1) : vec3(0.6 * luminance);
}

// The per-pixel schedule's way: this invocation shades its pixel's covered samples in turn.
void shadeSamplesInRegisters(ivec2 pixel, uint pixelIndex) {
    for (uint s = 0u; s < kSamples; ++s) {
        float d = sampleDepth(pixel, s);
        if (isSky(d)) continue;
        Aggregate ag = oneSampleAggregate(pixel, pixelIndex, s, sampleViewPosition(pixel, s, d));
        Shading shading;
        OffLayerShading unused;
        shadeAggregate(ag, noOffLayer(ag), shading, unused);
        addSampleShading(pixel, s, shading.radiance);
    }
}
