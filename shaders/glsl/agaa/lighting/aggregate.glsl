// An aggregate as step 3 shades it: the means its generation path loaded (moments.glsl) and the
// walk's sums (pixel_samples.glsl), normalised into a surface with a filtered normal distribution
// (paper section 3.5.2): the Toksvig lobe of the mean vector, or the anisotropic lobe of the SGGX
// matrix (shared/sggx.h).
struct Aggregate {
    SurfaceInputs surface; // the lobe's normal; roughness: Toksvig's filtered one, or SGGX's material one
    vec3 tangent;          // SGGX: the lobe's axes and their alphas, clamped to the BRDF's range;
    vec3 bitangent;        // Toksvig: alphas = (filtered alpha, material alpha) for the spike ratio
    vec2 alphas;
    // The mean length of the aggregate's unit normals, the material's roughness taken out:
    // the spread the filtered diffuse integrates over (1: one direction).
    float spread;
    float environmentRoughness; // common/environment.glsl environmentAggregateRoughness
    vec3 position;              // view space, the shading point
    float depthSigma;           // its samples' depth deviation along the view ray (shadow footprint)
    vec3 screenSpread;          // the covariance (xx, xy, yy) of its samples' sub-pixel positions, pixel^2
    // Where its samples are: the pixel, and the id the metadata gives them.
    ivec2 pixel;
    uint pixelIndex;
    uint id;
    uint samples;     // the pixel's samples the metadata assigns it
    uint accumulated; // the samples its generation path summed (0: not present)
    bool present;
};

// The pixel's aggregates, module state as the walk's (pixel_samples.glsl): the per-sample resolve
// indexes them by the metadata's id, and lavapipe keeps a copied array of dynamic index in memory.
Aggregate aggregates[kMaxAggregates];

Aggregate normaliseAggregate(uint a, AggregateMoments m, ivec2 pixel, uint pixelIndex) {
    Aggregate ag;
    ag.pixel = pixel;
    ag.pixelIndex = pixelIndex;
    ag.id = a;
    ag.samples = walk.samplesIn[a];
    ag.present = aggregatePresent(a, walk.count, m.accumulated, walk.samplesIn[a]);
    ag.accumulated = ag.present ? m.accumulated : 0u;
    ag.tangent = vec3(0.0);
    ag.bitangent = vec3(0.0);
    ag.alphas = vec2(0.0);
    ag.spread = 1.0;
    ag.environmentRoughness = 0.0;
    ag.depthSigma = 0.0;
    ag.screenSpread = vec3(0.0);
    if (!ag.present) return ag;
    float fs = float(walk.samplesIn[a]);
    float meanDepth = walk.depthSum[a] / fs;
    // Position: the mean of the samples' view positions, or the UE4 shortcut (seed 004): the
    // mean depth on the pixel centre's ray.
    ag.position = agaa.options.y == 0u
                      ? walk.positionSum[a] / fs
                      : viewPositionAtDistance(vec2(pixel) + 0.5, meanDepth, frame.extent, frame.projParams);
    vec3 V = normalize(-ag.position); // |P| >= znear > 0
    ag.surface.albedo = m.albedo;
    ag.surface.metallic = m.metallic;
    if (kSggx) {
        SggxLobe lobe = sggxLobe(m.mean0.x, m.mean0.y, m.mean0.z, m.mean1.x, m.mean1.y, m.mean1.z, V,
                                 kSggxDegenerate, kMinSggxEigenvalue);
        {
            // A matrix's spread below the resolution of its sums is rounding (shared/sggx.h): the
            // fixed point's quantisation on the accumulate path, fp32 on the samples path.
            float step = kQuantizedMoments ? kSggxQuantizationSteps / float(unitScale(kSggxFieldBits, kSamples))
                                           : kSggxFloatRoundingStep;
            float material = clamp(m.materialAlpha, kMinGgxAlpha, kMaxGgxAlpha);
            lobe.alphaT = sggxDequantizedAlpha(lobe.alphaT, material, step);
            lobe.alphaB = sggxDequantizedAlpha(lobe.alphaB, material, step);
        }
        ag.surface.normal = lobe.normal;
        ag.tangent = lobe.tangent;
        ag.bitangent = lobe.bitangent;
        ag.alphas = clamp(vec2(lobe.alphaT, lobe.alphaB), kMinGgxAlpha, kMaxGgxAlpha);
        // The material alpha of the spike ratio (the anisotropic BRDF reads only the alphas).
        ag.surface.roughness = sqrt(clamp(m.materialAlpha, kMinGgxAlpha, ag.alphas.y));
        // The normals' spread from the matrix's second moment along the lobe normal, the
        // material's lobe taken out (S = (1 - a^2) E[N N^T] + a^2 I): m = E[(N.n)^2], and a vMF
        // lobe of mean length r has E[P2(N.n)] = (3m - 1) / 2 = r^3 (the band factors of
        // common/brdf.glsl filteredClampedCosine).
        vec3 nn = lobe.normal;
        float sn = dot(nn * nn, m.mean0) +
                   2.0 * (nn.x * nn.y * m.mean1.x + nn.x * nn.z * m.mean1.y + nn.y * nn.z * m.mean1.z);
        float a2 = clamp(m.materialAlpha, kMinGgxAlpha, kMaxGgxAlpha);
        a2 *= a2;
        float second = clamp((sn - a2) / (1.0 - a2), 1.0 / 3.0, 1.0); // 1 - a2 >= 1 - 0.81
        ag.spread = pow(1.5 * second - 0.5, 1.0 / 3.0);
    } else {
        float len = length(m.mean0);
        // |N| -> 0 when opposing normals cancel: no mean direction; shade facing the viewer
        // (the filtered roughness is then 1, so the direction barely matters).
        ag.surface.normal = len > kMinNormalLength ? m.mean0 / len : V;
        ag.surface.roughness = sqrt(filteredAlpha(len, agaa.toksvig.x)); // the BRDF squares it back
        // The Toksvig length is the normals' mean length times the material's own length
        // (toksvigLength(alpha) >= 0.32 for alpha <= kMaxGgxAlpha: the division is bounded).
        ag.spread = clamp(
            len / toksvigLength(m.materialAlpha, agaa.toksvig.x, agaa.toksvig.y, agaa.toksvig.z), 0.0, 1.0);
        float filtered = clamp(ag.surface.roughness * ag.surface.roughness, kMinGgxAlpha, kMaxGgxAlpha);
        ag.alphas = vec2(filtered, clamp(m.materialAlpha, kMinGgxAlpha, filtered));
    }
    ag.environmentRoughness = environmentAggregateRoughness(
        kSggx ? sqrt(ag.alphas.x * ag.alphas.y) : ag.alphas.x, m.rawMaterialAlpha);
    exportAggregate(pixelIndex, a, vec4(m.mean0, m.mean1.x), vec4(m.mean1.yz, m.albedo.rg),
                    vec4(m.albedo.b, m.metallic, float(m.accumulated), ag.surface.roughness),
                    vec4(ag.surface.normal, 1.0));
    // Depth variance (E[t^2] - E[t]^2, clamped: cancellation can make it slightly negative): the
    // aggregate's extent along the view ray, the footprint shadow filtering samples in.
    float meanShifted = walk.depthShifted[a] / fs;
    ag.depthSigma = sqrt(max(walk.depthSquares[a] / fs - meanShifted * meanShifted, 0.0));
    vec2 ms = walk.screenSum[a] / fs;
    ag.screenSpread = walk.screenSquares[a] / fs - vec3(ms.x * ms.x, ms.x * ms.y, ms.y * ms.y);
    return ag;
}
