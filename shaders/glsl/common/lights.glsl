#ifndef AGAA_LIGHTS_GLSL
#define AGAA_LIGHTS_GLSL
#include "common/epsilon.glsl"
#include "shared/frame.h"
// KHR_lights_punctual in glTF units: directional lights in lux, point and spot
// in candela with inverse-square falloff and the range window recommended by
// the extension: clamp(1 - (d/range)^4, 0, 1)^2.

float rangeWindow(float distance2, float range) {
    if (range <= 0.0) return 1.0; // undefined range: infinite
    float r = distance2 / (range * range);
    float w = clamp(1.0 - r * r, 0.0, 1.0);
    return w * w;
}

// Direction towards the light (unit) and the incoming radiance scale at P.
// Returns false when the light cannot reach P.
bool lightIncidence(GpuLight light, vec3 P, out vec3 L, out vec3 irradiance) {
    uint type = uint(light.directionType.w);
    if (type == kLightDirectional) {
        L = -light.directionType.xyz;
        irradiance = light.radiance.rgb;
        return true;
    }
    vec3 toLight = light.positionRange.xyz - P;
    float d2 = dot(toLight, toLight);
    // A light inside the geometry (d -> 0): the floor keeps 1/d^2 finite and the direction falls
    // back to the view axis, both below the same squared distance (m^2; issue 14: the direction
    // guard once squared it again, an m^4 threshold, so a light 1e-4..1e-2 m away kept its
    // direction while its falloff was already floored).
    L = d2 > kMinLightDistance2 ? toLight * inversesqrt(d2) : vec3(0.0, 0.0, 1.0);
    float attenuation = rangeWindow(d2, light.positionRange.w) / max(d2, kMinLightDistance2);
    if (type == kLightSpot) {
        float cd = dot(light.directionType.xyz, -L);
        float s = clamp((cd - light.spot.x) * light.spot.y, 0.0, 1.0);
        attenuation *= s * s;
    }
    irradiance = light.radiance.rgb * attenuation;
    return attenuation > 0.0;
}
#endif
