#include "agaa/common/shadow_map.h"

#include "engine/frame/frame_constants.h"
#include "engine/vk/check.h"
#include "engine/vk/descriptors.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

namespace {

std::array<glm::dvec3, 8> boxCorners(glm::dvec3 lo, glm::dvec3 hi) {
    std::array<glm::dvec3, 8> c;
    for (int i = 0; i < 8; ++i)
        c[i] = {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
    return c;
}

glm::dvec3 anyPerpendicular(glm::dvec3 d) {
    return std::abs(d.y) < 0.99 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
}

} // namespace

// In double throughout: 1e5 m from the origin (hard-far) fp32 lost the fit's light view and the
// camera frustum to cancellation, and the map moved against the scene between two frames that
// differ only by where the origin is.
glm::dmat4 ShadowMapPass::fitLight(const eng::scene::Bounds& bounds, const eng::scene::Light& light,
                                   const shared::FrameConstants* frame, float* texelMetres) {
    glm::dvec3 lo = bounds.min, hi = bounds.max;
    if (!(glm::all(glm::lessThanEqual(lo, hi)))) lo = hi = glm::dvec3(0.0);
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double radius = std::max(0.5 * glm::length(hi - lo), 1e-3);
    const glm::dvec3 position = light.position;
    glm::dvec3 d = glm::length(light.direction) > 0.0f ? glm::normalize(glm::dvec3(light.direction))
                                                       : glm::dvec3(0, -1, 0);
    if (light.type == eng::scene::LightType::Spot) {
        const glm::dmat4 view = glm::lookAt(position, position + d, anyPerpendicular(d));
        double far = 0.0;
        for (const glm::dvec3& c : boxCorners(lo, hi))
            far = std::max(far, glm::length(c - position));
        if (light.range > 0.0f) far = std::min(far, double(light.range));
        far = std::max(far, 0.1);
        const double near = std::max(0.01, far * 1e-3);
        const double fov = std::clamp(2.0 * double(light.outerConeAngle), 0.02, 2.9);
        if (texelMetres)
            *texelMetres = float(2.0 * std::tan(0.5 * fov) * glm::length(centre - position) / 1024.0);
        return glm::perspectiveRH_ZO(fov, 1.0, near, far) * view;
    }
    const glm::dmat4 view = glm::lookAt(centre - d * (2.0 * radius), centre, anyPerpendicular(d));
    glm::dvec3 sceneLo(1e300), sceneHi(-1e300);
    for (const glm::dvec3& c : boxCorners(lo, hi)) {
        glm::dvec3 p = glm::dvec3(view * glm::dvec4(c, 1.0));
        sceneLo = glm::min(sceneLo, p);
        sceneHi = glm::max(sceneHi, p);
    }
    // The camera frustum's corners (reversed Z: ndc z 1 near, 0 far) in light space. For a tile of
    // a larger view (FrameConstants::viewTile) the whole view's: x_tile = s x - P'20, so the whole
    // view's +-1 lies at +-s - P'20 in the tile's NDC, and every tile gets the same shadow map.
    glm::dvec3 viewLo(1e300), viewHi(-1e300);
    const glm::dmat4 inverseViewProj =
        frame ? glm::inverse(glm::dmat4(frame->proj) * glm::dmat4(frame->view)) : glm::dmat4(0.0);
    const double tileScale = frame && frame->viewTile.x > 1.0f ? frame->viewTile.x : 1.0;
    const glm::dvec2 tileOffset =
        frame && tileScale > 1.0 ? glm::dvec2(frame->projParams.z, frame->projParams.w) : glm::dvec2(0.0);
    for (int i = 0; frame && i < 8; ++i) {
        glm::dvec4 ndc((i & 1) ? tileScale - tileOffset.x : -tileScale - tileOffset.x,
                       (i & 2) ? tileScale - tileOffset.y : -tileScale - tileOffset.y, (i & 4) ? 1.0 : 0.0,
                       1.0);
        glm::dvec4 w = inverseViewProj * ndc;
        if (std::abs(w.w) < 1e-12) continue;
        glm::dvec3 p = glm::dvec3(view * glm::dvec4(glm::dvec3(w) / w.w, 1.0));
        viewLo = glm::min(viewLo, p);
        viewHi = glm::max(viewHi, p);
    }
    glm::dvec2 xyLo = glm::max(glm::dvec2(sceneLo), glm::dvec2(viewLo));
    glm::dvec2 xyHi = glm::min(glm::dvec2(sceneHi), glm::dvec2(viewHi));
    if (!(xyLo.x < xyHi.x && xyLo.y < xyHi.y)) { // no overlap (or NaN): the whole scene
        xyLo = glm::dvec2(sceneLo);
        xyHi = glm::dvec2(sceneHi);
    }
    const double pad = 1e-3 * radius;
    xyLo -= pad;
    xyHi += pad;
    if (texelMetres) *texelMetres = float(std::max(xyHi.x - xyLo.x, xyHi.y - xyLo.y) / 1024.0);
    // Light view looks down -z: depth from the light is -z, in [-sceneHi.z, -sceneLo.z].
    return glm::orthoRH_ZO(xyLo.x, xyHi.x, xyLo.y, xyHi.y, -sceneHi.z - pad, -sceneLo.z + pad) * view;
}

ShadowMapPass::ShadowMapPass(vk::Device& device, const TechniqueContent& content,
                             const eng::scene::SceneFeatures& features, const EffectSettings& settings,
                             std::string name)
    : m_device(device), m_name(std::move(name)),
      m_constantsRing(device, sizeof(shared::ShadowConstants), m_name + ".shadow.constants"),
      m_settings(settings), m_traits(content.traits), m_lights(features.shadowedLights),
      m_mapCount(uint32_t(std::min<size_t>(features.shadowedLights.size(), shared::kMaxShadowMaps))) {
    validate(settings);
    if (!enabled()) return;
    m_raster.name = m_name + ".shadow";
    m_raster.output = RasterOutput::ShadowDepth;
    m_raster.depthFormat = kFormat;
    m_raster.depthCompare = VK_COMPARE_OP_LESS; // standard depth: 0 nearest the light
    m_raster.layers = m_mapCount;               // instance l renders light l's map
    m_raster.bothFaces = true;                  // both faces cast: thin and open meshes do not leak light
    m_raster.moduleSet = {
        {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 1}};
    m_sceneDrawer = makeSceneDrawer(device, content, features);
    m_sampler = vk::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f,
                                  m_name + ".shadow.sampler");
}

