#include "agaa/common/sample_gbuffer.h"

#include "engine/frame/sample_pattern.h"
#include "engine/vk/check.h"
#include "engine/vk/descriptors.h"

#include <bit>
#include <stdexcept>

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

SampleGBufferPass::SampleGBufferPass(vk::Device& device, const TechniqueContent& content, uint32_t samples,
                                     std::string name, const eng::scene::SceneFeatures& features,
                                     const GBufferOptions& options)
    : m_device(device), m_samples(samples), m_name(std::move(name)), m_options(options) {
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
    if (m_options.primitiveIds && content.traits.triangles >= (1u << 24) - 1u)
        throw std::invalid_argument(content.traits.source + ": " + std::to_string(content.traits.triangles) +
                                    " triangles; primitive ids per sample are exact below 2^24 - 1");

    const eng::frame::SamplePattern pattern = eng::frame::makeSamplePattern(m_samples);
    m_raster.name = m_name + ".gbuffer";
    m_raster.output = m_options.visibilityOnly ? RasterOutput::SurfaceVisibility
                      : m_options.primitiveIds ? RasterOutput::SampleGBufferPrimitive
                                               : RasterOutput::SampleGBuffer;
    // Colour locations: normal, albedoMetal, emissiveRoughness, primitive; the visibility
    // prepass: geometricNormal, primitive.
    if (m_options.visibilityOnly)
        m_raster.colorFormats = {kGeometricNormalFormat, kPrimitiveFormat};
    else
        m_raster.colorFormats = {kNormalFormat, kAlbedoMetalFormat, kEmissiveRoughnessFormat};
    if (m_raster.output == RasterOutput::SampleGBufferPrimitive)
        m_raster.colorFormats.push_back(kPrimitiveFormat);
    m_raster.depthFormat = kDepthFormat;
    m_raster.depthCompare = VK_COMPARE_OP_GREATER; // reversed Z: nearer is larger
    m_raster.samples = pattern.samplesPerLayer == 4 ? VK_SAMPLE_COUNT_4_BIT : VK_SAMPLE_COUNT_1_BIT;
    m_raster.layers = pattern.layers; // one instance per emulation layer (common/scene_vertex.glsl)
    m_raster.sampleRateShading = m_options.sampleRateShading && m_samples > 1; // one invocation per sample
    m_raster.moduleSet = {
        {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 1}};
    m_raster.specialization.byId = curvatureSpecialization(m_options.curvature);
    m_sceneDrawer = makeSceneDrawer(device, content, features);
}

SampleGBufferPass::~SampleGBufferPass() = default;

bool SampleGBufferPass::isStorage(const std::string& resourceName) const {
    return resourceName.rfind(m_name + ".gbuffer.", 0) == 0;
}

SampleGBuffer SampleGBufferPass::add(rg::Graph& graph, const FrameInputs& in) {
    auto desc = [&](VkFormat f, VkFormat sampled = VK_FORMAT_UNDEFINED) {
        return rg::TextureDesc{f, in.width, in.height, m_raster.layers, m_raster.samples, sampled};
    };
    GeometryDrawer* drawer = &frameDrawer(in, m_sceneDrawer.get(), m_raster.name);
    drawer->prepare(m_raster); // pipelines now, never while a command buffer records
    struct Data {
        rg::Buffer frame;
        SampleGBuffer g;
    };
    const Data& out = graph.addGraphics<Data>(
        m_raster.name,
        [&](rg::Builder& b, Data& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            rg::Attachment clearDepth;
            clearDepth.clear.depthStencil = {0.0f, 0}; // reversed Z: 0 is the far plane (sky)
            d.g.depth = b.depthStencil(b.create(m_name + ".gbuffer.depth", desc(kDepthFormat)),
                                       rg::Use::DepthStencilWrite, clearDepth);
            // Colour locations in RasterPass::colorFormats' order.
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
        [this, drawer](const rg::Context& ctx, const Data& d) {
            const VkBuffer frame = ctx.buffer(d.frame).buffer;
            drawer->recordDraws(ctx.cmd(), m_raster,
                                [this, frame](VkCommandBuffer cmd, VkPipelineLayout layout) {
                                    vk::PushDescriptors().uniform(0, frame).push(
                                        m_device, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout);
                                });
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
