#include "engine/vk/pipeline.h"

#include "engine/vk/check.h"

namespace eng::vk {
namespace {

VkShaderModule createModule(const Device& device, std::span<const uint32_t> spirv, const std::string& name) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = spirv.size_bytes();
    info.pCode = spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    VK_CHECK(vkCreateShaderModule(device.device(), &info, nullptr, &module));
    device.setName(VK_OBJECT_TYPE_SHADER_MODULE, module, name);
    return module;
}

struct SpecializationData {
    std::vector<VkSpecializationMapEntry> entries;
    std::vector<uint32_t> data;
    VkSpecializationInfo info{};
};

SpecializationData makeSpecialization(const Specialization& spec) {
    SpecializationData d;
    d.data = spec.values;
    for (uint32_t i = 0; i < spec.values.size(); ++i)
        d.entries.push_back({i, i * 4u, 4u});
    for (const auto& [id, value] : spec.byId) {
        d.entries.push_back({id, uint32_t(d.data.size()) * 4u, 4u});
        d.data.push_back(value);
    }
    d.info.mapEntryCount = uint32_t(d.entries.size());
    d.info.pMapEntries = d.entries.data();
    d.info.dataSize = d.data.size() * 4;
    d.info.pData = d.data.data();
    return d;
}

} // namespace

VkDescriptorSetLayout createSetLayout(const Device& device, std::span<const Binding> bindings,
                                      const std::string& name) {
    std::vector<VkDescriptorSetLayoutBinding> b;
    for (const Binding& x : bindings)
        b.push_back({x.binding, x.type, x.count, x.stages, nullptr});
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = uint32_t(b.size());
    info.pBindings = b.data();
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    VK_CHECK(vkCreateDescriptorSetLayout(device.device(), &info, nullptr, &layout));
    device.setName(VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, layout, name);
    return layout;
}

PipelineLayout createPipelineLayout(const Device& device, const LayoutDesc& desc, const std::string& name) {
    PipelineLayout out;
    std::vector<VkDescriptorSetLayoutBinding> b;
    for (const Binding& x : desc.pushBindings)
        b.push_back({x.binding, x.type, x.count, x.stages, nullptr});
    VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setInfo.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
    setInfo.bindingCount = uint32_t(b.size());
    setInfo.pBindings = b.data();
    VK_CHECK(vkCreateDescriptorSetLayout(device.device(), &setInfo, nullptr, &out.pushSet));
    device.setName(VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, out.pushSet, name + ".set0");

    std::vector<VkDescriptorSetLayout> sets{out.pushSet};
    sets.insert(sets.end(), desc.extraSets.begin(), desc.extraSets.end());
    VkPushConstantRange range{VK_SHADER_STAGE_ALL, 0, desc.pushConstantBytes};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = uint32_t(sets.size());
    info.pSetLayouts = sets.data();
    info.pushConstantRangeCount = desc.pushConstantBytes ? 1 : 0;
    info.pPushConstantRanges = &range;
    VK_CHECK(vkCreatePipelineLayout(device.device(), &info, nullptr, &out.layout));
    device.setName(VK_OBJECT_TYPE_PIPELINE_LAYOUT, out.layout, name);
    return out;
}

void destroyPipelineLayout(const Device& device, PipelineLayout& layout) {
    if (layout.layout) vkDestroyPipelineLayout(device.device(), layout.layout, nullptr);
    if (layout.pushSet) vkDestroyDescriptorSetLayout(device.device(), layout.pushSet, nullptr);
    layout = PipelineLayout{};
}

