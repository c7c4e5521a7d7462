#include "engine/frame/environment_maps.h"

#include <algorithm>
#include <cmath>

namespace eng::frame {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The rough levels are filtered from, and into, a map of this size: a GGX lobe of roughness
// >= 0.2 spans several of its 5.6-degree texels. They are then resampled to the level-0 size.
constexpr uint32_t kFilterWidth = 64, kFilterHeight = 32;
// Same floor as kMinGgxAlpha in shaders/glsl/common/epsilon.glsl.
constexpr double kMinGgxAlpha = 1.0e-3;

double ggxD(double NoH, double alpha) {
    const double a2 = alpha * alpha;
    const double f = (NoH * a2 - NoH) * NoH + 1.0;
    return a2 / (kPi * f * f);
}

glm::vec3 texelDirection(uint32_t x, uint32_t y, uint32_t w, uint32_t h) {
    return scene::equirectDirection((float(x) + 0.5f) / float(w), (float(y) + 0.5f) / float(h));
}

// Bilinear lookup of an equirectangular map at (u, v): u wraps, v clamps (texel centres).
glm::vec3 sampleEquirect(const std::vector<glm::vec3>& map, uint32_t w, uint32_t h, float u, float v) {
    const float fx = u * float(w) - 0.5f, fy = std::clamp(v * float(h) - 0.5f, 0.0f, float(h - 1));
    const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
    const float tx = fx - float(x0), ty = fy - float(y0);
    auto at = [&](int x, int y) {
        x = ((x % int(w)) + int(w)) % int(w);
        y = std::clamp(y, 0, int(h) - 1);
        return map[size_t(y) * w + size_t(x)];
    };
    return (at(x0, y0) * (1 - tx) + at(x0 + 1, y0) * tx) * (1 - ty) +
           (at(x0, y0 + 1) * (1 - tx) + at(x0 + 1, y0 + 1) * tx) * ty;
}

} // namespace

std::array<float, 9> shBasis(const glm::vec3& n) {
    const float x = n.x, y = n.y, z = n.z;
    return {0.282095f,
            0.488603f * y,
            0.488603f * z,
            0.488603f * x,
            1.092548f * x * y,
            1.092548f * y * z,
            0.315392f * (3.0f * z * z - 1.0f),
            1.092548f * x * z,
            0.546274f * (x * x - y * y)};
}

glm::vec3 evaluateIrradianceSh(const std::array<glm::vec3, 9>& sh, const glm::vec3& n) {
    const std::array<float, 9> y = shBasis(n);
    glm::vec3 e(0.0f);
    for (int i = 0; i < 9; ++i)
        e += sh[size_t(i)] * y[size_t(i)];
    return e;
}

