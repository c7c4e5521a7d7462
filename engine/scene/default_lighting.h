#pragma once
// Lighting for scenes that bring none (issue 16). Most glTF files in the wild carry no lights;
// every viewer graphics engineers judge assets in (the Khronos glTF Sample Viewer, Filament's
// gltf_viewer, Blender's look-dev) lights them with an environment. The default here is clear
// daylight:
//   - a sun: a directional light of 100 klux that casts shadows, 50 degrees above the horizon,
//     35 degrees to the right of the camera's back (camera 0), so the side the camera sees is lit
//     and the shadows fall away from it;
//   - a sky: the procedural sky of engine/scene/environment.h (20 klux on a horizontal plane, a
//     grey ground of albedo 0.2), lighting every surface through its pre-filtered irradiance and
//     specular levels, and showing behind the geometry. A user's environment map
//     (--environment FILE.exr) replaces it; it then carries its own sun, and none is added.
// A scene that brings lights but no environment gets, by default, the same sky as fill light
// (no sun), scaled to a quarter of the illuminance its lights give the centre of its bounds (the
// 4:1 key-to-fill ratio of lighting practice; engines do the same with an ambient term, such as
// Bevy's default AmbientLight): faces turned away from its lights are then dim, not black.

#include "engine/scene/scene.h"

#include <optional>
#include <string>

namespace eng::scene {

// scene: the scene's own lights only; fill: its lights and the fill sky; default: the sun and sky
// instead of them; both: the sun and sky added to them; automatic: fill when the scene has
// lights, default when it has none.
enum class LightingMode { Automatic, Scene, Fill, Default, Both };

// "auto" | "scene" | "fill" | "default" | "both"; throws std::invalid_argument naming the allowed
// values.
LightingMode parseLightingMode(const std::string& name);

// Illuminance (lux, the brightest channel) the scene's punctual lights give a plane facing each of
// them at `point`: directional lights their intensity, point and spot lights I / d^2.
double lightIlluminanceAt(const Scene& scene, const glm::vec3& point);

// The fill sky's share of the lights' illuminance.
inline constexpr double kFillRatio = 0.25;

// The default sun's direction (unit, towards the sun) for the scene's camera `camera`.
glm::vec3 defaultSunDirection(const Scene& scene, uint32_t camera = 0);

// Applies `mode` to the scene: adds the sun and the sky (or the user's environment) where the
// mode asks, and records scene.lightingMode and scene.lightingCause. With mode Scene, an
// environment given by the user still lights the scene (and the scene's lights stay).
void applyLighting(Scene& scene, LightingMode mode, std::optional<Environment> userEnvironment = std::nullopt,
                   uint32_t camera = 0);

} // namespace eng::scene
