#include "agaa/simple_complex/classify.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace agaa {
namespace {

// The GLSL constants these mirror live in shaders/glsl/common/epsilon.glsl.
constexpr float kMinCosine = 1.0e-4f;
constexpr float kDepthCompareRelative = 1.0e-4f;
constexpr float kMinNormalLength = 1.0e-6f;

// common/depth.glsl
float viewDistanceFromDepth(float d, float znear, float zfar) {
    return znear * zfar / (d * (zfar - znear) + znear);
}
bool isSky(float d) {
    return d <= 0.0f;
}

// common/octahedral.glsl
glm::vec3 decodeOctahedral(glm::vec2 e) {
    glm::vec3 n(e, 1.0f - std::abs(e.x) - std::abs(e.y));
    if (n.z < 0.0f) {
        glm::vec2 w = (1.0f - glm::abs(glm::vec2(n.y, n.x))) *
                      glm::vec2(n.x >= 0.0f ? 1.0f : -1.0f, n.y >= 0.0f ? 1.0f : -1.0f);
        n.x = w.x;
        n.y = w.y;
    }
    return n / std::max(glm::length(n), kMinNormalLength);
}

} // namespace

float planeDepthTolerance(const shared::FrameConstants& frame, glm::vec2 pixelPos0, float t0, glm::vec3 n0,
                          float slopeScale) {
    glm::vec2 ext(frame.extent.z, frame.extent.w);
    glm::vec2 ndc = pixelPos0 * ext * 2.0f - 1.0f;
    glm::vec3 D(ndc.x / frame.projParams.x, ndc.y / frame.projParams.y, -1.0f);
    glm::vec2 dDdq = 2.0f * ext / glm::abs(glm::vec2(frame.projParams.x, frame.projParams.y));
    float NoD = std::max(std::abs(glm::dot(n0, D)), kMinCosine * glm::length(D));
    float slope = t0 * (std::abs(n0.x) * dDdq.x + std::abs(n0.y) * dDdq.y) / NoD;
    return slopeScale * slope + kDepthCompareRelative * t0;
}

Classification classifyPixel(const shared::FrameConstants& frame, const ClassificationSample* samples, int px,
                             int py, const ClassificationThresholds& thresholds) {
    const uint32_t n = frame.counts.x;
    const float znear = frame.depthParams.x, zfar = frame.depthParams.y;
    Classification c;
    c.margin = std::numeric_limits<float>::infinity();
    const float d0 = samples[0].x;
    const bool sky0 = isSky(d0);
    float t0 = 0.0f, tolerance = 0.0f;
    glm::vec3 n0(0.0f, 0.0f, 1.0f);
    if (!sky0) {
        t0 = viewDistanceFromDepth(d0, znear, zfar);
        n0 = decodeOctahedral({samples[0].y, samples[0].z});
        glm::vec2 pos0 = glm::vec2(float(px), float(py)) + glm::vec2(frame.samplePositions[0]);
        tolerance = planeDepthTolerance(frame, pos0, t0, n0, thresholds.depthSlopeScale);
    }
    for (uint32_t s = 1; s < n; ++s) {
        const float d = samples[s].x;
        const bool sky = isSky(d);
        if (sky != sky0) {
            c.complex = true;
            return c;
        }
        if (sky) continue;
        float dt = std::abs(viewDistanceFromDepth(d, znear, zfar) - t0);
        c.margin = std::min(c.margin, std::abs(dt - tolerance) / tolerance); // tolerance >= 1e-4 t0 > 0
        if (dt > tolerance) {
            c.complex = true;
            return c;
        }
        float cosine = glm::dot(decodeOctahedral({samples[s].y, samples[s].z}), n0);
        c.margin = std::min(c.margin, std::abs(cosine - thresholds.minNormalCos));
        if (cosine < thresholds.minNormalCos) {
            c.complex = true;
            return c;
        }
    }
    return c;
}

} // namespace agaa
