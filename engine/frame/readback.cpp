#include "engine/frame/readback.h"

#include <algorithm>
#include <stdexcept>

namespace eng::frame {

vk::Buffer createReadbackBuffer(const vk::Device& device, uint32_t width, uint32_t height, VkFormat format,
                                const std::string& name) {
    uint32_t bpp = vk::bytesPerTexel(format);
    if (bpp == 0) throw std::logic_error("readback of an unsupported format");
    return vk::createBuffer(device, VkDeviceSize(width) * height * bpp, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            vk::MemoryUse::Readback, name);
}

void addReadbackPass(rg::Graph& graph, rg::Texture texture, const vk::Buffer& host, const std::string& name) {
    // Final state HostRead: the graph makes the copy's writes visible to the host after the
    // fence (a fence wait alone does not).
    rg::Buffer target =
        graph.importBuffer(name + ".host", {host.buffer, host.size}, std::nullopt, rg::Use::HostRead);
    struct Data {
        rg::Texture source;
        rg::Buffer target;
    };
    graph.addPass<Data>(
        name, rg::PassKind::Transfer,
        [&](rg::Builder& b, Data& d) {
            d.source = b.read(texture, rg::Use::TransferSrc);
            d.target = b.write(target, rg::Use::TransferDst);
            b.sideEffect(); // the host reads the result: nothing in the graph consumes it
        },
        [](const rg::Context& ctx, const Data& d) {
            const rg::PhysicalTexture& src = ctx.texture(d.source);
            VkBufferImageCopy copy{};
            copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            copy.imageExtent = {src.desc.width, src.desc.height, 1};
            vkCmdCopyImageToBuffer(ctx.cmd(), src.image, ctx.layout(d.source), ctx.buffer(d.target).buffer, 1,
                                   &copy);
        });
}

void addBufferReadbackPass(rg::Graph& graph, rg::Buffer buffer, const vk::Buffer& host,
                           const std::string& name) {
    rg::Buffer target =
        graph.importBuffer(name + ".host", {host.buffer, host.size}, std::nullopt, rg::Use::HostRead);
    struct Data {
        rg::Buffer source, target;
    };
    VkDeviceSize bytes = host.size;
    graph.addPass<Data>(
        name, rg::PassKind::Transfer,
        [&](rg::Builder& b, Data& d) {
            d.source = b.read(buffer, rg::Use::TransferSrc);
            d.target = b.write(target, rg::Use::TransferDst);
            b.sideEffect();
        },
        [bytes](const rg::Context& ctx, const Data& d) {
            VkBufferCopy copy{0, 0, std::min(bytes, ctx.buffer(d.source).size)};
            vkCmdCopyBuffer(ctx.cmd(), ctx.buffer(d.source).buffer, ctx.buffer(d.target).buffer, 1, &copy);
        });
}

} // namespace eng::frame
