#ifndef AGAA_FACE_NORMAL_GLSL
#define AGAA_FACE_NORMAL_GLSL
#include "common/epsilon.glsl"
// The primitive's face normal (paper section 3.2: "the primitive's normal (from the plane, no
// normal map perturbation)"), in view space, from the screen-space derivatives of the
// interpolated view position: a triangle's attributes are interpolated with its own plane
// equation (helper invocations included), so the two derivatives span that plane exactly, up to
// rounding. (gl_PrimitiveID would need the Geometry capability in a fragment shader.)
// Oriented towards the viewer: back faces of double-sided materials come out flipped.
vec3 viewFaceNormal(vec3 viewPosition, vec3 towardsCamera) {
    vec3 n = cross(dFdx(viewPosition), dFdy(viewPosition));
    float len = length(n);
    // A sliver seen edge-on can have (numerically) no area: face the camera.
    n = len > kMinNormalLength * kMinNormalLength ? n / len : towardsCamera;
    return dot(n, towardsCamera) < 0.0 ? -n : n;
}
#endif
