#include "agaa/streaming/streaming_compression.h"

#include "shared/streaming.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <bit>
#include <cmath>

namespace agaa {
namespace {

// The GLSL constants these mirror live in shaders/glsl/common/epsilon.glsl.
constexpr float kDepthCompareRelative = 1.0e-4f;
constexpr float kMinNormalLength = 1.0e-6f;

float viewDistance(float d, const shared::FrameConstants& frame) {
    const float znear = frame.depthParams.x, zfar = frame.depthParams.y;
    return znear * zfar / (d * (zfar - znear) + znear);
}

float sign1(float v) {
    return v >= 0.0f ? 1.0f : -1.0f;
}

glm::vec3 octahedralNormal(float x, float y) {
    glm::vec3 n(x, y, 1.0f - std::abs(x) - std::abs(y));
    if (n.z < 0.0f) {
        const float wx = (1.0f - std::abs(y)) * sign1(x);
        const float wy = (1.0f - std::abs(x)) * sign1(y);
        n.x = wx;
        n.y = wy;
    }
    return n / std::max(glm::length(n), kMinNormalLength);
}

glm::vec2 octahedralCode(glm::vec3 n) {
    n /= std::max(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), kMinNormalLength);
    if (n.z >= 0.0f) return {n.x, n.y};
    return {(1.0f - std::abs(n.y)) * sign1(n.x), (1.0f - std::abs(n.x)) * sign1(n.y)};
}

// Relative distance of a to b, for the decision margins.
float relative(float a, float b) {
    return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1.0e-30f});
}

} // namespace

float streamingZMin(const StreamingSurface& s) {
    return s.zView - (std::abs(s.dzdx) + std::abs(s.dzdy) + kDepthCompareRelative * s.zView);
}

float streamingZMax(const StreamingSurface& s) {
    return s.zView + (std::abs(s.dzdx) + std::abs(s.dzdy) + kDepthCompareRelative * s.zView);
}

bool streamingCanMerge(const StreamingSurface& s, const StreamingSurface& f, float normalCos) {
    return (s.coverage & f.coverage) == 0 && streamingZMin(s) <= streamingZMax(f) &&
           streamingZMin(f) <= streamingZMax(s) && glm::dot(s.normal, f.normal) > normalCos;
}

StreamingSurface streamingMerge(const StreamingSurface& s, const StreamingSurface& f) {
    StreamingSurface m;
    m.coverage = s.coverage | f.coverage;
    m.depthTested = s.depthTested | f.depthTested;
    m.zView = std::min(s.zView, f.zView);
    m.dzdx = 0.5f * (s.dzdx + f.dzdx);
    m.dzdy = 0.5f * (s.dzdy + f.dzdy);
    const glm::vec3 sum = s.normal + f.normal;
    const float len = glm::length(sum);
    m.normal = len > kMinNormalLength ? sum / len : s.normal; // opposing normals: keep the surface's
    m.albedo = 0.5f * (s.albedo + f.albedo);
    m.metallic = 0.5f * (s.metallic + f.metallic);
    m.roughness = 0.5f * (s.roughness + f.roughness);
    m.emissive = 0.5f * (s.emissive + f.emissive);
    return m;
}

StreamingOutcome StreamingCompressor::add(const StreamingSurface& f) {
    std::vector<StreamingSurface>& list = m_surfaces;
    StreamingOutcome outcome = StreamingOutcome::Inserted;
    // Section 3.1: the first surface, front to back, that passes all three conditions.
    auto into = list.end();
    for (auto it = list.begin(); it != list.end(); ++it) {
        if ((it->coverage & f.coverage) != 0) continue;
        const float dot = glm::dot(it->normal, f.normal);
        const bool overlap = streamingZMin(*it) <= streamingZMax(f) && streamingZMin(f) <= streamingZMax(*it);
        m_margin =
            std::min({m_margin, std::abs(dot - m_normalCos), relative(streamingZMin(*it), streamingZMax(f)),
                      relative(streamingZMin(f), streamingZMax(*it))});
        if (overlap && dot > m_normalCos) {
            into = it;
            break;
        }
    }
    auto byDepth = [](const StreamingSurface& a, const StreamingSurface& b) { return a.zView < b.zView; };
    if (into != list.end()) {
        *into = streamingMerge(*into, f);
        outcome = StreamingOutcome::Merged;
        std::stable_sort(list.begin(), list.end(), byDepth); // a merge keeps the minimum zView
    } else {
        // Behind every surface at the same or a smaller zView.
        list.insert(std::upper_bound(list.begin(), list.end(), f, byDepth), f);
    }
    // Section 3.2.1, occluder fusion: a surface entirely behind nearer ones loses their samples.
    for (size_t j = 1; j < list.size(); ++j) {
        uint32_t occluders = 0;
        for (size_t i = 0; i < j; ++i)
            if (streamingZMax(list[i]) < streamingZMin(list[j])) occluders |= list[i].coverage;
        list[j].depthTested &= ~occluders;
    }
    if (list.size() <= m_capacity) return outcome;
    // Full: first the farthest surface that the nearer ones fully cover and that lies entirely
    // behind them (it adds nothing to the pixel)...
    for (size_t k = list.size() - 1; k > 0; --k) {
        uint32_t nearer = 0;
        float nearMax = -3.0e38f;
        for (size_t i = 0; i < k; ++i) {
            nearer |= list[i].coverage;
            nearMax = std::max(nearMax, streamingZMax(list[i]));
        }
        if ((list[k].coverage & ~nearer) == 0 && streamingZMin(list[k]) > nearMax) {
            list.erase(list.begin() + std::ptrdiff_t(k));
            return StreamingOutcome::DroppedCovered;
        }
    }
    // ... else the one with the fewest depth-tested samples; among equals the farther one.
    size_t drop = 0;
    for (size_t k = 1; k < list.size(); ++k)
        if (std::popcount(list[k].depthTested) <= std::popcount(list[drop].depthTested)) drop = k;
    list.erase(list.begin() + std::ptrdiff_t(drop));
    return StreamingOutcome::DroppedFewest;
}

