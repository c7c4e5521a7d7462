#include "agaa/common/scene_drawer.h"

#include "agaa/common/shipping_programs.h"

#include <span>

namespace agaa {
namespace vk = eng::vk;

struct SceneDrawer::Prepared {
    RasterPass pass;
    vk::PipelineLayout layout;
    std::vector<VkPipeline> perDraw; // the scene's draws, in order
    std::unique_ptr<vk::PipelineCache<DrawVariant>> pipelines;
};

namespace {

bool pushesFirstTriangle(RasterOutput o) {
    return o == RasterOutput::SampleGBufferPrimitive || o == RasterOutput::SurfaceVisibility ||
           o == RasterOutput::SurfaceFill;
}

bool aggregateOutput(RasterOutput o) {
    return o == RasterOutput::AggregateVisibility || o == RasterOutput::AggregateAccumulation;
}

// This project's programs for each output, by their names in the shader table.
std::string vertexProgram(RasterOutput o) {
    return o == RasterOutput::ShadowDepth ? "common/shadow_map.vert"
           : aggregateOutput(o)           ? "agaa/scene.vert"
                                          : "reference/gbuffer.vert";
}

// Opaque shadow casters run no fragment shader at all (an empty name).
std::string fragmentProgram(const RasterPass& pass, AlphaPath alpha) {
    const std::string perSample = pass.sampleRateShading ? "_sample_rate" : "";
    switch (pass.output) {
    case RasterOutput::SampleGBuffer:
        return "reference/gbuffer" + perSample + ".frag";
    case RasterOutput::SampleGBufferPrimitive:
        return "reference/gbuffer_primitive" + perSample + ".frag";
    case RasterOutput::SurfaceVisibility:
        return "sbaa/prepass" + perSample + ".frag";
    case RasterOutput::SurfaceFill:
        return "sbaa/fill" + perSample + ".frag";
    case RasterOutput::ShadowDepth:
        return alpha == AlphaPath::Opaque ? "" : "common/shadow_map.frag";
    case RasterOutput::AggregateVisibility:
        return "agaa/visibility.frag";
    case RasterOutput::AggregateAccumulation:
        return std::string("agaa/generation") + (pass.defined("AGAA_EMISSIVE") ? "_emissive" : "") +
               (pass.defined("AGAA_INT64") ? "_int64" : "") +
               (pass.defined("AGAA_SUBGROUP") ? "_subgroup" : "") + ".frag";
    }
    return "";
}

} // namespace

SceneDrawer::SceneDrawer(vk::Device& device, const eng::frame::GpuScene& scene,
                         const eng::scene::SceneFeatures& features, ProgramOverrides overrides)
    : m_device(device), m_scene(scene), m_features(features), m_overrides(std::move(overrides)) {}

std::span<const uint32_t> SceneDrawer::program(const std::string& name) const {
    return name.empty() ? std::span<const uint32_t>() : programCode(m_overrides, shippingProgram(name));
}

SceneDrawer::~SceneDrawer() {
    vkDeviceWaitIdle(m_device.device());
    for (auto& p : m_prepared) {
        p->pipelines->release();
        vk::destroyPipelineLayout(m_device, p->layout);
    }
}

size_t SceneDrawer::preparedPasses() const {
    std::lock_guard lock(m_mutex);
    return m_prepared.size();
}

const SceneDrawer::Prepared* SceneDrawer::find(const RasterPass& pass) const {
    for (const auto& p : m_prepared)
        if (p->pass == pass) return p.get();
    return nullptr;
}

// The shadow pass alpha-tests masked materials only (no coverage: one sample per texel); SBAA's
// fill and AGAA's accumulation none (their prepass applied the alpha: what survived its depth is
// what they may draw over, and they must not discard); the camera's other passes take the
// material's path at the pass's sample count.
DrawVariant SceneDrawer::variantOf(const RasterPass& pass, const eng::scene::Material& m) const {
    if (pass.output == RasterOutput::ShadowDepth)
        return {m.alphaMode == eng::scene::AlphaMode::Mask ? AlphaPath::Discard : AlphaPath::Opaque, false};
    if (pass.output == RasterOutput::SurfaceFill || pass.output == RasterOutput::AggregateAccumulation)
        return {AlphaPath::Opaque, m.doubleSided};
    return {materialAlphaPath(m, m_features.forced, uint32_t(pass.samples)), m.doubleSided};
}

void SceneDrawer::prepare(const RasterPass& pass) {
    std::lock_guard lock(m_mutex);
    if (find(pass)) return;
    auto p = std::make_unique<Prepared>();
    p->pass = pass;
    vk::LayoutDesc layout;
    layout.pushBindings = pass.moduleSet;
    layout.extraSets = {m_scene.materialSetLayout()};
    layout.pushConstantBytes = pushesFirstTriangle(pass.output) ? 8 : 4; // material (, first triangle)
    p->layout = vk::createPipelineLayout(m_device, layout, pass.name + ".layout");
    const VkPipelineLayout pipelineLayout = p->layout.layout;
    p->pipelines = std::make_unique<vk::PipelineCache<DrawVariant>>(
        m_device, [this, &pass = p->pass, pipelineLayout](const DrawVariant& v) {
            return makePipeline(pass, pipelineLayout, v);
        });
    try {
        // Every draw's pipeline now, so none is made while a command buffer records.
        const eng::scene::Scene& scene = m_scene.scene();
        for (const eng::scene::Draw& draw : scene.draws)
            p->perDraw.push_back(p->pipelines->get(variantOf(pass, scene.materials.at(draw.material))));
    } catch (...) {
        p->pipelines->release();
        vk::destroyPipelineLayout(m_device, p->layout);
        throw;
    }
    m_prepared.push_back(std::move(p));
}

VkPipeline SceneDrawer::makePipeline(const RasterPass& pass, VkPipelineLayout layout,
                                     const DrawVariant& variant) const {
    vk::GraphicsPipelineDesc d = rasterPipelineState(pass, variant.doubleSided);
    d.vertex = program(vertexProgram(pass.output));
    d.fragment = program(fragmentProgram(pass, variant.alpha));
    d.layout = layout;
    // The programs' own ids: the effects the material evaluation reads, and the alpha path where
    // the program takes one (ids overlap between programs: each gets only its own).
    switch (pass.output) {
    case RasterOutput::ShadowDepth:
        break;
    case RasterOutput::AggregateVisibility:
        d.specialization.byId = {{shared::kSpecVisibilityAlphaPath, uint32_t(variant.alpha)}};
        break;
    case RasterOutput::AggregateAccumulation:
        d.specialization = effectSpecialization(m_features, 1);
        break;
    default:
        d.specialization = effectSpecialization(m_features, 1);
        d.specialization.byId.push_back({shared::kSpecFillAlphaPath, uint32_t(variant.alpha)});
    }
    d.specialization.byId.insert(d.specialization.byId.end(), pass.specialization.byId.begin(),
                                 pass.specialization.byId.end());
    addMaterialSpecialization(d.specialization, m_features);
    d.alphaToCoverage = usesAlphaToCoverage(variant.alpha);
    const bool shadow = pass.output == RasterOutput::ShadowDepth;
    const std::string name =
        shadow ? pass.name + (variant.alpha == AlphaPath::Opaque ? ".opaque" : ".masked")
               : pass.name + alphaPathName(variant.alpha) + (variant.doubleSided ? ".twoSided" : "");
    return vk::createGraphicsPipeline(m_device, d, name);
}

void SceneDrawer::recordDraws(VkCommandBuffer cmd, const RasterPass& pass,
                              const PushModuleSet& pushModuleSet) const {
    const Prepared* p = nullptr;
    {
        std::lock_guard lock(m_mutex);
        p = find(pass);
    }
    if (!p) throw std::logic_error(pass.name + ": recorded before SceneDrawer::prepare");
    // One pipeline layout for every draw of the pass: set 0 pushed once, before the first bind.
    pushModuleSet(cmd, p->layout.layout);
    m_scene.recordDraws(cmd, p->layout.layout, p->perDraw, pass.layers, pushesFirstTriangle(pass.output));
}

std::unique_ptr<SceneDrawer> makeSceneDrawer(eng::vk::Device& device, const TechniqueContent& content,
                                             const eng::scene::SceneFeatures& features,
                                             ProgramOverrides overrides) {
    if (!content.scene) return nullptr;
    return std::make_unique<SceneDrawer>(device, *content.scene, features, std::move(overrides));
}

} // namespace agaa
