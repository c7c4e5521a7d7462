#pragma once
// A scene's device copy, shared by every technique: world-space vertices and
// indices, the material table, decoded textures with CPU-built mip chains, and
// descriptor set 1 (sampler2D textures[kMaxSceneTextures]) that every material-
// evaluating pass binds. Uploads run through a render graph, which owns the
// layout transitions like everywhere else.

#include "engine/scene/scene.h"
#include "engine/vk/device.h"
#include "engine/vk/resources.h"

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
    // buffers and the texture set (set 1 of `layout`), and per draw its pipeline
    // (pipelinePerDraw[i]) and its material index (push constant, 4 bytes at offset 0), with
    // `instances` instances (one per emulation layer or shadow-map layer).
    void recordDraws(VkCommandBuffer cmd, VkPipelineLayout layout,
                     std::span<const VkPipeline> pipelinePerDraw, uint32_t instances) const;
    const vk::Buffer& materials() const { return m_materials; }
    VkDescriptorSetLayout textureSetLayout() const { return m_textureSetLayout; }
    VkDescriptorSet textureSet() const { return m_textureSet; }
    // Bytes of device memory the scene occupies (not counted as any technique's storage).
    VkDeviceSize bytes() const;

  private:
    void release(); // destroys whatever exists (the destructor, and a constructor that throws)
    void uploadTextures();

    vk::Device& m_device;
    const scene::Scene& m_scene;
    vk::Buffer m_vertices, m_indices, m_materials;
    std::vector<vk::Image> m_textures; // scene textures, then one 1x1 white fallback
    VkSampler m_sampler = VK_NULL_HANDLE;
    VkDescriptorSetLayout m_textureSetLayout = VK_NULL_HANDLE;
    VkDescriptorPool m_pool = VK_NULL_HANDLE;
    VkDescriptorSet m_textureSet = VK_NULL_HANDLE;
};

} // namespace eng::frame
