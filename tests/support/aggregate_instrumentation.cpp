#include "tests/support/aggregate_instrumentation.h"

#include "agaa/aggregate/flagged_tiles.h"
#include "agaa/common/effects.h"
#include "engine/frame/gpu_scene.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/reflection.h"
#include "shaders/agaa/lighting_gbuffer_comp.h"
#include "shaders/agaa/scene_vert.h"
#include "shaders/tests/agaa_clustering_inputs_comp.h"
#include "shaders/tests/agaa_generation_record_frag.h"
#include "shaders/tests/agaa_lighting_export_comp.h"
#include "shared/frame.h"

#include <algorithm>
#include <stdexcept>

namespace agaa::test {
namespace rg = eng::rg;
namespace vk = eng::vk;

namespace {

uint32_t groups(uint32_t size, uint32_t group) {
    return (size + group - 1) / group;
}

VkSampler fetchSampler(vk::Device& device, const char* name) {
    return vk::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f, name);
}

vk::PipelineLayout reflectedLayout(vk::Device& device, std::span<const uint32_t> code, const char* name) {
    vk::LayoutDesc desc;
    desc.pushBindings = vk::reflectBindings({{code, VK_SHADER_STAGE_COMPUTE_BIT}});
    return vk::createPipelineLayout(device, desc, name);
}

// A specialisation as (id, value) pairs, the key of a pipeline made with it.
std::vector<std::pair<uint32_t, uint32_t>> flatten(const vk::Specialization& spec) {
    std::vector<std::pair<uint32_t, uint32_t>> out;
    for (uint32_t i = 0; i < spec.values.size(); ++i)
        out.push_back({i, spec.values[i]});
    out.insert(out.end(), spec.byId.begin(), spec.byId.end());
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

ClusteringInputReadback::ClusteringInputReadback(vk::Device& device)
    : m_device(device),
      m_layout(reflectedLayout(device, kTestsAgaaClusteringInputsComp, "test.clusteringInputs.layout")) {
    m_pipeline = vk::createComputePipeline(device, kTestsAgaaClusteringInputsComp, m_layout.layout, {},
                                           "test.clusteringInputs");
    m_sampler = fetchSampler(device, "test.clusteringInputs.sampler");
}

ClusteringInputReadback::~ClusteringInputReadback() {
    vkDeviceWaitIdle(m_device.device());
    vkDestroyPipeline(m_device.device(), m_pipeline, nullptr);
    vkDestroySampler(m_device.device(), m_sampler, nullptr);
    vk::destroyPipelineLayout(m_device, m_layout);
}

void ClusteringInputReadback::add(rg::Graph& graph, const AggregateAA& aggregate, const FrameInputs& in,
                                  const vk::Buffer& host) {
    if (aggregate.settings().generation != AggregateGeneration::Accumulate)
        throw std::logic_error(
            "test: the clustering inputs are the visibility prepass's (accumulate path only)");
    const AggregateResources& r = aggregate.resources();
    rg::Buffer target = graph.importBuffer("test.clusteringInputs.host", {host.buffer, host.size},
                                           std::nullopt, std::nullopt);
    struct Data {
        rg::Buffer frame, agaa, target;
        rg::Texture depth, normal;
    };
    graph.addCompute<Data>(
        "test.clusteringInputs",
        [&](rg::Builder& b, Data& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.agaa = b.read(r.agaaConstants, rg::Use::UniformRead);
            d.depth = b.read(r.depth, rg::Use::SampledCompute);
            d.normal = b.read(r.normal, rg::Use::SampledCompute);
            d.target = b.write(target, rg::Use::StorageWriteCompute);
            b.sideEffect();
        },
        [this, w = in.width, h = in.height](const rg::Context& ctx, const Data& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_pipeline);
            vk::PushDescriptors()
                .uniform(0, ctx.buffer(d.frame).buffer)
                .uniform(1, ctx.buffer(d.agaa).buffer)
                .sampled(2, m_sampler, ctx.texture(d.depth).sampledView)
                .sampled(3, m_sampler, ctx.texture(d.normal).sampledView)
                .storage(4, ctx.buffer(d.target).buffer)
                .push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_layout.layout);
            vkCmdDispatch(cmd, groups(w, 8), groups(h, 8), 1);
        });
}

AggregateExportPass::AggregateExportPass(vk::Device& device)
    : m_device(device),
      m_layout(reflectedLayout(device, kTestsAgaaLightingExportComp, "test.aggregateExport.layout")),
      m_sampler(fetchSampler(device, "test.aggregateExport.sampler")) {}

AggregateExportPass::~AggregateExportPass() {
    vkDeviceWaitIdle(m_device.device());
    for (auto& [key, pipeline] : m_pipelines)
        vkDestroyPipeline(m_device.device(), pipeline, nullptr);
    vkDestroySampler(m_device.device(), m_sampler, nullptr);
    vk::destroyPipelineLayout(m_device, m_layout);
}

