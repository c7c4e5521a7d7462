#include "agaa/reference/reference.h"

#include "engine/frame/sample_pattern.h"
#include "engine/vk/check.h"
#include "engine/vk/resources.h"
#include "shaders/reference/gbuffer_frag.h"
#include "shaders/reference/gbuffer_vert.h"
#include "shaders/reference/lighting_ms_comp.h"
#include "shaders/reference/lighting_ss_comp.h"
#include "shared/frame.h"

#include <stdexcept>

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

namespace {

VkDescriptorBufferInfo bufferInfo(const rg::PhysicalBuffer& b) { return {b.buffer, 0, VK_WHOLE_SIZE}; }

VkWriteDescriptorSet bufferWrite(uint32_t binding, VkDescriptorType type, const VkDescriptorBufferInfo* info) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    w.pBufferInfo = info;
    return w;
}

VkWriteDescriptorSet imageWrite(uint32_t binding, VkDescriptorType type, const VkDescriptorImageInfo* info) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    w.pImageInfo = info;
    return w;
}

} // namespace

Reference::Reference(vk::Device& device, const eng::frame::GpuScene& scene, const ReferenceSettings& settings,
                     std::string name)
    : m_device(device), m_settings(settings), m_name(std::move(name)) {
    if (!eng::frame::isSupportedSampleCount(settings.samples))
        throw std::invalid_argument("--samples " + std::to_string(settings.samples) + " is not supported (allowed: " +
                                    eng::frame::supportedSampleCounts() + ")");
    if (settings.samples > 1 && !device.caps().supportsSamples(4))
        throw vk::MissingCapability(device.caps().deviceName + " lacks 4x MSAA colour/depth (needed for --samples " +
                                    std::to_string(settings.samples) + ")");

    vk::LayoutDesc gbuffer;
    gbuffer.pushBindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT},
                            {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT}};
    gbuffer.extraSets = {scene.textureSetLayout()};
    gbuffer.pushConstantBytes = 4;
    m_gbufferLayout = vk::createPipelineLayout(device, gbuffer, m_name + ".gbuffer.layout");

    vk::LayoutDesc lighting;
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    lighting.pushBindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                             {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                             {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, cs},
                             {3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, cs},
                             {4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, cs},
                             {5, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, cs},
                             {6, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                             {7, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                             {8, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs}};
    m_lightingLayout = vk::createPipelineLayout(device, lighting, m_name + ".lighting.layout");
    std::span<const uint32_t> code = settings.samples > 1 ? kReferenceLightingMsComp : kReferenceLightingSsComp;
    m_lightingPipeline = vk::createComputePipeline(device, code, m_lightingLayout.layout, {}, m_name + ".lighting");
    m_fetchSampler = vk::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f,
                                       m_name + ".fetchSampler");
}

Reference::~Reference() {
    VkDevice d = m_device.device();
    vkDeviceWaitIdle(d);
    for (VkPipeline p : m_gbufferPipelines)
        if (p) vkDestroyPipeline(d, p, nullptr);
    vkDestroyPipeline(d, m_lightingPipeline, nullptr);
    vkDestroySampler(d, m_fetchSampler, nullptr);
    vk::destroyPipelineLayout(m_device, m_gbufferLayout);
    vk::destroyPipelineLayout(m_device, m_lightingLayout);
}

VkPipeline Reference::gbufferPipeline(bool alphaTested, bool doubleSided) {
    VkPipeline& p = m_gbufferPipelines[(alphaTested ? 2 : 0) + (doubleSided ? 1 : 0)];
    if (p) return p;
    vk::GraphicsPipelineDesc d;
    d.vertex = kReferenceGbufferVert;
    d.fragment = kReferenceGbufferFrag;
    d.layout = m_gbufferLayout.layout;
    d.specialization.values = {alphaTested ? 1u : 0u};
    d.colorFormats = {kNormalFormat, kAlbedoMetalFormat, kEmissiveRoughnessFormat};
    d.depthFormat = kDepthFormat;
    d.samples = m_settings.samples > 1 ? VK_SAMPLE_COUNT_4_BIT : VK_SAMPLE_COUNT_1_BIT;
    d.cullMode = doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
    d.depthCompare = VK_COMPARE_OP_GREATER; // reversed Z: nearer is larger
    std::string name = m_name + ".gbuffer" + (alphaTested ? ".masked" : ".opaque") + (doubleSided ? ".twoSided" : "");
    p = vk::createGraphicsPipeline(m_device, d, name);
    return p;
}

