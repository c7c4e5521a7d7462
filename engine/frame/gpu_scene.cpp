#include "engine/frame/gpu_scene.h"

#include "engine/frame/environment_maps.h"
#include "engine/frame/frame_constants.h"
#include "engine/frame/frame_runner.h"
#include "engine/graph/graph.h"
#include "engine/vk/check.h"
#include "engine/vk/pipeline.h"
#include "shared/frame.h"

#include <glm/glm.hpp>
#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace eng::frame {
namespace {

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
float linearToSrgb(float c) {
    return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

struct MipLevel {
    uint32_t width, height;
    std::vector<uint8_t> rgba;
};

// Toksvig pre-filtering of a normal map's MIP chain (Toksvig 2005; seed 004): a texel of level
// k+1 holds the mean of the tangent-space normals beneath it. RGB stores that mean's direction
// (renormalised, so bilinear taps stay well-conditioned) and A its length |Na| in [0, 1]: 1 at
// level 0 by construction, shorter where the normals below disagree. common/material.glsl turns
// the fetched length into extra roughness, so each sample's normal carries its variance into
// the aggregate. The mean is built from the stored (direction * length) of the level above, so
// the chain is the exact box-filtered mean of level 0 up to 8-bit rounding.
std::vector<MipLevel> buildNormalMips(const scene::Texture& t) {
    std::vector<MipLevel> mips{{t.width, t.height, t.rgba8}};
    auto decode = [](const uint8_t* p) { return glm::vec3(p[0], p[1], p[2]) / 255.0f * 2.0f - 1.0f; };
    for (size_t i = 0; i + 3 < mips[0].rgba.size(); i += 4)
        mips[0].rgba[i + 3] = 255; // glTF ignores alpha here
    while (mips.back().width > 1 || mips.back().height > 1) {
        const MipLevel& src = mips.back();
        MipLevel dst{std::max(1u, src.width / 2), std::max(1u, src.height / 2), {}};
        dst.rgba.resize(size_t(dst.width) * dst.height * 4);
        for (uint32_t y = 0; y < dst.height; ++y)
            for (uint32_t x = 0; x < dst.width; ++x) {
                glm::vec3 sum(0.0f);
                for (uint32_t dy = 0; dy < 2; ++dy)
                    for (uint32_t dx = 0; dx < 2; ++dx) {
                        uint32_t sx = std::min(src.width - 1, 2 * x + dx),
                                 sy = std::min(src.height - 1, 2 * y + dy);
                        const uint8_t* p = &src.rgba[(size_t(sy) * src.width + sx) * 4];
                        glm::vec3 n = decode(p);
                        float len = glm::length(n);
                        // Stored direction times stored length; a zero vector has no direction.
                        if (len > 1e-6f) sum += n / len * (p[3] / 255.0f);
                    }
                glm::vec3 mean = sum * 0.25f;
                float len = glm::length(mean);
                glm::vec3 dir = len > 1e-6f ? mean / len : glm::vec3(0.0f, 0.0f, 1.0f);
                uint8_t* q = &dst.rgba[(size_t(y) * dst.width + x) * 4];
                for (int c = 0; c < 3; ++c)
                    q[c] = uint8_t(std::lround(std::clamp(dir[c] * 0.5f + 0.5f, 0.0f, 1.0f) * 255.0f));
                q[3] = uint8_t(std::lround(std::clamp(len, 0.0f, 1.0f) * 255.0f));
            }
        mips.push_back(std::move(dst));
    }
    return mips;
}

// 2x2 box filter down to 1x1; sRGB colour averaged in linear space so dark/bright edges keep their weight.
std::vector<MipLevel> buildMips(const scene::Texture& t) {
    std::vector<MipLevel> mips{{t.width, t.height, t.rgba8}};
    while (mips.back().width > 1 || mips.back().height > 1) {
        const MipLevel& src = mips.back();
        MipLevel dst{std::max(1u, src.width / 2), std::max(1u, src.height / 2), {}};
        dst.rgba.resize(size_t(dst.width) * dst.height * 4);
        for (uint32_t y = 0; y < dst.height; ++y)
            for (uint32_t x = 0; x < dst.width; ++x)
                for (uint32_t c = 0; c < 4; ++c) {
                    float sum = 0.0f;
                    for (uint32_t dy = 0; dy < 2; ++dy)
                        for (uint32_t dx = 0; dx < 2; ++dx) {
                            uint32_t sx = std::min(src.width - 1, 2 * x + dx),
                                     sy = std::min(src.height - 1, 2 * y + dy);
                            float v = src.rgba[(size_t(sy) * src.width + sx) * 4 + c] / 255.0f;
                            sum += (t.srgb && c < 3) ? srgbToLinear(v) : v;
                        }
                    float v = sum * 0.25f;
                    if (t.srgb && c < 3) v = linearToSrgb(v);
                    dst.rgba[(size_t(y) * dst.width + x) * 4 + c] =
                        uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
                }
        mips.push_back(std::move(dst));
    }
    return mips;
}

template <class T> std::span<const std::byte> bytesOf(const std::vector<T>& v) {
    return std::as_bytes(std::span<const T>(v));
}

} // namespace

GpuScene::GpuScene(vk::Device& device, const scene::Scene& scene) : m_device(device), m_scene(scene) {
    if (scene.textures.size() + 1 > shared::kMaxSceneTextures)
        throw std::invalid_argument(scene.source + ": " + std::to_string(scene.textures.size()) +
                                    " textures; at most " + std::to_string(shared::kMaxSceneTextures - 1) +
                                    " are supported");
    // Whatever was created is released if a later step throws (out of memory, a lost device).
    try {
        // Host-visible vertex data: lavapipe's memory is all host-visible; on a discrete GPU this
        // is read over the bus (a staging copy would be the next step there).
        m_vertices =
            vk::createBuffer(device, std::max<size_t>(16, scene.vertices.size() * sizeof(scene::Vertex)),
                             VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                             vk::MemoryUse::Upload, "scene.vertices");
        m_indices = vk::createBuffer(device, std::max<size_t>(16, scene.indices.size() * 4),
                                     VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                     vk::MemoryUse::Upload, "scene.indices");
        if (!scene.vertices.empty()) vk::writeBuffer(device, m_vertices, bytesOf(scene.vertices));
        if (!scene.indices.empty()) vk::writeBuffer(device, m_indices, bytesOf(scene.indices));
        std::vector<shared::GpuMaterial> materials = makeGpuMaterials(scene);
        if (materials.empty()) materials.push_back(shared::GpuMaterial{});
        m_materials =
            vk::createBuffer(device, materials.size() * sizeof(shared::GpuMaterial),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Upload, "scene.materials");
        vk::writeBuffer(device, m_materials, bytesOf(materials));

        m_sampler = vk::createSampler(device, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_REPEAT, 16.0f,
                                      "scene.sampler");
        m_environment = std::make_unique<GpuEnvironment>(m_device, &m_scene.environment);
        uploadTextures();

        // Set 1 of every pass that draws this scene (shaders/glsl/common/scene_materials.glsl):
        // the textures, then the material table.
        const std::array<vk::Binding, 2> bindings{
            vk::Binding{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                        VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT,
                        shared::kMaxSceneTextures},
            vk::Binding{1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                        VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT, 1}};
        m_materialSetLayout = vk::createSetLayout(device, bindings, "scene.materials.layout");
        const std::array<VkDescriptorPoolSize, 2> sizes{
            VkDescriptorPoolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, shared::kMaxSceneTextures},
            VkDescriptorPoolSize{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}};
        VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        poolInfo.maxSets = 1;
        poolInfo.poolSizeCount = uint32_t(sizes.size());
        poolInfo.pPoolSizes = sizes.data();
        VK_CHECK(vkCreateDescriptorPool(device.device(), &poolInfo, nullptr, &m_pool));
        VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        alloc.descriptorPool = m_pool;
        alloc.descriptorSetCount = 1;
        alloc.pSetLayouts = &m_materialSetLayout;
        VK_CHECK(vkAllocateDescriptorSets(device.device(), &alloc, &m_materialSet));
        // Unused slots point at the white fallback, so no descriptor is ever undefined.
        std::vector<VkDescriptorImageInfo> infos(shared::kMaxSceneTextures);
        for (uint32_t i = 0; i < shared::kMaxSceneTextures; ++i) {
            const vk::Image& img = i < scene.textures.size() ? m_textures[i] : m_textures.back();
            // The layout the upload graph leaves them in (its final state, SampledFragment).
            infos[i] = {m_sampler, img.view, rg::useInfo(rg::Use::SampledFragment).layout};
        }
        const VkDescriptorBufferInfo materialsInfo{m_materials.buffer, 0, VK_WHOLE_SIZE};
        std::array<VkWriteDescriptorSet, 2> writes{};
        writes[0] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[0].dstSet = m_materialSet;
        writes[0].descriptorCount = shared::kMaxSceneTextures;
        writes[0].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        writes[0].pImageInfo = infos.data();
        writes[1] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[1].dstSet = m_materialSet;
        writes[1].dstBinding = 1;
        writes[1].descriptorCount = 1;
        writes[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        writes[1].pBufferInfo = &materialsInfo;
        vkUpdateDescriptorSets(device.device(), uint32_t(writes.size()), writes.data(), 0, nullptr);
    } catch (...) {
        release();
        throw;
    }
}

void GpuScene::uploadTextures() {
    std::vector<scene::Texture> sources = m_scene.textures;
    sources.push_back({"fallback.white", 1, 1, false, {255, 255, 255, 255}});

    struct Pending {
        std::vector<MipLevel> mips;
        VkDeviceSize offset;
    };
    std::vector<Pending> pending;
    VkDeviceSize total = 0;
    // Textures used only as normal maps get the Toksvig chain; one shared with a colour slot keeps
    // the plain box filter (its alpha may mean something there).
    std::vector<int> normalUse(sources.size(), 0), otherUse(sources.size(), 0);
    for (const scene::Material& m : m_scene.materials) {
        auto mark = [&](int32_t index, std::vector<int>& use) {
            if (index >= 0 && size_t(index) < use.size()) use[size_t(index)] = 1;
        };
        mark(m.normalTexture, normalUse);
        mark(m.baseColorTexture, otherUse);
        mark(m.metallicRoughnessTexture, otherUse);
        mark(m.emissiveTexture, otherUse);
    }
    for (size_t i = 0; i < sources.size(); ++i) {
        const scene::Texture& t = sources[i];
        const bool normalMap = normalUse[i] && !otherUse[i] && !t.srgb;
        Pending p{normalMap ? buildNormalMips(t) : buildMips(t), total};
        for (const MipLevel& m : p.mips)
            total += m.rgba.size();
        pending.push_back(std::move(p));
    }
    // The staging buffer lives for this call only, on every path out (a texture's allocation or
    // the upload's submission may throw).
    struct Staging {
        vk::Device& device;
        vk::Buffer buffer;
        ~Staging() { vk::destroyBuffer(device, buffer); }
    } stagingOwner{m_device, {}};
    stagingOwner.buffer = vk::createBuffer(m_device, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                           vk::MemoryUse::Upload, "scene.textures.staging");
    const vk::Buffer& staging = stagingOwner.buffer;
    rg::Graph graph;
    std::vector<rg::Texture> handles;
    for (size_t i = 0; i < sources.size(); ++i) {
        const scene::Texture& t = sources[i];
        VkDeviceSize offset = pending[i].offset;
        for (const MipLevel& m : pending[i].mips) {
            vk::writeBuffer(m_device, staging, std::as_bytes(std::span(m.rgba)), offset);
            offset += m.rgba.size();
        }
        vk::ImageDesc desc{t.srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM,
                           t.width,
                           t.height,
                           1,
                           uint32_t(pending[i].mips.size()),
                           VK_SAMPLE_COUNT_1_BIT,
                           VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                           VK_IMAGE_VIEW_TYPE_2D};
        m_textures.push_back(vk::createImage(
            m_device, desc, "scene.texture." + (t.name.empty() ? std::to_string(i) : t.name)));
        const vk::Image& img = m_textures.back();
        rg::PhysicalTexture physical{
            img.image, img.view, img.sampledView, {desc.format, t.width, t.height, 1}};
        handles.push_back(graph.importTexture("scene.texture." + std::to_string(i), physical, std::nullopt,
                                              rg::Use::SampledFragment));
    }
    rg::PhysicalBuffer stagingPhysical{staging.buffer, staging.size};
    rg::Buffer stagingHandle =
        graph.importBuffer("scene.textures.staging", stagingPhysical, std::nullopt, std::nullopt);
    struct Data {
        rg::Buffer staging;
        std::vector<rg::Texture> textures;
    };
    graph.addPass<Data>(
        "scene.upload", rg::PassKind::Transfer,
        [&](rg::Builder& b, Data& d) {
            d.staging = b.read(stagingHandle, rg::Use::TransferSrc);
            for (rg::Texture t : handles)
                d.textures.push_back(b.write(t, rg::Use::TransferDst));
        },
        [&](const rg::Context& ctx, const Data& d) {
            for (size_t i = 0; i < d.textures.size(); ++i) {
                VkDeviceSize offset = pending[i].offset;
                for (uint32_t level = 0; level < pending[i].mips.size(); ++level) {
                    const MipLevel& m = pending[i].mips[level];
                    VkBufferImageCopy copy{};
                    copy.bufferOffset = offset;
                    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
                    copy.imageExtent = {m.width, m.height, 1};
                    vkCmdCopyBufferToImage(ctx.cmd(), ctx.buffer(d.staging).buffer,
                                           ctx.texture(d.textures[i]).image, ctx.layout(d.textures[i]), 1,
                                           &copy);
                    offset += m.rgba.size();
                }
            }
        });
    FrameRunner(m_device).run(graph); // compiles, submits, waits, releases the transients
}

GpuScene::~GpuScene() {
    release();
}

void GpuScene::release() {
    VkDevice d = m_device.device();
    vkDeviceWaitIdle(d);
    if (m_pool) vkDestroyDescriptorPool(d, m_pool, nullptr);
    if (m_materialSetLayout) vkDestroyDescriptorSetLayout(d, m_materialSetLayout, nullptr);
    if (m_sampler) vkDestroySampler(d, m_sampler, nullptr);
    m_environment.reset();
    for (auto& t : m_textures)
        vk::destroyImage(m_device, t);
    vk::destroyBuffer(m_device, m_vertices);
    vk::destroyBuffer(m_device, m_indices);
    vk::destroyBuffer(m_device, m_materials);
    m_textures.clear();
    m_pool = VK_NULL_HANDLE;
    m_materialSetLayout = VK_NULL_HANDLE;
    m_sampler = VK_NULL_HANDLE;
}

void GpuScene::recordDraws(VkCommandBuffer cmd, VkPipelineLayout layout,
                           std::span<const VkPipeline> pipelinePerDraw, uint32_t instances,
                           bool pushFirstTriangle) const {
    VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &m_vertices.buffer, &offset);
    vkCmdBindIndexBuffer(cmd, m_indices.buffer, 0, VK_INDEX_TYPE_UINT32);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 1, 1, &m_materialSet, 0, nullptr);
    VkPipeline bound = VK_NULL_HANDLE;
    const auto& draws = m_scene.draws;
    for (size_t i = 0; i < draws.size() && i < pipelinePerDraw.size(); ++i) {
        if (draws[i].indexCount == 0) continue;
        if (pipelinePerDraw[i] != bound) {
            bound = pipelinePerDraw[i];
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound);
        }
        const uint32_t push[2] = {draws[i].material, draws[i].firstIndex / 3};
        vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_ALL, 0, pushFirstTriangle ? 8 : 4, push);
        vkCmdDrawIndexed(cmd, draws[i].indexCount, instances, draws[i].firstIndex, 0, 0);
    }
}

bool GpuScene::hasEmissive() const {
    for (const scene::Material& m : m_scene.materials)
        if (m.emissiveStrength > 0.0f &&
            (m.emissiveFactor.r > 0.0f || m.emissiveFactor.g > 0.0f || m.emissiveFactor.b > 0.0f))
            return true;
    return false;
}

VkDeviceSize GpuScene::bytes() const {
    VkDeviceSize b = m_vertices.size + m_indices.size + m_materials.size + m_environment->bytes();
    for (const auto& t : m_textures)
        b += t.bytes;
    return b;
}

} // namespace eng::frame
