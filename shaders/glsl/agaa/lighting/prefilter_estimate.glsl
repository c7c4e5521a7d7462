// The error-driven shading rate's estimate (docs/decisions/shading-rate-estimate.md): how far an
// aggregate's normals spread against the lobe of its sharpest member. For small spreads
// 2 (1 - |mean unit normal|) is about the normals' variance in slope space, and alpha^2 is the
// GGX lobe's; their ratio is large where one filtered lobe stands for highlights its samples
// would each place elsewhere, which is where lighting the aggregate once fails. Measured against
// the converged truth, it ranks the pixels that hold most of the pre-filter's error first.
// Both loaders sum it in the walk from each covered sample's own material: the samples path's
// G-buffer (load_samples.glsl), the accumulate path's per-sample material (load_accumulated.glsl).
layout(constant_id = kSpecLightingShadingRate) const uint kShadingRate = 0u;

// Below this, 1 - |mean unit normal| is the rounding of the sum of up to 32 unit normals in fp32
// (each of length 1 +- a few 2^-24: a few 1e-6), not a spread: a flat pixel's estimate is 0, and
// only a tolerance of 0 flags it.
const float kNormalSpreadFloor = 1.0e-5;

// One sample's material, as each loader's loadSampleMaterial reads it.
struct SampleMaterial {
    vec3 normal; // unit, view space
    vec4 albedoMetal;
    float roughness;
};

struct SpreadSums {
    vec3 normalSum[kMaxAggregates]; // the members' unit shading normals
    float alphaMin[kMaxAggregates]; // the sharpest member's GGX alpha, at least kMinGgxAlpha
};

// Module state, as the walk's (pixel_samples.glsl): indexed by the metadata's aggregate id.
SpreadSums spreadSums;

void clearSpreadSums() {
    spreadSums.normalSum = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    spreadSums.alphaMin = float[](1.0, 1.0, 1.0, 1.0);
}

void addSpreadSample(uint a, vec3 N, float alpha) {
    if (kShadingRate == 0u) return;
    for (uint k = 0u; k < kAggregates; ++k) { // constant indices (pixel_samples.glsl)
        bool mine = k == a;
        spreadSums.normalSum[k] += mine ? N : vec3(0.0);
        spreadSums.alphaMin[k] =
            mine ? min(spreadSums.alphaMin[k], max(alpha, kMinGgxAlpha)) : spreadSums.alphaMin[k];
    }
}

// The estimate of aggregate a, whose walk counted `samples` samples: 0 for one sample or one
// direction.
float prefilterEstimate(uint a, uint samples) {
    if (samples < 2u) return 0.0;
    float spread = 1.0 - length(spreadSums.normalSum[a]) / float(samples);
    if (spread <= kNormalSpreadFloor) return 0.0;
    float sharpest = spreadSums.alphaMin[a]; // >= kMinGgxAlpha
    return 2.0 * spread / (sharpest * sharpest);
}