ShadowMapPass::~ShadowMapPass() {
    if (!enabled()) return;
    release();
}

void ShadowMapPass::release() {
    VkDevice d = m_device.device();
    vkDeviceWaitIdle(d);
    vkDestroySampler(d, m_sampler, nullptr);
    m_sceneDrawer.reset();
}

shared::ShadowConstants ShadowMapPass::makeConstants(const SceneTraits& traits,
                                                     std::span<const uint32_t> lights, uint32_t size,
                                                     const shared::FrameConstants* frame) {
    const uint32_t maps = uint32_t(std::min<size_t>(lights.size(), shared::kMaxShadowMaps));
    shared::ShadowConstants c{};
    c.lightIndex = glm::uvec4(shared::kMaxLights);
    // Hosts that fill only the frame-constants buffer (no FrameConstants given) render camera 0
    // (what makeFrameConstants builds by default); the fit then covers the whole scene.
    const glm::mat4 view =
        frame ? frame->view : (traits.cameras.empty() ? glm::mat4(1.0f) : traits.cameras[0].view);
    // In double: the product's translation is a difference of terms as large as the world
    // coordinates (1e5 m from the origin fp32 cancels them to millimetres; FrameConstants::eye).
    const glm::dmat4 viewToWorld = glm::inverse(glm::dmat4(view));
    c.eye = glm::vec4(glm::vec3(eng::frame::cameraEye(view)), 0.0f);
    for (uint32_t l = 0; l < maps; ++l) {
        float texel = 0.0f;
        const glm::dmat4 worldToShadow = fitLight(traits.bounds, traits.lights.at(lights[l]), frame, &texel);
        texel *= 1024.0f / float(size);
        c.relativeToShadow[l] = glm::mat4(glm::translate(worldToShadow, eng::frame::cameraEye(view)));
        c.viewToShadow[l] = glm::mat4(worldToShadow * viewToWorld);
        c.lightIndex[l] = lights[l];
        c.normalOffset[l] = 1.5f * texel;
    }
    // Depth bias in shadow clip z: a few ulps of D32 plus a small constant for the comparison.
    c.params = {float(maps), 1.0f / float(size), 2.0e-4f, 0.0f};
    return c;
}

