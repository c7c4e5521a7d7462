#include "agaa/common/host_targets.h"

#include "engine/vk/descriptors.h"
#include "engine/vk/reflection.h"
#include "engine/vk/resources.h"
#include "shaders/common/depth_resolve_ms_comp.h"
#include "shaders/common/depth_resolve_ss_comp.h"

#include <stdexcept>

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

HostTargetWriter::HostTargetWriter(vk::Device& device) : m_device(device) {
    vk::LayoutDesc layout;
    // One layout for both resolves: the same bindings, sampled 1x or MS.
    layout.pushBindings =
        vk::mergeBindings(vk::reflectBindings({{kCommonDepthResolveSsComp, VK_SHADER_STAGE_COMPUTE_BIT}}),
                          vk::reflectBindings({{kCommonDepthResolveMsComp, VK_SHADER_STAGE_COMPUTE_BIT}}));
    m_layout = vk::createPipelineLayout(device, layout, "host.depth.layout");
    m_resolve[0] = vk::createComputePipeline(device, kCommonDepthResolveSsComp, m_layout.layout, {},
                                             "host.depth.resolve");
    m_resolve[1] = vk::createComputePipeline(device, kCommonDepthResolveMsComp, m_layout.layout, {},
                                             "host.depth.resolve.ms");
    m_sampler = vk::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f,
                                  "host.depth.sampler");
}

HostTargetWriter::~HostTargetWriter() {
    VkDevice d = m_device.device();
    vkDeviceWaitIdle(d);
    for (VkPipeline p : m_resolve)
        if (p) vkDestroyPipeline(d, p, nullptr);
    vkDestroySampler(d, m_sampler, nullptr);
    vk::destroyPipelineLayout(m_device, m_layout);
}

namespace {

// Refused here, at recording, rather than by the validation layer at submission.
void check(const HostTarget& target, const char* what, uint32_t w, uint32_t h) {
    const rg::TextureDesc& d = target.texture.desc;
    if (d.width != w || d.height != h || d.samples != VK_SAMPLE_COUNT_1_BIT)
        throw std::invalid_argument(std::string("host ") + what + " target is " + std::to_string(d.width) +
                                    "x" + std::to_string(d.height) + " with " +
                                    std::to_string(int(d.samples)) +
                                    " sample(s); it must be single-sample and the frame's " +
                                    std::to_string(w) + "x" + std::to_string(h));
}

// `source` into the host's `target` by a 1:1 blit: a format conversion, never a resample. Returns
// the target's version after it.
rg::Texture blitInto(rg::Graph& graph, const char* name, rg::Texture source, const HostTarget& target,
                     uint32_t w, uint32_t h) {
    const rg::Texture imported = graph.importTexture(name, target.texture, target.initial, target.final);
    struct Blit {
        rg::Texture source, target;
    };
    const Blit& blit = graph.addPass<Blit>(
        name, rg::PassKind::Transfer,
        [&](rg::Builder& b, Blit& d) {
            d.source = b.read(source, rg::Use::TransferSrc);
            d.target = b.write(imported, rg::Use::TransferDst);
        },
        [w, h](const rg::Context& ctx, const Blit& d) {
            VkImageBlit2 region{VK_STRUCTURE_TYPE_IMAGE_BLIT_2};
            region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.srcOffsets[1] = {int32_t(w), int32_t(h), 1};
            region.dstOffsets[1] = {int32_t(w), int32_t(h), 1};
            VkBlitImageInfo2 info{VK_STRUCTURE_TYPE_BLIT_IMAGE_INFO_2};
            info.srcImage = ctx.texture(d.source).image;
            info.srcImageLayout = rg::useInfo(rg::Use::TransferSrc).layout; // the graph's table
            info.dstImage = ctx.texture(d.target).image;
            info.dstImageLayout = rg::useInfo(rg::Use::TransferDst).layout;
            info.regionCount = 1;
            info.pRegions = &region;
            info.filter = VK_FILTER_NEAREST;
            vkCmdBlitImage2(ctx.cmd(), &info);
        });
    return blit.target;
}

} // namespace

