#include "agaa/temporal/temporal_aa.h"

#include "agaa/temporal/reprojection.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/reflection.h"
#include "shaders/temporal/resolve_comp.h"
#include "shaders/temporal/resolve_ms_comp.h"
#include "shared/temporal.h"

#include <cmath>
#include <stdexcept>

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

namespace {

constexpr VkFormat kHistoryFormat = VK_FORMAT_R32G32B32A32_SFLOAT; // the frame's HDR format

TemporalSettings checked(const TemporalSettings& s) {
    if (!(s.minimumWeight > 0.0f && s.minimumWeight <= 1.0f))
        throw std::invalid_argument("taa: the minimum weight " + std::to_string(s.minimumWeight) +
                                    " is out of range (0, 1]");
    if (!(s.clipGamma > 0.0f) || !std::isfinite(s.clipGamma))
        throw std::invalid_argument("taa: the clip gamma must be a finite number > 0");
    if (s.jitterPhases < 1 || s.jitterPhases > 256)
        throw std::invalid_argument("taa: jitter phases " + std::to_string(s.jitterPhases) +
                                    " is out of range (1..256)");
    return s;
}

} // namespace

TemporalAA::TemporalAA(vk::Device& device, std::unique_ptr<Technique> inner, const TemporalSettings& settings,
                       std::string name)
    : m_device(device), m_settings(checked(settings)), m_name(std::move(name)), m_inner(std::move(inner)) {
    if (!m_inner) throw std::invalid_argument(m_name + ": no inner method");
    // One sample per pixel, or the 4x layered per-sample depth (eng::frame::makeSamplePattern).
    const std::span<const uint32_t> program = m_inner->samples() > 1
                                                  ? std::span<const uint32_t>(kTemporalResolveMsComp)
                                                  : std::span<const uint32_t>(kTemporalResolveComp);
    vk::LayoutDesc layout;
    layout.pushBindings = vk::reflectBindings({{program, VK_SHADER_STAGE_COMPUTE_BIT}});
    layout.pushConstantBytes = sizeof(shared::TemporalParams);
    m_layout = vk::createPipelineLayout(device, layout, m_name + ".layout");
    m_pipeline = vk::createComputePipeline(device, program, m_layout.layout, {}, m_name + ".resolve");
    m_fetchSampler = vk::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f,
                                       m_name + ".fetchSampler");
}

TemporalAA::~TemporalAA() {
    VkDevice d = m_device.device();
    vkDeviceWaitIdle(d);
    releaseHistory();
    vkDestroyPipeline(d, m_pipeline, nullptr);
    vkDestroySampler(d, m_fetchSampler, nullptr);
    vk::destroyPipelineLayout(m_device, m_layout);
}

void TemporalAA::releaseHistory() {
    for (vk::Image& image : m_history)
        if (image.image) vk::destroyImage(m_device, image);
    m_history = {};
}

void TemporalAA::allocateHistory(uint32_t width, uint32_t height) {
    vkDeviceWaitIdle(m_device.device()); // a frame in flight may still read the old history
    releaseHistory();
    for (uint32_t i = 0; i < m_history.size(); ++i) {
        vk::ImageDesc desc;
        desc.format = kHistoryFormat;
        desc.width = width;
        desc.height = height;
        desc.usage =
            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        desc.viewType = VK_IMAGE_VIEW_TYPE_2D;
        m_history[i] = vk::createImage(
            m_device, desc, m_name + (i < 2 ? ".history.hdr." : ".history.display.") + std::to_string(i % 2));
    }
    resetHistory();
}

glm::vec2 TemporalAA::subpixelJitter() const {
    return m_settings.motionView ? glm::vec2(0.0f) : haltonJitter(m_frame, m_settings.jitterPhases);
}

void TemporalAA::resetHistory() {
    m_framesInHistory = 0;
    m_previous.reset();
    m_frame = 0;
}

bool TemporalAA::isStorage(const std::string& resourceName) const {
    return m_inner->isStorage(resourceName) || resourceName.rfind(m_name + ".history", 0) == 0;
}

std::string TemporalAA::storageCategory(const std::string& resourceName) const {
    return resourceName.rfind(m_name + ".history", 0) == 0 ? "per-sample" // a pixel's one history value
                                                           : m_inner->storageCategory(resourceName);
}

std::vector<VariantChoice> TemporalAA::variants() const {
    std::vector<VariantChoice> v = m_inner->variants();
    v.push_back({"taa-jitter", "Halton (2, 3), " + std::to_string(m_settings.jitterPhases) + " phases",
                 "temporal AA's default (Karis 2014)"});
    v.push_back({"taa-history",
                 "reprojected by depth and the camera's motion, clipped to the 3x3 neighbourhood in YCoCg; "
                 "current weight 1/frames down to " +
                     std::to_string(m_settings.minimumWeight).substr(0, 4),
                 "the scenes are static: the camera's motion is all the motion"});
    return v;
}

