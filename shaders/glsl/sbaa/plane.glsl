#ifndef AGAA_SBAA_PLANE_GLSL
#define AGAA_SBAA_PLANE_GLSL
// The depth tolerance of a surface's plane for SBAA's MERGE test: how much view-space depth the
// plane through the representative sample changes over one pixel step in x plus one in y,
// |dz/dx| + |dz/dy| = t0 (|N.x| dD/dx + |N.y| dD/dy) / |N.D0| for the ray t D(q) (the same
// analytic slope Lauritzen's classification uses; this technique keeps its own copy), plus a
// relative floor for face-on planes. Requires `frame` and common/epsilon.glsl.
float sbaaPlaneDepthTolerance(vec2 pixelPos0, float t0, vec3 n0, float slopeScale) {
    vec2 ndc = pixelPos0 * frame.extent.zw * 2.0 - 1.0;
    vec3 D = vec3(ndc.x / frame.projParams.x, ndc.y / frame.projParams.y, -1.0);
    vec2 dDdq = 2.0 * frame.extent.zw / abs(frame.projParams.xy);
    float NoD = max(abs(dot(n0, D)), kMinCosine * length(D)); // grazing: the normal test decides
    float slope = t0 * (abs(n0.x) * dDdq.x + abs(n0.y) * dDdq.y) / NoD;
    return slopeScale * slope + kDepthCompareRelative * t0;
}
#endif
