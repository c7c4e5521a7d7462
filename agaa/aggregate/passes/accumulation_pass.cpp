// agaa.clear and agaa.generation (agaa/aggregate/passes/accumulation_pass.h).

#include "agaa/aggregate/passes/accumulation_pass.h"

#include "agaa/aggregate/passes/aggregate_programs.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/reflection.h"
#include "shaders/agaa/scene_vert.h"
#include "shared/ag_buffer.h"
#include "shared/sample_material.h"

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

AccumulationPass::AccumulationPass(vk::Device& device, const eng::frame::GpuScene& scene,
                                   const AggregatePlan& plan)
    : m_device(device), m_plan(plan), m_pipelines(device, [this](const DrawVariant& v) {
          return vk::createGraphicsPipeline(m_device, pipelineDesc(v.doubleSided),
                                            std::string("agaa.generation") +
                                                (v.doubleSided ? ".twoSided" : ""));
      }) {
    vk::LayoutDesc layout;
    layout.extraSets = {scene.textureSetLayout()};
    layout.pushConstantBytes = 4;
    layout.pushBindings = vk::reflectBindings(
        {{kAgaaSceneVert, VK_SHADER_STAGE_VERTEX_BIT}, {code(), VK_SHADER_STAGE_FRAGMENT_BIT}});
    m_layout = vk::createPipelineLayout(m_device, layout, "agaa.generation.layout");
}

AccumulationPass::~AccumulationPass() {
    m_pipelines.release();
    vk::destroyPipelineLayout(m_device, m_layout);
}

std::span<const uint32_t> AccumulationPass::code() const {
    const AggregateSettings& s = m_plan.settings;
    return programCode(s.programs, generationProgram(m_plan.emissive(), s.atomics == AggregateAtomics::Bits64,
                                                     s.subgroupReduction == SubgroupReduction::On));
}

vk::GraphicsPipelineDesc AccumulationPass::pipelineDesc(bool doubleSided) const {
    vk::GraphicsPipelineDesc d;
    d.vertex = kAgaaSceneVert;
    d.fragment = code();
    d.layout = m_layout.layout;
    d.specialization = effectSpecialization(m_plan.features, 1);
    d.specialization.byId.insert(d.specialization.byId.end(),
                                 {{shared::kSpecGenerationNdf, uint32_t(m_plan.settings.ndf)},
                                  {shared::kSpecGenerationRouting, uint32_t(m_plan.settings.routing)},
                                  {shared::kSpecGenerationSampleMaterial, m_plan.shadingRate() ? 1u : 0u}});
    addMaterialSpecialization(d.specialization, m_plan.features);
    if (m_plan.emissive()) d.colorFormats = {VK_FORMAT_B10G11R11_UFLOAT_PACK32};
    d.depthFormat = m_plan.depthFormat;
    d.samples = VK_SAMPLE_COUNT_4_BIT;
    d.cullMode = doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
    // Algorithm 2 step 1: depth EQUAL without writes; stencil keeps the first fragment per sample
    // (GREATER against reference 1 passes while the sample's stencil is 0; INCREMENT_AND_CLAMP on pass).
    d.depthCompare = VK_COMPARE_OP_EQUAL;
    d.depthWrite = false;
    d.stencilTest = true;
    d.stencil = {VK_STENCIL_OP_KEEP,
                 VK_STENCIL_OP_INCREMENT_AND_CLAMP,
                 VK_STENCIL_OP_KEEP,
                 VK_COMPARE_OP_GREATER,
                 0xFF,
                 0xFF,
                 1};
    return d;
}

