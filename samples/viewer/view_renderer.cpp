#include "samples/viewer/view_renderer.h"

#include "agaa/methods.h"
#include "engine/frame/frame_constants.h"
#include "engine/frame/readback.h"
#include "engine/frame/sample_pattern.h"
#include "engine/graph/graph.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/reflection.h"
#include "shaders/viewer/difference_comp.h"
#include "shared/frame.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace agaa::viewer {
namespace rg = eng::rg;
namespace vk = eng::vk;

ViewRenderer::ViewRenderer(vk::Device& device, const eng::scene::Scene& scene)
    : m_device(device), m_scene(scene), m_gpuScene(device, scene), m_runner(device) {
    if (scene.lights.size() > shared::kMaxLights)
        throw std::invalid_argument(scene.source + ": " + std::to_string(scene.lights.size()) +
                                    " lights; at most " + std::to_string(shared::kMaxLights) +
                                    " are supported");
    for (int i = 0; i < 2; ++i)
        m_frameConstants[i] = vk::createBuffer(device, sizeof(shared::FrameConstants),
                                               VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryUse::Upload,
                                               i == 0 ? "viewer.constants" : "viewer.referenceConstants");
    vk::LayoutDesc layout;
    layout.pushBindings = vk::reflectBindings({{kViewerDifferenceComp, VK_SHADER_STAGE_COMPUTE_BIT}});
    layout.pushConstantBytes = sizeof(float); // difference.comp: the gain
    m_differenceLayout = vk::createPipelineLayout(device, layout, "viewer.difference.layout");
    m_difference = vk::createComputePipeline(device, kViewerDifferenceComp, m_differenceLayout.layout, {},
                                             "viewer.difference");
    m_fetchSampler = vk::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f,
                                       "viewer.fetchSampler");
    m_lights = vk::createBuffer(device, std::max<size_t>(1, scene.lights.size()) * sizeof(shared::GpuLight),
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Upload, "viewer.lights");
}

ViewRenderer::~ViewRenderer() {
    vkDeviceWaitIdle(m_device.device());
    m_techniques.clear();
    vkDestroyPipeline(m_device.device(), m_difference, nullptr);
    vkDestroySampler(m_device.device(), m_fetchSampler, nullptr);
    vk::destroyPipelineLayout(m_device, m_differenceLayout);
    for (vk::Buffer& b : m_frameConstants)
        vk::destroyBuffer(m_device, b);
    vk::destroyBuffer(m_device, m_lights);
    if (m_events.buffer) vk::destroyBuffer(m_device, m_events);
    if (m_screenshot.buffer) vk::destroyBuffer(m_device, m_screenshot);
}

Technique& ViewRenderer::technique(const std::string& method, const MethodSettings& s) {
    // Everything the viewer can change; the rest stays at MethodSettings' defaults.
    const std::string key =
        method + "/" + std::to_string(s.samples) + "/" + std::to_string(s.aggregates) + "/" + s.debug + "/" +
        nameOf(s.agaa.ndf, kAggregateNdfNames) + "/" + nameOf(s.agaa.generation, kAggregateGenerationNames) +
        (s.effects.forceAll ? "/all" : "") + "/" + std::to_string(s.effects.shadowMapSize) + "/" +
        std::to_string(s.effects.shadowTaps) + "/" + std::to_string(uint32_t(s.effects.shadowFootprint));
    auto it = m_techniques.find(key);
    if (it == m_techniques.end())
        it = m_techniques.emplace(key, createTechnique(method, m_device, m_gpuScene, s)).first;
    return *it->second;
}

rg::Texture ViewRenderer::addDifferencePass(rg::Graph& graph, rg::Texture method, rg::Texture reference,
                                            float gain, uint32_t width, uint32_t height) {
    struct Data {
        rg::Texture method, reference, output;
    };
    constexpr uint32_t kGroup = 16; // difference.comp local size
    const Data& out = graph.addCompute<Data>(
        "viewer.difference",
        [&](rg::Builder& b, Data& d) {
            d.method = b.read(method, rg::Use::SampledCompute);
            d.reference = b.read(reference, rg::Use::SampledCompute);
            const rg::TextureDesc desc{VK_FORMAT_R32G32B32A32_SFLOAT, width, height, 1,
                                       VK_SAMPLE_COUNT_1_BIT};
            d.output = b.write(b.create("viewer.difference", desc), rg::Use::StorageImageWriteCompute);
        },
        [this, gain](const rg::Context& ctx, const Data& d) {
            VkCommandBuffer cmd = ctx.cmd();
            const rg::PhysicalTexture& output = ctx.texture(d.output);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_difference);
            vk::PushDescriptors()
                .sampled(0, m_fetchSampler, ctx.texture(d.method).sampledView)
                .sampled(1, m_fetchSampler, ctx.texture(d.reference).sampledView)
                .storageImage(2, output.view)
                .push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_differenceLayout.layout);
            vkCmdPushConstants(cmd, m_differenceLayout.layout, VK_SHADER_STAGE_ALL, 0, sizeof(gain), &gain);
            vkCmdDispatch(cmd, (output.desc.width + kGroup - 1) / kGroup,
                          (output.desc.height + kGroup - 1) / kGroup, 1);
        });
    return out.output;
}

