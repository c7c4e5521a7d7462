// agaa.visibility (agaa/aggregate/passes/visibility_pass.h).

#include "agaa/aggregate/passes/visibility_pass.h"

#include "agaa/aggregate/passes/aggregate_programs.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/reflection.h"
#include "shaders/agaa/scene_vert.h"

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

VisibilityPass::VisibilityPass(vk::Device& device, const eng::frame::GpuScene& scene,
                               const AggregatePlan& plan)
    : m_device(device), m_plan(plan),
      m_pipelines(device, [this](const DrawVariant& v) { return makePipeline(v); }) {
    // Set 0 is read from the SPIR-V the layout serves (engine/vk/reflection.h).
    vk::LayoutDesc layout;
    layout.pushBindings = vk::reflectBindings(
        {{kAgaaSceneVert, VK_SHADER_STAGE_VERTEX_BIT},
         {programCode(plan.settings.programs, visibilityProgram()), VK_SHADER_STAGE_FRAGMENT_BIT}});
    layout.extraSets = {scene.textureSetLayout()};
    layout.pushConstantBytes = 4;
    m_layout = vk::createPipelineLayout(m_device, layout, "agaa.visibility.layout");
}

VisibilityPass::~VisibilityPass() {
    m_pipelines.release();
    vk::destroyPipelineLayout(m_device, m_layout);
}

VkPipeline VisibilityPass::makePipeline(const DrawVariant& variant) {
    const AlphaPath alpha = variant.alpha;
    const bool doubleSided = variant.doubleSided;
    vk::GraphicsPipelineDesc d;
    d.vertex = kAgaaSceneVert;
    d.fragment = programCode(m_plan.settings.programs, visibilityProgram());
    d.layout = m_layout.layout;
    // Paper section 3.6: masked materials sample alpha here only, with alpha-to-coverage; the
    // generation pass inherits the coverage through its depth EQUAL test.
    d.specialization.byId = {{shared::kSpecVisibilityAlphaPath, uint32_t(alpha)}};
    addMaterialSpecialization(d.specialization, m_plan.features);
    d.alphaToCoverage = usesAlphaToCoverage(alpha);
    d.colorFormats = {VK_FORMAT_R8G8_UNORM};
    d.depthFormat = m_plan.depthFormat;
    d.samples = VK_SAMPLE_COUNT_4_BIT;
    d.cullMode = doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
    d.depthCompare = VK_COMPARE_OP_GREATER; // reversed Z
    return vk::createGraphicsPipeline(m_device, d,
                                      std::string("agaa.visibility") + alphaPathName(alpha) +
                                          (doubleSided ? ".twoSided" : ""));
}

void VisibilityPass::add(rg::Graph& graph, AggregateFrame& frame) {
    struct Visibility {
        rg::Buffer frame, agaa, materials;
        rg::Texture depth, normal;
    };
    const eng::frame::GpuScene* scene = frame.in.scene;
    std::vector<VkPipeline> pipelines;
    for (const eng::scene::Draw& draw : scene->scene().draws) {
        const eng::scene::Material& m = scene->scene().materials.at(draw.material);
        pipelines.push_back(m_pipelines.get(
            {materialAlphaPath(m, m_plan.features.forced, m_plan.settings.samples), m.doubleSided}));
    }
    const uint32_t layers = m_plan.layers();
    const VkPipelineLayout layout = m_layout.layout;
    const Visibility& pass = graph.addGraphics<Visibility>(
        "agaa.visibility",
        [&](rg::Builder& b, Visibility& d) {
            d.frame = b.read(frame.in.frameConstants, rg::Use::UniformRead);
            d.agaa = b.read(frame.constants, rg::Use::UniformRead);
            d.materials = b.read(frame.materials, rg::Use::StorageReadFragment);
            // Reversed Z: 0 = far (sky); stencil 0 for generation's first-fragment test.
            rg::Attachment clearDepth;
            clearDepth.clear.depthStencil = {0.0f, 0};
            d.depth = b.depthStencil(b.create("agaa.visibility.depth", frame.sampleDesc(m_plan.depthFormat)),
                                     rg::Use::DepthStencilWrite, clearDepth);
            d.normal = b.color(b.create("agaa.visibility.normal", frame.sampleDesc(VK_FORMAT_R8G8_UNORM)));
        },
        [=, this](const rg::Context& ctx, const Visibility& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vk::PushDescriptors()
                .uniform(0, ctx.buffer(d.frame).buffer)
                .storage(1, ctx.buffer(d.materials).buffer)
                .uniform(2, ctx.buffer(d.agaa).buffer)
                .push(m_device, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout);
            // One instance per emulation layer (common/scene_vertex.glsl).
            scene->recordDraws(cmd, layout, pipelines, layers);
        });
    frame.depth = pass.depth;
    frame.normal = pass.normal;
}

} // namespace agaa
