// Step 1's one walk over a pixel's n samples (paper section 3.5): per aggregate, the sample count,
// the depth mean and variance, the mean view position and the sub-pixel positions' covariance,
// from the per-sample depths the clustering's metadata assigns it; the pixel's sky samples, c = 1's
// off-layer samples, and the pixel's view-distance range for the tile bounds. The generation
// path's loader adds each covered sample's material (sumSampleMaterial).

// Sample s's aggregate id from the bit-packed metadata (shared/clustering.h; c = 1: kOffLayer
// marks a sample off aggregate 0's layer).
uint sampleAggregate(uint s, uint pixelIndex) {
    const uint words = (kSamples * metadataBits(kAggregates) + 31u) / 32u;
    const uint c = kAggregates;
    return unpackMetadata(metadata[pixelIndex * words + (s * metadataBits(c)) / 32u], s, c);
}

float sampleDepth(ivec2 pixel, uint s) {
    return texelFetch(visibilityDepth, ivec3(pixel, s / 4u), int(s % 4u)).r;
}

vec3 sampleViewPosition(ivec2 pixel, uint s, float d) {
    return viewPositionFromDepth(vec2(pixel) + frame.samplePositions[s].xy, d, frame.extent,
                                 frame.depthParams, frame.projParams);
}

struct PixelSamples {
    uint count;      // aggregates the clustering made in this pixel
    uint skySamples; // uncovered samples
    // c = 1: covered samples off aggregate 0's layer (off_layer.glsl), and their view positions.
    uint offLayerSamples;
    vec3 offLayerPositionSum;
    float tmin, tmax; // the covered samples' view distances
    uint samplesIn[kMaxAggregates];
    float depthSum[kMaxAggregates];
    // Depths relative to the pixel's first covered sample, for the variance: E[t^2] - E[t]^2 at
    // t ~ metres cancels in fp32 below about 1e-6 t^2, the whole spread of a face-on pixel.
    float depthShifted[kMaxAggregates];
    float depthSquares[kMaxAggregates];
    vec3 positionSum[kMaxAggregates];
    vec2 screenSum[kMaxAggregates];     // sub-pixel positions
    vec3 screenSquares[kMaxAggregates]; // (xx, xy, yy)
};

// The invocation's walk, module state rather than a value: its arrays are indexed by the
// metadata's aggregate id, and lavapipe keeps a copied array of dynamic index in memory (passing
// it by value cost the pass 15 to 30 %).
PixelSamples walk;

void walkPixelSamples(ivec2 pixel, uint pixelIndex, bool inside) {
    walk.count = inside ? imageLoad(aggregateCount, pixel).r : 0u;
    walk.skySamples = 0u;
    walk.offLayerSamples = 0u;
    walk.offLayerPositionSum = vec3(0.0);
    walk.tmin = 1e30;
    walk.tmax = -1e30;
    walk.samplesIn = uint[](0u, 0u, 0u, 0u);
    walk.depthSum = float[](0.0, 0.0, 0.0, 0.0);
    walk.depthShifted = float[](0.0, 0.0, 0.0, 0.0);
    walk.depthSquares = float[](0.0, 0.0, 0.0, 0.0);
    walk.positionSum = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    walk.screenSum = vec2[](vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0));
    walk.screenSquares = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    if (!inside) return;
    float depthOrigin = -1.0;
    for (uint s = 0u; s < kSamples; ++s) {
        float d = sampleDepth(pixel, s);
        if (isSky(d)) {
            walk.skySamples += 1u;
            exportSample(pixelIndex, s, vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));
            continue;
        }
        uint a = sampleAggregate(s, pixelIndex);
        vec3 P = sampleViewPosition(pixel, s, d);
        walk.tmin = min(walk.tmin, -P.z);
        walk.tmax = max(walk.tmax, -P.z);
        // c = 1, off the aggregate's layer: the sample's coverage joins aggregate 0, its position
        // and normal distribution do not; its colour joins aggregate 0's on the accumulate path,
        // and is resolved on its own on the samples path (off_layer.glsl).
        bool offLayer = a >= kAggregates;
        if (offLayer) {
            walk.offLayerSamples += 1u;
            walk.offLayerPositionSum += P;
            a = 0u;
        }
        sumSampleMaterial(pixel, pixelIndex, s, a, offLayer, P);
        if (offLayer) continue;
        float t = -P.z;
        if (depthOrigin < 0.0) depthOrigin = t;
        float shifted = t - depthOrigin;
        vec2 sp = frame.samplePositions[s].xy;
        vec3 spSquares = vec3(sp.x * sp.x, sp.x * sp.y, sp.y * sp.y);
        // Every aggregate's sums at a constant index, the sample's own taking it:
        // indexed by the sample's id, llvmpipe gathers and scatters each lane's element of an
        // array it keeps in memory; at a constant index it loads and stores the whole vector.
        for (uint k = 0u; k < kAggregates; ++k) {
            bool mine = k == a;
            walk.depthSum[k] += mine ? t : 0.0;
            walk.depthShifted[k] += mine ? shifted : 0.0;
            walk.depthSquares[k] += mine ? shifted * shifted : 0.0;
            walk.positionSum[k] += mine ? P : vec3(0.0);
            walk.samplesIn[k] += mine ? 1u : 0u;
            walk.screenSum[k] += mine ? sp : vec2(0.0);
            walk.screenSquares[k] += mine ? spSquares : vec3(0.0);
        }
    }
}
