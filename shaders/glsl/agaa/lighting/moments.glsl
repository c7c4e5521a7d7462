// What a generation path hands step 1 of the lighting pass: one aggregate's means, and c = 1's
// off-layer samples' means. agaa/lighting/load_accumulated.glsl and load_samples.glsl each fill
// them from their own storage; agaa/lighting/aggregate.glsl turns them into the shaded surface.

// One aggregate's means over its samples.
struct AggregateMoments {
    uint accumulated; // samples its generation path summed (0: not present)
    vec3 mean0;       // Toksvig: the mean Toksvig vector; SGGX: the matrix's diagonal
    vec3 mean1;       // SGGX: the off-diagonal (xy, xz, yz); Toksvig: 0
    vec3 albedo;
    float metallic;
    float materialAlpha;    // the samples' mean GGX alpha, in the BRDF's range
    float rawMaterialAlpha; // the same below the BRDF's floor: a near mirror's environment level
};

// c = 1's samples off the aggregate's layer (shared/clustering.h kOffLayer): their means.
struct OffLayerMeans {
    vec3 diffuse; // albedo (1 - metallic)
    vec3 normal;  // the mean of their unit shading normals (its length: their spread)
    vec4 f0Alpha; // F0, and the mean material alpha
};

OffLayerMeans noOffLayerMeans() {
    return OffLayerMeans(vec3(0.0), vec3(0.0), vec4(0.0));
}

// An aggregate is lit when the clustering made it (a < count), its generation path summed a
// sample into it (accumulated) and the metadata assigns it one of the pixel's samples (samplesIn).
// Otherwise it has nothing to normalise: its samples resolve to black, not to a division by 0.
bool aggregatePresent(uint a, uint count, uint accumulated, uint samplesIn) {
    return a < count && accumulated > 0u && samplesIn > 0u;
}
