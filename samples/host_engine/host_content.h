#pragma once
// The host sample's content (issue 50): its vertex layout (interleaved position and normal, 16-bit
// indices with a base vertex per draw), its material (a constant per draw, in its own push
// constant), its shaders (shaders/, which include only the module's installed GLSL), its drawer
// (agaa::GeometryDrawer) and what it tells the module of its content (agaa::SceneTraits).
// Header-only, on installed headers alone: the sample, the package test's consumer and the node
// tests draw with it.

#include "agaa/common/raster_pass.h"
#include "agaa/common/scene_traits.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/device.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/resources.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace host_engine {

// The host's content in its own layout: interleaved position and normal, 16-bit indices with a
// base vertex per draw, and a constant material per draw (its push constant).
struct HostVertex {
    float position[3];
    float normal[3];
};
struct HostMaterial {
    float albedoRoughness[4];
    float metallic[4];
};
struct HostDraw {
    uint32_t firstIndex, indexCount;
    int32_t vertexOffset;
    HostMaterial material;
    bool twoSided;
};
struct HostMesh {
    std::vector<HostVertex> vertices;
    std::vector<uint16_t> indices;
    std::vector<HostDraw> draws;
};

// What this host tells the module of its content (agaa/common/scene_traits.h), from its own mesh,
// materials and light list, as agaa::sceneTraits does for the module's own scenes.
inline agaa::SceneTraits hostTraits(const HostMesh& mesh, const std::vector<agaa::Light>& lights,
                                    std::string source) {
    using agaa::LightType;
    agaa::SceneTraits t;
    t.source = std::move(source);
    t.triangles = mesh.indices.size() / 3;
    t.bounds = {glm::vec3(INFINITY), glm::vec3(-INFINITY)};
    for (const HostVertex& v : mesh.vertices) {
        const glm::vec3 p(v.position[0], v.position[1], v.position[2]);
        t.bounds.min = glm::min(t.bounds.min, p);
        t.bounds.max = glm::max(t.bounds.max, p);
    }
    t.lights = lights;
    agaa::SceneFeatures& f = t.features;
    for (uint32_t i = 0; i < lights.size(); ++i) {
        const LightType type = lights[i].type;
        f.directionalLights += type == LightType::Directional ? 1 : 0;
        f.pointLights += type == LightType::Point ? 1 : 0;
        f.spotLights += type == LightType::Spot ? 1 : 0;
        if (lights[i].castsShadows && type != LightType::Point &&
            f.shadowedLights.size() < agaa::kMaxShadowedLights)
            f.shadowedLights.push_back(i);
    }
    std::vector<HostMaterial> materials; // this host's materials are the distinct ones its draws push
    for (const HostDraw& d : mesh.draws)
        if (std::none_of(materials.begin(), materials.end(),
                         [&](const HostMaterial& m) { return std::memcmp(&m, &d.material, sizeof m) == 0; }))
            materials.push_back(d.material);
    for (const HostMaterial& m : materials) {
        const float roughness = m.albedoRoughness[3], metallic = m.metallic[0];
        const bool glossyMetal = metallic >= agaa::kGlossyMetallic && roughness <= agaa::kGlossyRoughness;
        const bool nearMirror = roughness < agaa::kNearMirrorRoughness;
        ++f.drawnMaterials;
        f.glossyMetalMaterials += glossyMetal ? 1 : 0;
        f.anisotropicMetalMaterials += glossyMetal && !nearMirror ? 1 : 0;
        f.nearMirrorMaterials += nearMirror ? 1 : 0;
    }
    t.materials = uint32_t(materials.size());
    return t;
}

// The host's SPIR-V by program name (programs.cmake: "host_gbuffer.frag", ...): read from the
// files the sample's build writes by the sample and the package test's consumer, embedded in the
// node tests (tests/node/host_programs.h).
using HostPrograms = std::map<std::string, std::span<const uint32_t>, std::less<>>;

