// execute(): realises transients and records, per pass, its baked barriers, a debug label,
// timestamps and the pass's own commands. The only place in the project that records barriers.

#include "engine/graph/graph.h"

#include <stdexcept>

namespace eng::rg {
namespace {

// Label colours by pass kind, so captures separate graphics, compute and copies at a glance.
void labelColor(PassKind kind, float (&color)[4]) {
    const float graphics[4] = {0.25f, 0.55f, 0.95f, 1.0f};
    const float compute[4] = {0.95f, 0.6f, 0.2f, 1.0f};
    const float transfer[4] = {0.6f, 0.6f, 0.6f, 1.0f};
    const float* chosen = kind == PassKind::Graphics  ? graphics
                          : kind == PassKind::Compute ? compute
                                                      : transfer;
    for (int i = 0; i < 4; ++i)
        color[i] = chosen[i];
}

class VulkanRecorder final : public CommandRecorder {
  public:
    void pipelineBarrier(VkCommandBuffer cmd, const VkDependencyInfo& dependency) override {
        vkCmdPipelineBarrier2(cmd, &dependency);
    }
    void writeTimestamp(VkCommandBuffer cmd, VkPipelineStageFlags2 stage, VkQueryPool pool,
                        uint32_t query) override {
        vkCmdWriteTimestamp2(cmd, stage, pool, query);
    }
    void beginRendering(VkCommandBuffer cmd, const VkRenderingInfo& rendering) override {
        vkCmdBeginRendering(cmd, &rendering);
    }
    void setViewport(VkCommandBuffer cmd, const VkViewport& viewport, const VkRect2D& scissor) override {
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
    }
    void endRendering(VkCommandBuffer cmd) override { vkCmdEndRendering(cmd); }
};

} // namespace

CommandRecorder& vulkanRecorder() {
    static VulkanRecorder recorder;
    return recorder;
}

const PhysicalTexture& Context::texture(Texture texture) const {
    const uint32_t resource = m_graph.checkHandle(texture.id, true, "pass '" + passName() + "'").resource;
    if (!m_graph.findAccess(m_pass, resource))
        throw std::logic_error("render graph: pass '" + passName() + "' resolves texture '" +
                               m_graph.m_resources[resource].name + "' that its setup never declared");
    return m_graph.m_resources[resource].texture;
}

const PhysicalBuffer& Context::buffer(Buffer buffer) const {
    const uint32_t resource = m_graph.checkHandle(buffer.id, false, "pass '" + passName() + "'").resource;
    if (!m_graph.findAccess(m_pass, resource))
        throw std::logic_error("render graph: pass '" + passName() + "' resolves buffer '" +
                               m_graph.m_resources[resource].name + "' that its setup never declared");
    return m_graph.m_resources[resource].buffer;
}

VkImageLayout Context::layout(Texture texture) const {
    const uint32_t resource = m_graph.checkHandle(texture.id, true, "pass '" + passName() + "'").resource;
    const Graph::Access* access = m_graph.findAccess(m_pass, resource);
    if (!access)
        throw std::logic_error("render graph: pass '" + passName() + "' asks the layout of texture '" +
                               m_graph.m_resources[resource].name + "' that its setup never declared");
    return access->layout;
}

const std::string& Context::passName() const {
    return m_graph.m_passes[m_pass].name;
}

std::vector<TransientAllocation> Allocator::acquireTransients(const std::vector<TransientRequest>& requests) {
    std::vector<TransientAllocation> allocations(requests.size());
    for (size_t i = 0; i < requests.size(); ++i) {
        const TransientRequest& request = requests[i];
        if (request.isImage)
            allocations[i].texture = acquireTexture(request.name, request.textureDesc, request.imageUsage);
        else
            allocations[i].buffer = acquireBuffer(request.name, request.bufferDesc, request.bufferUsage);
    }
    return allocations;
}

void Graph::realiseTransients(Allocator& allocator) {
    const CompiledGraph& graph = compiled();
    if (m_allocator && m_allocator != &allocator)
        throw std::logic_error("render graph: transients are realised by another allocator; call "
                               "releaseTransients() before switching");
    std::vector<uint32_t> position(m_passes.size(), kInvalidId);
    for (uint32_t i = 0; i < graph.order.size(); ++i)
        position[graph.order[i].pass] = i;
    std::vector<uint32_t> resources;
    std::vector<TransientRequest> requests;
    for (uint32_t r = 0; r < m_resources.size(); ++r) {
        const Resource& resource = m_resources[r];
        if (resource.imported || resource.realised || graph.firstUse[r] == kInvalidId) continue;
        TransientRequest request;
        request.name = resource.name;
        request.isImage = resource.isImage;
        request.textureDesc = resource.textureDesc;
        request.bufferDesc = resource.bufferDesc;
        request.imageUsage = graph.imageUsage[r];
        request.bufferUsage = graph.bufferUsage[r];
        request.firstUse = position[graph.firstUse[r]];
        request.lastUse = position[graph.lastUse[r]];
        resources.push_back(r);
        requests.push_back(std::move(request));
    }
    if (requests.empty()) return;
    std::vector<TransientAllocation> allocations = allocator.acquireTransients(requests);
    if (allocations.size() != requests.size())
        throw std::logic_error("render graph: the allocator answered " + std::to_string(allocations.size()) +
                               " allocations for " + std::to_string(requests.size()) + " transients");
    for (size_t i = 0; i < resources.size(); ++i) {
        Resource& resource = m_resources[resources[i]];
        resource.texture = allocations[i].texture;
        resource.buffer = allocations[i].buffer;
        resource.realised = true;
    }
    m_allocator = &allocator;
    computeAliasWaits(resources, allocations);
}

void Graph::computeAliasWaits(const std::vector<uint32_t>& resources,
                              const std::vector<TransientAllocation>& allocations) {
    // Every access of a resource in this graph, as the stages and writes a sharer must wait on.
    // Sharers both before and after in the frame count: a re-execution (the next frame, a
    // benchmark loop) runs the later one's accesses before this one's first use again.
    const auto accessesOf = [&](uint32_t resource, VkPipelineStageFlags2& stage, VkAccessFlags2& access) {
        for (const CompiledPass& compiledPass : m_compiled.order)
            if (const Access* a = findAccess(compiledPass.pass, resource)) {
                stage |= a->stage;
                access |= a->access & kWriteAccessMask;
            }
    };
    for (size_t i = 0; i < resources.size(); ++i) {
        Resource& resource = m_resources[resources[i]];
        resource.aliasStage = VK_PIPELINE_STAGE_2_NONE;
        resource.aliasAccess = VK_ACCESS_2_NONE;
        const TransientAllocation& mine = allocations[i];
        if (mine.memory == kInvalidId) continue;
        for (size_t j = 0; j < resources.size(); ++j) {
            const TransientAllocation& other = allocations[j];
            if (i == j || other.memory != mine.memory) continue;
            if (!(mine.offset < other.offset + other.size && other.offset < mine.offset + mine.size))
                continue;
            accessesOf(resources[j], resource.aliasStage, resource.aliasAccess);
        }
    }
}

std::vector<Barrier> Graph::barriersWithAliasing(const CompiledPass& pass) const {
    std::vector<Barrier> barriers = pass.barriers;
    for (const Access& access : m_passes[pass.pass].accesses) {
        const Resource& resource = m_resources[access.resource];
        if (resource.aliasStage == VK_PIPELINE_STAGE_2_NONE ||
            m_compiled.firstUse[access.resource] != pass.pass)
            continue;
        Barrier* first = nullptr;
        for (Barrier& barrier : barriers)
            if (barrier.resource == access.resource) first = &barrier;
        if (!first) {
            // compile() saw no hazard on this resource alone; the memory it shares has one.
            Barrier barrier;
            barrier.resource = access.resource;
            barrier.isImage = resource.isImage;
            barrier.dstStage = access.stage;
            barrier.dstAccess = access.access;
            if (resource.isImage) {
                barrier.newLayout = access.layout;
                barrier.aspect = imageAspect(resource.textureDesc.format);
            }
            barriers.push_back(barrier);
            first = &barriers.back();
        }
        first->srcStage |= resource.aliasStage;
        first->srcAccess |= resource.aliasAccess;
        if (first->isImage) first->oldLayout = VK_IMAGE_LAYOUT_UNDEFINED; // the contents belong to another
    }
    return barriers;
}

void Graph::releaseTransients() {
    for (Resource& resource : m_resources) {
        if (!resource.realised) continue;
        if (resource.isImage) {
            m_allocator->release(resource.texture);
            resource.texture = PhysicalTexture{};
        } else {
            m_allocator->release(resource.buffer);
            resource.buffer = PhysicalBuffer{};
        }
        resource.realised = false;
        resource.aliasStage = VK_PIPELINE_STAGE_2_NONE;
        resource.aliasAccess = VK_ACCESS_2_NONE;
    }
    m_allocator = nullptr;
}

void Graph::recordBarriers(CommandRecorder& recorder, VkCommandBuffer cmd,
                           const std::vector<Barrier>& barriers) const {
    if (barriers.empty()) return;
    std::vector<VkImageMemoryBarrier2> images;
    std::vector<VkBufferMemoryBarrier2> buffers;
    for (const Barrier& barrier : barriers) {
        const Resource& resource = m_resources[barrier.resource];
        if (barrier.isImage) {
            VkImageMemoryBarrier2 image{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
            image.srcStageMask = barrier.srcStage;
            image.srcAccessMask = barrier.srcAccess;
            image.dstStageMask = barrier.dstStage;
            image.dstAccessMask = barrier.dstAccess;
            image.oldLayout = barrier.oldLayout;
            image.newLayout = barrier.newLayout;
            // One queue family on the targets we support: never an ownership transfer.
            image.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            image.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            image.image = resource.texture.image;
            image.subresourceRange = {barrier.aspect, 0, VK_REMAINING_MIP_LEVELS, 0,
                                      VK_REMAINING_ARRAY_LAYERS};
            images.push_back(image);
        } else {
            VkBufferMemoryBarrier2 buffer{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
            buffer.srcStageMask = barrier.srcStage;
            buffer.srcAccessMask = barrier.srcAccess;
            buffer.dstStageMask = barrier.dstStage;
            buffer.dstAccessMask = barrier.dstAccess;
            buffer.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            buffer.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            buffer.buffer = resource.buffer.buffer;
            buffer.offset = 0;
            buffer.size = VK_WHOLE_SIZE;
            buffers.push_back(buffer);
        }
    }
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.bufferMemoryBarrierCount = static_cast<uint32_t>(buffers.size());
    dependency.pBufferMemoryBarriers = buffers.data();
    dependency.imageMemoryBarrierCount = static_cast<uint32_t>(images.size());
    dependency.pImageMemoryBarriers = images.data();
    recorder.pipelineBarrier(cmd, dependency);
}

void Graph::recordPass(CommandRecorder& recorder, VkCommandBuffer cmd, uint32_t passIndex) const {
    const Pass& pass = m_passes[passIndex];
    const RenderTargets& targets = pass.targets;
    if (targets.empty()) {
        if (pass.callback) pass.callback->run(Context(*this, passIndex, cmd));
        return;
    }
    const auto view = [&](uint32_t resource) {
        const PhysicalTexture& texture = m_resources[resource].texture;
        return RenderingView{texture.view, findAccess(passIndex, resource)->layout, texture.desc.format};
    };
    std::vector<RenderingView> colors;
    for (const RenderTargets::Target& target : targets.colors)
        colors.push_back(view(target.resource));
    const RenderingView depth =
        targets.depth.resource != kInvalidId ? view(targets.depth.resource) : RenderingView{};
    Rendering rendering;
    buildRendering(targets, colors, depth, rendering);
    recorder.beginRendering(cmd, rendering.info);
    recorder.setViewport(cmd, rendering.viewport, rendering.scissor);
    if (pass.callback) pass.callback->run(Context(*this, passIndex, cmd));
    recorder.endRendering(cmd);
}

void Graph::execute(const ExecuteInfo& info) {
    const CompiledGraph& graph = compiled();
    if (info.cmd == VK_NULL_HANDLE)
        throw std::logic_error("render graph: execute() without a command buffer");
    bool needsTransients = false;
    for (uint32_t r = 0; r < m_resources.size(); ++r)
        needsTransients = needsTransients || (!m_resources[r].imported && graph.firstUse[r] != kInvalidId);
    if (needsTransients) {
        if (!info.allocator)
            throw std::logic_error("render graph: execute() needs an allocator for the graph's transients");
        realiseTransients(*info.allocator);
    }
    const bool labels = info.beginLabel && info.endLabel;
    CommandRecorder& recorder = info.recorder ? *info.recorder : vulkanRecorder();

    for (uint32_t i = 0; i < graph.order.size(); ++i) {
        const CompiledPass& compiledPass = graph.order[i];
        const Pass& pass = m_passes[compiledPass.pass];
        if (labels) {
            VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
            label.pLabelName = pass.name.c_str();
            labelColor(pass.kind, label.color);
            info.beginLabel(info.cmd, &label);
        }
        recordBarriers(recorder, info.cmd, barriersWithAliasing(compiledPass));
        // ALL_COMMANDS on both ends: the first stamp waits for everything before the pass, the
        // second for the pass itself, so per-pass times add up to the frame without overlap.
        if (info.queryPool != VK_NULL_HANDLE)
            recorder.writeTimestamp(info.cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, info.queryPool,
                                    info.firstQuery + 2 * i);
        recordPass(recorder, info.cmd, compiledPass.pass);
        if (info.queryPool != VK_NULL_HANDLE)
            recorder.writeTimestamp(info.cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, info.queryPool,
                                    info.firstQuery + 2 * i + 1);
        if (labels) info.endLabel(info.cmd);
    }

    if (!graph.finalBarriers.empty()) {
        if (labels) {
            VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
            label.pLabelName = "rg.finalState";
            labelColor(PassKind::Transfer, label.color);
            info.beginLabel(info.cmd, &label);
        }
        recordBarriers(recorder, info.cmd, graph.finalBarriers);
        if (labels) info.endLabel(info.cmd);
    }
}

} // namespace eng::rg
