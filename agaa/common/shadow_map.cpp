#include "agaa/common/shadow_map.h"

#include "engine/vk/check.h"
#include "engine/vk/descriptors.h"
#include "shaders/common/shadow_map_frag.h"
#include "shaders/common/shadow_map_vert.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

namespace {

std::array<glm::vec3, 8> boxCorners(glm::vec3 lo, glm::vec3 hi) {
    std::array<glm::vec3, 8> c;
    for (int i = 0; i < 8; ++i)
        c[i] = {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
    return c;
}

glm::vec3 anyPerpendicular(glm::vec3 d) {
    return std::abs(d.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
}

} // namespace

glm::mat4 ShadowMapPass::fitLight(const eng::scene::Scene& scene, const eng::scene::Light& light,
                                  const shared::FrameConstants* frame, float* texelMetres) {
    glm::vec3 lo = scene.bounds.min, hi = scene.bounds.max;
    if (!(glm::all(glm::lessThanEqual(lo, hi)))) lo = hi = glm::vec3(0.0f);
    const glm::vec3 centre = 0.5f * (lo + hi);
    const float radius = std::max(0.5f * glm::length(hi - lo), 1e-3f);
    glm::vec3 d = glm::length(light.direction) > 0.0f ? glm::normalize(light.direction) : glm::vec3(0, -1, 0);
    if (light.type == eng::scene::LightType::Spot) {
        const glm::mat4 view = glm::lookAt(light.position, light.position + d, anyPerpendicular(d));
        float far = 0.0f;
        for (const glm::vec3& c : boxCorners(lo, hi))
            far = std::max(far, glm::length(c - light.position));
        if (light.range > 0.0f) far = std::min(far, light.range);
        far = std::max(far, 0.1f);
        const float near = std::max(0.01f, far * 1e-3f);
        const float fov = std::clamp(2.0f * light.outerConeAngle, 0.02f, 2.9f);
        if (texelMetres)
            *texelMetres = 2.0f * std::tan(0.5f * fov) * glm::length(centre - light.position) / 1024.0f;
        return glm::perspectiveRH_ZO(fov, 1.0f, near, far) * view;
    }
    const glm::mat4 view = glm::lookAt(centre - d * (2.0f * radius), centre, anyPerpendicular(d));
    glm::vec3 sceneLo(1e30f), sceneHi(-1e30f);
    for (const glm::vec3& c : boxCorners(lo, hi)) {
        glm::vec3 p = glm::vec3(view * glm::vec4(c, 1.0f));
        sceneLo = glm::min(sceneLo, p);
        sceneHi = glm::max(sceneHi, p);
    }
    // The camera frustum's corners (reversed Z: ndc z 1 near, 0 far) in light space. For a tile of
    // a larger view (FrameConstants::viewTile) the whole view's: x_tile = s x - P'20, so the whole
    // view's +-1 lies at +-s - P'20 in the tile's NDC, and every tile gets the same shadow map.
    glm::vec3 viewLo(1e30f), viewHi(-1e30f);
    const glm::mat4 inverseViewProj = frame ? glm::inverse(frame->viewProj) : glm::mat4(0.0f);
    const float tileScale = frame && frame->viewTile.x > 1.0f ? frame->viewTile.x : 1.0f;
    const glm::vec2 tileOffset =
        frame && tileScale > 1.0f ? glm::vec2(frame->projParams.z, frame->projParams.w) : glm::vec2(0.0f);
    for (int i = 0; frame && i < 8; ++i) {
        glm::vec4 ndc((i & 1) ? tileScale - tileOffset.x : -tileScale - tileOffset.x,
                      (i & 2) ? tileScale - tileOffset.y : -tileScale - tileOffset.y, (i & 4) ? 1.0f : 0.0f,
                      1.0f);
        glm::vec4 w = inverseViewProj * ndc;
        if (std::abs(w.w) < 1e-12f) continue;
        glm::vec3 p = glm::vec3(view * glm::vec4(glm::vec3(w) / w.w, 1.0f));
        viewLo = glm::min(viewLo, p);
        viewHi = glm::max(viewHi, p);
    }
    glm::vec2 xyLo = glm::max(glm::vec2(sceneLo), glm::vec2(viewLo));
    glm::vec2 xyHi = glm::min(glm::vec2(sceneHi), glm::vec2(viewHi));
    if (!(xyLo.x < xyHi.x && xyLo.y < xyHi.y)) { // no overlap (or NaN): the whole scene
        xyLo = glm::vec2(sceneLo);
        xyHi = glm::vec2(sceneHi);
    }
    const float pad = 1e-3f * radius;
    xyLo -= pad;
    xyHi += pad;
    if (texelMetres) *texelMetres = std::max(xyHi.x - xyLo.x, xyHi.y - xyLo.y) / 1024.0f;
    // Light view looks down -z: depth from the light is -z, in [-sceneHi.z, -sceneLo.z].
    return glm::orthoRH_ZO(xyLo.x, xyHi.x, xyLo.y, xyHi.y, -sceneHi.z - pad, -sceneLo.z + pad) * view;
}

ShadowMapPass::ShadowMapPass(vk::Device& device, const eng::frame::GpuScene& scene,
                             const eng::scene::SceneFeatures& features, const EffectSettings& settings,
                             std::string name)
    : m_device(device), m_name(std::move(name)),
      m_constantsRing(device, sizeof(shared::ShadowConstants), m_name + ".shadow.constants"),
      m_settings(settings), m_lights(features.shadowedLights),
      m_mapCount(uint32_t(std::min<size_t>(features.shadowedLights.size(), shared::kMaxShadowMaps))) {
    validate(settings);
    if (!enabled()) return;
    vk::LayoutDesc layout;
    layout.pushBindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT},
                           {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT}};
    layout.extraSets = {scene.textureSetLayout()};
    layout.pushConstantBytes = 4; // material index
    m_layout = vk::createPipelineLayout(device, layout, m_name + ".shadow.layout");
    for (int masked = 0; masked < 2; ++masked) {
        vk::GraphicsPipelineDesc d;
        d.vertex = kCommonShadowMapVert;
        if (masked) d.fragment = kCommonShadowMapFrag;
        d.layout = m_layout.layout;
        d.depthFormat = kFormat;
        d.cullMode = VK_CULL_MODE_NONE;      // both faces cast: thin and open meshes do not leak light
        d.depthCompare = VK_COMPARE_OP_LESS; // standard depth: 0 nearest the light
        addMaterialSpecialization(d.specialization, features);
        m_pipelines[masked] =
            vk::createGraphicsPipeline(device, d, m_name + ".shadow" + (masked ? ".masked" : ".opaque"));
    }
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
    for (VkPipeline p : m_pipelines)
        if (p) vkDestroyPipeline(d, p, nullptr);
    vkDestroySampler(d, m_sampler, nullptr);
    vk::destroyPipelineLayout(m_device, m_layout);
}

