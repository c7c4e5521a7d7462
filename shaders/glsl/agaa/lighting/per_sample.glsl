// Steps 3 and 4 for a pixel the shading rate flags (prefilter_estimate.glsl): each covered sample
// lit on its own, with its own G-buffer material and position, and tone-mapped on its own, as the
// reference shades and resolves it. Samples path only: the accumulate path keeps no per-sample
// material (AggregateAA refuses --agaa-tolerance there).

// Whether the pixel is shaded per sample: one of its aggregates' estimates reaches the tolerance
// (at 0, every covered pixel: the reference at the same n).
bool shadePerSample(bool inside) {
    if (kShadingRate == 0u || !inside) return false;
    for (uint a = 0u; a < kAggregates; ++a)
        if (walk.samplesIn[a] > 0u && prefilterEstimate(a, walk.samplesIn[a]) >= agaa.shadingRate.x) return true;
    return false;
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

Resolved resolvePerSample(ivec2 pixel, uint pixelIndex) {
    float exposure = frame.depthParams.z;
    float weight = 1.0 / float(kSamples);
    vec3 sky = skyRadiance(pixel) * exposure;
    Resolved r = Resolved(vec3(0.0), vec3(0.0));
    for (uint s = 0u; s < kSamples; ++s) {
        float d = sampleDepth(pixel, s);
        if (isSky(d)) {
            r.display += weight * toneMapAces(sky);
            r.hdr += weight * sky;
            continue;
        }
        Aggregate ag = oneSampleAggregate(pixel, pixelIndex, s, sampleViewPosition(pixel, s, d));
        Shading shading;
        OffLayerShading unused;
        shadeAggregate(ag, noOffLayer(ag), shading, unused);
        vec3 L = shading.radiance;
#if AGAA_EMISSIVE
        L += texelFetch(emissiveSamples, ivec3(pixel, s / 4u), int(s % 4u)).rgb;
#endif
        L = exposedRadiance(L, exposure);
        r.display += weight * toneMapAces(L);
        r.hdr += weight * L;
    }
    return r;
}
#else
Resolved resolvePerSample(ivec2 pixel, uint pixelIndex) {
    return Resolved(vec3(0.0), vec3(0.0));
}
#endif