void ViewRenderer::sizeChanged() {
    vkDeviceWaitIdle(m_device.device());
    m_runner.pool().destroyAll();
}

namespace {

// bytesPerTexel: 4 for both the R32_UINT events and the 8-bit BGRA/RGBA swapchain formats.
void ensureReadback(vk::Device& device, vk::Buffer& buffer, uint32_t w, uint32_t h, uint32_t bytesPerTexel,
                    const std::string& name) {
    const VkDeviceSize size = VkDeviceSize(w) * h * bytesPerTexel;
    if (buffer.buffer && buffer.size == size) return;
    if (buffer.buffer) vk::destroyBuffer(device, buffer); // the previous frame was waited for
    buffer = vk::createBuffer(device, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::Readback, name);
}

struct DisplayBlit {
    rg::Texture display, reference, target;
};

// Rendered pixels [src0, src1) onto swapchain pixels [dst0, dst1).
struct Span {
    uint32_t src0, src1, dst0, dst1;
};

// Rendered [begin, end) at `pixel` swapchain pixels each, ending at dstEnd: all but the last
// rendered pixel at exactly `pixel` wide, the last one clipped to dstEnd (the render size is
// the swapchain's divided by `pixel`, rounded up), so the blit never scales by a fraction.
std::vector<Span> spans(uint32_t begin, uint32_t end, uint32_t pixel, uint32_t dstEnd) {
    std::vector<Span> out;
    if (end <= begin) return out;
    if (end - 1 > begin) out.push_back({begin, end - 1, begin * pixel, (end - 1) * pixel});
    out.push_back({end - 1, end, (end - 1) * pixel, dstEnd});
    return out;
}

} // namespace