void AggregateExportPass::add(rg::Graph& graph, const AggregateAA& aggregate, const FrameInputs& in,
                              const vk::Buffer& host) {
    // The test build is the samples path's plain variant with the export compiled in: the technique
    // must be running that variant for the two to have read and built the same.
    if (aggregate.lightingCode().data() != kAgaaLightingGbufferComp.data())
        throw std::logic_error(
            "test: the aggregate export is the samples path's lighting without emissive or shadows; this "
            "technique runs another variant");
    const AggregateSettings& s = aggregate.settings();
    const VkDeviceSize needed =
        VkDeviceSize(in.width) * in.height * (s.samples + s.aggregates) * kExportRecordFloats * sizeof(float);
    if (host.size < needed)
        throw std::invalid_argument("test: the aggregate export needs " + std::to_string(needed) +
                                    " bytes; the buffer has " + std::to_string(host.size));
    const vk::Specialization spec = aggregate.lightingVariant();
    const auto key = flatten(spec);
    VkPipeline pipeline = VK_NULL_HANDLE;
    for (const auto& [k, p] : m_pipelines)
        if (k == key) pipeline = p;
    if (!pipeline) {
        pipeline = vk::createComputePipeline(m_device, kTestsAgaaLightingExportComp, m_layout.layout, spec,
                                             "test.aggregateExport");
        m_pipelines.push_back({key, pipeline});
    }

    const AggregateResources& r = aggregate.resources();
    rg::Buffer target =
        graph.importBuffer("test.aggregateExport.host", {host.buffer, host.size}, std::nullopt, std::nullopt);
    struct Data {
        rg::Buffer frame, lights, agaa, metadata, target, flaggedTiles;
        rg::Texture depth, count, normal, albedoMetal, emissive, hdr, display, events, perSampleShaded;
    };
    // The shading rate's tile list (agaa/aggregate/flagged_tiles.h): the test build lists its
    // tiles too, so it gets one of its own.
    const rg::Buffer flaggedTiles =
        addFlaggedTileList(graph, in.width, in.height, "test.aggregateExport.flaggedTiles");
    const rg::TextureDesc colour{VK_FORMAT_R32G32B32A32_SFLOAT, in.width, in.height, 1,
                                 VK_SAMPLE_COUNT_1_BIT};
    const rg::TextureDesc counts{VK_FORMAT_R32_UINT, in.width, in.height, 1, VK_SAMPLE_COUNT_1_BIT};
    graph.addCompute<Data>(
        "test.aggregateExport",
        [&](rg::Builder& b, Data& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.lights = b.read(in.lights, rg::Use::StorageReadCompute);
            d.agaa = b.read(r.agaaConstants, rg::Use::UniformRead);
            d.depth = b.read(r.depth, rg::Use::SampledCompute);
            d.metadata = b.read(r.metadata, rg::Use::StorageReadCompute);
            d.count = b.read(r.aggregateCount, rg::Use::StorageImageReadCompute);
            d.normal = b.read(r.gbuffer.normal, rg::Use::SampledCompute);
            d.albedoMetal = b.read(r.gbuffer.albedoMetal, rg::Use::SampledCompute);
            d.emissive = b.read(r.gbuffer.emissiveRoughness, rg::Use::SampledCompute);
            // The test build lights the frame too: scratch images nothing reads.
            d.hdr = b.write(b.create("test.aggregateExport.hdr", colour), rg::Use::StorageImageWriteCompute);
            d.display =
                b.write(b.create("test.aggregateExport.display", colour), rg::Use::StorageImageWriteCompute);
            d.events =
                b.write(b.create("test.aggregateExport.events", counts), rg::Use::StorageImageWriteCompute);
            d.flaggedTiles = b.readWrite(flaggedTiles, rg::Use::StorageReadWriteCompute);
            d.perSampleShaded = b.write(b.create("test.aggregateExport.perSampleShaded", counts),
                                        rg::Use::StorageImageWriteCompute);
            d.target = b.write(target, rg::Use::StorageWriteCompute);
            b.sideEffect();
        },
        [this, pipeline, environment = frameEnvironment(in, aggregate.scene(), "test"), w = in.width,
         h = in.height](const rg::Context& ctx, const Data& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
            vk::PushDescriptors pd;
            pd.uniform(0, ctx.buffer(d.frame).buffer)
                .storage(1, ctx.buffer(d.lights).buffer)
                .uniform(2, ctx.buffer(d.agaa).buffer)
                .sampled(3, m_sampler, ctx.texture(d.depth).sampledView)
                .storage(4, ctx.buffer(d.metadata).buffer)
                .storageImage(5, ctx.texture(d.count).view)
                .sampled(6, m_sampler, ctx.texture(d.normal).sampledView)
                .storageImage(7, ctx.texture(d.hdr).view)
                .storageImage(8, ctx.texture(d.display).view)
                .storageImage(9, ctx.texture(d.events).view)
                .sampled(10, m_sampler, ctx.texture(d.emissive).sampledView)
                .sampled(13, m_sampler, ctx.texture(d.albedoMetal).sampledView)
                .storage(14, ctx.buffer(d.target).buffer)
                .storageImage(18, ctx.texture(d.perSampleShaded).view)
                .storage(19, ctx.buffer(d.flaggedTiles).buffer);
            pushEnvironment(pd, environment);
            pd.push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_layout.layout);
            vkCmdDispatch(cmd, groups(w, shared::kTileSize), groups(h, shared::kTileSize), 1);
        });
}

