#pragma once
// Writes a node's frame into a host engine's own targets (issue 18), so the host can present
// the result or keep drawing after the node without copying anything itself.
//
// The host hands in each target with its current state and the state it wants it left in (as
// Graph::importTexture takes them: a Use, or nullopt for "contents undefined" / "its last use"),
// e.g. {{image, view, view, desc}, rg::Use::ColorAttachment, rg::Use::ColorAttachment}; write()
// imports them as "host.color" and "host.depth", and the graph moves them from that state to what
// the writer needs and on to the final one (every barrier and layout change is the graph's).
// What goes where:
//  - colour <- FrameTargets::display (each shading event tone-mapped, weighted, summed; linear
//    [0,1]) by a 1:1 blit, which converts the format: an *_SRGB target receives sRGB-encoded
//    values, UNORM and float targets linear ones. The target must be single-sample, frame-sized,
//    created with TRANSFER_DST usage, and of a format with BLIT_DST support (not integer).
//  - depth (optional) <- the nearest of each pixel's visibility samples, in the node's reversed
//    Z (1 at znear, 0 = sky; shaders/glsl/common/depth_resolve.comp says why nearest). The host
//    drawing after the node must use the same projection (FrameConstants::proj) and a GREATER /
//    GREATER_OR_EQUAL depth test. D32_SFLOAT or D32_SFLOAT_S8_UINT (stencil left as it was),
//    single-sample, frame-sized, TRANSFER_DST usage.
//  - hdr (optional) <- FrameTargets::hdr, copied exactly, for a host's own post-processing (a host
//    of our graph can read FrameTargets::hdr itself).
//
// Lifetimes: the writer owns two compute pipelines and must outlive every submitted graph that
// holds its passes; it keeps no per-frame state, so any number of views and frames may be
// recorded through it before any executes. Threads: as a technique (technique.h).

#include "agaa/common/technique.h"
#include "engine/vk/device.h"
#include "engine/vk/pipeline.h"

#include <array>
#include <optional>

namespace agaa {

// One of the host's images, with the state it is in before the graph and the one to leave it in.
struct HostTarget {
    eng::rg::PhysicalTexture texture;
    std::optional<eng::rg::Use> initial, final;
};

struct HostTargets {
    HostTarget color;                // required
    std::optional<HostTarget> depth; // nullopt: the node leaves the host's depth alone
    // FrameTargets::hdr copied exactly (R32G32B32A32_SFLOAT, single-sample, frame-sized,
    // TRANSFER_DST), for a host's own post-processing; nullopt: none.
    std::optional<HostTarget> hdr;
};

// The host targets as graph resources after the node wrote them, for the host's later passes.
struct HostTargetVersions {
    eng::rg::Texture color, depth, hdr; // depth, hdr: invalid without those host targets
};

class HostTargetWriter {
  public:
    explicit HostTargetWriter(eng::vk::Device& device);
    ~HostTargetWriter();
    HostTargetWriter(const HostTargetWriter&) = delete;
    HostTargetWriter& operator=(const HostTargetWriter&) = delete;

    // Adds "host.color" (the blit) and, with a depth target, "host.depth.resolve" and
    // "host.depth.copy". Returns the targets' new versions for the host's later passes.
    // Throws std::invalid_argument naming the target and what is wrong with it.
    HostTargetVersions write(eng::rg::Graph& graph, const FrameTargets& frame, const FrameInputs& inputs,
                             const HostTargets& host) const;

  private:
    eng::vk::Device& m_device;
    eng::vk::PipelineLayout m_layout;
    std::array<VkPipeline, 2> m_resolve{}; // [multisampled]
    VkSampler m_sampler = VK_NULL_HANDLE;
};

} // namespace agaa
