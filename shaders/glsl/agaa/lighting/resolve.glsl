// Step 4, the resolve (DESIGN section 6): each shading event's radiance, tone-mapped and weighted
// by its sample fraction, plus the sky for uncovered samples. The tone map takes the expected value
// over the aggregate's samples (common/tonemap.glsl toneMapAggregate, the two-point resolve).
// Without emission every sample of an aggregate has the same radiance, so this costs c tone maps,
// not n; with emission it runs per sample (emission stays per sample, seed 004).
struct Resolved {
    vec3 display; // tone-mapped, the displayed colour
    vec3 hdr;     // linear, exposed
};

vec3 exposedRadiance(vec3 radiance, float exposure) {
    return min(radiance * exposure, vec3(kMaxRadiance));
}

vec3 toneMapShading(vec3 L, Shading shading, float exposure) {
    return toneMapAggregate(L, shading.specular * exposure, shading.specularVariance * (exposure * exposure));
}

vec3 toneMapOffLayer(vec3 L, OffLayerShading shading, float exposure) {
    return toneMapAggregate(L, shading.specular * exposure, shading.specularVariance * (exposure * exposure));
}

#if AGAA_EMISSIVE
// Per sample: each sample adds its own emission to its aggregate's radiance.
Resolved resolvePixel(ivec2 pixel, OffLayer off, OffLayerShading offShaded) {
    float exposure = frame.depthParams.z;
    float weight = 1.0 / float(kSamples);
    vec3 sky = skyRadiance(pixel) * exposure;
    Resolved r = Resolved(vec3(0.0), vec3(0.0));
    uint pixelIndex = aggregates[0].pixelIndex;
    for (uint s = 0u; s < kSamples; ++s) {
        if (((perSampleMembers >> s) & 1u) != 0u) continue; // the next pass's (shading_rate.glsl)
        float d = sampleDepth(pixel, s);
        if (isSky(d)) {
            r.display += weight * toneMapAces(sky);
            r.hdr += weight * sky;
            continue;
        }
        vec3 emission = texelFetch(emissiveSamples, ivec3(pixel, s / 4u), int(s % 4u)).rgb;
        uint id = sampleAggregate(s, pixelIndex);
        uint a = min(id, kAggregates - 1u); // c = 1: off-layer samples take aggregate 0's (accumulate path)
        // Fragment routing: a sample whose aggregate received no fragment takes aggregate 0's.
        if (kRouteFragment != 0u && !aggregates[a].present) a = 0u;
        if (id >= kAggregates &&
            kOffLayerOwnColour) { // c = 1, off the layer: its diffuse colour, their specular
            vec3 L = offLayerRadiance(offLayerSampleDiffuse(off.diffuse, pixel, s), offShaded) + emission;
            L = min(L * exposure, vec3(kMaxRadiance));
            r.display += weight * toneMapOffLayer(L, offShaded, exposure);
            r.hdr += weight * L;
            continue;
        }
        bool present = aggregates[a].present;
        vec3 L = (present ? shaded[a].radiance : vec3(0.0)) + emission;
        L = min(L * exposure, vec3(kMaxRadiance));
        r.display += weight * (present ? toneMapShading(L, shaded[a], exposure) : toneMapAces(L));
        r.hdr += weight * L;
    }
    return r;
}
#else
// Per aggregate: every sample of an aggregate shares its radiance; one tone map per aggregate,
// weighted by its sample count. Samples of an aggregate that received no fragment are black, and so
// are those of an aggregate the shading rate distrusts: the next pass adds theirs.
Resolved resolvePixel(ivec2 pixel, OffLayer off, OffLayerShading offShaded) {
    float exposure = frame.depthParams.z;
    float weight = 1.0 / float(kSamples);
    vec3 sky = skyRadiance(pixel) * exposure;
    float skyWeight = weight * float(walk.skySamples);
    Resolved r = Resolved(skyWeight * toneMapAces(sky), skyWeight * sky);
    for (uint a = 0u; a < kAggregates; ++a) {
        // c = 1: the aggregate stands for every covered sample, the off-layer ones too (with
        // fragment routing the fragments whose first sample is off the layer fed it nothing).
        uint stands = kRouteFragment != 0u && kAggregates > 1u
                          ? aggregates[a].accumulated
                          : walk.samplesIn[a] + (a == 0u && !kOffLayerOwnColour ? walk.offLayerSamples : 0u);
        if (a == 0u && kOffLayerOwnColour && walk.offLayerSamples > 0u) {
            vec3 L = exposedRadiance(offLayerRadiance(off.diffuse, offShaded), exposure);
            r.display += weight * float(walk.offLayerSamples) * toneMapOffLayer(L, offShaded, exposure);
            r.hdr += weight * float(walk.offLayerSamples) * L;
        }
        if (stands == 0u) continue;
        bool present = aggregates[a].present;
        vec3 L = present ? exposedRadiance(shaded[a].radiance, exposure) : vec3(0.0);
        float w = weight * float(stands);
        r.display += w * (present ? toneMapShading(L, shaded[a], exposure) : toneMapAces(L));
        r.hdr += w * L;
    }
    return r;
}
#endif
