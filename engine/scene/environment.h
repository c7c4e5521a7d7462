#pragma once
// Distant environment lighting (issue 16): the radiance arriving from every direction at
// infinity, stored as an equirectangular (latitude-longitude) image in world space. The
// renderer pre-filters it (engine/frame/environment_maps.h) into diffuse irradiance and
// specular levels; uncovered samples show it as the sky. Units: cd/m^2 (W/sr/m^2 scaled like
// the scene's lights, which are in lux and candela).
//
// Mapping (glTF axes, +Y up): u = 0.5 + atan2(d.x, -d.z) / 2 pi, v = acos(d.y) / pi; texel (x, y)
// covers u in [x, x+1) / width, v in [y, y+1) / height. Row 0 is the zenith.

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace eng::scene {

struct Environment {
    std::string source; // "procedural sky" or the file it was read from; empty = no environment
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<glm::vec3> radiance; // width * height, row-major from the zenith

    bool empty() const { return radiance.empty(); }
};

// The unit direction at the centre of equirectangular coordinates (u, v) in [0,1]^2, and back.
glm::vec3 equirectDirection(float u, float v);
glm::vec2 equirectCoordinates(const glm::vec3& direction);
// Solid angle of texel row y of a width x height map (sr); the rows sum to 4 pi.
double equirectTexelSolidAngle(uint32_t y, uint32_t width, uint32_t height);

// Clear daylight for scenes without lights (engine/scene/default_lighting.h): a sky dome whose
// radiance grows from the zenith to the horizon and around the sun, over a grey ground that
// reflects the sun and the sky as a Lambertian plane of albedo groundAlbedo. Scaled so the sky
// alone gives skyIlluminance lux on a horizontal plane (the sun's own disc is left to the
// directional light, not to the map).
struct SkySettings {
    glm::vec3 sunDirection{0.0f, 1.0f, 0.0f}; // unit, towards the sun, world space
    float sunIlluminance = 100000.0f;         // lux on a plane facing the sun (clear noon: ~100 klux)
    float skyIlluminance = 20000.0f;          // lux on a horizontal plane from the sky alone
    float groundAlbedo = 0.2f;
    uint32_t width = 128, height = 64;
};
Environment proceduralSky(const SkySettings& settings);

// Illuminance (lux) the environment gives a plane with unit normal n: the integral of
// L(w) max(n.w, 0) dw over the map, by its texels.
glm::dvec3 environmentIrradiance(const Environment& env, const glm::dvec3& n);

// A user's equirectangular image (--environment FILE.exr, read by engine/io), RGBA floats,
// resampled to width x height by box filtering. Throws SceneError naming `source` when the image
// is not 2:1 or at least width x height, or holds a negative or non-finite value.
Environment environmentFromEquirect(const std::string& source, uint32_t imageWidth, uint32_t imageHeight,
                                    const std::vector<float>& rgba, uint32_t width = 128,
                                    uint32_t height = 64);

} // namespace eng::scene
