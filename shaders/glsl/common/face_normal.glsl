#ifndef AGAA_FACE_NORMAL_GLSL
#define AGAA_FACE_NORMAL_GLSL
#include "common/epsilon.glsl"
// The primitive's face normal (paper section 3.2: "the primitive's normal (from the plane, no
// normal map perturbation)"), in view space, from the screen-space derivatives of the
// interpolated view position: a triangle's attributes are interpolated with its own plane
// equation (helper invocations included), so the two derivatives span that plane exactly, up to
// rounding. (gl_PrimitiveID would need the Geometry capability in a fragment shader.)
// Oriented towards the viewer: back faces of double-sided materials come out flipped.
// The guard is relative: |dPdx x dPdy| = |dPdx| |dPdy| sin(angle), and only a sliver seen edge-on
// (parallel derivatives, sin -> 0) has no plane, whatever the footprint's size. An absolute area
// floor (issue 14: 1e-12 m^2) sent every micrometre-sized footprint (the near-plane hard case) to
// the fallback although its plane was well defined.
vec3 faceNormalFromDerivatives(vec3 dPdx, vec3 dPdy, vec3 towardsCamera) {
    vec3 n = cross(dPdx, dPdy);
    float len = length(n);
    float scale = length(dPdx) * length(dPdy); // 0 (also by underflow): no plane, as sin -> 0
    n = len > kMinFaceNormalSine * scale ? n / len : towardsCamera;
    return dot(n, towardsCamera) < 0.0 ? -n : n;
}

// Fragment shaders only (the derivatives); AGAA_NO_DERIVATIVES: a compute includer (the math test).
#ifndef AGAA_NO_DERIVATIVES
vec3 viewFaceNormal(vec3 viewPosition, vec3 towardsCamera) {
    return faceNormalFromDerivatives(dFdx(viewPosition), dFdy(viewPosition), towardsCamera);
}
#endif
#endif
