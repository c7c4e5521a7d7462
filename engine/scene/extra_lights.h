#pragma once
// The light-count axis (issue 15): K generated point lights added to a scene, so a method's
// frame time can be measured as the number of lights grows (Simple/Complex lights every sample of
// a complex pixel once per light; AGAA lights c aggregates once per light).
//
// Placement: light i (0-based) sits at the point of the Halton sequence with index i + 1 in bases
// 2, 3 and 5, mapped into the scene's bounds grown by kExtraLightMargin of its diagonal on every
// side (a flat scene gets lights above and below it, not inside its one plane). The sequence is
// low-discrepancy, so any prefix of it spreads evenly over the box, and deterministic: the same
// scene and K give the same lights, bit for bit.
//
// Intensity: the lights split the box's volume V between them; each light's neighbourhood is a
// sphere of radius r = 0.5 (V / K)^(1/3) (half the mean spacing). Its intensity I = E r^2 (cd)
// gives a surface at the neighbourhood's edge the illuminance E of the scene's key light (the
// single light giving the most illuminance at the bounds' centre, lightIlluminanceAt per light;
// 1 lux when the scene has no light). Each light's range (the glTF falloff window) is 4 r, so
// tile light culling has something to cull once K is large. White, no shadows.

#include "engine/scene/scene.h"

#include <cstdint>

namespace eng::scene {

// The most lights --extra-lights adds: the renderer holds shared::kMaxLights (1024), and the
// scene's own lights (the built-ins have 17) need room beside them.
inline constexpr uint32_t kMaxExtraLights = 1000;
// How far the box the lights fill reaches beyond the scene's bounds, as a share of the diagonal.
inline constexpr float kExtraLightMargin = 0.1f;

// The radical inverse of `index` in `base` (the Halton sequence's coordinate), in [0, 1).
double radicalInverse(uint32_t index, uint32_t base);

// The illuminance (lux) of the scene's key light at the bounds' centre: the largest of its lights'
// (directional: the intensity; point and spot: I / d^2), the brightest channel; 0 when it has none.
double keyLightIlluminance(const Scene& scene);

// Appends `count` generated point lights (see above) to scene.lights, named "extra.<i>".
// Throws std::invalid_argument when count exceeds kMaxExtraLights.
void addExtraLights(Scene& scene, uint32_t count);

} // namespace eng::scene
