// agaa.clear and agaa.generation (agaa/aggregate/passes/accumulation_pass.h).

#include "agaa/aggregate/passes/accumulation_pass.h"

#include "engine/vk/descriptors.h"
#include "shared/ag_buffer.h"
#include "shared/sample_material.h"

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

AccumulationPass::AccumulationPass(vk::Device& device, const TechniqueContent& content,
                                   const AggregatePlan& plan)
    : m_device(device), m_plan(plan),
      m_sceneDrawer(makeSceneDrawer(device, content, plan.features, plan.settings.programs)) {
    const AggregateSettings& s = plan.settings;
    m_raster.name = "agaa.generation";
    m_raster.output = RasterOutput::AggregateAccumulation;
    if (plan.emissive()) m_raster.colorFormats = {kEmissiveFormat};
    m_raster.depthFormat = plan.depthFormat;
    m_raster.samples = VK_SAMPLE_COUNT_4_BIT;
    m_raster.layers = plan.layers(); // one instance per emulation layer (common/scene_vertex.glsl)
    // Algorithm 2 step 1: depth EQUAL without writes; stencil keeps the first fragment per sample
    // (GREATER against reference 1 passes while the sample's stencil is 0; INCREMENT_AND_CLAMP on pass).
    m_raster.depthCompare = VK_COMPARE_OP_EQUAL;
    m_raster.depthWrite = false;
    m_raster.stencilTest = true;
    m_raster.stencil = {VK_STENCIL_OP_KEEP,
                        VK_STENCIL_OP_INCREMENT_AND_CLAMP,
                        VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_GREATER,
                        0xFF,
                        0xFF,
                        1};
    const bool int64 = s.atomics == AggregateAtomics::Bits64;
    const VkShaderStageFlags fs = VK_SHADER_STAGE_FRAGMENT_BIT;
    m_raster.moduleSet = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT | fs, 1},
                          {2, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, fs, 1},
                          {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fs, 1},
                          {4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fs, 1},
                          {7, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fs, 1}};
    if (int64) m_raster.moduleSet.push_back({6, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fs, 1});
    m_raster.specialization.byId = {{shared::kSpecGenerationNdf, uint32_t(s.ndf)},
                                    {shared::kSpecGenerationRouting, uint32_t(s.routing)},
                                    {shared::kSpecGenerationSampleMaterial, plan.shadingRate() ? 1u : 0u}};
    for (const auto& constant : curvatureSpecialization(s.effects.curvatureRoughness))
        m_raster.specialization.byId.push_back(constant);
    if (plan.emissive()) m_raster.defines.push_back("AGAA_EMISSIVE");
    if (int64) m_raster.defines.push_back("AGAA_INT64");
    if (s.subgroupReduction == SubgroupReduction::On) m_raster.defines.push_back("AGAA_SUBGROUP");
}

AccumulationPass::~AccumulationPass() = default;

void AccumulationPass::add(rg::Graph& graph, AggregateFrame& frame) {
    struct Clear {
        rg::Buffer agBuffer, sampleMaterial;
    };
    struct Generation {
        rg::Buffer frame, agaa, metadata, agBuffer, sampleMaterial;
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

    const bool emissive = m_plan.emissive();
    const bool int64 = m_plan.settings.atomics == AggregateAtomics::Bits64;
    GeometryDrawer* drawer = &frameDrawer(in, m_sceneDrawer.get(), m_raster.name);
    drawer->prepare(m_raster); // pipelines now, never while a command buffer records
    const Generation& gen = graph.addGraphics<Generation>(
        m_raster.name,
        [&](rg::Builder& b, Generation& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.agaa = b.read(frame.constants, rg::Use::UniformRead);
            d.metadata = b.read(frame.clusters.metadata, rg::Use::StorageReadFragment);
            d.agBuffer = b.readWrite(clear.agBuffer, rg::Use::StorageReadWriteFragment);
            d.sampleMaterial = b.readWrite(clear.sampleMaterial, rg::Use::StorageReadWriteFragment);
            rg::Attachment loadDepth;
            loadDepth.load = VK_ATTACHMENT_LOAD_OP_LOAD;
            d.depth = b.depthStencil(frame.depth, rg::Use::DepthStencilRead,
                                     loadDepth); // EQUAL test, stencil written
            if (emissive) d.emissive = b.color(b.create("agaa.emissive", frame.sampleDesc(kEmissiveFormat)));
        },
        [this, drawer, int64](const rg::Context& ctx, const Generation& d) {
            const VkBuffer frameConstants = ctx.buffer(d.frame).buffer, agaa = ctx.buffer(d.agaa).buffer,
                           metadata = ctx.buffer(d.metadata).buffer, agBuffer = ctx.buffer(d.agBuffer).buffer,
                           sampleMaterial = ctx.buffer(d.sampleMaterial).buffer;
            drawer->recordDraws(ctx.cmd(), m_raster, [=, this](VkCommandBuffer cmd, VkPipelineLayout layout) {
                vk::PushDescriptors pd;
                pd.uniform(0, frameConstants)
                    .uniform(2, agaa)
                    .storage(3, metadata)
                    .storage(4, agBuffer)
                    .storage(7, sampleMaterial);
                if (int64) pd.storage(6, agBuffer); // the same buffer as 64-bit words
                pd.push(m_device, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout);
            });
        });
    frame.accumulation = {gen.agBuffer, gen.sampleMaterial, gen.depth,
                          emissive ? gen.emissive : rg::Texture{}};
    frame.depth = gen.depth; // the generation pass wrote the stencil: later readers use that version
}

} // namespace agaa
