#ifndef AGAA_SHARED_ENVIRONMENT_H
#define AGAA_SHARED_ENVIRONMENT_H
#include "shared/glsl_cpp.h"

SHARED_BEGIN

// Pre-filtered specular levels of the environment (engine/frame/environment_maps.h): layer k of
// the array texture holds the map convolved for perceptual roughness k / (levels - 1).
SHARED_CONST kEnvironmentLevels = 6u;

// Written once per scene by engine/frame/gpu_scene.cpp, read by every lighting pass that
// includes common/environment.glsl.
struct EnvironmentConstants {
    // Irradiance E(n) = sum_i irradianceSh[i].rgb Y_i(n) for a world-space unit normal n, with the
    // real spherical harmonics of bands 0..2 (Ramamoorthi and Hanrahan 2001: the radiance's
    // coefficients already convolved with the clamped cosine), lux.
    vec4 irradianceSh[9];
    // x: 1 when the scene has an environment; y: the texels' scale (stored = radiance / y, so
    // half floats hold a 100 klux sky); z: levels - 1; w unused.
    vec4 params;
};

SHARED_END
#endif
