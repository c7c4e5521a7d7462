#pragma once
// The error-driven shading rate's list of tiles with a flagged pixel (shaders/glsl/agaa/lighting/
// shading_rate.glsl): a VkDispatchIndirectCommand {tiles, 1, 1} that the lighting pass counts up,
// then one word per tile (x | y << 16). The per-sample pass dispatches indirectly through it.

#include "engine/graph/graph.h"

#include <cstdint>
#include <string>

namespace agaa {

// A transfer pass that makes the list for a width x height frame, cleared to a dispatch of no
// tile, into a buffer called `name`; returns the cleared buffer.
eng::rg::Buffer addFlaggedTileList(eng::rg::Graph& graph, uint32_t width, uint32_t height,
                                   const std::string& name);

} // namespace agaa