FrameTargets TemporalAA::addPasses(rg::Graph& graph, const FrameInputs& in) {
    if (!in.constants)
        throw std::invalid_argument(
            m_name + ": FrameInputs::constants is missing (the reprojection needs the camera)");
    if (!m_history[0].image || m_history[0].desc.width != in.width || m_history[0].desc.height != in.height)
        allocateHistory(in.width, in.height);
    const FrameTargets inner = m_inner->addPasses(graph, in);

    shared::TemporalParams params{};
    const bool haveHistory = m_framesInHistory > 0 && m_previous.has_value();
    params.reprojection = haveHistory ? reprojectionMatrix(*m_previous, *in.constants) : glm::mat4(1.0f);
    params.blend = {std::max(1.0f / float(m_framesInHistory + 1), m_settings.minimumWeight),
                    haveHistory ? 1.0f : 0.0f, m_settings.clipGamma, m_settings.motionView ? 1.0f : 0.0f};

    const auto physical = [](const vk::Image& image) {
        return rg::PhysicalTexture{image.image, image.view, image.sampledView,
                                   rg::TextureDesc{image.desc.format, image.desc.width, image.desc.height, 1,
                                                   VK_SAMPLE_COUNT_1_BIT}};
    };
    // Each history read is last frame's write, left sampled; the one written starts undefined.
    // Images: [0, 1] the HDR pair, [2, 3] the display pair; m_write picks the one written.
    const auto read = [&](uint32_t image, const char* what, rg::Texture standIn) {
        return haveHistory
                   ? graph.importTexture(m_name + ".history." + what + ".read", physical(m_history[image]),
                                         rg::Use::SampledCompute, rg::Use::SampledCompute)
                   : standIn; // bound but not read (blend.y = 0)
    };
    const auto written = [&](uint32_t image, const char* what) {
        return graph.importTexture(m_name + ".history." + what + ".write", physical(m_history[image]),
                                   std::nullopt, rg::Use::SampledCompute);
    };
    const rg::Texture hdrRead = read(1 - m_write, "hdr", inner.hdr);
    const rg::Texture displayRead = read(3 - m_write, "display", inner.display);
    const rg::Texture hdrWrite = written(m_write, "hdr"), displayWrite = written(2 + m_write, "display");
    struct Data {
        rg::Buffer frame;
        rg::Texture hdr, depth, display, history, historyDisplay, outHistory, outDisplay;
    };
    const Data& out = graph.addCompute<Data>(
        m_name + ".resolve",
        [&](rg::Builder& b, Data& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.hdr = b.read(inner.hdr, rg::Use::SampledCompute);
            d.depth = b.read(inner.depth, rg::Use::SampledCompute);
            d.display = b.read(inner.display, rg::Use::SampledCompute);
            d.history = hdrRead == inner.hdr ? d.hdr : b.read(hdrRead, rg::Use::SampledCompute);
            d.historyDisplay =
                displayRead == inner.display ? d.display : b.read(displayRead, rg::Use::SampledCompute);
            d.outHistory = b.write(hdrWrite, rg::Use::StorageImageWriteCompute);
            d.outDisplay = b.write(displayWrite, rg::Use::StorageImageWriteCompute);
        },
        [this, params](const rg::Context& ctx, const Data& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_pipeline);
            vk::PushDescriptors()
                .uniform(0, ctx.buffer(d.frame).buffer)
                .sampled(1, m_fetchSampler, ctx.texture(d.hdr).sampledView)
                .sampled(2, m_fetchSampler, ctx.texture(d.depth).sampledView)
                .sampled(3, m_fetchSampler, ctx.texture(d.history).sampledView)
                .storageImage(4, ctx.texture(d.outHistory).view)
                .storageImage(5, ctx.texture(d.outDisplay).view)
                .sampled(6, m_fetchSampler, ctx.texture(d.display).sampledView)
                .sampled(7, m_fetchSampler, ctx.texture(d.historyDisplay).sampledView)
                .push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_layout.layout);
            vkCmdPushConstants(cmd, m_layout.layout, VK_SHADER_STAGE_ALL, 0, sizeof(params), &params);
            const rg::PhysicalTexture& output = ctx.texture(d.outDisplay);
            vkCmdDispatch(cmd, (output.desc.width + shared::kTileSize - 1) / shared::kTileSize,
                          (output.desc.height + shared::kTileSize - 1) / shared::kTileSize, 1);
        });

    // The next frame's state.
    m_previous = *in.constants;
    m_framesInHistory = std::min(m_framesInHistory + 1, 1u << 16);
    m_write = 1 - m_write;
    ++m_frame;
    FrameTargets targets = inner;
    targets.hdr = out.outHistory;
    targets.display = out.outDisplay;
    return targets;
}

} // namespace agaa
