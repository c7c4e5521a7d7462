#pragma once
// CPU twin of the simple/complex classification (shaders/glsl/simple_complex/
// classify.glsl, Lauritzen 2010): same inputs, same tests, same order, in fp32. The
// GPU classification is tested against it (tests/gpu/test_peers.cpp).

#include "shared/frame.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace agaa {

// What the classification reads per sample, as the test kernel
// shaders/glsl/tests/simple_complex_classification_inputs.comp writes it: x raw depth (reversed Z, 0 = sky),
// yz the octahedral normal as fetched (RG16_SNORM).
using ClassificationSample = glm::vec4;

struct ClassificationThresholds {
    float minNormalCos = 0.99f;   // a sample whose normal's cosine to sample 0's is below this is different
    float depthSlopeScale = 1.0f; // depth tolerance in units of sample 0's plane slope |dz/dx| + |dz/dy|
};

struct Classification {
    bool complex = false;
    // Smallest relative distance of any test that was evaluated to its threshold:
    // |(|t - t0|) - tol| / tol for depth, |cos - minNormalCos| for normals; +inf when only
    // exact tests (sky vs geometry) ran. A GPU whose fp32 rounding differs from this one
    // can disagree only where this is tiny.
    float margin = 0.0f;
};

// Classifies one pixel from its n samples (frame.counts.x of them, in sample order).
Classification classifyPixel(const shared::FrameConstants& frame, const ClassificationSample* samples, int px,
                             int py, const ClassificationThresholds& thresholds);

// The depth tolerance of sample 0's plane (classify.glsl planeDepthTolerance).
float planeDepthTolerance(const shared::FrameConstants& frame, glm::vec2 pixelPos0, float t0, glm::vec3 n0,
                          float slopeScale);

} // namespace agaa
