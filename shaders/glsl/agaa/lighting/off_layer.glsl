// c = 1's samples off the aggregate's layer (shared/clustering.h kOffLayer): a surface the one
// shading event does not describe, behind or in front of the layer, with normals the aggregate
// does not carry. They resolve as one surface of their own: Lambert of their mean diffuse colour
// (with emission, which resolves per sample, the samples path takes each sample's own) under their
// own irradiance, and GGX of their mean F0 through their own mean normal and its Toksvig-filtered
// alpha. Their light comes from the tile's lights at their mean position, through their mean
// normal's lobe (filteredClampedCosine and the environment's bands), each shadowed light taken by
// one tap at that position. A chrome wall behind a sphere's rim takes the wall's own flat normals
// there, not the rim's; a metal bar behind the layer keeps its specular.
struct OffLayer {
    uint samples;
    vec3 diffuse;        // mean albedo (1 - metallic)
    vec4 position;       // their mean view position; w = 1 where the pixel has off-layer samples
    vec4 lobe;           // their mean normal's direction and length (meanNormalLobe)
    vec4 specular;       // F0, and the roughness Toksvig filters from the lobe's length
    float materialAlpha; // their samples' mean material alpha (the two-point resolve's)
};

OffLayer offLayerSurface(OffLayerMeans means) {
    OffLayer off;
    off.samples = walk.offLayerSamples;
    off.diffuse = means.diffuse;
    off.position = walk.offLayerSamples > 0u
                       ? vec4(walk.offLayerPositionSum / float(walk.offLayerSamples), 1.0)
                       : vec4(0.0);
    off.lobe = meanNormalLobe(means.normal);
    // Toksvig's filtered alpha from the normals' mean length times the material's own Toksvig
    // length (the aggregates' Toksvig path, section 4.4), as a roughness.
    off.specular =
        vec4(means.f0Alpha.rgb, sqrt(filteredAlpha(off.lobe.w * toksvigLength(means.f0Alpha.w, agaa.toksvig.x,
                                                                              agaa.toksvig.y, agaa.toksvig.z),
                                                   agaa.toksvig.x)));
    off.materialAlpha = means.f0Alpha.w;
    return off;
}

// The aggregates of the tile list and c >= 2 have none.
OffLayer noOffLayer(Aggregate ag) {
    return OffLayer(0u, vec3(0.0), vec4(0.0), vec4(ag.surface.normal, ag.spread), vec4(0.0), 0.0);
}

// What the lights give the off-layer samples: diffuse irradiance, specular radiance towards the
// eye, and its variance over their samples (the two-point resolve's, as an aggregate's).
struct OffLayerShading {
    vec3 irradiance;
    vec3 specular;
    vec3 specularSquares;
    vec3 specularVariance;
};

OffLayerShading noOffLayerShading() {
    return OffLayerShading(vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
}

// What light i gives the off-layer samples, unshadowed, from their mean position (a wall behind
// leaves is not where the leaves are: the range window and 1/d^2 differ): the irradiance through
// their normals' lobe, and the specular radiance towards the eye through the same mean normal.
// False where the light does not reach that position.
bool offLayerLight(uint i, OffLayer off, out vec3 irradiance, out vec3 specular) {
    irradiance = vec3(0.0);
    specular = vec3(0.0);
    vec3 L, incidence;
    // kAggregates: a specialisation constant, so c >= 2 (no off-layer samples) compiles this away.
    if (kAggregates != 1u || off.position.w == 0.0 ||
        !lightIncidence(lights[i], off.position.xyz, L, incidence))
        return false;
    irradiance = incidence * filteredClampedCosine(dot(off.lobe.xyz, L), off.lobe.w);
    SurfaceInputs surface;
    surface.albedo = off.specular.rgb; // metallic 1: F0 is the albedo, and no diffuse lobe
    surface.metallic = 1.0;
    surface.roughness = off.specular.w;
    surface.normal = off.lobe.xyz;
    specular = evaluateBrdf(surface, normalize(-off.position.xyz), L, incidence); // |P| >= znear
    return true;
}

// The spread of their specular over their samples: their Toksvig lobe (filtered, material
// alpha), as an aggregate's. Without it the spike ball's off-layer gold, a wide lobe of the same
// mean, tone-mapped to a glow: 1.38x no-AA's display error at c = 1.
void offLayerSpecularVariance(OffLayer off, inout OffLayerShading shading) {
    if (kAggregates != 1u || off.position.w == 0.0) return;
    float filtered = clamp(off.specular.w * off.specular.w, kMinGgxAlpha, kMaxGgxAlpha);
    float axis = spikeRatioAxis(filtered, clamp(off.materialAlpha, kMinGgxAlpha, filtered));
    shading.specularVariance = (axis * axis - 1.0) * shading.specularSquares;
}

// An off-layer sample's linear radiance before exposure, emission aside.
vec3 offLayerRadiance(vec3 diffuseColour, OffLayerShading shading) {
    return diffuseColour / kPi * shading.irradiance + shading.specular;
}
