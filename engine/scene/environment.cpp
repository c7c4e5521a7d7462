#include "engine/scene/environment.h"

#include "engine/scene/scene_error.h"

#include <algorithm>
#include <cmath>

namespace eng::scene {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Rec. 709 luminance: the photometric weight that makes rgb radiance cd/m^2 and illuminance lux.
double luminance(const glm::dvec3& c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// The sky dome's relative radiance towards d (d.y >= 0): a zenith-to-horizon gradient (clear
// skies are about 3x brighter at the horizon than at the zenith away from the sun) times a
// circumsolar glow that peaks at 4x towards the sun and falls off within about 25 degrees.
glm::dvec3 skyShape(const glm::dvec3& d, const glm::dvec3& sun) {
    const glm::dvec3 zenith(0.25, 0.45, 1.0), horizon(0.75, 0.85, 1.0);
    const double t = std::pow(1.0 - std::clamp(d.y, 0.0, 1.0), 2.0);
    const double glow = 1.0 + 3.0 * std::exp(-6.0 * (1.0 - glm::dot(d, sun)));
    return (zenith * (1.0 - t) + horizon * (3.0 * t)) * glow;
}

} // namespace

glm::vec3 equirectDirection(float u, float v) {
    const double phi = (double(u) - 0.5) * 2.0 * kPi, theta = double(v) * kPi;
    return glm::vec3(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
}

glm::vec2 equirectCoordinates(const glm::vec3& d) {
    const float u = 0.5f + float(std::atan2(double(d.x), -double(d.z)) / (2.0 * kPi));
    const float v = float(std::acos(std::clamp(double(d.y), -1.0, 1.0)) / kPi);
    return {u, v};
}

double equirectTexelSolidAngle(uint32_t y, uint32_t width, uint32_t height) {
    const double t0 = kPi * double(y) / double(height), t1 = kPi * double(y + 1) / double(height);
    return (2.0 * kPi / double(width)) * (std::cos(t0) - std::cos(t1));
}

glm::dvec3 environmentIrradiance(const Environment& env, const glm::dvec3& n) {
    glm::dvec3 e(0.0);
    for (uint32_t y = 0; y < env.height; ++y) {
        const double dw = equirectTexelSolidAngle(y, env.width, env.height);
        for (uint32_t x = 0; x < env.width; ++x) {
            const glm::dvec3 d = equirectDirection((float(x) + 0.5f) / float(env.width),
                                                   (float(y) + 0.5f) / float(env.height));
            const double c = glm::dot(n, d);
            if (c > 0.0) e += glm::dvec3(env.radiance[size_t(y) * env.width + x]) * (c * dw);
        }
    }
    return e;
}

Environment proceduralSky(const SkySettings& s) {
    Environment env;
    env.source = "procedural sky";
    env.width = s.width;
    env.height = s.height;
    env.radiance.resize(size_t(s.width) * s.height);
    const glm::dvec3 sun = glm::normalize(glm::dvec3(s.sunDirection));
    // The sky's scale: skyIlluminance on a horizontal plane from the upper hemisphere alone.
    double shaped = 0.0;
    for (uint32_t y = 0; y < s.height; ++y) {
        const double dw = equirectTexelSolidAngle(y, s.width, s.height);
        for (uint32_t x = 0; x < s.width; ++x) {
            const glm::dvec3 d =
                equirectDirection((float(x) + 0.5f) / float(s.width), (float(y) + 0.5f) / float(s.height));
            if (d.y > 0.0) shaped += luminance(skyShape(d, sun)) * d.y * dw;
        }
    }
    const double scale = shaped > 0.0 ? double(s.skyIlluminance) / shaped : 0.0;
    // The ground: a Lambertian plane lit by the sun (at its elevation) and the whole sky.
    const double groundIlluminance =
        double(s.sunIlluminance) * std::max(sun.y, 0.0) + double(s.skyIlluminance);
    const glm::dvec3 ground = glm::dvec3(0.9, 0.85, 0.8) * (double(s.groundAlbedo) * groundIlluminance / kPi);
    for (uint32_t y = 0; y < s.height; ++y)
        for (uint32_t x = 0; x < s.width; ++x) {
            const glm::dvec3 d =
                equirectDirection((float(x) + 0.5f) / float(s.width), (float(y) + 0.5f) / float(s.height));
            env.radiance[size_t(y) * s.width + x] = glm::vec3(d.y > 0.0 ? skyShape(d, sun) * scale : ground);
        }
    return env;
}

Environment environmentFromEquirect(const std::string& source, uint32_t imageWidth, uint32_t imageHeight,
                                    const std::vector<float>& rgba, uint32_t width, uint32_t height) {
    if (imageWidth == 0 || imageHeight == 0 || imageWidth != 2 * imageHeight)
        throw SceneError(source + ": an equirectangular environment is 2:1 (width = 2 x height), not " +
                         std::to_string(imageWidth) + "x" + std::to_string(imageHeight));
    if (rgba.size() != size_t(imageWidth) * imageHeight * 4)
        throw SceneError(source + ": the image holds " + std::to_string(rgba.size()) + " floats, expected " +
                         std::to_string(size_t(imageWidth) * imageHeight * 4));
    width = std::min(width, imageWidth);
    height = std::min(height, imageHeight);
    std::vector<glm::dvec3> sum(size_t(width) * height, glm::dvec3(0.0));
    std::vector<uint32_t> count(size_t(width) * height, 0);
    for (uint32_t y = 0; y < imageHeight; ++y)
        for (uint32_t x = 0; x < imageWidth; ++x) {
            const float* p = &rgba[(size_t(y) * imageWidth + x) * 4];
            for (int c = 0; c < 3; ++c)
                if (!std::isfinite(p[c]) || p[c] < 0.0f)
                    throw SceneError(source + ": pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                     ") channel " + "RGB"[c] + " is " + std::to_string(p[c]) +
                                     "; radiance must be finite and >= 0");
            // Box filter: each source texel lands in the target texel holding its centre.
            const size_t t =
                size_t(uint64_t(y) * height / imageHeight) * width + uint64_t(x) * width / imageWidth;
            sum[t] += glm::dvec3(p[0], p[1], p[2]);
            ++count[t];
        }
    Environment env;
    env.source = source;
    env.width = width;
    env.height = height;
    env.radiance.resize(sum.size());
    for (size_t i = 0; i < sum.size(); ++i)
        env.radiance[i] = glm::vec3(sum[i] / double(std::max<uint32_t>(count[i], 1)));
    return env;
}

} // namespace eng::scene
