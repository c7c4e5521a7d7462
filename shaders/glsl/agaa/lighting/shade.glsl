// One shading event (paper section 3.5): an aggregate lit once by the environment and by every
// light of its tile, with the variance of its specular over its samples for the two-point
// resolve (common/tonemap.glsl toneMapAggregate, shared/sggx.h spike ratio). At c = 1 the pixel's
// off-layer samples are lit in the same pass over the lights (off_layer.glsl).
void shadeAggregate(Aggregate ag, OffLayer off, out Shading shading, out OffLayerShading offShading) {
    shading = noShading();
    offShading = noOffLayerShading();
    vec3 V = normalize(-ag.position); // |P| >= znear > 0
    // What the lights share: the lobe's Fresnel, alpha, view terms and diffuse band factors.
    AggregateLobe lobe = aggregateLobe(ag, V);
    // Near mirrors: the view directions' spread over the footprint against the lobe (light.glsl
    // addLightFootprint).
    float theta = pixelFootprint(-ag.position.z, frame.extent, frame.projParams) / length(ag.position);
    float viewWeight =
        kViewFootprint != 0u
            ? viewFootprintWeight(theta, ag.screenSpread, kSggx ? min(ag.alphas.x, ag.alphas.y) : ag.alphas.x)
            : 0.0;
    // The environment through the aggregate's filtered distribution: its mean normal and its
    // filtered roughness without the punctual BRDF's floor. Smooth at the scale of an aggregate:
    // no spike, so it stays out of the two-point resolve's variance.
    if (kEnvironment != 0u) {
        shading.radiance += environmentLightingFiltered(ag.surface, V, ag.environmentRoughness, ag.spread);
        float r = off.lobe.w; // the lobe's band factors, as filteredClampedCosine's
        if (kAggregates == 1u && off.position.w != 0.0)
            offShading.irradiance +=
                environmentIrradiance(environmentDirection(off.lobe.xyz), vec2(r, r * r * r));
    }
    for (uint i = nextTileLight(0u); i < kMaxLights; i = nextTileLight(i + 1u)) {
        vec3 offLayerE, offLayerS;
        if (offLayerLight(i, off, offLayerE, offLayerS)) {
            offShading.irradiance += offLayerE;
            offShading.specular += offLayerS;
            offShading.specularSquares += offLayerS * offLayerS;
        }
        vec3 L, irradiance;
        if (!lightIncidence(lights[i], ag.position, L, irradiance)) continue;
        addAggregateLight(ag, lobe, V, viewWeight, L, irradiance, shading);
    }
    addShadowedLights(ag, lobe, off, V, viewWeight, shading, offShading);
    // The spike ratio E[L^2] / E[L]^2 of the aggregate's samples (shared/sggx.h), once per event:
    // SGGX, alphas = (alphaT, alphaB) with the material alpha in surface.roughness; Toksvig,
    // alphas = (filtered alpha, material alpha), both axes alike.
    float axis = spikeRatioAxis(ag.alphas.x, ag.alphas.y);
    float ratio = kSggx
                      ? sggxSpikeRatio(ag.alphas.x, ag.alphas.y, ag.surface.roughness * ag.surface.roughness)
                      : axis * axis;
    shading.specularVariance = (ratio - 1.0) * shading.specularSquares;
    offLayerSpecularVariance(off, offShading);
}
