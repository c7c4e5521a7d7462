#pragma once
// Shader modules, pipeline layouts (set 0 is always a push-descriptor set, so
// passes bind per-dispatch resources without pools), compute and dynamic-
// rendering graphics pipelines. Specialisation constants pick shader variants.

#include "engine/vk/device.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace eng::vk {

struct Binding {
    uint32_t binding = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    VkShaderStageFlags stages = VK_SHADER_STAGE_ALL;
    uint32_t count = 1;
    bool operator==(const Binding&) const = default;
};

struct LayoutDesc {
    std::vector<Binding> pushBindings;            // set 0, push descriptors
    std::vector<VkDescriptorSetLayout> extraSets; // sets 1.. (owned by the caller)
    uint32_t pushConstantBytes = 0;               // one range, all stages
};

struct PipelineLayout {
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkDescriptorSetLayout pushSet = VK_NULL_HANDLE;
};

PipelineLayout createPipelineLayout(const Device&, const LayoutDesc&, const std::string& name);
void destroyPipelineLayout(const Device&, PipelineLayout&);

VkDescriptorSetLayout createSetLayout(const Device&, std::span<const Binding>, const std::string& name);

// Specialisation constants, all 32-bit: values for ids 0..n-1 in order, then (id, value) pairs
// for ids kept apart from the passes' own (effects shared by every lighting pass).
struct Specialization {
    std::vector<uint32_t> values;
    std::vector<std::pair<uint32_t, uint32_t>> byId;
    bool operator==(const Specialization&) const = default;
};

VkPipeline createComputePipeline(const Device&, std::span<const uint32_t> spirv, VkPipelineLayout,
                                 const Specialization&, const std::string& name);

struct GraphicsPipelineDesc {
    std::span<const uint32_t> vertex;
    std::span<const uint32_t> fragment; // empty: depth-only
    VkPipelineLayout layout = VK_NULL_HANDLE;
    Specialization specialization; // shared by both stages
    std::vector<VkFormat> colorFormats;
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    bool sceneVertexInput = true; // eng::scene::Vertex at binding 0
    // Without sceneVertexInput: a host's own vertex layout (none: the vertex shader makes its own).
    std::vector<VkVertexInputBindingDescription> vertexBindings;
    std::vector<VkVertexInputAttributeDescription> vertexAttributes;
    VkCullModeFlags cullMode = VK_CULL_MODE_BACK_BIT;
    VkFrontFace frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    bool depthTest = true;
    bool depthWrite = true;
    VkCompareOp depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL; // reversed Z
    bool stencilTest = false;
    VkStencilOpState stencil{};
    bool alphaToCoverage = false;
    bool sampleShading = false;
    bool additiveBlend = false;
    uint32_t viewMask = 0;
};

VkPipeline createGraphicsPipeline(const Device&, const GraphicsPipelineDesc&, const std::string& name);

} // namespace eng::vk
