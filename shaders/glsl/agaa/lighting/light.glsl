// One light's contribution to an aggregate (paper section 3.5): the reference's BRDF
// (common/brdf.glsl) through the aggregate's filtered lobe, its radiance, its specular part and
// the square of that. The two-point resolve's variance is (spike ratio - 1) times the sum of the
// squares: the highlights of different lights fall on different samples, so their variances add.
struct Shading {
    vec3 radiance; // linear, before exposure
    vec3 specular; // its specular part
    vec3 specularSquares;
    vec3 specularVariance; // over the aggregate's samples (shade.glsl)
};

Shading noShading() {
    return Shading(vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
}

// What step 3 gives each of the pixel's aggregates (module state, as aggregate.glsl's aggregates).
Shading shaded[kMaxAggregates];

// The aggregate's lobe seen from V (common/brdf.glsl): what its lights share, made once per
// shading event. kSggx picks which one is made; the other is left unset and compiled away.
struct AggregateLobe {
    FilteredLobe toksvig;
    AnisotropicLobe sggx;
};

AggregateLobe aggregateLobe(Aggregate ag, vec3 V) {
    AggregateLobe lobe;
    if (kSggx)
        lobe.sggx = anisotropicLobe(ag.surface, ag.tangent, ag.bitangent, ag.alphas.x, ag.alphas.y, ag.spread, V);
    else
        lobe.toksvig = filteredLobe(ag.surface, ag.spread, V);
    return lobe;
}

void addLight(Aggregate ag, AggregateLobe lobe, vec3 V, vec3 L, vec3 irradiance, inout vec3 radiance,
              inout vec3 specular, inout vec3 specularSquares) {
    vec3 spec;
    if (kSggx)
        radiance += evaluateAnisotropicLobe(ag.surface, lobe.sggx, ag.tangent, ag.bitangent, V, L, irradiance, spec);
    else
        radiance += evaluateFilteredLobe(ag.surface, lobe.toksvig, V, L, irradiance, spec);
    specular += spec;
    specularSquares += spec * spec;
}

// addLight for a near mirror (viewFootprintWeight > 0): the light seen from each of the
// aggregate's samples' own view direction, through the aggregate's lobe, averaged and blended
// with the one view direction by the weight t. On a flat mirror that is what per-sample shading
// gives those samples: hard-mirror's sun peak on the chrome wall falls between pixel centres, and
// one view direction a pixel finds it or misses it. Widening the lobe by the footprint instead
// draws halos: a GGX lobe's tails reach much further than the pixel's box. The specular's square
// goes in once, for the average: the view directions' spread is the footprint's, not the lobe's
// spike.
void addLightFootprint(Aggregate ag, AggregateLobe lobe, vec3 V, vec3 L, vec3 irradiance, float t,
                       inout Shading shading) {
    vec3 one = vec3(0.0), oneSpecular = vec3(0.0), unused = vec3(0.0);
    addLight(ag, lobe, V, L, irradiance, one, oneSpecular, unused);
    vec3 each = vec3(0.0), eachSpecular = vec3(0.0);
    uint count = 0u;
    for (uint s = 0u; s < kSamples; ++s) {
        float d = sampleDepth(ag.pixel, s);
        if (isSky(d) || sampleAggregate(s, ag.pixelIndex) != ag.id) continue;
        vec3 Vs = normalize(-sampleViewPosition(ag.pixel, s, d));
        addLight(ag, aggregateLobe(ag, Vs), Vs, L, irradiance, each, eachSpecular, unused);
        ++count;
    }
    if (count > 0u) {
        one = mix(one, each / float(count), t);
        oneSpecular = mix(oneSpecular, eachSpecular / float(count), t);
    }
    shading.radiance += one;
    shading.specular += oneSpecular;
    shading.specularSquares += oneSpecular * oneSpecular;
}

// Light L's irradiance at the aggregate, through its lobe; viewWeight > 0 on near mirrors.
void addAggregateLight(Aggregate ag, AggregateLobe lobe, vec3 V, float viewWeight, vec3 L, vec3 irradiance,
                       inout Shading shading) {
    if (viewWeight > 0.0)
        addLightFootprint(ag, lobe, V, L, irradiance, viewWeight, shading);
    else
        addLight(ag, lobe, V, L, irradiance, shading.radiance, shading.specular, shading.specularSquares);
}