EnvironmentMaps prefilterEnvironment(const scene::Environment& env, uint32_t levels) {
    EnvironmentMaps m;
    m.width = env.width;
    m.height = env.height;
    m.levels = std::max(levels, 2u);
    // Diffuse: project L onto Y_i by the texels' solid angles, then convolve with the clamped
    // cosine, whose zonal coefficients per band are A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4.
    std::array<glm::dvec3, 9> radianceSh{};
    for (uint32_t y = 0; y < env.height; ++y) {
        const double dw = scene::equirectTexelSolidAngle(y, env.width, env.height);
        for (uint32_t x = 0; x < env.width; ++x) {
            const std::array<float, 9> basis = shBasis(texelDirection(x, y, env.width, env.height));
            const glm::dvec3 L(env.radiance[size_t(y) * env.width + x]);
            for (int i = 0; i < 9; ++i)
                radianceSh[size_t(i)] += L * (double(basis[size_t(i)]) * dw);
        }
    }
    const double band[9] = {kPi,     2 * kPi / 3, 2 * kPi / 3, 2 * kPi / 3, kPi / 4,
                            kPi / 4, kPi / 4,     kPi / 4,     kPi / 4};
    for (int i = 0; i < 9; ++i)
        m.irradianceSh[size_t(i)] = glm::vec3(radianceSh[size_t(i)] * band[i]);

    // Specular: level 0 is the map; the rough levels are filtered at kFilterWidth x kFilterHeight.
    m.specular.assign(size_t(m.levels) * m.width * m.height, glm::vec3(0.0f));
    std::copy(env.radiance.begin(), env.radiance.end(), m.specular.begin());
    const uint32_t fw = std::min(kFilterWidth, env.width), fh = std::min(kFilterHeight, env.height);
    std::vector<glm::vec3> source(size_t(fw) * fh);
    std::vector<glm::dvec3> sourceDir(source.size());
    std::vector<double> sourceDw(source.size());
    for (uint32_t y = 0; y < fh; ++y)
        for (uint32_t x = 0; x < fw; ++x) {
            const glm::vec3 d = texelDirection(x, y, fw, fh);
            const glm::vec2 uv = scene::equirectCoordinates(d);
            // Box-filtered down: the mean of the level-0 texels under this one.
            glm::dvec3 sum(0.0);
            uint32_t count = 0;
            for (uint32_t sy = y * env.height / fh; sy < (y + 1) * env.height / fh; ++sy)
                for (uint32_t sx = x * env.width / fw; sx < (x + 1) * env.width / fw; ++sx, ++count)
                    sum += glm::dvec3(env.radiance[size_t(sy) * env.width + sx]);
            source[size_t(y) * fw + x] =
                count ? glm::vec3(sum / double(count))
                      : sampleEquirect(env.radiance, env.width, env.height, uv.x, uv.y);
            sourceDir[size_t(y) * fw + x] = glm::dvec3(d);
            sourceDw[size_t(y) * fw + x] = scene::equirectTexelSolidAngle(y, fw, fh);
        }
    std::vector<glm::vec3> filtered(source.size());
    for (uint32_t level = 1; level < m.levels; ++level) {
        const double roughness = double(level) / double(m.levels - 1);
        const double alpha = std::max(roughness * roughness, kMinGgxAlpha);
        for (size_t o = 0; o < filtered.size(); ++o) {
            const glm::dvec3 n = sourceDir[o];
            glm::dvec3 sum(0.0);
            double weights = 0.0;
            for (size_t i = 0; i < source.size(); ++i) {
                const double NoL = glm::dot(n, sourceDir[i]);
                if (NoL <= 0.0) continue;
                const glm::dvec3 h = glm::normalize(n + sourceDir[i]);
                const double w = ggxD(std::clamp(glm::dot(n, h), 0.0, 1.0), alpha) * NoL * sourceDw[i];
                sum += glm::dvec3(source[i]) * w;
                weights += w;
            }
            filtered[o] = weights > 0.0 ? glm::vec3(sum / weights) : source[o];
        }
        glm::vec3* out = &m.specular[size_t(level) * m.width * m.height];
        for (uint32_t y = 0; y < m.height; ++y)
            for (uint32_t x = 0; x < m.width; ++x)
                out[size_t(y) * m.width + x] =
                    sampleEquirect(filtered, fw, fh, (float(x) + 0.5f) / float(m.width),
                                   (float(y) + 0.5f) / float(m.height));
    }
    return m;
}

glm::dvec2 integrateDfg(double NoV, double roughness, uint32_t samples) {
    const double alpha = std::max(roughness * roughness, kMinGgxAlpha), a2 = alpha * alpha;
    const glm::dvec3 V(std::sqrt(std::max(0.0, 1.0 - NoV * NoV)), 0.0, NoV); // N = +Z
    glm::dvec2 ab(0.0);
    for (uint32_t i = 0; i < samples; ++i) {
        // Hammersley point i: (i / samples, radical inverse of i in base 2).
        uint32_t bits = i;
        bits = (bits << 16u) | (bits >> 16u);
        bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
        bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
        bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
        bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
        const double u = (i + 0.5) / samples, w = double(bits) * 2.3283064365386963e-10;
        // GGX half-vector sampling: pdf(h) = D(h) N.H.
        const double phi = 2.0 * kPi * u;
        const double cosTheta = std::sqrt((1.0 - w) / (1.0 + (a2 - 1.0) * w));
        const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
        const glm::dvec3 H(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
        const double VoH = glm::dot(V, H);
        const glm::dvec3 L = 2.0 * VoH * H - V;
        if (L.z <= 0.0 || VoH <= 0.0) continue;
        const double NoL = L.z, NoH = H.z;
        const double vis = 0.5 / (NoL * std::sqrt(NoV * NoV * (1.0 - a2) + a2) +
                                  NoV * std::sqrt(NoL * NoL * (1.0 - a2) + a2));
        // D Vis N.L / pdf(l), pdf(l) = D N.H / (4 V.H).
        const double weight = vis * NoL * 4.0 * VoH / NoH;
        const double fc = std::pow(1.0 - VoH, 5.0);
        ab += glm::dvec2(weight * (1.0 - fc), weight * fc);
    }
    return ab / double(samples);
}

std::vector<glm::vec2> integrateDfgTable(uint32_t size) {
    std::vector<glm::vec2> table(size_t(size) * size);
    for (uint32_t j = 0; j < size; ++j)
        for (uint32_t i = 0; i < size; ++i)
            table[size_t(j) * size + i] = glm::vec2(integrateDfg((i + 0.5) / size, (j + 0.5) / size));
    return table;
}

shared::EnvironmentConstants makeEnvironmentConstants(const EnvironmentMaps* maps, float texelScale) {
    shared::EnvironmentConstants c{};
    if (!maps) return c;
    for (int i = 0; i < 9; ++i)
        c.irradianceSh[i] = glm::vec4(maps->irradianceSh[size_t(i)], 0.0f);
    c.params = {1.0f, texelScale, float(maps->levels - 1), 0.0f};
    return c;
}

} // namespace eng::frame
