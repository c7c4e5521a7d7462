#pragma once
// A scene's device copy, shared by every technique: world-space vertices and
// indices, the material table, decoded textures with CPU-built mip chains, and
// descriptor set 1 (the textures and the material table; shaders/glsl/common/
// scene_materials.glsl) that every pass drawing the scene binds. Uploads run through a render graph, which
// owns the layout transitions like everywhere else.

#include "engine/frame/gpu_environment.h"
#include "engine/scene/scene.h"
#include "engine/vk/device.h"
#include "engine/vk/resources.h"

#include <memory>
#include <span>
#include <vector>

namespace eng::frame {

class GpuScene {
  public:
    GpuScene(vk::Device& device, const scene::Scene& scene);
    ~GpuScene();
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    const scene::Scene& scene() const { return m_scene; }
    VkBuffer vertexBuffer() const { return m_vertices.buffer; }
    VkBuffer indexBuffer() const { return m_indices.buffer; }
    // Also bound as storage buffers (face normals from gl_PrimitiveID).
    const vk::Buffer& vertices() const { return m_vertices; }
    const vk::Buffer& indices() const { return m_indices; }
    bool hasEmissive() const; // any material emits light

    // Records every draw of the scene into a rendering pass: binds the vertex and index
    // buffers and the material set (set 1 of `layout`), and per draw its pipeline
    // (pipelinePerDraw[i]) and its material index (push constant, 4 bytes at offset 0), with
    // `instances` instances (one per emulation layer or shadow-map layer). With
    // `pushFirstTriangle` the push constant is 8 bytes: the material, then the draw's first
    // triangle (firstIndex / 3), so firstTriangle + gl_PrimitiveID numbers the scene's triangles.
    void recordDraws(VkCommandBuffer cmd, VkPipelineLayout layout,
                     std::span<const VkPipeline> pipelinePerDraw, uint32_t instances,
                     bool pushFirstTriangle = false) const;
    const vk::Buffer& materials() const { return m_materials; }
    VkDescriptorSetLayout materialSetLayout() const { return m_materialSetLayout; }
    VkDescriptorSet materialSet() const { return m_materialSet; }
    // The scene's environment, or the stand-in when it has none (engine/frame/gpu_environment.h).
    bool hasEnvironment() const { return !m_scene.environment.empty(); }
    const GpuEnvironment& environment() const { return *m_environment; }
    // Bytes of device memory the scene occupies (not counted as any technique's storage).
    VkDeviceSize bytes() const;

  private:
    void release(); // destroys whatever exists (the destructor, and a constructor that throws)
    void uploadTextures();

    vk::Device& m_device;
    const scene::Scene& m_scene;
    vk::Buffer m_vertices, m_indices, m_materials;
    std::unique_ptr<GpuEnvironment> m_environment;
    std::vector<vk::Image> m_textures; // scene textures, then one 1x1 white fallback
    VkSampler m_sampler = VK_NULL_HANDLE;
    VkDescriptorSetLayout m_materialSetLayout = VK_NULL_HANDLE;
    VkDescriptorPool m_pool = VK_NULL_HANDLE;
    VkDescriptorSet m_materialSet = VK_NULL_HANDLE;
};

} // namespace eng::frame
