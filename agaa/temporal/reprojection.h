#pragma once
// Temporal anti-aliasing's camera side (agaa/temporal/temporal_aa.h): the sub-pixel jitter
// sequence and the reprojection from one frame's view into the previous frame's clip space.
// CPU only; the resolve applies the matrix (temporal/resolve.comp).

#include "shared/frame.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace agaa {

// The radical inverse of index in `base` (Halton 1964): 1/2, 1/4, 3/4, ... for base 2.
double radicalInverse(uint32_t index, uint32_t base);

// Frame `frame`'s jitter in pixels, in (-0.5, 0.5) each: the Halton (2, 3) point of index
// 1 + frame % phases, centred on the pixel (Karis 2014: 8 phases; index 0 is the corner).
glm::vec2 haltonJitter(uint64_t frame, uint32_t phases);

// The matrix that takes a view-space position of `current` (w = 1; w = 0 for a direction) into
// the clip space of `previous`: previous.proj * previous.view * inverse(current.view), in double.
// Both projections unjittered (eng::frame::ViewSettings::jitter moves the samples, not the
// projection). A pure rotation maps directions exactly and points whatever their depth.
glm::mat4 reprojectionMatrix(const shared::FrameConstants& previous, const shared::FrameConstants& current);

} // namespace agaa