std::vector<StreamingSurface> recordedFragments(const shared::FrameConstants& frame,
                                                const StreamingSample* samples, int px, int py) {
    struct Group {
        uint32_t id, mask, rep;
    };
    std::vector<Group> groups;
    for (uint32_t s = 0; s < frame.counts.x; ++s) {
        if (samples[s][0].x <= 0.0f) continue; // sky
        const uint32_t id = uint32_t(samples[s][0].w);
        auto it = std::find_if(groups.begin(), groups.end(), [&](const Group& g) { return g.id == id; });
        if (it == groups.end()) it = groups.insert(groups.end(), Group{id, 0, s});
        it->mask |= 1u << s;
    }
    std::sort(groups.begin(), groups.end(), [](const Group& a, const Group& b) { return a.id < b.id; });
    std::vector<StreamingSurface> out;
    for (const Group& g : groups) {
        const StreamingSample& r = samples[g.rep];
        StreamingSurface f;
        f.coverage = f.depthTested = g.mask; // depth-tested by the prepass: every sample visible
        f.zView = viewDistance(r[0].x, frame);
        f.normal = octahedralNormal(r[0].y, r[0].z);
        // The plane through the sample with its normal, t(q) = c / (N.D(q)) along the ray t D(q):
        // dt/dq = -t (N.dD/dq) / (N.D), N.D kept kStreamingMinFacing |D| from 0 with its sign.
        const glm::vec2 q = glm::vec2(float(px), float(py)) + glm::vec2(frame.samplePositions[g.rep]);
        const glm::vec2 ndc = q * glm::vec2(frame.extent.z, frame.extent.w) * 2.0f - 1.0f;
        const glm::vec3 ray(ndc.x / frame.projParams.x, ndc.y / frame.projParams.y, -1.0f);
        float facing = glm::dot(f.normal, ray);
        const float floorFacing = shared::kStreamingMinFacing * glm::length(ray);
        if (std::abs(facing) < floorFacing) facing = facing >= 0.0f ? floorFacing : -floorFacing;
        const float limit = shared::kStreamingMaxDerivative;
        f.dzdx = std::clamp(-f.zView * f.normal.x * (2.0f * frame.extent.z / frame.projParams.x) / facing,
                            -limit, limit);
        f.dzdy = std::clamp(-f.zView * f.normal.y * (2.0f * frame.extent.w / frame.projParams.y) / facing,
                            -limit, limit);
        // The plane's depth at the pixel centre, kept within [1/2, 2] of the sample's.
        const glm::vec2 toCentre = glm::vec2(0.5f) - glm::vec2(frame.samplePositions[g.rep]);
        const float range = shared::kStreamingCentreDepthRange;
        f.zView =
            std::clamp(f.zView + f.dzdx * toCentre.x + f.dzdy * toCentre.y, f.zView / range, f.zView * range);
        f.albedo = glm::vec3(r[1]);
        f.metallic = r[1].w;
        f.emissive = glm::vec3(r[2]);
        f.roughness = r[2].w;
        out.push_back(f);
    }
    return out;
}

StreamingPixel compressPixel(const shared::FrameConstants& frame, const StreamingSample* samples, int px,
                             int py, uint32_t surfaces, float normalCos) {
    StreamingCompressor c(surfaces, normalCos);
    StreamingPixel out;
    for (const StreamingSurface& f : recordedFragments(frame, samples, px, py)) {
        out.coveredSamples |= f.coverage;
        c.add(f);
    }
    uint32_t owned = 0;
    for (const StreamingSurface& s : c.surfaces())
        owned |= s.depthTested;
    out.surfaces = c.surfaces();
    out.lostSamples = uint32_t(std::popcount(out.coveredSamples & ~owned));
    out.coveredSamples = uint32_t(std::popcount(out.coveredSamples));
    out.margin = c.margin();
    return out;
}

std::vector<float> streamingResolveWeights(const StreamingPixel& pixel, uint32_t samples) {
    uint32_t owned = 0;
    for (const StreamingSurface& s : pixel.surfaces)
        owned += uint32_t(std::popcount(s.depthTested));
    const float norm = 1.0f / float(std::max(owned, samples));
    std::vector<float> w;
    for (const StreamingSurface& s : pixel.surfaces)
        w.push_back(float(std::popcount(s.depthTested)) * norm);
    w.push_back(float(samples - std::min(owned, samples)) * norm);
    return w;
}

std::array<uint32_t, 9> streamingRecord(const StreamingSurface& s) {
    auto snorm16 = [](float v) {
        return uint32_t(uint16_t(int16_t(std::lround(std::clamp(v, -1.0f, 1.0f) * 32767.0f))));
    };
    auto half2 = [](float a, float b) { return glm::packHalf2x16(glm::vec2(a, b)); };
    const glm::vec2 oct = octahedralCode(s.normal);
    return {s.coverage,
            s.depthTested,
            std::bit_cast<uint32_t>(s.zView),
            half2(s.dzdx, s.dzdy),
            snorm16(oct.x) | (snorm16(oct.y) << 16),
            half2(s.albedo.r, s.albedo.g),
            half2(s.albedo.b, s.metallic),
            half2(s.emissive.r, s.emissive.g),
            half2(s.emissive.b, s.roughness)};
}

} // namespace agaa
