#include "agaa/sbaa/surface_fill.h"

#include "agaa/common/effects.h"
#include "agaa/common/sample_gbuffer.h"
#include "engine/frame/sample_pattern.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/reflection.h"
#include "shaders/reference/gbuffer_vert.h"
#include "shaders/sbaa/fill_frag.h"
#include "shaders/sbaa/fill_sample_rate_frag.h"

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

SurfaceFillPass::SurfaceFillPass(vk::Device& device, const eng::frame::GpuScene& scene, uint32_t samples,
                                 uint32_t surfaces, const eng::scene::SceneFeatures& features,
                                 bool sampleRate)
    : m_device(device), m_samples(samples) {
    vk::GraphicsPipelineDesc d;
    d.vertex = kReferenceGbufferVert;
    sampleRate = sampleRate && samples > 1;
    d.fragment = sampleRate ? std::span<const uint32_t>(kSbaaFillSampleRateFrag) : kSbaaFillFrag;

    vk::LayoutDesc layout;
    layout.pushBindings = vk::reflectBindings(
        {{d.vertex, VK_SHADER_STAGE_VERTEX_BIT}, {d.fragment, VK_SHADER_STAGE_FRAGMENT_BIT}});
    layout.extraSets = {scene.textureSetLayout()};
    layout.pushConstantBytes = 8; // material index, first triangle
    m_layout = vk::createPipelineLayout(device, layout, "sbaa.fill.layout");
    d.layout = m_layout.layout;
    // Alpha path 0: the prepass already applied the alpha (its ids are what survived), and the
    // fill must not discard. Ids 8..10 (curvature roughness) off: the material's own roughness,
    // as the per-sample G-buffer of every peer.
    d.specialization = effectSpecialization(features, 1);
    d.specialization.byId.insert(d.specialization.byId.end(),
                                 {{shared::kSpecFillAlphaPath, uint32_t(AlphaPath::Opaque)},
                                  {shared::kSpecFillCurvatureRoughness, 0u},
                                  {shared::kSpecFillSbaaSurfaces, surfaces}});
    addMaterialSpecialization(d.specialization, features);
    d.sampleShading = sampleRate;
    d.colorFormats = {};
    d.depthFormat = SampleGBufferPass::kDepthFormat;
    d.depthWrite = false;
    d.depthCompare = VK_COMPARE_OP_EQUAL;
    d.samples = samples > 1 ? VK_SAMPLE_COUNT_4_BIT : VK_SAMPLE_COUNT_1_BIT;
    // The prepass's culling: a culled primitive never holds a sample, and rasterising it again
    // would cost the EQUAL test of every back-facing fragment.
    for (bool doubleSided : {false, true}) {
        d.cullMode = doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
        m_pipelines[doubleSided ? 1 : 0] =
            vk::createGraphicsPipeline(device, d, doubleSided ? "sbaa.fill.twoSided" : "sbaa.fill");
    }
}

SurfaceFillPass::~SurfaceFillPass() {
    vkDeviceWaitIdle(m_device.device());
    for (VkPipeline p : m_pipelines)
        vkDestroyPipeline(m_device.device(), p, nullptr);
    vk::destroyPipelineLayout(m_device, m_layout);
}

rg::Buffer SurfaceFillPass::add(rg::Graph& graph, const FrameInputs& in, rg::Texture depth,
                                rg::Buffer surfaces) {
    const eng::frame::GpuScene* gpuScene = in.scene;
    rg::Buffer materials =
        graph.importBuffer("sbaa.fill.materials", {gpuScene->materials().buffer, gpuScene->materials().size},
                           std::nullopt, std::nullopt);
    struct Data {
        rg::Buffer frame, materials, surfaces;
        rg::Texture depth;
    };
    const uint32_t layers = eng::frame::makeSamplePattern(m_samples).layers;
    const Data& out = graph.addGraphics<Data>(
        "sbaa.fill",
        [&](rg::Builder& b, Data& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.materials = b.read(materials, rg::Use::StorageReadFragment);
            d.surfaces = b.readWrite(surfaces, rg::Use::StorageReadWriteFragment);
            rg::Attachment loadDepth;
            loadDepth.load = VK_ATTACHMENT_LOAD_OP_LOAD;
            d.depth = b.depthStencil(depth, rg::Use::DepthReadOnly, loadDepth);
        },
        [this, gpuScene, layers](const rg::Context& ctx, const Data& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vk::PushDescriptors()
                .uniform(0, ctx.buffer(d.frame).buffer)
                .storage(1, ctx.buffer(d.materials).buffer)
                .storage(2, ctx.buffer(d.surfaces).buffer)
                .push(m_device, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, m_layout.layout);
            std::vector<VkPipeline> perDraw;
            for (const eng::scene::Draw& draw : gpuScene->scene().draws)
                perDraw.push_back(
                    m_pipelines[gpuScene->scene().materials.at(draw.material).doubleSided ? 1 : 0]);
            gpuScene->recordDraws(cmd, m_layout.layout, perDraw, layers, true);
        });
    return out.surfaces;
}

} // namespace agaa