ShadowMaps ShadowMapPass::add(rg::Graph& graph, const FrameInputs& in) {
    const eng::scene::Scene& scene = in.scene->scene();
    const uint32_t size = m_settings.shadowMapSize;
    m_constants = {};
    m_constants.lightIndex = glm::uvec4(shared::kMaxLights);
    // Hosts that fill only the frame-constants buffer (in.constants == nullptr) render scene
    // camera 0 (what makeFrameConstants builds by default); the fit then covers the whole scene.
    const glm::mat4 view =
        in.constants ? in.constants->view : (scene.cameras.empty() ? glm::mat4(1.0f) : scene.cameras[0].view);
    const glm::mat4 viewToWorld = glm::inverse(view);
    for (uint32_t l = 0; l < m_mapCount; ++l) {
        float texel = 0.0f;
        const glm::mat4 worldToShadow = fitLight(scene, scene.lights.at(m_lights[l]), in.constants, &texel);
        texel *= 1024.0f / float(size);
        m_constants.worldToShadow[l] = worldToShadow;
        m_constants.viewToShadow[l] = worldToShadow * viewToWorld;
        m_constants.lightIndex[l] = m_lights[l];
        m_constants.normalOffset[l] = 1.5f * texel;
    }
    // Depth bias in shadow clip z: a few ulps of D32 plus a small constant for the comparison.
    m_constants.params = {float(m_mapCount), 1.0f / float(size), 2.0e-4f, 0.0f};
    // The fit follows the camera: per frame slot, so views recorded before any executes keep theirs.
    const rg::Buffer constants =
        m_constantsRing.write(graph, in.frameSlot, std::as_bytes(std::span(&m_constants, 1)));

    const eng::frame::GpuScene* gpuScene = in.scene;
    std::vector<VkPipeline> drawPipelines;
    for (const eng::scene::Draw& draw : scene.draws) {
        const eng::scene::Material& m = scene.materials.at(draw.material);
        drawPipelines.push_back(m_pipelines[m.alphaMode == eng::scene::AlphaMode::Mask ? 1 : 0]);
    }
    rg::Buffer materials = graph.importBuffer(m_name + ".shadow.materials",
                                              {gpuScene->materials().buffer, gpuScene->materials().size},
                                              std::nullopt, std::nullopt);
    // An array view needs two layers under the transient pool's view rule (1 layer: a 2D view).
    const uint32_t layers = std::max(2u, m_mapCount);
    struct Data {
        rg::Buffer constants, materials;
        rg::Texture map;
    };
    const Data& out = graph.addGraphics<Data>(
        m_name + ".shadow",
        [&](rg::Builder& b, Data& d) {
            d.constants = b.read(constants, rg::Use::UniformRead);
            d.materials = b.read(materials, rg::Use::StorageReadFragment);
            rg::Attachment clearDepth;
            clearDepth.clear.depthStencil = {1.0f, 0}; // nothing occludes
            d.map = b.depthStencil(
                b.create(m_name + ".shadow.map", {kFormat, size, size, layers, VK_SAMPLE_COUNT_1_BIT}),
                rg::Use::DepthStencilWrite, clearDepth);
        },
        [this, gpuScene, drawPipelines](const rg::Context& ctx, const Data& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vk::PushDescriptors()
                .uniform(0, ctx.buffer(d.constants).buffer)
                .storage(1, ctx.buffer(d.materials).buffer)
                .push(m_device, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, m_layout.layout);
            gpuScene->recordDraws(cmd, m_layout.layout, drawPipelines, m_mapCount); // instance = layer
        });
    return {out.map, out.constants};
}

} // namespace agaa