void AccumulationPass::add(rg::Graph& graph, AggregateFrame& frame) {
    struct Clear {
        rg::Buffer agBuffer, sampleMaterial;
    };
    struct Generation {
        rg::Buffer frame, agaa, materials, metadata, agBuffer, sampleMaterial;
        rg::Texture depth, emissive;
    };
    const FrameInputs& in = frame.in;
    const uint32_t pixels = in.width * in.height;
    const VkDeviceSize agBytes = VkDeviceSize(shared::agBufferWords(pixels, m_plan.settings.aggregates)) * 4;
    // With a tolerance, each covered sample's material (shared/sample_material.h), cleared so that
    // no word is ever undefined; a 16-byte stand-in without one (binding 7 is in the layout
    // whatever the specialisation).
    const VkDeviceSize materialBytes =
        m_plan.shadingRate() ? VkDeviceSize(shared::sampleMaterialWords(pixels, m_plan.settings.samples)) * 4
                             : 16;
    const Clear& clear = graph.addPass<Clear>(
        "agaa.clear", rg::PassKind::Transfer,
        [&](rg::Builder& b, Clear& d) {
            d.agBuffer = b.write(b.create("agaa.agBuffer", {agBytes}), rg::Use::TransferDst);
            d.sampleMaterial =
                b.write(b.create("agaa.sampleMaterial", {materialBytes}), rg::Use::TransferDst);
        },
        [](const rg::Context& ctx, const Clear& d) {
            vkCmdFillBuffer(ctx.cmd(), ctx.buffer(d.agBuffer).buffer, 0, VK_WHOLE_SIZE, 0);
            vkCmdFillBuffer(ctx.cmd(), ctx.buffer(d.sampleMaterial).buffer, 0, VK_WHOLE_SIZE, 0);
        });

    const eng::frame::GpuScene* scene = in.scene;
    std::vector<VkPipeline> pipelines;
    for (const eng::scene::Draw& draw : scene->scene().draws)
        pipelines.push_back(
            m_pipelines.get({AlphaPath::Opaque, scene->scene().materials.at(draw.material).doubleSided}));
    const bool emissive = m_plan.emissive();
    const bool int64 = m_plan.settings.atomics == AggregateAtomics::Bits64;
    const uint32_t layers = m_plan.layers();
    const VkPipelineLayout layout = m_layout.layout;
    const Generation& gen = graph.addGraphics<Generation>(
        "agaa.generation",
        [&](rg::Builder& b, Generation& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.agaa = b.read(frame.constants, rg::Use::UniformRead);
            d.materials = b.read(frame.materials, rg::Use::StorageReadFragment);
            d.metadata = b.read(frame.clusters.metadata, rg::Use::StorageReadFragment);
            d.agBuffer = b.readWrite(clear.agBuffer, rg::Use::StorageReadWriteFragment);
            d.sampleMaterial = b.readWrite(clear.sampleMaterial, rg::Use::StorageReadWriteFragment);
            rg::Attachment loadDepth;
            loadDepth.load = VK_ATTACHMENT_LOAD_OP_LOAD;
            d.depth = b.depthStencil(frame.depth, rg::Use::DepthStencilRead,
                                     loadDepth); // EQUAL test, stencil written
            if (emissive)
                d.emissive =
                    b.color(b.create("agaa.emissive", frame.sampleDesc(VK_FORMAT_B10G11R11_UFLOAT_PACK32)));
        },
        [=, this](const rg::Context& ctx, const Generation& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vk::PushDescriptors pd;
            pd.uniform(0, ctx.buffer(d.frame).buffer)
                .storage(1, ctx.buffer(d.materials).buffer)
                .uniform(2, ctx.buffer(d.agaa).buffer)
                .storage(3, ctx.buffer(d.metadata).buffer)
                .storage(4, ctx.buffer(d.agBuffer).buffer)
                .storage(7, ctx.buffer(d.sampleMaterial).buffer);
            if (int64) pd.storage(6, ctx.buffer(d.agBuffer).buffer); // the same buffer as 64-bit words
            pd.push(m_device, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout);
            // One instance per emulation layer (common/scene_vertex.glsl).
            scene->recordDraws(cmd, layout, pipelines, layers);
        });
    frame.accumulation = {gen.agBuffer, gen.sampleMaterial, gen.depth,
                          emissive ? gen.emissive : rg::Texture{}};
    frame.depth = gen.depth; // the generation pass wrote the stencil: later readers use that version
}

} // namespace agaa