FragmentRecordPass::FragmentRecordPass(vk::Device& device) : m_device(device) {}

FragmentRecordPass::~FragmentRecordPass() = default;

void FragmentRecordPass::add(rg::Graph& graph, const AggregateAA& aggregate, const FrameInputs& in,
                             const vk::Buffer& host) {
    if (aggregate.settings().generation != AggregateGeneration::Accumulate)
        throw std::logic_error("test: fragment records are the accumulate path's generation pass's");
    if (aggregate.settings().routing != AggregateRouting::Samples)
        throw std::logic_error(
            "test: fragment records are replayed per sample (--agaa-routing samples only)");
    if (aggregate.features().hasEmissive())
        throw std::logic_error("test: the generation pass's test build has no emissive output (a scene "
                               "without emissive materials only)");
    // The shipping pass's state drawn by this project's scene drawer with the test build in place
    // of the generation program (its one build: 32-bit atomics, no subgroups, binding 5 the
    // records instead of 7), and a stencil that lets through the one fragment per sample the
    // shipping pass counted (its stencil is 1 there, 0 on sky): EQUAL 1, then incremented so no
    // later fragment of that sample passes.
    RasterPass raster = aggregate.generationRasterPass();
    raster.name = "test.fragmentRecords";
    raster.defines.clear();
    const VkShaderStageFlags fs = VK_SHADER_STAGE_FRAGMENT_BIT;
    raster.moduleSet = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT | fs, 1},
                        {2, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, fs, 1},
                        {5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fs, 1}};
    raster.stencil.compareOp = VK_COMPARE_OP_EQUAL;
    m_drawers.push_back(std::make_unique<SceneDrawer>(
        m_device, *aggregate.scene(), aggregate.features(),
        ProgramOverrides{{"agaa/generation.frag", kTestsAgaaGenerationRecordFrag}}));
    SceneDrawer* drawer = m_drawers.back().get();
    drawer->prepare(raster);

    const AggregateResources& r = aggregate.resources();
    rg::Buffer imported =
        graph.importBuffer("test.fragmentRecords.host", {host.buffer, host.size}, std::nullopt, std::nullopt);
    struct Clear {
        rg::Buffer records;
    };
    const rg::Buffer records =
        graph
            .addPass<Clear>(
                "test.fragmentRecords.clear", rg::PassKind::Transfer,
                [&](rg::Builder& b, Clear& d) { d.records = b.write(imported, rg::Use::TransferDst); },
                [](const rg::Context& ctx, const Clear& d) {
                    vkCmdFillBuffer(ctx.cmd(), ctx.buffer(d.records).buffer, 0, 4, 0); // the count only
                })
            .records;
    struct Record {
        rg::Buffer frame, agaa, records;
        rg::Texture depth;
    };
    graph.addGraphics<Record>(
        "test.fragmentRecords",
        [&](rg::Builder& b, Record& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.agaa = b.read(r.agaaConstants, rg::Use::UniformRead);
            d.records = b.readWrite(records, rg::Use::StorageReadWriteFragment);
            rg::Attachment loadDepth;
            loadDepth.load = VK_ATTACHMENT_LOAD_OP_LOAD;
            d.depth = b.depthStencil(r.depth, rg::Use::DepthStencilRead, loadDepth); // EQUAL, stencil written
            b.sideEffect();
        },
        [this, drawer, raster](const rg::Context& ctx, const Record& d) {
            const VkBuffer frame = ctx.buffer(d.frame).buffer, agaa = ctx.buffer(d.agaa).buffer,
                           records = ctx.buffer(d.records).buffer;
            drawer->recordDraws(ctx.cmd(), raster, [=, this](VkCommandBuffer cmd, VkPipelineLayout layout) {
                vk::PushDescriptors()
                    .uniform(0, frame)
                    .uniform(2, agaa)
                    .storage(5, records)
                    .push(m_device, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout);
            });
        });
}

vk::Buffer createFragmentRecords(vk::Device& device, uint32_t capacity, uint32_t recordWords) {
    vk::Buffer records =
        vk::createBuffer(device, 8 + VkDeviceSize(capacity) * recordWords * 4,
                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                         vk::MemoryUse::Readback, "test.records");
    static_cast<uint32_t*>(records.mapped)[1] = capacity;
    return records;
}

} // namespace agaa::test
