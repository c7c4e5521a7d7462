#include "agaa/sbaa/surface_fill.h"

#include "agaa/common/effects.h"
#include "agaa/common/sample_gbuffer.h"
#include "engine/frame/sample_pattern.h"
#include "engine/vk/descriptors.h"

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

SurfaceFillPass::SurfaceFillPass(vk::Device& device, const TechniqueContent& content, uint32_t samples,
                                 uint32_t surfaces, const eng::scene::SceneFeatures& features,
                                 bool sampleRate, const CurvatureRoughness& curvature)
    : m_device(device), m_sceneDrawer(makeSceneDrawer(device, content, features)) {
    const eng::frame::SamplePattern pattern = eng::frame::makeSamplePattern(samples);
    m_raster.name = "sbaa.fill";
    m_raster.output = RasterOutput::SurfaceFill;
    m_raster.depthFormat = SampleGBufferPass::kDepthFormat;
    m_raster.depthCompare = VK_COMPARE_OP_EQUAL; // the prepass's depth, read-only
    m_raster.depthWrite = false;
    m_raster.samples = pattern.samplesPerLayer == 4 ? VK_SAMPLE_COUNT_4_BIT : VK_SAMPLE_COUNT_1_BIT;
    m_raster.layers = pattern.layers;
    m_raster.sampleRateShading = sampleRate && samples > 1;
    m_raster.moduleSet = {
        {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 1},
        {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT, 1}};
    // The curvature roughness as every method's G-buffer takes it. The drawer culls as the prepass
    // did: a culled primitive never holds a sample, and rasterising it again would cost the EQUAL
    // test of every back-facing fragment.
    m_raster.specialization.byId = curvatureSpecialization(curvature);
    m_raster.specialization.byId.push_back({shared::kSpecFillSbaaSurfaces, surfaces});
}

SurfaceFillPass::~SurfaceFillPass() = default;

rg::Buffer SurfaceFillPass::add(rg::Graph& graph, const FrameInputs& in, rg::Texture depth,
                                rg::Buffer surfaces) {
    GeometryDrawer* drawer = &frameDrawer(in, m_sceneDrawer.get(), m_raster.name);
    drawer->prepare(m_raster); // pipelines now, never while a command buffer records
    struct Data {
        rg::Buffer frame, surfaces;
        rg::Texture depth;
    };
    const Data& out = graph.addGraphics<Data>(
        m_raster.name,
        [&](rg::Builder& b, Data& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.surfaces = b.readWrite(surfaces, rg::Use::StorageReadWriteFragment);
            rg::Attachment loadDepth;
            loadDepth.load = VK_ATTACHMENT_LOAD_OP_LOAD;
            d.depth = b.depthStencil(depth, rg::Use::DepthReadOnly, loadDepth);
        },
        [this, drawer](const rg::Context& ctx, const Data& d) {
            const VkBuffer frame = ctx.buffer(d.frame).buffer, records = ctx.buffer(d.surfaces).buffer;
            drawer->recordDraws(ctx.cmd(), m_raster,
                                [this, frame, records](VkCommandBuffer cmd, VkPipelineLayout layout) {
                                    vk::PushDescriptors()
                                        .uniform(0, frame)
                                        .storage(2, records)
                                        .push(m_device, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout);
                                });
        });
    return out.surfaces;
}

} // namespace agaa
