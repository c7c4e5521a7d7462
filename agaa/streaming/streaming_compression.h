#pragma once
// CPU reference of streaming G-buffer compression (Kerzner and Salvi 2014, section 3; the shader
// is shaders/glsl/streaming/compress.comp) and of its resolve weights (streaming/lighting.comp),
// written from the paper and issue 15, not from the shader: the GPU output is tested against it
// (tests/gpu/test_streaming.cpp), the merge and evict edge cases in
// tests/agaa/test_streaming_compression.cpp.

#include "shared/frame.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace agaa {

// The paper's normal threshold alpha = pi/4 (section 3.1: n0 . n1 > cos alpha). The authors'
// public D3D11 code compares the dot product with 0.78539816 (pi/4 used directly as the cosine,
// about 38.2 degrees): a stricter test than the paper's 45 degrees.
inline constexpr float kStreamingDefaultNormalAngleDegrees = 45.0f;
inline constexpr float kStreamingPublicCodeNormalCos = 0.78539816f;

// A fragment, or a surface of the compressed G-buffer (figure 2): one pixel's worth.
struct StreamingSurface {
    uint32_t coverage = 0;              // raster coverage mask (bit s = sample s)
    uint32_t depthTested = 0;           // depth-tested coverage: the samples it still owns
    float zView = 0.0f;                 // view-space depth, metres (a merge keeps the minimum)
    float dzdx = 0.0f, dzdy = 0.0f;     // depth change per pixel step
    glm::vec3 normal{0.0f, 0.0f, 1.0f}; // unit, view space
    glm::vec3 albedo{0.0f}, emissive{0.0f};
    float metallic = 0.0f, roughness = 1.0f;
};

// What happened to one fragment in StreamingCompressor::add.
enum class StreamingOutcome {
    Merged,         // into an existing surface (section 3.1)
    Inserted,       // a new surface, the array not full
    DroppedCovered, // full: a surface (maybe the arrival) fully covered and behind nearer ones dropped
    DroppedFewest,  // full: the one with the fewest depth-tested samples dropped (ties: the farther)
};

// The per-pixel streaming state: at most `surfaces` surfaces, front to back.
class StreamingCompressor {
  public:
    StreamingCompressor(uint32_t surfaces, float normalCos) : m_capacity(surfaces), m_normalCos(normalCos) {}
    StreamingOutcome add(const StreamingSurface& fragment);
    const std::vector<StreamingSurface>& surfaces() const { return m_surfaces; }
    // Smallest relative distance of a normal or depth-overlap decision to its threshold; an fp32
    // implementation that rounds differently can disagree only where this is tiny.
    float margin() const { return m_margin; }

  private:
    uint32_t m_capacity;
    float m_normalCos;
    float m_margin = 3.0e38f;
    std::vector<StreamingSurface> m_surfaces;
};

// Section 3.1's depth interval: zView -+ (|dz/dx| + |dz/dy|), widened by kDepthCompareRelative
// zView (face-on planes have slope 0 but fp32 depths that differ in the last bits).
float streamingZMin(const StreamingSurface& s);
float streamingZMax(const StreamingSurface& s);
bool streamingCanMerge(const StreamingSurface& surface, const StreamingSurface& fragment, float normalCos);
StreamingSurface streamingMerge(const StreamingSurface& surface, const StreamingSurface& fragment);

// What the compression reads per sample, as the test kernel shaders/glsl/tests/streaming_fragments.comp
// writes it: [0] (raw depth, reversed Z, 0 = sky; octahedral normal x, y as fetched; primitive id as an exact
// float), [1] albedo, metallic, [2] emissive, roughness.
using StreamingSample = std::array<glm::vec4, 3>;

// The pixel's recorded fragments in primitive order (ascending id = draw order): its samples
// grouped by primitive, each with its first sample's normal and material, the derivatives of the
// plane through that sample with that normal, and the plane's depth at the pixel centre.
std::vector<StreamingSurface> recordedFragments(const shared::FrameConstants& frame,
                                                const StreamingSample* samples, int px, int py);

struct StreamingPixel {
    std::vector<StreamingSurface> surfaces; // kept, front to back
    uint32_t coveredSamples = 0;            // non-sky samples
    uint32_t lostSamples = 0;               // covered samples no kept surface owns
    float margin = 3.0e38f;
};

StreamingPixel compressPixel(const shared::FrameConstants& frame, const StreamingSample* samples, int px,
                             int py, uint32_t surfaces, float normalCos);

// Resolve weights (section 3.3 as issue 15 states it): per kept surface the popcount of its
// depth-tested coverage over max(n, their sum), then the sky's (the rest) last.
std::vector<float> streamingResolveWeights(const StreamingPixel& pixel, uint32_t samples);

// The 9-word record the compression writes (shared/streaming.h); words 3 and 5..8 are half
// floats and word 4 an octahedral snorm pair, compared by value by the test.
std::array<uint32_t, 9> streamingRecord(const StreamingSurface& surface);

} // namespace agaa
