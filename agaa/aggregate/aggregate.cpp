// The AGAA passes as render-graph nodes (pipelines: aggregate_pipelines.cpp).

#include "agaa/aggregate/aggregate.h"
#include "agaa/aggregate/flagged_tiles.h"
#include "agaa/common/frame_inputs.h"

#include "engine/vk/descriptors.h"
#include "shared/ag_buffer.h"
#include "shared/clustering.h"
#include "shared/sample_material.h"

#include <algorithm>
#include <stdexcept>

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

namespace {

rg::Buffer importScene(rg::Graph& graph, const char* name, const vk::Buffer& b) {
    return graph.importBuffer(name, {b.buffer, b.size}, std::nullopt, std::nullopt);
}

uint32_t groups(uint32_t size, uint32_t group) {
    return (size + group - 1) / group;
}

} // namespace

FrameTargets AggregateAA::addPasses(rg::Graph& graph, const FrameInputs& in) {
    checkFrameInputs(in);
    m_constants = makeAgaaConstants(m_settings, *in.constants, m_hasEmissive);
    // Per frame slot, so views and frames recorded before any executes keep their own (issue 18).
    const rg::Buffer agaaConstants =
        m_constantsRing.write(graph, in.frameSlot, std::as_bytes(std::span(&m_constants, 1)));
    const uint32_t layers = m_settings.samples / 4;
    const uint32_t c = m_settings.aggregates;
    const uint32_t pixels = in.width * in.height;
    const eng::frame::GpuScene* scene = in.scene;

    const bool samplesPath = m_settings.generation == AggregateGeneration::Samples;
    std::vector<VkPipeline> visibilityPipelines, generationPipelines;
    for (const eng::scene::Draw& draw :
         samplesPath ? std::vector<eng::scene::Draw>{} : scene->scene().draws) {
        const eng::scene::Material& m = scene->scene().materials.at(draw.material);
        visibilityPipelines.push_back(m_visibilityPipelines.get(
            {materialAlphaPath(m, m_features.forced, m_settings.samples), m.doubleSided}));
        generationPipelines.push_back(m_generationPipelines.get({AlphaPath::Opaque, m.doubleSided}));
    }

    rg::Buffer materials = importScene(graph, "scene.materials", scene->materials());
    m_resources.agaaConstants = agaaConstants;

    // One instance per emulation layer (common/scene_vertex.glsl).
    auto drawScene = [scene, layers](VkCommandBuffer cmd, VkPipelineLayout layout,
                                     const std::vector<VkPipeline>& pipes) {
        scene->recordDraws(cmd, layout, pipes, layers);
    };

    // ---- 1. visibility prepass, or the samples path's per-sample G-buffer ------------------
    struct Visibility {
        rg::Buffer frame, agaa, materials;
        rg::Texture depth, normal;
    };
    SampleGBuffer gbuffer;
    if (samplesPath) gbuffer = m_gbuffer->add(graph, in);
    const rg::TextureDesc sampleDesc{VK_FORMAT_UNDEFINED, in.width, in.height, layers, VK_SAMPLE_COUNT_4_BIT};
    auto desc = [&](VkFormat f) {
        rg::TextureDesc d = sampleDesc;
        d.format = f;
        return d;
    };
    const Visibility* visPass = nullptr;
    if (!samplesPath)
        visPass = &graph.addGraphics<Visibility>(
            "agaa.visibility",
            [&](rg::Builder& b, Visibility& d) {
                d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
                d.agaa = b.read(agaaConstants, rg::Use::UniformRead);
                d.materials = b.read(materials, rg::Use::StorageReadFragment);
                // Reversed Z: 0 = far (sky); stencil 0 for generation's first-fragment test.
                rg::Attachment clearDepth;
                clearDepth.clear.depthStencil = {0.0f, 0};
                d.depth = b.depthStencil(b.create("agaa.visibility.depth", desc(m_depthFormat)),
                                         rg::Use::DepthStencilWrite, clearDepth);
                d.normal = b.color(b.create("agaa.visibility.normal", desc(VK_FORMAT_R8G8_UNORM)));
            },
            [=, this](const rg::Context& ctx, const Visibility& d) {
                VkCommandBuffer cmd = ctx.cmd();
                vk::PushDescriptors()
                    .uniform(0, ctx.buffer(d.frame).buffer)
                    .storage(1, ctx.buffer(d.materials).buffer)
                    .uniform(2, ctx.buffer(d.agaa).buffer)
                    .push(m_device, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, m_visibilityLayout.layout);
                drawScene(cmd, m_visibilityLayout.layout, visibilityPipelines);
            });
    // What the clustering reads: the prepass's depth and face normals, or the G-buffer's.
    const rg::Texture sampleDepth = samplesPath ? gbuffer.depth : visPass->depth;
    const rg::Texture sampleNormal = samplesPath ? gbuffer.normal : visPass->normal;

    // ---- 2. clustering ----------------------------------------------------------------------
    struct Cluster {
        rg::Buffer frame, agaa, metadata;
        rg::Texture depth, normal, albedoMetal, count;
    };
    const uint32_t words = shared::metadataWords(m_settings.samples, c);
    const Cluster& cl = graph.addCompute<Cluster>(
        "agaa.cluster",
        [&](rg::Builder& b, Cluster& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.agaa = b.read(agaaConstants, rg::Use::UniformRead);
            d.depth = b.read(sampleDepth, rg::Use::SampledCompute);
            d.normal = b.read(sampleNormal, rg::Use::SampledCompute);
            if (samplesPath) d.albedoMetal = b.read(gbuffer.albedoMetal, rg::Use::SampledCompute);
            // c = 1 needs no metadata bits; keep a minimal buffer so the binding stays valid.
            d.metadata = b.write(
                b.create("agaa.metadata", {std::max<VkDeviceSize>(4, VkDeviceSize(pixels) * words * 4)}),
                rg::Use::StorageWriteCompute);
            d.count = b.write(b.create("agaa.aggregateCount",
                                       {VK_FORMAT_R8_UINT, in.width, in.height, 1, VK_SAMPLE_COUNT_1_BIT}),
                              rg::Use::StorageImageWriteCompute);
        },
        [=, this](const rg::Context& ctx, const Cluster& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_clusterPipeline);
            vk::PushDescriptors pd;
            pd.uniform(0, ctx.buffer(d.frame).buffer)
                .uniform(1, ctx.buffer(d.agaa).buffer)
                .sampled(2, m_fetchSampler, ctx.texture(d.depth).sampledView)
                .sampled(3, m_fetchSampler, ctx.texture(d.normal).sampledView)
                .storage(4, ctx.buffer(d.metadata).buffer)
                .storageImage(5, ctx.texture(d.count).view);
            if (samplesPath) pd.sampled(6, m_fetchSampler, ctx.texture(d.albedoMetal).sampledView);
            pd.push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_clusterLayout.layout);
            vkCmdDispatch(cmd, groups(in.width, 8), groups(in.height, 8), 1);
        });
    m_resources.depth = sampleDepth;
    m_resources.normal = sampleNormal;
    m_resources.gbuffer = gbuffer;
    m_resources.metadata = cl.metadata;
    m_resources.aggregateCount = cl.count;

    const rg::TextureDesc outDesc{VK_FORMAT_R32G32B32A32_SFLOAT, in.width, in.height, 1,
                                  VK_SAMPLE_COUNT_1_BIT};
    const rg::TextureDesc eventsDesc{VK_FORMAT_R32_UINT, in.width, in.height, 1, VK_SAMPLE_COUNT_1_BIT};

    // ---- shadow maps: added whenever the scene has a shadowed light; lighting reads them (the
    // aggregates debug view does not, and the graph culls the pass) ---------------------------
    const bool shadows = m_shadow->enabled();
    ShadowMaps shadowMaps;
    if (shadows) shadowMaps = m_shadow->add(graph, in);

    if (m_settings.debugView == AggregateDebugView::Aggregates) {
        struct Debug {
            rg::Buffer frame, agaa, metadata;
            rg::Texture count, depth, hdr, display, events;
        };
        const Debug& dbg = graph.addCompute<Debug>(
            "agaa.debug.aggregates",
            [&](rg::Builder& b, Debug& d) {
                d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
                d.agaa = b.read(agaaConstants, rg::Use::UniformRead);
                d.metadata = b.read(cl.metadata, rg::Use::StorageReadCompute);
                d.count = b.read(cl.count, rg::Use::StorageImageReadCompute);
                d.depth = b.read(sampleDepth, rg::Use::SampledCompute);
                d.hdr = b.write(b.create("agaa.debug.hdr", outDesc), rg::Use::StorageImageWriteCompute);
                d.display =
                    b.write(b.create("agaa.debug.display", outDesc), rg::Use::StorageImageWriteCompute);
                d.events =
                    b.write(b.create("agaa.debug.events", eventsDesc), rg::Use::StorageImageWriteCompute);
            },
            [=, this](const rg::Context& ctx, const Debug& d) {
                VkCommandBuffer cmd = ctx.cmd();
                vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_debugPipeline);
                vk::PushDescriptors()
                    .uniform(0, ctx.buffer(d.frame).buffer)
                    .uniform(1, ctx.buffer(d.agaa).buffer)
                    .storage(2, ctx.buffer(d.metadata).buffer)
                    .storageImage(3, ctx.texture(d.count).view)
                    .sampled(4, m_fetchSampler, ctx.texture(d.depth).sampledView)
                    .storageImage(5, ctx.texture(d.hdr).view)
                    .storageImage(6, ctx.texture(d.display).view)
                    .storageImage(7, ctx.texture(d.events).view)
                    .push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_debugLayout.layout);
                vkCmdDispatch(cmd, groups(in.width, 8), groups(in.height, 8), 1);
            });
        return {dbg.hdr, dbg.display, dbg.events, {}, sampleDepth};
    }

    // ---- 3. AG-buffer generation (accumulation kernel; the samples path has none) -----------
    const bool emissive = m_hasEmissive;
    const bool shadingRate = m_settings.tolerance >= 0.0f;
    rg::Buffer agBuffer, sampleMaterial;
    rg::Texture lightingDepth = sampleDepth, emissiveSamples;
    if (!samplesPath) {
        struct Clear {
            rg::Buffer agBuffer, sampleMaterial;
        };
        const VkDeviceSize agBytes = VkDeviceSize(shared::agBufferWords(pixels, c)) * 4;
        // With a tolerance, each covered sample's material (shared/sample_material.h), cleared so
        // that no word is ever undefined; a 16-byte stand-in without one (binding 7 is in the
        // layout whatever the specialisation).
        const VkDeviceSize materialBytes =
            shadingRate ? VkDeviceSize(shared::sampleMaterialWords(pixels, m_settings.samples)) * 4 : 16;
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
        struct Generation {
            rg::Buffer frame, agaa, materials, metadata, agBuffer, sampleMaterial;
            rg::Texture depth, emissive;
        };
        const bool int64 = m_settings.atomics == AggregateAtomics::Bits64;
        const VkPipelineLayout generationLayout = m_generationLayout.layout;
        const Generation& gen = graph.addGraphics<Generation>(
            "agaa.generation",
            [&](rg::Builder& b, Generation& d) {
                d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
                d.agaa = b.read(agaaConstants, rg::Use::UniformRead);
                d.materials = b.read(materials, rg::Use::StorageReadFragment);
                d.metadata = b.read(cl.metadata, rg::Use::StorageReadFragment);
                d.agBuffer = b.readWrite(clear.agBuffer, rg::Use::StorageReadWriteFragment);
                d.sampleMaterial = b.readWrite(clear.sampleMaterial, rg::Use::StorageReadWriteFragment);
                rg::Attachment loadDepth;
                loadDepth.load = VK_ATTACHMENT_LOAD_OP_LOAD;
                d.depth = b.depthStencil(visPass->depth, rg::Use::DepthStencilRead,
                                         loadDepth); // EQUAL test, stencil written
                if (emissive)
                    d.emissive = b.color(b.create("agaa.emissive", desc(VK_FORMAT_B10G11R11_UFLOAT_PACK32)));
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
                pd.push(m_device, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, generationLayout);
                drawScene(cmd, generationLayout, generationPipelines);
            });
        agBuffer = gen.agBuffer;
        sampleMaterial = gen.sampleMaterial;
        lightingDepth = gen.depth; // the generation pass wrote the stencil: later readers use that version
        if (emissive) emissiveSamples = gen.emissive;
    }
    m_resources.agBuffer = agBuffer;
    m_resources.sampleMaterial = shadingRate ? sampleMaterial : rg::Buffer{};
    m_resources.depth = lightingDepth;

    // ---- 4. tiled lighting, aggregating at the top of each tile ------------------------------
    struct Lighting {
        rg::Buffer frame, lights, agaa, metadata, agBuffer, sampleMaterial, flaggedTiles;
        ShadowMaps shadow;
        rg::Texture depth, count, emissive, hdr, display, events, perSampleShaded;
        rg::Texture normal, albedoMetal; // samples path: the G-buffer (emissive: its emissive + roughness)
    };
    const uint32_t tilesX = groups(in.width, shared::kTileSize),
                   tilesY = groups(in.height, shared::kTileSize);
    const rg::Buffer flaggedTiles =
        shadingRate ? addFlaggedTileList(graph, in.width, in.height, "agaa.flaggedTiles") : rg::Buffer{};
    const Lighting& lit = graph.addCompute<Lighting>(
        "agaa.lighting",
        [&](rg::Builder& b, Lighting& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.lights = b.read(in.lights, rg::Use::StorageReadCompute);
            d.agaa = b.read(agaaConstants, rg::Use::UniformRead);
            d.depth = b.read(lightingDepth, rg::Use::SampledCompute);
            d.metadata = b.read(cl.metadata, rg::Use::StorageReadCompute);
            d.count = b.read(cl.count, rg::Use::StorageImageReadCompute);
            if (samplesPath) {
                d.normal = b.read(gbuffer.normal, rg::Use::SampledCompute);
                d.albedoMetal = b.read(gbuffer.albedoMetal, rg::Use::SampledCompute);
                d.emissive = b.read(gbuffer.emissiveRoughness, rg::Use::SampledCompute);
            } else {
                d.agBuffer = b.read(agBuffer, rg::Use::StorageReadCompute);
                d.sampleMaterial = b.read(sampleMaterial, rg::Use::StorageReadCompute);
                if (emissive) d.emissive = b.read(emissiveSamples, rg::Use::SampledCompute);
            }
            if (shadows) d.shadow = ShadowMapPass::read(b, shadowMaps);
            d.hdr = b.write(b.create("agaa.hdr", outDesc), rg::Use::StorageImageWriteCompute);
            d.display = b.write(b.create("agaa.display", outDesc), rg::Use::StorageImageWriteCompute);
            d.events = b.write(b.create("agaa.shadingEvents", eventsDesc), rg::Use::StorageImageWriteCompute);
            // Without a tolerance the shader never writes it, but binding 18 is in the layout (the
            // validation layer counts it as used whatever the specialisation): one texel then.
            const rg::TextureDesc flagsDesc =
                shadingRate ? eventsDesc
                            : rg::TextureDesc{VK_FORMAT_R32_UINT, 1, 1, 1, VK_SAMPLE_COUNT_1_BIT};
            d.perSampleShaded =
                b.write(b.create("agaa.perSampleShaded", flagsDesc), rg::Use::StorageImageWriteCompute);
            // Binding 19 likewise: a 16-byte stand-in without a tolerance.
            d.flaggedTiles = shadingRate
                                 ? b.readWrite(flaggedTiles, rg::Use::StorageReadWriteCompute)
                                 : b.write(b.create("agaa.flaggedTiles", {16}), rg::Use::StorageWriteCompute);
        },
        [=, this](const rg::Context& ctx, const Lighting& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_lightingPipeline);
            vk::PushDescriptors pd;
            pd.uniform(0, ctx.buffer(d.frame).buffer)
                .storage(1, ctx.buffer(d.lights).buffer)
                .uniform(2, ctx.buffer(d.agaa).buffer)
                .sampled(3, m_fetchSampler, ctx.texture(d.depth).sampledView)
                .storage(4, ctx.buffer(d.metadata).buffer)
                .storageImage(5, ctx.texture(d.count).view)
                .storageImage(7, ctx.texture(d.hdr).view)
                .storageImage(8, ctx.texture(d.display).view)
                .storageImage(9, ctx.texture(d.events).view);
            pd.storageImage(18, ctx.texture(d.perSampleShaded).view)
                .storage(19, ctx.buffer(d.flaggedTiles).buffer);
            if (samplesPath) {
                pd.sampled(6, m_fetchSampler, ctx.texture(d.normal).sampledView)
                    .sampled(10, m_fetchSampler, ctx.texture(d.emissive).sampledView)
                    .sampled(13, m_fetchSampler, ctx.texture(d.albedoMetal).sampledView);
            } else {
                pd.storage(6, ctx.buffer(d.agBuffer).buffer).storage(20, ctx.buffer(d.sampleMaterial).buffer);
                if (emissive) pd.sampled(10, m_fetchSampler, ctx.texture(d.emissive).sampledView);
            }
            if (shadows) m_shadow->push(pd, ctx, d.shadow, 11, 12);
            pushEnvironment(pd, *in.scene);
            pd.push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_lightingLayout.layout);
            vkCmdDispatch(cmd, tilesX, tilesY, 1);
        });
    if (!shadingRate) return {lit.hdr, lit.display, lit.events, {}, lightingDepth, {}};

    // ---- the shading rate's flagged pixels, each sample lit and resolved on its own ----------
    struct PerSample {
        rg::Buffer frame, lights, tiles, sampleMaterial;
        SampleGBuffer g;             // samples path
        rg::Texture depth, emissive; // accumulate path
        ShadowMaps shadow;
        rg::Texture flags, hdr, display, events;
    };
    const PerSample& flagged = graph.addCompute<PerSample>(
        "agaa.lighting.perSample",
        [&](rg::Builder& b, PerSample& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.lights = b.read(in.lights, rg::Use::StorageReadCompute);
            if (samplesPath) {
                d.g = readSampleGBuffer(b, gbuffer);
            } else {
                d.depth = b.read(lightingDepth, rg::Use::SampledCompute);
                d.sampleMaterial = b.read(sampleMaterial, rg::Use::StorageReadCompute);
                if (emissive) d.emissive = b.read(emissiveSamples, rg::Use::SampledCompute);
            }
            if (shadows) d.shadow = ShadowMapPass::read(b, shadowMaps);
            d.flags = b.read(lit.perSampleShaded, rg::Use::StorageImageReadCompute);
            d.tiles = b.read(lit.flaggedTiles, rg::Use::IndirectRead);
            b.read(lit.flaggedTiles, rg::Use::StorageReadCompute);
            // The lighting pass's images: this pass writes the flagged pixels and keeps the rest.
            d.hdr = b.readWrite(lit.hdr, rg::Use::StorageImageReadWriteCompute);
            d.display = b.readWrite(lit.display, rg::Use::StorageImageReadWriteCompute);
            d.events = b.readWrite(lit.events, rg::Use::StorageImageReadWriteCompute);
        },
        [=, this](const rg::Context& ctx, const PerSample& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_perSamplePipeline);
            vk::PushDescriptors pd;
            pd.uniform(0, ctx.buffer(d.frame).buffer).storage(1, ctx.buffer(d.lights).buffer);
            if (samplesPath) {
                pushSampleGBuffer(pd, ctx, m_fetchSampler, d.g);
            } else {
                pd.sampled(2, m_fetchSampler, ctx.texture(d.depth).sampledView)
                    .storage(3, ctx.buffer(d.sampleMaterial).buffer);
                if (emissive) pd.sampled(4, m_fetchSampler, ctx.texture(d.emissive).sampledView);
            }
            pushLightingTargets(pd, ctx, d.hdr, d.display, d.events);
            pd.storageImage(11, ctx.texture(d.flags).view).storage(12, ctx.buffer(d.tiles).buffer);
            if (shadows) m_shadow->push(pd, ctx, d.shadow, 9, 10);
            pushEnvironment(pd, *in.scene);
            pd.push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_perSampleLayout.layout);
            vkCmdDispatchIndirect(cmd, ctx.buffer(d.tiles).buffer, 0); // the listed tiles only
        });
    return {flagged.hdr, flagged.display, flagged.events, {}, lightingDepth, lit.perSampleShaded};
}

} // namespace agaa
