#include "agaa/sbaa/surface_selection.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace agaa {
namespace {

// The GLSL constants these mirror live in shaders/glsl/common/epsilon.glsl.
constexpr float kMinCosine = 1.0e-4f;
constexpr float kDepthCompareRelative = 1.0e-4f;
constexpr float kMinNormalLength = 1.0e-6f;

float viewDistance(float d, const shared::FrameConstants& frame) {
    const float znear = frame.depthParams.x, zfar = frame.depthParams.y;
    return znear * zfar / (d * (zfar - znear) + znear);
}

// How far the plane through a point at view distance t0 with normal n0, seen at pixel position
// q0, moves in depth over one pixel step in x plus one in y, plus a relative floor.
float planeTolerance(const shared::FrameConstants& frame, glm::vec2 q0, float t0, glm::vec3 n0, float scale) {
    const glm::vec2 inv(frame.extent.z, frame.extent.w);
    const glm::vec2 ndc = q0 * inv * 2.0f - 1.0f;
    const glm::vec3 ray(ndc.x / frame.projParams.x, ndc.y / frame.projParams.y, -1.0f);
    const float stepX = 2.0f * inv.x / std::abs(frame.projParams.x);
    const float stepY = 2.0f * inv.y / std::abs(frame.projParams.y);
    const float facing = std::max(std::abs(glm::dot(n0, ray)), kMinCosine * glm::length(ray));
    return scale * (t0 * (std::abs(n0.x) * stepX + std::abs(n0.y) * stepY) / facing) +
           kDepthCompareRelative * t0;
}

struct Candidate {
    uint32_t mask = 0, representative = 0, primitive = 0;
};

} // namespace

// RG8_UNORM octahedral, v * 0.5 + 0.5.
glm::vec3 storedGeometricNormal(const SbaaSample& sample) {
    const float x = sample.y * 2.0f - 1.0f, y = sample.z * 2.0f - 1.0f;
    glm::vec3 n(x, y, 1.0f - std::abs(x) - std::abs(y));
    if (n.z < 0.0f) {
        const float wx = (1.0f - std::abs(n.y)) * (n.x >= 0.0f ? 1.0f : -1.0f);
        const float wy = (1.0f - std::abs(n.x)) * (n.y >= 0.0f ? 1.0f : -1.0f);
        n.x = wx;
        n.y = wy;
    }
    return n / std::max(glm::length(n), kMinNormalLength);
}

SbaaSelection selectSurfaces(const shared::FrameConstants& frame, const SbaaSample* samples, int px, int py,
                             uint32_t surfaces, const SbaaMergeTest& test) {
    const uint32_t n = frame.counts.x;
    SbaaSelection out;
    out.margin = std::numeric_limits<float>::infinity();
    // Primitives, in the order of their first covered sample.
    std::vector<Candidate> primitives;
    for (uint32_t s = 0; s < n; ++s) {
        if (samples[s].x <= 0.0f) {
            ++out.skySamples;
            continue;
        }
        const uint32_t id = uint32_t(samples[s].w);
        auto it = std::find_if(primitives.begin(), primitives.end(),
                               [&](const Candidate& c) { return c.primitive == id; });
        if (it == primitives.end()) it = primitives.insert(primitives.end(), Candidate{0, s, id});
        it->mask |= 1u << s;
    }
    // MERGE: a primitive on the plane of an earlier surface (tested at the representatives) joins it.
    std::vector<Candidate> found;
    for (const Candidate& p : primitives) {
        Candidate* into = nullptr;
        if (test.merge) {
            const SbaaSample& b = samples[p.representative];
            const float tb = viewDistance(b.x, frame);
            const glm::vec3 nb = storedGeometricNormal(b);
            for (Candidate& f : found) {
                const SbaaSample& a = samples[f.representative];
                const float ta = viewDistance(a.x, frame);
                const glm::vec3 na = storedGeometricNormal(a);
                const glm::vec2 qa =
                    glm::vec2(float(px), float(py)) + glm::vec2(frame.samplePositions[f.representative]);
                const float tolerance = planeTolerance(frame, qa, ta, na, test.depthSlopeScale);
                const float cosine = glm::dot(na, nb), dt = std::abs(tb - ta);
                out.margin = std::min(
                    {out.margin, std::abs(cosine - test.minNormalCos), std::abs(dt - tolerance) / tolerance});
                if (cosine >= test.minNormalCos && dt <= tolerance) {
                    into = &f;
                    break;
                }
            }
        }
        if (into)
            into->mask |= p.mask;
        else
            found.push_back(p);
    }
    // The S most covered; a stable sort keeps the earlier representative first among equals, and
    // `found` is in representative order.
    std::stable_sort(found.begin(), found.end(), [](const Candidate& a, const Candidate& b) {
        return std::popcount(a.mask) > std::popcount(b.mask);
    });
    for (size_t i = 0; i < found.size(); ++i) {
        if (i < surfaces)
            out.kept.push_back({found[i].mask, found[i].representative, found[i].primitive});
        else
            out.lostSamples += uint32_t(std::popcount(found[i].mask));
    }
    return out;
}

std::vector<float> resolveWeights(const SbaaSelection& selection) {
    uint32_t total = selection.skySamples;
    for (const SbaaSurfaceChoice& s : selection.kept)
        total += uint32_t(std::popcount(s.mask));
    const float norm = 1.0f / float(std::max(total, 1u));
    std::vector<float> w;
    for (const SbaaSurfaceChoice& s : selection.kept)
        w.push_back(float(std::popcount(s.mask)) * norm);
    w.push_back(float(selection.skySamples) * norm);
    return w;
}

std::array<uint32_t, 8> surfaceRecord(const SbaaSurfaceChoice& surface, const SbaaSample* samples) {
    return {surface.mask, std::bit_cast<uint32_t>(samples[surface.representative].x), 0u, 0u, 0u, 0u,
            0u,           surface.representative | (surface.primitive << 8)};
}

} // namespace agaa