VkPipeline createComputePipeline(const Device& device, std::span<const uint32_t> spirv,
                                 VkPipelineLayout layout, const Specialization& spec,
                                 const std::string& name) {
    VkShaderModule module = createModule(device, spirv, name);
    SpecializationData sd = makeSpecialization(spec);
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module;
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = sd.entries.empty() ? nullptr : &sd.info;
    info.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VK_CHECK(vkCreateComputePipelines(device.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    vkDestroyShaderModule(device.device(), module, nullptr);
    device.setName(VK_OBJECT_TYPE_PIPELINE, pipeline, name);
    return pipeline;
}

VkPipeline createGraphicsPipeline(const Device& device, const GraphicsPipelineDesc& d,
                                  const std::string& name) {
    SpecializationData sd = makeSpecialization(d.specialization);
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    std::vector<VkShaderModule> modules;
    auto addStage = [&](VkShaderStageFlagBits stage, std::span<const uint32_t> code, const char* suffix) {
        modules.push_back(createModule(device, code, name + suffix));
        VkPipelineShaderStageCreateInfo s{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        s.stage = stage;
        s.module = modules.back();
        s.pName = "main";
        s.pSpecializationInfo = sd.entries.empty() ? nullptr : &sd.info;
        stages.push_back(s);
    };
    addStage(VK_SHADER_STAGE_VERTEX_BIT, d.vertex, ".vert");
    if (!d.fragment.empty()) addStage(VK_SHADER_STAGE_FRAGMENT_BIT, d.fragment, ".frag");

    // eng::scene::Vertex: position vec3, normal vec3, tangent vec4, uv vec2 (48 bytes).
    VkVertexInputBindingDescription binding{0, 72, VK_VERTEX_INPUT_RATE_VERTEX}; // sizeof(eng::scene::Vertex)
    VkVertexInputAttributeDescription attributes[] = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},     {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 12},
        {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 24}, {3, 0, VK_FORMAT_R32G32_SFLOAT, 40},
        {4, 0, VK_FORMAT_R32G32_SFLOAT, 48},       {5, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 56},
    };
    VkPipelineVertexInputStateCreateInfo vertexInput{
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    if (d.sceneVertexInput) {
        vertexInput.vertexBindingDescriptionCount = 1;
        vertexInput.pVertexBindingDescriptions = &binding;
        vertexInput.vertexAttributeDescriptionCount = 6;
        vertexInput.pVertexAttributeDescriptions = attributes;
    } else {
        vertexInput.vertexBindingDescriptionCount = uint32_t(d.vertexBindings.size());
        vertexInput.pVertexBindingDescriptions = d.vertexBindings.data();
        vertexInput.vertexAttributeDescriptionCount = uint32_t(d.vertexAttributes.size());
        vertexInput.pVertexAttributeDescriptions = d.vertexAttributes.data();
    }
    VkPipelineInputAssemblyStateCreateInfo assembly{
        VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = d.cullMode;
    raster.frontFace = d.frontFace;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    ms.rasterizationSamples = d.samples;
    ms.sampleShadingEnable = d.sampleShading;
    ms.minSampleShading = 1.0f;
    ms.alphaToCoverageEnable = d.alphaToCoverage;
    VkPipelineDepthStencilStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    ds.depthTestEnable = d.depthTest;
    ds.depthWriteEnable = d.depthWrite;
    ds.depthCompareOp = d.depthCompare;
    ds.stencilTestEnable = d.stencilTest;
    ds.front = d.stencil;
    ds.back = d.stencil;
    std::vector<VkPipelineColorBlendAttachmentState> blends(d.colorFormats.size());
    for (auto& b : blends) {
        b.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                           VK_COLOR_COMPONENT_A_BIT;
        if (d.additiveBlend) {
            b.blendEnable = VK_TRUE;
            b.srcColorBlendFactor = b.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
            b.srcAlphaBlendFactor = b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
            b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
        }
    }
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = uint32_t(blends.size());
    blend.pAttachments = blends.data();
    VkDynamicState dynamics[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = 2;
    dynamic.pDynamicStates = dynamics;

    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.viewMask = d.viewMask;
    rendering.colorAttachmentCount = uint32_t(d.colorFormats.size());
    rendering.pColorAttachmentFormats = d.colorFormats.data();
    rendering.depthAttachmentFormat = d.depthFormat;
    bool stencilFormat =
        d.depthFormat == VK_FORMAT_D24_UNORM_S8_UINT || d.depthFormat == VK_FORMAT_D32_SFLOAT_S8_UINT;
    rendering.stencilAttachmentFormat = stencilFormat ? d.depthFormat : VK_FORMAT_UNDEFINED;

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.pNext = &rendering;
    info.stageCount = uint32_t(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &vertexInput;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &ms;
    info.pDepthStencilState = &ds;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
    info.layout = d.layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VK_CHECK(vkCreateGraphicsPipelines(device.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    for (VkShaderModule m : modules)
        vkDestroyShaderModule(device.device(), m, nullptr);
    device.setName(VK_OBJECT_TYPE_PIPELINE, pipeline, name);
    return pipeline;
}

} // namespace eng::vk
