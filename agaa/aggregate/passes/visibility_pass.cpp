// agaa.visibility (agaa/aggregate/passes/visibility_pass.h).

#include "agaa/aggregate/passes/visibility_pass.h"

#include "engine/vk/descriptors.h"

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

VisibilityPass::VisibilityPass(vk::Device& device, const TechniqueContent& content, const AggregatePlan& plan)
    : m_device(device), m_plan(plan),
      m_sceneDrawer(makeSceneDrawer(device, content, plan.features, plan.settings.programs)) {
    m_raster.name = "agaa.visibility";
    m_raster.output = RasterOutput::AggregateVisibility;
    m_raster.colorFormats = {kNormalFormat};
    m_raster.depthFormat = plan.depthFormat;
    m_raster.depthCompare = VK_COMPARE_OP_GREATER; // reversed Z
    m_raster.samples = VK_SAMPLE_COUNT_4_BIT;
    m_raster.layers = plan.layers(); // one instance per emulation layer (common/scene_vertex.glsl)
    m_raster.moduleSet = {
        {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 1},
        {2, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT, 1}};
}

VisibilityPass::~VisibilityPass() = default;

void VisibilityPass::add(rg::Graph& graph, AggregateFrame& frame) {
    struct Visibility {
        rg::Buffer frame, agaa;
        rg::Texture depth, normal;
    };
    // Paper section 3.6: masked materials sample alpha here only, with alpha-to-coverage; the
    // generation pass inherits the coverage through its depth EQUAL test (the drawer's alpha path).
    GeometryDrawer* drawer = &frameDrawer(frame.in, m_sceneDrawer.get(), m_raster.name);
    drawer->prepare(m_raster); // pipelines now, never while a command buffer records
    const Visibility& pass = graph.addGraphics<Visibility>(
        m_raster.name,
        [&](rg::Builder& b, Visibility& d) {
            d.frame = b.read(frame.in.frameConstants, rg::Use::UniformRead);
            d.agaa = b.read(frame.constants, rg::Use::UniformRead);
            // Reversed Z: 0 = far (sky); stencil 0 for generation's first-fragment test.
            rg::Attachment clearDepth;
            clearDepth.clear.depthStencil = {0.0f, 0};
            d.depth = b.depthStencil(b.create("agaa.visibility.depth", frame.sampleDesc(m_plan.depthFormat)),
                                     rg::Use::DepthStencilWrite, clearDepth);
            d.normal = b.color(b.create("agaa.visibility.normal", frame.sampleDesc(kNormalFormat)));
        },
        [this, drawer](const rg::Context& ctx, const Visibility& d) {
            const VkBuffer frameConstants = ctx.buffer(d.frame).buffer, agaa = ctx.buffer(d.agaa).buffer;
            drawer->recordDraws(ctx.cmd(), m_raster,
                                [this, frameConstants, agaa](VkCommandBuffer cmd, VkPipelineLayout layout) {
                                    vk::PushDescriptors()
                                        .uniform(0, frameConstants)
                                        .uniform(2, agaa)
                                        .push(m_device, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout);
                                });
        });
    frame.depth = pass.depth;
    frame.normal = pass.normal;
}

} // namespace agaa
