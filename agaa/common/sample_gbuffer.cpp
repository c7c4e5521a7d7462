#include "agaa/common/sample_gbuffer.h"

#include "engine/frame/sample_pattern.h"
#include "engine/vk/check.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/reflection.h"
#include "shaders/reference/gbuffer_frag.h"
#include "shaders/reference/gbuffer_primitive_frag.h"
#include "shaders/reference/gbuffer_primitive_sample_rate_frag.h"
#include "shaders/reference/gbuffer_sample_rate_frag.h"
#include "shaders/reference/gbuffer_vert.h"
#include "shaders/sbaa/prepass_frag.h"
#include "shaders/sbaa/prepass_sample_rate_frag.h"

#include <bit>
#include <stdexcept>

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

SampleGBufferPass::SampleGBufferPass(vk::Device& device, const eng::frame::GpuScene& scene, uint32_t samples,
                                     std::string name, const eng::scene::SceneFeatures& features,
                                     const GBufferOptions& options)
    : m_device(device), m_samples(samples), m_name(std::move(name)), m_features(features), m_options(options),
      m_pipelines(device, [this](const DrawVariant& v) { return makePipeline(v); }) {
    if (m_options.visibilityOnly) m_options.primitiveIds = true;
    if (!eng::frame::isSupportedSampleCount(samples))
        throw std::invalid_argument("--samples " + std::to_string(samples) + " is not supported (allowed: " +
                                    eng::frame::supportedSampleCounts() + ")");
    if (samples > 1 && !device.caps().supportsSamples(4))
        throw vk::MissingCapability(device.caps().deviceName +
                                    " lacks 4x MSAA colour/depth (needed for --samples " +
                                    std::to_string(samples) + ")");
    if (options.sampleRateShading && !device.caps().sampleRateShading)
        throw vk::MissingCapability(device.caps().deviceName +
                                    " lacks sampleRateShading (--sample-rate-shading on; allowed here: off)");
    if (m_options.primitiveIds && !device.caps().fragmentPrimitiveId)
        throw vk::MissingCapability(device.caps().deviceName +
                                    " lacks geometryShader (gl_PrimitiveID in a fragment shader: the "
                                    "primitive id per sample)");
    if (m_options.primitiveIds && scene.scene().triangleCount() >= (1u << 24) - 1u)
        throw std::invalid_argument(scene.scene().source + ": " +
                                    std::to_string(scene.scene().triangleCount()) +
                                    " triangles; primitive ids per sample are exact below 2^24 - 1");
    vk::LayoutDesc layout;
    layout.pushBindings = vk::reflectBindings({{kReferenceGbufferVert, VK_SHADER_STAGE_VERTEX_BIT},
                                               {fragmentCode(), VK_SHADER_STAGE_FRAGMENT_BIT}});
    layout.extraSets = {scene.textureSetLayout()};
    layout.pushConstantBytes = m_options.primitiveIds ? 8 : 4; // material index (, first triangle)
    m_layout = vk::createPipelineLayout(device, layout, m_name + ".gbuffer.layout");
}

SampleGBufferPass::~SampleGBufferPass() {
    VkDevice d = m_device.device();
    vkDeviceWaitIdle(d);
    m_pipelines.release();
    vk::destroyPipelineLayout(m_device, m_layout);
}

std::span<const uint32_t> SampleGBufferPass::fragmentCode() const {
    const bool sampleRate = m_options.sampleRateShading && m_samples > 1;
    return m_options.visibilityOnly ? (sampleRate ? std::span<const uint32_t>(kSbaaPrepassSampleRateFrag)
                                                  : std::span<const uint32_t>(kSbaaPrepassFrag))
           : m_options.primitiveIds
               ? (sampleRate ? std::span<const uint32_t>(kReferenceGbufferPrimitiveSampleRateFrag)
                             : std::span<const uint32_t>(kReferenceGbufferPrimitiveFrag))
               : (sampleRate ? std::span<const uint32_t>(kReferenceGbufferSampleRateFrag)
                             : kReferenceGbufferFrag);
}

VkPipeline SampleGBufferPass::makePipeline(const DrawVariant& variant) {
    const AlphaPath alpha = variant.alpha;
    const bool doubleSided = variant.doubleSided;
    vk::GraphicsPipelineDesc d;
    d.vertex = kReferenceGbufferVert;
    const bool sampleRate = m_options.sampleRateShading && m_samples > 1;
    d.fragment = fragmentCode();
    d.layout = m_layout.layout;
    d.specialization = effectSpecialization(m_features, 1);
    d.specialization.byId.insert(
        d.specialization.byId.end(),
        {{shared::kSpecFillAlphaPath, uint32_t(alpha)},
         {shared::kSpecFillCurvatureRoughness, m_options.curvatureRoughness ? 1u : 0u},
         {shared::kSpecFillCurvatureMaxFootprint, std::bit_cast<uint32_t>(m_options.curvatureMaxFootprint)},
         {shared::kSpecFillCurvatureBoost, std::bit_cast<uint32_t>(m_options.curvatureBoost)}});
    addMaterialSpecialization(d.specialization, m_features);
    d.sampleShading = sampleRate; // minSampleShading 1: one invocation per sample
    d.alphaToCoverage = usesAlphaToCoverage(alpha);
    if (m_options.visibilityOnly)
        d.colorFormats = {kGeometricNormalFormat, kPrimitiveFormat};
    else
        d.colorFormats = {kNormalFormat, kAlbedoMetalFormat, kEmissiveRoughnessFormat};
    if (m_options.primitiveIds && !m_options.visibilityOnly) d.colorFormats.push_back(kPrimitiveFormat);
    d.depthFormat = kDepthFormat;
    d.samples = m_samples > 1 ? VK_SAMPLE_COUNT_4_BIT : VK_SAMPLE_COUNT_1_BIT;
    d.cullMode = doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
    d.depthCompare = VK_COMPARE_OP_GREATER; // reversed Z: nearer is larger
    const char* path = alphaPathName(alpha);
    std::string name = m_name + ".gbuffer" + path + (doubleSided ? ".twoSided" : "");
    return vk::createGraphicsPipeline(m_device, d, name);
}