// Every <name>.spv in `dir` (the sample's build writes them to <build>/shaders). Throws
// std::runtime_error naming a folder without programs or a file that is not SPIR-V.
struct HostProgramFiles {
    std::map<std::string, std::vector<uint32_t>, std::less<>> code;
    HostPrograms programs() const {
        HostPrograms p;
        for (const auto& [name, words] : code)
            p.emplace(name, words);
        return p;
    }
};
inline HostProgramFiles readHostPrograms(const std::string& dir) {
    HostProgramFiles files;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(dir, error)) {
        const std::filesystem::path& path = entry.path();
        if (path.extension() != ".spv") continue;
        std::ifstream file(path, std::ios::binary | std::ios::ate);
        const std::streamsize bytes = file ? std::streamsize(file.tellg()) : 0;
        std::vector<uint32_t> words(size_t(std::max<std::streamsize>(bytes, 0)) / 4);
        file.seekg(0);
        file.read(reinterpret_cast<char*>(words.data()), bytes);
        if (bytes < 20 || bytes % 4 != 0 || !file || words[0] != 0x07230203u)
            throw std::runtime_error(path.string() + ": not a SPIR-V file");
        files.code.emplace(path.stem().string(), std::move(words));
    }
    if (files.code.empty()) throw std::runtime_error(dir + ": no host programs (*.spv) in this folder");
    return files;
}

class HostGeometry final : public agaa::GeometryDrawer {
  public:
    HostGeometry(eng::vk::Device& device, HostMesh mesh, HostPrograms programs)
        : m_device(device), m_mesh(std::move(mesh)), m_programs(std::move(programs)) {
        m_vertices = eng::vk::createBuffer(device, m_mesh.vertices.size() * sizeof(HostVertex),
                                           VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, eng::vk::MemoryUse::Upload,
                                           "host.vertices");
        m_indices = eng::vk::createBuffer(device, std::max<size_t>(4, m_mesh.indices.size() * 2),
                                          VK_BUFFER_USAGE_INDEX_BUFFER_BIT, eng::vk::MemoryUse::Upload,
                                          "host.indices");
        eng::vk::writeBuffer(device, m_vertices, std::as_bytes(std::span(m_mesh.vertices)));
        eng::vk::writeBuffer(device, m_indices, std::as_bytes(std::span(m_mesh.indices)));
    }
    ~HostGeometry() override {
        vkDeviceWaitIdle(m_device.device());
        for (Pass& p : m_passes) {
            for (VkPipeline pipeline : p.pipelines)
                vkDestroyPipeline(m_device.device(), pipeline, nullptr);
            eng::vk::destroyPipelineLayout(m_device, p.layout);
        }
        eng::vk::destroyBuffer(m_device, m_vertices);
        eng::vk::destroyBuffer(m_device, m_indices);
    }

