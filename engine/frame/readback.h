#pragma once
// Copies a single-sample, single-layer texture into a host-visible buffer at the
// end of a graph, so tools and tests can read rendered images back.

#include "engine/graph/graph.h"
#include "engine/vk/device.h"
#include "engine/vk/resources.h"

#include <string>

namespace eng::frame {

// Host buffer sized for a width x height texture of `format`.
vk::Buffer createReadbackBuffer(const vk::Device&, uint32_t width, uint32_t height, VkFormat format,
                                const std::string& name);
// Adds "<name>" pass copying `texture` (layer 0) into `host` (tightly packed rows).
void addReadbackPass(rg::Graph&, rg::Texture texture, const vk::Buffer& host, const std::string& name);
// Adds "<name>" pass copying the first host.size bytes of `buffer` into `host`.
void addBufferReadbackPass(rg::Graph&, rg::Buffer buffer, const vk::Buffer& host, const std::string& name);

} // namespace eng::frame
