#pragma once
// CPU twin of SBAA's surface selection (shaders/glsl/sbaa/surfaces.comp; Salvi and Vidimce 2012)
// and of its resolve weights (sbaa/lighting.comp), written from the algorithm, not from the shader:
// the GPU output is tested against it (tests/gpu/test_sbaa.cpp).

#include "shared/frame.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace agaa {

// What the selection reads per sample, as the test kernel shaders/glsl/tests/sbaa_selection_inputs.comp
// writes it from the prepass: raw depth (reversed Z, 0 = sky); the geometric normal as stored (RG8_UNORM
// octahedral, v * 0.5 + 0.5) x, y; the primitive id as an exact float (0 = none).
using SbaaSample = glm::vec4;

struct SbaaMergeTest {
    bool merge = true;            // the paper's MERGE mode; off: one surface per primitive
    float minNormalCos = 0.9f;    // two primitives' representative normals at least this close
    float depthSlopeScale = 1.0f; // depth within this many plane slopes |dz/dx| + |dz/dy|
};

struct SbaaSurfaceChoice {
    uint32_t mask = 0;           // the samples it covers
    uint32_t representative = 0; // its first sample: where it is shaded and its material evaluated
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

// The sample's geometric normal (view space, unit), decoded from its stored RG8 octahedral form.
glm::vec3 storedGeometricNormal(const SbaaSample& sample);

// Selects the pixel's surfaces from its n = frame.counts.x samples (in sample order).
SbaaSelection selectSurfaces(const shared::FrameConstants& frame, const SbaaSample* samples, int px, int py,
                             uint32_t surfaces, const SbaaMergeTest& test);

// Resolve weights (sbaa/lighting.comp): per kept surface its sample count over the kept surfaces'
// and the sky's, then the sky's weight last. The lost coverage is not in the denominator.
std::vector<float> resolveWeights(const SbaaSelection& selection);

// The words of the 8-word record (shared/sbaa.h) the surface pass writes for a kept surface:
// coverage, representative depth, representative sample and primitive. Words 2..6 (the material)
// are the fill pass's and 0 here.
std::array<uint32_t, 8> surfaceRecord(const SbaaSurfaceChoice& surface, const SbaaSample* samples);

} // namespace agaa