ShadowMaps ShadowMapPass::importHostMaps(rg::Graph& graph, const HostShadowMaps& host) const {
    const rg::TextureDesc& d = host.map.desc;
    auto refuse = [](const std::string& what) {
        throw std::invalid_argument("FrameInputs::shadowMaps: " + what);
    };
    if (d.format != kFormat) refuse("map.desc.format must be VK_FORMAT_D32_SFLOAT");
    if (d.layers < std::max(2u, m_mapCount))
        refuse("map.desc.layers is " + std::to_string(d.layers) + "; a 2D array needs at least " +
               std::to_string(std::max(2u, m_mapCount)) + " (one per shadowed light, at least 2)");
    if (d.samples != VK_SAMPLE_COUNT_1_BIT) refuse("map.desc.samples must be VK_SAMPLE_COUNT_1_BIT");
    if (host.map.image == VK_NULL_HANDLE || host.map.sampledView == VK_NULL_HANDLE)
        refuse("map.image and map.sampledView (a depth-aspect 2D array view) are required");
    if (host.constants.buffer == VK_NULL_HANDLE || host.constants.size < sizeof(shared::ShadowConstants))
        refuse("constants must be a uniform buffer of at least " +
               std::to_string(sizeof(shared::ShadowConstants)) + " bytes (shared::ShadowConstants)");
    return {graph.importTexture(m_name + ".shadow.hostMap", host.map, host.initial, std::nullopt),
            graph.importBuffer(m_name + ".shadow.hostConstants", host.constants, std::nullopt, std::nullopt)};
}

ShadowMaps ShadowMapPass::add(rg::Graph& graph, const FrameInputs& in) {
    if (in.shadowMaps) return importHostMaps(graph, *in.shadowMaps);
    const uint32_t size = m_settings.shadowMapSize;
    m_constants = makeConstants(m_traits, m_lights, size, in.constants);
    // The fit follows the camera: per frame slot, so views recorded before any executes keep theirs.
    const rg::Buffer constants =
        m_constantsRing.write(graph, in.frameSlot, std::as_bytes(std::span(&m_constants, 1)));

    GeometryDrawer* drawer = &frameDrawer(in, m_sceneDrawer.get(), m_raster.name);
    drawer->prepare(m_raster); // pipelines now, never while a command buffer records
    // An array view needs two layers under the transient pool's view rule (1 layer: a 2D view).
    const uint32_t layers = std::max(2u, m_mapCount);
    struct Data {
        rg::Buffer constants;
        rg::Texture map;
    };
    const Data& out = graph.addGraphics<Data>(
        m_raster.name,
        [&](rg::Builder& b, Data& d) {
            d.constants = b.read(constants, rg::Use::UniformRead);
            rg::Attachment clearDepth;
            clearDepth.clear.depthStencil = {1.0f, 0}; // nothing occludes
            d.map = b.depthStencil(
                b.create(m_name + ".shadow.map", {kFormat, size, size, layers, VK_SAMPLE_COUNT_1_BIT}),
                rg::Use::DepthStencilWrite, clearDepth);
        },
        [this, drawer](const rg::Context& ctx, const Data& d) {
            const VkBuffer constants = ctx.buffer(d.constants).buffer;
            drawer->recordDraws(ctx.cmd(), m_raster,
                                [this, constants](VkCommandBuffer cmd, VkPipelineLayout layout) {
                                    vk::PushDescriptors()
                                        .uniform(0, constants)
                                        .push(m_device, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout);
                                });
        });
    return {out.map, out.constants};
}

ShadowMaps ShadowMapPass::read(eng::rg::Builder& b, const ShadowMaps& maps) {
    return {b.read(maps.map, eng::rg::Use::SampledCompute),
            b.read(maps.constants, eng::rg::Use::UniformRead)};
}

void ShadowMapPass::push(eng::vk::PushDescriptors& pd, const eng::rg::Context& ctx, const ShadowMaps& maps,
                         uint32_t mapBinding, uint32_t constantsBinding) const {
    pd.sampled(mapBinding, m_sampler, ctx.texture(maps.map).sampledView)
        .uniform(constantsBinding, ctx.buffer(maps.constants).buffer);
}

} // namespace agaa
