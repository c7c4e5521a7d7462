#ifndef AGAA_SIMPLE_COMPLEX_CLASSIFY_GLSL
#define AGAA_SIMPLE_COMPLEX_CLASSIFY_GLSL
// Simple/complex pixel classification (Lauritzen 2010, "Deferred Rendering for
// Current and Future Rendering Pipelines", RequiresPerSampleShading): a pixel is
// complex when any sample departs from sample 0. The CPU twin is
// agaa::isComplexPixel (agaa/simple_complex/classify.cpp); the two must agree.
// Requires common/gbuffer_lighting.glsl (G-buffer fetches, depth helpers).

// Depth tolerance for sample 0's surface: how much view-space depth the plane through
// sample 0 with sample 0's normal changes over one pixel step in x plus one in y,
// |dz/dx| + |dz/dy|, the quantity Lauritzen takes from the position derivatives he
// stores in the G-buffer. We store none, so the slope is derived analytically: the
// ray through pixel position q is t D(q), D = (ndc.x / P00, ndc.y / P11, -1); on the
// plane N.X = N.P0 the depth is z(q) = -(N.P0) / (N.D(q)), so
//   dz/dq = (N.P0)(N.dD/dq) / (N.D)^2 = t0 (N.dD/dq) / (N.D0)   (N.P0 = t0 N.D0).
// Every sample lies less than one pixel from sample 0 in x and in y, so a sample on
// the same plane stays within this tolerance up to the plane's curvature in screen
// space. Plus a relative floor (kDepthCompareRelative) for face-on planes.
float planeDepthTolerance(vec2 pixelPos0, float t0, vec3 n0, float slopeScale) {
    vec2 ndc = pixelPos0 * frame.extent.zw * 2.0 - 1.0;
    vec3 D = vec3(ndc.x / frame.projParams.x, ndc.y / frame.projParams.y, -1.0);
    vec2 dDdq = 2.0 * frame.extent.zw / abs(frame.projParams.xy); // |dD.x/dq.x|, |dD.y/dq.y|
    // |N.D0| = |N.V| |D0|: at grazing view (N.V -> 0) the plane's depth slope goes to
    // infinity; the N.V floor keeps it finite (only the normal test then decides).
    float NoD = max(abs(dot(n0, D)), kMinCosine * length(D));
    float slope = t0 * (abs(n0.x) * dDdq.x + abs(n0.y) * dDdq.y) / NoD;
    return slopeScale * slope + kDepthCompareRelative * t0;
}

// Sky samples differ from geometry; two sky samples are equal.
bool isComplexPixel(ivec2 pixel, float minNormalCos, float slopeScale) {
#ifdef AGAA_TEST_PERTURB_METHODS
    return false; // tools/perturb-test.sh: every pixel simple, shaded once
#endif
    uint n = frame.counts.x;
    float d0 = gbufferDepth(pixel, 0u);
    bool sky0 = isSky(d0);
    float t0 = 0.0, tolerance = 0.0;
    vec3 n0 = vec3(0.0, 0.0, 1.0);
    if (!sky0) {
        t0 = viewDistanceFromDepth(d0, frame.depthParams.x, frame.depthParams.y);
        n0 = gbufferNormal(pixel, 0u);
        tolerance = planeDepthTolerance(vec2(pixel) + frame.samplePositions[0].xy, t0, n0, slopeScale);
    }
    for (uint s = 1u; s < n; ++s) {
        float d = gbufferDepth(pixel, s);
        bool sky = isSky(d);
        if (sky != sky0) return true;
        if (sky) continue;
        float t = viewDistanceFromDepth(d, frame.depthParams.x, frame.depthParams.y);
        if (abs(t - t0) > tolerance) return true;
        if (dot(gbufferNormal(pixel, s), n0) < minNormalCos) return true;
    }
    return false;
}
// Where a simple, covered pixel is shaded: sample 0's plane (its depth and normal) at
// the pixel centre, the centroid of every sample pattern (engine/frame/sample_pattern.h).
// Lauritzen shades sample 0 at its own position; that is a first-order bias towards
// wherever sample 0 sits (0.4 px off centre at n = 4), visible near point lights. The
// centre's shade equals the average over the pixel's samples to second order, as the
// reference's resolve does. A simple pixel's samples all lie within the depth tolerance
// of sample 0, so the centre's view distance is clamped to it, which also bounds the
// ray-plane intersection at grazing angles.
vec3 simplePixelShadingPoint(ivec2 pixel, float slopeScale) {
    float d0 = gbufferDepth(pixel, 0u);
    float t0 = viewDistanceFromDepth(d0, frame.depthParams.x, frame.depthParams.y);
    vec3 n0 = gbufferNormal(pixel, 0u);
    vec2 pos0 = vec2(pixel) + frame.samplePositions[0].xy;
    vec3 P0 = viewPositionAtDistance(pos0, t0, frame.extent, frame.projParams);
    vec2 centre = vec2(pixel) + 0.5;
    vec2 ndc = centre * frame.extent.zw * 2.0 - 1.0;
    vec3 D = vec3(ndc.x / frame.projParams.x, ndc.y / frame.projParams.y, -1.0); // view distance t at t D
    float NoD = dot(n0, D);
    float tolerance = planeDepthTolerance(pos0, t0, n0, slopeScale);
    // The ray meets the plane N.X = N.P0 at t = N.P0 / N.D; edge-on (N.D -> 0) it does not: keep t0.
    float t = abs(NoD) > kMinCosine * length(D) ? dot(n0, P0) / NoD : t0;
    return viewPositionAtDistance(centre, clamp(t, t0 - tolerance, t0 + tolerance), frame.extent, frame.projParams);
}
#endif
