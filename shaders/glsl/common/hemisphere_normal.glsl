#ifndef AGAA_HEMISPHERE_NORMAL_GLSL
#define AGAA_HEMISPHERE_NORMAL_GLSL
#include "common/epsilon.glsl"
#include "shared/clustering.h"
// Face normals as two 8-bit spherical angles over the visible hemisphere (paper section 3.2):
// the frame is built around V, the unit direction from the pixel centre's view ray to the
// camera (shared/clustering.h, shared with the decoder and its CPU twin), so back-face-culled
// (or flipped) normals, which face the camera, fit in theta <= pi/2.

vec3 pixelToCamera(uvec2 pixel, vec4 ndcParams) {
    float vx, vy, vz;
    pixelCentreToCamera(pixel.x, pixel.y, ndcParams.x, ndcParams.y, ndcParams.z, ndcParams.w, vx, vy, vz);
    return vec3(vx, vy, vz);
}

uvec2 encodeHemisphereNormal(vec3 N, vec3 V) {
    float tx, ty, tz, bx, by, bz;
    hemisphereBasis(V.x, V.y, V.z, tx, ty, tz, bx, by, bz);
    float c = clamp(dot(N, V), 0.0, 1.0); // a grazing normal just past the rim clamps onto it
    float theta = acos(c);
    // atan(0, 0) (N == V) is implementation-defined but finite; phi is irrelevant at theta = 0.
    float phi = atan(dot(N, vec3(bx, by, bz)), dot(N, vec3(tx, ty, tz)));
    uint qt = uint(clamp(round(theta * (255.0 / 1.5707963)), 0.0, 255.0));
    uint qp = uint(round((phi * 0.15915494 + 0.5) * 256.0)) & 255u;
    return uvec2(qt, qp);
}
#endif
