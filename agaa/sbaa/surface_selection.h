#pragma once
// CPU twin of SBAA's surface selection (shaders/glsl/sbaa/surfaces.comp; Salvi and Vidimce 2012)
// and of its resolve weights (sbaa/lighting.glsl), written from the algorithm, not from the shader:
// the GPU output is tested against it (tests/gpu/test_sbaa.cpp).

#include "shared/frame.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace agaa {

// What the selection reads per sample, as sbaa/export.comp writes it: [0] (raw depth, reversed
// Z, 0 = sky; octahedral normal x, y as fetched; primitive id as an exact float, 0 = none),
// [1] albedo, metallic, [2] emissive, roughness.
using SbaaSample = std::array<glm::vec4, 3>;

struct SbaaMergeTest {
    bool merge = true;            // the paper's MERGE mode; off: one surface per primitive
    float minNormalCos = 0.9f;    // two primitives' representative normals at least this close
    float depthSlopeScale = 1.0f; // depth within this many plane slopes |dz/dx| + |dz/dy|
};

struct SbaaSurfaceChoice {
    uint32_t mask = 0;           // the samples it covers
    uint32_t representative = 0; // its first sample: where it is shaded, whose G-buffer it keeps
    uint32_t primitive = 0;      // the representative's primitive id
};

struct SbaaSelection {
    std::vector<SbaaSurfaceChoice> kept; // at most S, most covered first (ties: earlier sample)
    uint32_t skySamples = 0;
    uint32_t lostSamples = 0; // covered samples of the surfaces not kept
    // Smallest relative distance of a merge decision to its thresholds (cosine and depth); a GPU
    // whose fp32 rounding differs can disagree only where this is tiny. +inf without merge tests.
    float margin = 0.0f;
};

// Selects the pixel's surfaces from its n = frame.counts.x samples (in sample order).
SbaaSelection selectSurfaces(const shared::FrameConstants& frame, const SbaaSample* samples, int px, int py,
                             uint32_t surfaces, const SbaaMergeTest& test);

// Resolve weights (sbaa/lighting.glsl): per kept surface its sample count over the kept surfaces'
// and the sky's, then the sky's weight last. The lost coverage is not in the denominator.
std::vector<float> resolveWeights(const SbaaSelection& selection);

// The 8-word record the surface pass writes for a kept surface (shared/sbaa.h), from its
// representative sample; words 3..6 are half floats, compared by value by the test.
std::array<uint32_t, 8> surfaceRecord(const SbaaSurfaceChoice& surface, const SbaaSample* samples);

} // namespace agaa
