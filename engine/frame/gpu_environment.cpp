#include "engine/frame/gpu_environment.h"

#include "engine/frame/environment_maps.h"
#include "engine/frame/frame_runner.h"
#include "engine/graph/graph.h"
#include "engine/vk/check.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <optional>
#include <span>
#include <vector>

namespace eng::frame {

GpuEnvironment::GpuEnvironment(vk::Device& device, const scene::Environment* environment)
    : m_device(device), m_present(environment && !environment->empty()) {
    try {
        // Pre-filtered on the CPU (a few hundred ms at most, once per environment), stored as half
        // floats divided by a scale that keeps the brightest texel below half's range.
        std::optional<EnvironmentMaps> maps;
        float scale = 1.0f;
        std::vector<uint16_t> texels, dfgTexels;
        if (m_present) {
            maps = prefilterEnvironment(*environment);
            float peak = 0.0f;
            for (const glm::vec3& t : maps->specular)
                peak = std::max({peak, t.x, t.y, t.z});
            scale = std::max(1.0f, peak / 32768.0f);
            texels.reserve(maps->specular.size() * 4);
            for (const glm::vec3& t : maps->specular) {
                for (int c = 0; c < 3; ++c)
                    texels.push_back(glm::packHalf1x16(t[c] / scale));
                texels.push_back(glm::packHalf1x16(1.0f));
            }
        } else {
            texels.assign(4, 0);
        }
        const shared::EnvironmentConstants constants =
            makeEnvironmentConstants(maps ? &*maps : nullptr, scale);
        m_constants = vk::createBuffer(device, sizeof constants, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                       vk::MemoryUse::Upload, "scene.environment.constants");
        vk::writeBuffer(device, m_constants, std::as_bytes(std::span(&constants, 1)));
        const uint32_t w = maps ? maps->width : 1, h = maps ? maps->height : 1,
                       layers = maps ? maps->levels : 1;
        m_prefiltered = vk::createImage(
            device,
            {VK_FORMAT_R16G16B16A16_SFLOAT, w, h, layers, 1, VK_SAMPLE_COUNT_1_BIT,
             VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, VK_IMAGE_VIEW_TYPE_2D_ARRAY},
            "scene.environment");
        for (const glm::vec2& ab : integrateDfgTable()) {
            dfgTexels.push_back(glm::packHalf1x16(ab.x));
            dfgTexels.push_back(glm::packHalf1x16(ab.y));
        }
        m_dfg = vk::createImage(
            device,
            {VK_FORMAT_R16G16_SFLOAT, kDfgTableSize, kDfgTableSize, 1, 1, VK_SAMPLE_COUNT_1_BIT,
             VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, VK_IMAGE_VIEW_TYPE_2D},
            "scene.environment.dfg");
        // Longitude wraps, latitude stops at the poles.
        VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
        info.magFilter = info.minFilter = VK_FILTER_LINEAR;
        info.addressModeU = VK_SAMPLER_ADDRESS_MODE_REPEAT;
        info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        info.maxLod = 0.0f;
        VK_CHECK(vkCreateSampler(device.device(), &info, nullptr, &m_sampler));
        device.setName(VK_OBJECT_TYPE_SAMPLER, m_sampler, "scene.environment.sampler");
        info.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        VK_CHECK(vkCreateSampler(device.device(), &info, nullptr, &m_dfgSampler));
        device.setName(VK_OBJECT_TYPE_SAMPLER, m_dfgSampler, "scene.environment.dfg.sampler");

        // The upload, through a render graph that owns the layout transitions. The staging buffer
        // lives for this call only, on every path out.
        const std::span<const std::byte> levels = std::as_bytes(std::span(texels));
        const std::span<const std::byte> table = std::as_bytes(std::span(dfgTexels));
        const VkDeviceSize dfgOffset = (levels.size() + 15) / 16 * 16; // a multiple of the texel size
        struct Staging {
            vk::Device& device;
            vk::Buffer buffer;
            ~Staging() { vk::destroyBuffer(device, buffer); }
        } staging{device, vk::createBuffer(device, dfgOffset + table.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                           vk::MemoryUse::Upload, "scene.environment.staging")};
        vk::writeBuffer(device, staging.buffer, levels);
        vk::writeBuffer(device, staging.buffer, table, dfgOffset);
        rg::Graph graph;
        const rg::Buffer source =
            graph.importBuffer("scene.environment.staging", {staging.buffer.buffer, staging.buffer.size},
                               std::nullopt, std::nullopt);
        const rg::Texture prefiltered = graph.importTexture("scene.environment",
                                                            {m_prefiltered.image,
                                                             m_prefiltered.view,
                                                             m_prefiltered.sampledView,
                                                             {VK_FORMAT_R16G16B16A16_SFLOAT, w, h, layers}},
                                                            std::nullopt, rg::Use::SampledCompute);
        const rg::Texture dfg =
            graph.importTexture("scene.environment.dfg",
                                {m_dfg.image,
                                 m_dfg.view,
                                 m_dfg.sampledView,
                                 {VK_FORMAT_R16G16_SFLOAT, kDfgTableSize, kDfgTableSize, 1}},
                                std::nullopt, rg::Use::SampledCompute);
        struct Data {
            rg::Buffer staging;
            rg::Texture prefiltered, dfg;
        };
        graph.addPass<Data>(
            "scene.environment.upload", rg::PassKind::Transfer,
            [&](rg::Builder& b, Data& d) {
                d.staging = b.read(source, rg::Use::TransferSrc);
                d.prefiltered = b.write(prefiltered, rg::Use::TransferDst);
                d.dfg = b.write(dfg, rg::Use::TransferDst);
            },
            [&](const rg::Context& ctx, const Data& d) {
                VkBufferImageCopy copy{};
                copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, layers};
                copy.imageExtent = {w, h, 1};
                vkCmdCopyBufferToImage(ctx.cmd(), ctx.buffer(d.staging).buffer,
                                       ctx.texture(d.prefiltered).image, ctx.layout(d.prefiltered), 1, &copy);
                copy.bufferOffset = dfgOffset;
                copy.imageSubresource.layerCount = 1;
                copy.imageExtent = {kDfgTableSize, kDfgTableSize, 1};
                vkCmdCopyBufferToImage(ctx.cmd(), ctx.buffer(d.staging).buffer, ctx.texture(d.dfg).image,
                                       ctx.layout(d.dfg), 1, &copy);
            });
        FrameRunner(device).run(graph); // compiles, submits, waits, releases the transients
    } catch (...) {
        release();
        throw;
    }
}

GpuEnvironment::~GpuEnvironment() {
    release();
}

void GpuEnvironment::release() {
    VkDevice d = m_device.device();
    vkDeviceWaitIdle(d);
    if (m_sampler) vkDestroySampler(d, m_sampler, nullptr);
    if (m_dfgSampler) vkDestroySampler(d, m_dfgSampler, nullptr);
    vk::destroyImage(m_device, m_prefiltered);
    vk::destroyImage(m_device, m_dfg);
    vk::destroyBuffer(m_device, m_constants);
    m_sampler = m_dfgSampler = VK_NULL_HANDLE;
}

} // namespace eng::frame