    void prepare(const agaa::RasterPass& pass) override {
        if (find(pass)) return;
        const std::span<const uint32_t> fragment = fragmentCode(pass);
        Pass p{pass, {}, {}};
        eng::vk::LayoutDesc layout;
        layout.pushBindings = pass.moduleSet; // set 0: the module's; this host has no set of its own
        layout.pushConstantBytes = sizeof(DrawConstants);
        p.layout = eng::vk::createPipelineLayout(m_device, layout, pass.name + ".host.layout");
        for (int twoSided = 0; twoSided < 2; ++twoSided) {
            eng::vk::GraphicsPipelineDesc d = agaa::rasterPipelineState(pass, twoSided != 0);
            const bool shadow = pass.output == agaa::RasterOutput::ShadowDepth;
            d.vertex = program(shadow ? "host_shadow.vert" : "host_gbuffer.vert", pass);
            d.fragment = fragment;
            d.layout = p.layout.layout;
            d.specialization = pass.specialization;
            d.sceneVertexInput = false;
            d.vertexBindings = {{0, sizeof(HostVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
            d.vertexAttributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
                                  {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 12}};
            p.pipelines[twoSided] = eng::vk::createGraphicsPipeline(m_device, d, pass.name + ".host");
        }
        m_passes.push_back(std::move(p));
    }

    void recordDraws(VkCommandBuffer cmd, const agaa::RasterPass& pass,
                     const agaa::PushModuleSet& push) const override {
        if (pass.output == agaa::RasterOutput::ShadowDepth) ++shadowMapsDrawn;
        const Pass* p = find(pass);
        if (!p) throw std::logic_error(pass.name + ": not prepared");
        push(cmd, p->layout.layout);
        VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &m_vertices.buffer, &offset);
        vkCmdBindIndexBuffer(cmd, m_indices.buffer, 0, VK_INDEX_TYPE_UINT16);
        for (const HostDraw& d : m_mesh.draws) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p->pipelines[d.twoSided ? 1 : 0]);
            const DrawConstants constants{d.material, d.firstIndex / 3};
            vkCmdPushConstants(cmd, p->layout.layout, VK_SHADER_STAGE_ALL, 0, sizeof constants, &constants);
            vkCmdDrawIndexed(cmd, d.indexCount, pass.layers, d.firstIndex, d.vertexOffset, 0);
        }
    }

    mutable int shadowMapsDrawn = 0;

  private:
    // What the host's shaders push (shaders/host_material.glsl): the material and the draw's first
    // triangle, so that a triangle's number is the same in every pass.
    struct DrawConstants {
        HostMaterial material;
        uint32_t firstTriangle;
    };

    // This host's builds (programs.cmake), by the pass's output and build, as
    // agaa::RasterPass::defines and sampleRateShading ask.
    std::span<const uint32_t> fragmentCode(const agaa::RasterPass& pass) const {
        using agaa::RasterOutput;
        const std::string perSample = pass.sampleRateShading ? "_sample_rate" : "";
        switch (pass.output) {
        case RasterOutput::SampleGBuffer:
            return program("host_gbuffer" + perSample + ".frag", pass);
        case RasterOutput::SampleGBufferPrimitive:
            return program("host_gbuffer_primitive" + perSample + ".frag", pass);
        case RasterOutput::SurfaceVisibility:
            return program("host_surface_visibility" + perSample + ".frag", pass);
        case RasterOutput::SurfaceFill:
            return program("host_surface_fill" + perSample + ".frag", pass);
        case RasterOutput::ShadowDepth:
            return {}; // opaque casters: depth only
        case RasterOutput::AggregateVisibility:
            return program("host_visibility.frag", pass);
        case RasterOutput::AggregateAccumulation:
            // One build: no emissive, 32-bit atomics, no subgroup reduction.
            if (pass.defines.empty()) return program("host_accumulation.frag", pass);
            break;
        }
        throw std::invalid_argument(std::string("this host has no build of ") +
                                    agaa::rasterOutputName(pass.output) + " with " + pass.defines.front());
    }
    std::span<const uint32_t> program(const std::string& name, const agaa::RasterPass& pass) const {
        const auto found = m_programs.find(name);
        if (found == m_programs.end())
            throw std::invalid_argument(pass.name + ": this host has no program " + name + " (" +
                                        agaa::rasterOutputName(pass.output) + ")");
        return found->second;
    }

    struct Pass {
        agaa::RasterPass pass;
        eng::vk::PipelineLayout layout;
        std::array<VkPipeline, 2> pipelines{}; // [two-sided]
    };
    const Pass* find(const agaa::RasterPass& pass) const {
        for (const Pass& p : m_passes)
            if (p.pass == pass) return &p;
        return nullptr;
    }

    eng::vk::Device& m_device;
    HostMesh m_mesh;
    HostPrograms m_programs;
    eng::vk::Buffer m_vertices, m_indices;
    std::vector<Pass> m_passes;
};

} // namespace host_engine
