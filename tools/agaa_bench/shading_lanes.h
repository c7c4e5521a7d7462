#pragma once
// The shading cost a SIMD machine pays (AGAA paper, section 5.2 and figure 13): the lanes of one
// subgroup run in lockstep, so a group of pixels costs its worst pixel's shading events. The
// lighting passes run one pixel per invocation, x fastest, so a subgroup of L lanes is L
// consecutive pixels of a row (lavapipe: L = 8).

#include <cstdint>
#include <vector>

namespace agaa::bench {

inline constexpr uint32_t kLavapipeSubgroupSize = 8;

// Mean over the pixels of the shading events of the worst pixel in each one's lane group (row
// runs of `lanes` pixels, the last one of a row shorter): the events per pixel a lockstep SIMD
// machine executes. At least the mean events, equal to it only where every group is uniform.
double worstLaneEventsPerPixel(const std::vector<uint32_t>& events, uint32_t width, uint32_t height,
                               uint32_t lanes = kLavapipeSubgroupSize);

} // namespace agaa::bench