ViewFrame ViewRenderer::render(const ViewRequest& request, const AcquiredImage& target,
                               const OverlayPass& overlay) {
    const RenderRequest& r = request.render;
    // The swapchain's size, and the render size: the same at pixelSize 1.
    const uint32_t sw = target.texture.desc.width, sh = target.texture.desc.height;
    if (request.pixelSize < 1 || request.pixelSize > kMaxPixelSize)
        throw std::invalid_argument("pixel size " + std::to_string(request.pixelSize) +
                                    " is out of range (1..4)");
    const uint32_t w = renderSize(sw, request.pixelSize), h = renderSize(sh, request.pixelSize);
    // Created (and validated) before anything is written or recorded, so a refused setting
    // leaves the frame untouched.
    Technique& tech = technique(r.method, r.settings);
    Technique* reference = nullptr;
    // The reference against itself needs no second render: both sides are the same image.
    if (request.compare != Compare::Off && r.method != "reference") {
        MethodSettings refSettings;
        refSettings.samples = r.settings.samples;
        refSettings.effects = r.settings.effects;
        reference = &technique("reference", refSettings);
    }

    eng::frame::ViewSettings view = r.view;
    view.width = w;
    view.height = h;
    shared::FrameConstants constants[2];
    constants[0] =
        eng::frame::makeFrameConstants(m_scene, view, eng::frame::makeSamplePattern(tech.samples()));
    const std::vector<shared::GpuLight> lights = eng::frame::makeGpuLights(m_scene, constants[0].view);
    vk::writeBuffer(m_device, m_frameConstants[0], std::as_bytes(std::span(&constants[0], 1)));
    vk::writeBuffer(m_device, m_lights, std::as_bytes(std::span(lights)));
    if (reference) {
        constants[1] = eng::frame::makeFrameConstants(m_scene, view,
                                                      eng::frame::makeSamplePattern(reference->samples()));
        vk::writeBuffer(m_device, m_frameConstants[1], std::as_bytes(std::span(&constants[1], 1)));
    }

    rg::Graph graph;
    // Host-written before the submit (which makes them visible): no earlier GPU use.
    const rg::Buffer lightsBuffer =
        graph.importBuffer("frame.lights", {m_lights.buffer, m_lights.size}, std::nullopt, std::nullopt);
    auto inputs = [&](int i) {
        FrameInputs in;
        in.constants = &constants[i];
        in.width = w;
        in.height = h;
        in.frameConstants = graph.importBuffer(i == 0 ? "frame.constants" : "frame.referenceConstants",
                                               {m_frameConstants[i].buffer, m_frameConstants[i].size},
                                               std::nullopt, std::nullopt);
        in.lights = lightsBuffer;
        return in;
    };
    const FrameTargets targets = tech.addPasses(graph, inputs(0));
    rg::Texture referenceDisplay;
    if (reference) referenceDisplay = reference->addPasses(graph, inputs(1)).display;

    // The acquired image's contents are discarded (initial nullopt); it leaves in PRESENT_SRC.
    rg::Texture swapchain =
        graph.importTexture("viewer.swapchain", target.texture, std::nullopt, rg::Use::Present);
    if (request.compare != Compare::Off && !reference) referenceDisplay = targets.display;
    rg::Texture shown = targets.display;
    if (request.compare == Compare::Difference) {
        shown = addDifferencePass(graph, targets.display, referenceDisplay, request.differenceGain, w, h);
        referenceDisplay = {}; // the whole frame shows the difference
    }
    const uint32_t splitX =
        referenceDisplay.valid() && w >= 2
            ? std::clamp(uint32_t(std::lround(request.splitFraction * float(w))), 1u, w - 1)
            : w;
    const uint32_t pixel = request.pixelSize;
    const DisplayBlit& blit = graph.addPass<DisplayBlit>(
        "viewer.display", rg::PassKind::Transfer,
        [&](rg::Builder& b, DisplayBlit& d) {
            d.display = b.read(shown, rg::Use::TransferSrc);
            if (referenceDisplay.valid()) d.reference = b.read(referenceDisplay, rg::Use::TransferSrc);
            d.target = b.write(swapchain, rg::Use::TransferDst);
        },
        [splitX, w, h, sw, sh, pixel](const rg::Context& ctx, const DisplayBlit& d) {
            // NEAREST, each rendered pixel an exact pixel x pixel block (1:1 by default); the
            // blit converts RGBA32F linear to the SRGB swapchain format (the sRGB encode).
            const std::vector<Span> columns0 = spans(0, splitX, pixel, splitX == w ? sw : splitX * pixel);
            const std::vector<Span> columns1 = spans(splitX, w, pixel, sw);
            const std::vector<Span> rows = spans(0, h, pixel, sh);
            auto blitFrom = [&](rg::Texture source, const std::vector<Span>& columns) {
                std::vector<VkImageBlit2> regions;
                for (const Span& c : columns)
                    for (const Span& r : rows) {
                        VkImageBlit2 region{VK_STRUCTURE_TYPE_IMAGE_BLIT_2};
                        region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
                        region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
                        region.srcOffsets[0] = {int32_t(c.src0), int32_t(r.src0), 0};
                        region.srcOffsets[1] = {int32_t(c.src1), int32_t(r.src1), 1};
                        region.dstOffsets[0] = {int32_t(c.dst0), int32_t(r.dst0), 0};
                        region.dstOffsets[1] = {int32_t(c.dst1), int32_t(r.dst1), 1};
                        regions.push_back(region);
                    }
                if (regions.empty()) return;
                VkBlitImageInfo2 info{VK_STRUCTURE_TYPE_BLIT_IMAGE_INFO_2};
                info.srcImage = ctx.texture(source).image;
                info.srcImageLayout = eng::rg::useInfo(rg::Use::TransferSrc).layout;
                info.dstImage = ctx.texture(d.target).image;
                info.dstImageLayout = eng::rg::useInfo(rg::Use::TransferDst).layout;
                info.regionCount = uint32_t(regions.size());
                info.pRegions = regions.data();
                info.filter = VK_FILTER_NEAREST;
                vkCmdBlitImage2(ctx.cmd(), &info);
            };
            blitFrom(d.display, columns0);
            if (d.reference.valid()) blitFrom(d.reference, columns1);
        });
    swapchain = blit.target;
    if (overlay) swapchain = overlay(graph, swapchain);
    if (request.screenshot) {
        ensureReadback(m_device, m_screenshot, sw, sh, 4, "viewer.screenshot");
        eng::frame::addReadbackPass(graph, swapchain, m_screenshot, "viewer.screenshot");
    }
    if (request.readShadingEvents) {
        ensureReadback(m_device, m_events, w, h, 4, "viewer.events");
        eng::frame::addReadbackPass(graph, targets.shadingEvents, m_events, "viewer.events");
    }
    graph.compile();

    ViewFrame frame;
    frame.samples = tech.samples();
    frame.timing = m_runner.run(graph);

    const double pixels = double(w) * h;
    for (const auto& [name, bytes] : m_runner.pool().bytesByName()) {
        if (!tech.isStorage(name)) continue;
        frame.bytesPerPixel += double(bytes) / pixels;
        frame.bytesPerPixelSplit[tech.storageCategory(name)] += double(bytes) / pixels;
    }
    if (request.readShadingEvents) {
        vk::invalidateBuffer(m_device, m_events);
        const uint32_t* events = static_cast<const uint32_t*>(m_events.mapped);
        uint64_t sum = 0;
        for (size_t i = 0; i < size_t(w) * h; ++i)
            sum += events[i];
        frame.shadingEventsPerPixel = double(sum) / pixels;
    }
    if (request.screenshot) {
        vk::invalidateBuffer(m_device, m_screenshot);
        eng::io::ImageU8 image = eng::io::makeImageU8(sw, sh);
        std::memcpy(image.rgba.data(), m_screenshot.mapped, image.rgba.size());
        if (target.texture.desc.format == VK_FORMAT_B8G8R8A8_SRGB)
            for (size_t i = 0; i < image.rgba.size(); i += 4)
                std::swap(image.rgba[i], image.rgba[i + 2]);
        frame.screenshot = std::move(image);
    }
    return frame;
}

} // namespace agaa::viewer