HostTargetVersions HostTargetWriter::write(rg::Graph& graph, const FrameTargets& frame, const FrameInputs& in,
                                           const HostTargets& host) const {
    const uint32_t w = in.width, h = in.height;
    check(host.color, "colour", w, h);
    if (vk::isDepthFormat(host.color.texture.desc.format))
        throw std::invalid_argument("host colour target has a depth format");
    HostTargetVersions out{blitInto(graph, "host.color", frame.display, host.color, w, h), {}, {}};
    if (host.hdr) {
        check(*host.hdr, "HDR", w, h);
        if (host.hdr->texture.desc.format != VK_FORMAT_R32G32B32A32_SFLOAT)
            throw std::invalid_argument("host HDR target: format " +
                                        std::to_string(int(host.hdr->texture.desc.format)) +
                                        " is not R32G32B32A32_SFLOAT (the node's HDR, copied exactly)");
        out.hdr = blitInto(graph, "host.hdr", frame.hdr, *host.hdr, w, h);
    }
    if (!host.depth) return out;
    if (!frame.depth.valid())
        throw std::invalid_argument("host depth target given, but this technique hands back no depth");
    check(*host.depth, "depth", w, h);
    const VkFormat depthFormat = host.depth->texture.desc.format;
    if (depthFormat != VK_FORMAT_D32_SFLOAT && depthFormat != VK_FORMAT_D32_SFLOAT_S8_UINT)
        throw std::invalid_argument(
            "host depth target: format " + std::to_string(int(depthFormat)) +
            " is not D32_SFLOAT or D32_SFLOAT_S8_UINT (the node's depth is 32-bit float)");
    const rg::Texture depth =
        graph.importTexture("host.depth", host.depth->texture, host.depth->initial, host.depth->final);

    struct Resolve {
        rg::Texture samples;
        rg::Buffer resolved;
    };
    const Resolve& resolve = graph.addCompute<Resolve>(
        "host.depth.resolve",
        [&](rg::Builder& b, Resolve& d) {
            d.samples = b.read(frame.depth, rg::Use::SampledCompute);
            d.resolved = b.write(b.create("host.depth.resolved", rg::BufferDesc{VkDeviceSize(w) * h * 4}),
                                 rg::Use::StorageWriteCompute);
        },
        [this, w, h](const rg::Context& ctx, const Resolve& d) {
            const rg::PhysicalTexture& samples = ctx.texture(d.samples);
            const bool ms = samples.desc.samples != VK_SAMPLE_COUNT_1_BIT;
            vkCmdBindPipeline(ctx.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, m_resolve[ms ? 1 : 0]);
            vk::PushDescriptors()
                .sampled(0, m_sampler, samples.sampledView)
                .storage(1, ctx.buffer(d.resolved).buffer)
                .push(m_device, ctx.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, m_layout.layout);
            vkCmdDispatch(ctx.cmd(), (w + 7) / 8, (h + 7) / 8, 1);
        });
    struct Copy {
        rg::Buffer resolved;
        rg::Texture depth;
    };
    const Copy& copy = graph.addPass<Copy>(
        "host.depth.copy", rg::PassKind::Transfer,
        [&](rg::Builder& b, Copy& d) {
            d.resolved = b.read(resolve.resolved, rg::Use::TransferSrc);
            d.depth = b.write(depth, rg::Use::TransferDst);
        },
        [w, h](const rg::Context& ctx, const Copy& d) {
            const rg::PhysicalTexture& dst = ctx.texture(d.depth);
            VkBufferImageCopy2 region{VK_STRUCTURE_TYPE_BUFFER_IMAGE_COPY_2};
            region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1}; // a stencil stays as it was
            region.imageExtent = {w, h, 1};
            VkCopyBufferToImageInfo2 info{VK_STRUCTURE_TYPE_COPY_BUFFER_TO_IMAGE_INFO_2};
            info.srcBuffer = ctx.buffer(d.resolved).buffer;
            info.dstImage = dst.image;
            info.dstImageLayout = rg::useInfo(rg::Use::TransferDst).layout;
            info.regionCount = 1;
            info.pRegions = &region;
            vkCmdCopyBufferToImage2(ctx.cmd(), &info);
        });
    out.depth = copy.depth;
    return out;
}

} // namespace agaa