bool SampleGBufferPass::isStorage(const std::string& resourceName) const {
    return resourceName.rfind(m_name + ".gbuffer.", 0) == 0;
}

SampleGBuffer SampleGBufferPass::add(rg::Graph& graph, const FrameInputs& in) {
    const eng::frame::SamplePattern pattern = eng::frame::makeSamplePattern(m_samples);
    const VkSampleCountFlagBits hwSamples =
        pattern.samplesPerLayer == 4 ? VK_SAMPLE_COUNT_4_BIT : VK_SAMPLE_COUNT_1_BIT;
    auto desc = [&](VkFormat f, VkFormat sampled = VK_FORMAT_UNDEFINED) {
        return rg::TextureDesc{f, in.width, in.height, pattern.layers, hwSamples, sampled};
    };

    // Variants each draw needs, chosen up front so pipeline creation never happens mid-recording.
    const eng::frame::GpuScene* gpuScene = in.scene;
    const eng::scene::Scene& scene = gpuScene->scene();
    std::vector<VkPipeline> drawPipelines;
    for (const eng::scene::Draw& draw : scene.draws) {
        const eng::scene::Material& m = scene.materials.at(draw.material);
        drawPipelines.push_back(
            m_pipelines.get({materialAlphaPath(m, m_features.forced, m_samples), m.doubleSided}));
    }
    rg::Buffer materials =
        graph.importBuffer(m_name + ".materials", {gpuScene->materials().buffer, gpuScene->materials().size},
                           std::nullopt, std::nullopt);
    struct Data {
        rg::Buffer frame, materials;
        SampleGBuffer g;
    };
    const Data& out = graph.addGraphics<Data>(
        m_name + ".gbuffer",
        [&](rg::Builder& b, Data& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.materials = b.read(materials, rg::Use::StorageReadFragment);
            rg::Attachment clearDepth;
            clearDepth.clear.depthStencil = {0.0f, 0}; // reversed Z: 0 is the far plane (sky)
            d.g.depth = b.depthStencil(b.create(m_name + ".gbuffer.depth", desc(kDepthFormat)),
                                       rg::Use::DepthStencilWrite, clearDepth);
            // Colour locations in declaration order: normal, albedoMetal, emissiveRoughness, primitive;
            // the visibility prepass: geometricNormal, primitive.
            if (m_options.visibilityOnly) {
                d.g.geometricNormal =
                    b.color(b.create(m_name + ".gbuffer.geometricNormal", desc(kGeometricNormalFormat)));
                d.g.primitive = b.color(b.create(m_name + ".gbuffer.primitive", desc(kPrimitiveFormat)));
                return;
            }
            d.g.normal = b.color(b.create(m_name + ".gbuffer.normal", desc(kNormalFormat)));
            d.g.albedoMetal = b.color(b.create(m_name + ".gbuffer.albedoMetal",
                                               desc(kAlbedoMetalFormat, kAlbedoMetalSampledFormat)));
            d.g.emissiveRoughness =
                b.color(b.create(m_name + ".gbuffer.emissiveRoughness", desc(kEmissiveRoughnessFormat)));
            if (m_options.primitiveIds)
                d.g.primitive = b.color(b.create(m_name + ".gbuffer.primitive", desc(kPrimitiveFormat)));
        },
        [this, gpuScene, drawPipelines, layers = pattern.layers](const rg::Context& ctx, const Data& d) {
            VkCommandBuffer cmd = ctx.cmd();
            eng::vk::PushDescriptors()
                .uniform(0, ctx.buffer(d.frame).buffer)
                .storage(1, ctx.buffer(d.materials).buffer)
                .push(m_device, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, m_layout.layout);
            // One instance per emulation layer (common/scene_vertex.glsl).
            gpuScene->recordDraws(cmd, m_layout.layout, drawPipelines, layers, m_options.primitiveIds);
        });
    return out.g;
}

void pushSampleGBuffer(eng::vk::PushDescriptors& pd, const eng::rg::Context& ctx, VkSampler sampler,
                       const SampleGBuffer& g) {
    pd.sampled(2, sampler, ctx.texture(g.depth).sampledView)
        .sampled(3, sampler, ctx.texture(g.normal).sampledView)
        .sampled(4, sampler, ctx.texture(g.albedoMetal).sampledView)
        .sampled(5, sampler, ctx.texture(g.emissiveRoughness).sampledView);
}

void pushLightingTargets(eng::vk::PushDescriptors& pd, const eng::rg::Context& ctx, eng::rg::Texture hdr,
                         eng::rg::Texture display, eng::rg::Texture events) {
    pd.storageImage(6, ctx.texture(hdr).view)
        .storageImage(7, ctx.texture(display).view)
        .storageImage(8, ctx.texture(events).view);
}

SampleGBuffer readSampleGBuffer(eng::rg::Builder& b, const SampleGBuffer& g) {
    SampleGBuffer read;
    read.depth = b.read(g.depth, eng::rg::Use::SampledCompute);
    read.normal = b.read(g.normal, eng::rg::Use::SampledCompute);
    read.albedoMetal = b.read(g.albedoMetal, eng::rg::Use::SampledCompute);
    read.emissiveRoughness = b.read(g.emissiveRoughness, eng::rg::Use::SampledCompute);
    return read;
}

} // namespace agaa