bool Reference::isStorage(const std::string& resourceName) const {
    return resourceName.rfind(m_name + ".gbuffer.", 0) == 0;
}

FrameTargets Reference::addPasses(rg::Graph& graph, const FrameInputs& in) {
    const eng::frame::SamplePattern pattern = eng::frame::makeSamplePattern(m_settings.samples);
    const VkSampleCountFlagBits hwSamples = pattern.samplesPerLayer == 4 ? VK_SAMPLE_COUNT_4_BIT : VK_SAMPLE_COUNT_1_BIT;
    const rg::TextureDesc base{VK_FORMAT_UNDEFINED, in.width, in.height, pattern.layers, hwSamples};
    auto desc = [&](VkFormat f) {
        rg::TextureDesc d = base;
        d.format = f;
        return d;
    };

    // Variants each draw needs, chosen up front so pipeline creation never happens mid-recording.
    const eng::scene::Scene& scene = in.scene->scene();
    std::vector<VkPipeline> drawPipelines;
    for (const eng::scene::Draw& draw : scene.draws) {
        const eng::scene::Material& m = scene.materials.at(draw.material);
        drawPipelines.push_back(gbufferPipeline(m.alphaMode == eng::scene::AlphaMode::Mask, m.doubleSided));
    }

    struct GBuffer {
        rg::Buffer frame, materials;
        rg::Texture depth, normal, albedoMetal, emissiveRoughness;
    };
    const eng::frame::GpuScene* gpuScene = in.scene;
    rg::Buffer materials = graph.importBuffer(m_name + ".materials", {gpuScene->materials().buffer, gpuScene->materials().size},
                                              std::nullopt, std::nullopt);
    const GBuffer& g = graph.addGraphics<GBuffer>(
        m_name + ".gbuffer",
        [&](rg::Builder& b, GBuffer& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.materials = b.read(materials, rg::Use::StorageReadFragment);
            d.depth = b.write(b.create(m_name + ".gbuffer.depth", desc(kDepthFormat)), rg::Use::DepthStencilWrite);
            d.normal = b.write(b.create(m_name + ".gbuffer.normal", desc(kNormalFormat)), rg::Use::ColorAttachment);
            d.albedoMetal =
                b.write(b.create(m_name + ".gbuffer.albedoMetal", desc(kAlbedoMetalFormat)), rg::Use::ColorAttachment);
            d.emissiveRoughness = b.write(b.create(m_name + ".gbuffer.emissiveRoughness", desc(kEmissiveRoughnessFormat)),
                                          rg::Use::ColorAttachment);
        },
        [this, gpuScene, drawPipelines, layers = pattern.layers, w = in.width, h = in.height](const rg::Context& ctx,
                                                                                          const GBuffer& d) {
            VkCommandBuffer cmd = ctx.cmd();
            VkRenderingAttachmentInfo colors[3];
            const rg::Texture targets[3] = {d.normal, d.albedoMetal, d.emissiveRoughness};
            for (int i = 0; i < 3; ++i) {
                colors[i] = {VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
                colors[i].imageView = ctx.texture(targets[i]).view;
                colors[i].imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
                colors[i].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
                colors[i].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
            }
            VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
            depth.imageView = ctx.texture(d.depth).view;
            depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
            depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
            depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
            depth.clearValue.depthStencil = {0.0f, 0}; // reversed Z: 0 is the far plane (sky)
            VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
            info.renderArea = {{0, 0}, {w, h}};
            info.layerCount = layers;
            info.colorAttachmentCount = 3;
            info.pColorAttachments = colors;
            info.pDepthAttachment = &depth;
            vkCmdBeginRendering(cmd, &info);
            VkViewport viewport{0.0f, 0.0f, float(w), float(h), 0.0f, 1.0f};
            VkRect2D scissor{{0, 0}, {w, h}};
            vkCmdSetViewport(cmd, 0, 1, &viewport);
            vkCmdSetScissor(cmd, 0, 1, &scissor);
            VkDeviceSize offset = 0;
            VkBuffer vb = gpuScene->vertexBuffer();
            vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
            vkCmdBindIndexBuffer(cmd, gpuScene->indexBuffer(), 0, VK_INDEX_TYPE_UINT32);
            VkDescriptorBufferInfo frameInfo = bufferInfo(ctx.buffer(d.frame));
            VkDescriptorBufferInfo materialInfo = bufferInfo(ctx.buffer(d.materials));
            VkWriteDescriptorSet writes[] = {bufferWrite(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &frameInfo),
                                             bufferWrite(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &materialInfo)};
            m_device.pushDescriptorSet()(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, m_gbufferLayout.layout, 0, 2, writes);
            VkDescriptorSet textures = gpuScene->textureSet();
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, m_gbufferLayout.layout, 1, 1, &textures, 0,
                                    nullptr);
            VkPipeline bound = VK_NULL_HANDLE;
            const auto& draws = gpuScene->scene().draws;
            for (size_t i = 0; i < draws.size(); ++i) {
                if (draws[i].indexCount == 0) continue;
                if (drawPipelines[i] != bound) {
                    bound = drawPipelines[i];
                    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound);
                }
                uint32_t material = draws[i].material;
                vkCmdPushConstants(cmd, m_gbufferLayout.layout, VK_SHADER_STAGE_ALL, 0, 4, &material);
                // One instance per emulation layer (common/scene_vertex.glsl).
                vkCmdDrawIndexed(cmd, draws[i].indexCount, layers, draws[i].firstIndex, 0, 0);
            }
            vkCmdEndRendering(cmd);
        });

    struct Lighting {
        rg::Buffer frame, lights;
        rg::Texture depth, normal, albedoMetal, emissiveRoughness;
        rg::Texture hdr, display, events;
    };
    const rg::TextureDesc out{VK_FORMAT_R32G32B32A32_SFLOAT, in.width, in.height, 1, VK_SAMPLE_COUNT_1_BIT};
    const rg::TextureDesc eventsDesc{VK_FORMAT_R32_UINT, in.width, in.height, 1, VK_SAMPLE_COUNT_1_BIT};
    const Lighting& l = graph.addCompute<Lighting>(
        m_name + ".lighting",
        [&](rg::Builder& b, Lighting& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.lights = b.read(in.lights, rg::Use::StorageReadCompute);
            d.depth = b.read(g.depth, rg::Use::SampledCompute);
            d.normal = b.read(g.normal, rg::Use::SampledCompute);
            d.albedoMetal = b.read(g.albedoMetal, rg::Use::SampledCompute);
            d.emissiveRoughness = b.read(g.emissiveRoughness, rg::Use::SampledCompute);
            d.hdr = b.write(b.create(m_name + ".hdr", out), rg::Use::StorageImageWriteCompute);
            d.display = b.write(b.create(m_name + ".display", out), rg::Use::StorageImageWriteCompute);
            d.events = b.write(b.create(m_name + ".shadingEvents", eventsDesc), rg::Use::StorageImageWriteCompute);
        },
        [this, w = in.width, h = in.height](const rg::Context& ctx, const Lighting& d) {
            VkCommandBuffer cmd = ctx.cmd();
            VkDescriptorBufferInfo frameInfo = bufferInfo(ctx.buffer(d.frame));
            VkDescriptorBufferInfo lightInfo = bufferInfo(ctx.buffer(d.lights));
            auto sampled = [&](rg::Texture t) {
                return VkDescriptorImageInfo{m_fetchSampler, ctx.texture(t).sampledView,
                                             VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
            };
            auto storage = [&](rg::Texture t) {
                return VkDescriptorImageInfo{VK_NULL_HANDLE, ctx.texture(t).view, VK_IMAGE_LAYOUT_GENERAL};
            };
            VkDescriptorImageInfo images[] = {sampled(d.depth), sampled(d.normal), sampled(d.albedoMetal),
                                              sampled(d.emissiveRoughness), storage(d.hdr), storage(d.display),
                                              storage(d.events)};
            std::vector<VkWriteDescriptorSet> writes = {bufferWrite(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &frameInfo),
                                                        bufferWrite(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &lightInfo)};
            for (uint32_t i = 0; i < 4; ++i)
                writes.push_back(imageWrite(2 + i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, &images[i]));
            for (uint32_t i = 4; i < 7; ++i) writes.push_back(imageWrite(2 + i, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, &images[i]));
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_lightingPipeline);
            m_device.pushDescriptorSet()(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_lightingLayout.layout, 0,
                                         uint32_t(writes.size()), writes.data());
            vkCmdDispatch(cmd, (w + shared::kTileSize - 1) / shared::kTileSize,
                          (h + shared::kTileSize - 1) / shared::kTileSize, 1);
        });
    return {l.hdr, l.display, l.events};
}

} // namespace agaa
