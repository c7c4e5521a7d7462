// compile(): reference-count culling (Filament), declaration-order scheduling, resource
// lifetimes and usage flags, and sync2 barrier generation. CPU only: no Vulkan calls here.

#include "engine/graph/graph.h"

#include <stdexcept>
#include <utility>

namespace eng::rg {
namespace {

// What one pass (or an imported resource's final state) needs from a resource.
struct Request {
    VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    bool writes = false;
};

// Synchronisation state of one resource while walking the passes in execution order.
struct SyncState {
    // Stages a later access must wait on to observe the last write: the writer's stages, plus the
    // destination stages of any layout transition since (a transition is itself a write, ordered
    // only before its barrier's destination stages).
    VkPipelineStageFlags2 writeStages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 writeAccess = VK_ACCESS_2_NONE;
    bool writeAvailable = true; // a barrier already made the last write available
    VkPipelineStageFlags2 readStages = VK_PIPELINE_STAGE_2_NONE; // readers since the last write
    // (stages, accesses) that a barrier already made the last write visible to.
    std::vector<std::pair<VkPipelineStageFlags2, VkAccessFlags2>> visible;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
};

Request requestFor(Use use) {
    const UseInfo& info = useInfo(use);
    return Request{info.stage, info.access, info.layout, info.writes};
}

bool isVisible(const SyncState& state, const Request& request) {
    for (uint32_t bit = 0; bit < 64; ++bit) {
        const VkPipelineStageFlags2 stage = VkPipelineStageFlags2{1} << bit;
        if (!(request.stage & stage)) continue;
        VkAccessFlags2 visibleAccess = VK_ACCESS_2_NONE;
        for (const auto& [stages, access] : state.visible)
            if (stages & stage) visibleAccess |= access;
        if (request.access & ~visibleAccess) return false;
    }
    return true;
}

// Advances `state` past an access and returns the barrier that must precede it, if any.
std::optional<Barrier> synchronise(SyncState& state, const Request& request, bool isImage) {
    Barrier barrier;
    barrier.isImage = isImage;
    barrier.dstStage = request.stage;
    barrier.dstAccess = request.access;
    if (isImage) {
        barrier.oldLayout = state.layout;
        barrier.newLayout = request.layout;
    }
    const bool layoutChange = isImage && request.layout != state.layout;

    if (request.writes || layoutChange) {
        // Write-after-write and write-after-read (a layout transition counts as a write): wait for
        // the last write and every reader since. Readers need only an execution dependency, and
        // the last write needs making available only if no barrier has done so yet.
        barrier.srcStage = state.writeStages | state.readStages;
        barrier.srcAccess = state.writeAvailable ? VK_ACCESS_2_NONE : state.writeAccess;
        const bool needed = layoutChange || barrier.srcStage != VK_PIPELINE_STAGE_2_NONE;
        if (request.writes) {
            state.writeStages = request.stage;
            state.writeAccess = request.access & kWriteAccessMask;
            state.writeAvailable = false;
            state.readStages = VK_PIPELINE_STAGE_2_NONE;
            state.visible.clear();
        } else {
            state.writeStages |= request.stage;
            state.writeAvailable = true;
            state.readStages = request.stage;
            state.visible.assign(1, {request.stage, request.access});
        }
        if (isImage) state.layout = request.layout;
        return needed ? std::optional<Barrier>(barrier) : std::nullopt;
    }

    // Read in the current layout: needs the last write made visible to this stage and access,
    // unless an earlier barrier since that write already did.
    state.readStages |= request.stage;
    if (state.writeStages == VK_PIPELINE_STAGE_2_NONE || isVisible(state, request)) return std::nullopt;
    barrier.srcStage = state.writeStages;
    barrier.srcAccess = state.writeAccess;
    state.visible.emplace_back(request.stage, request.access);
    state.writeAvailable = true;
    return barrier;
}

SyncState importedState(const std::optional<Use>& initial, bool isImage) {
    SyncState state;
    if (!initial) {
        // Contents undefined and prior accesses unknown: wait for everything before the graph.
        state.writeStages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        state.writeAccess = VK_ACCESS_2_MEMORY_WRITE_BIT;
        state.writeAvailable = false;
        return state;
    }
    const UseInfo& info = useInfo(*initial);
    if (isImage) state.layout = info.layout;
    if (info.writes) {
        state.writeStages = info.stage;
        state.writeAccess = info.access & kWriteAccessMask;
        state.writeAvailable = false;
    } else {
        // The importer vouches that the last write was already made visible to this use.
        state.readStages = info.stage;
        state.visible.assign(1, {info.stage, info.access});
    }
    return state;
}

} // namespace

std::vector<bool> Graph::cullPasses() const {
    const size_t passCount = m_passes.size();
    std::vector<uint32_t> passRefs(passCount, 0);
    std::vector<uint32_t> versionRefs(m_versions.size(), 0);
    for (size_t p = 0; p < passCount; ++p) {
        const Pass& pass = m_passes[p];
        if (pass.sideEffect) ++passRefs[p];
        for (const Access& access : pass.accesses) {
            if (access.writeVersion != kInvalidId) ++passRefs[p];
            if (access.readVersion != kInvalidId) ++versionRefs[access.readVersion];
        }
    }
    for (size_t v = 0; v < m_versions.size(); ++v)
        if (m_versions[v].output || m_resources[m_versions[v].resource].imported) ++versionRefs[v];

    for (size_t v = 0; v < m_versions.size(); ++v)
        if (versionRefs[v] == 0 && m_versions[v].writer != kInvalidId) --passRefs[m_versions[v].writer];
    std::vector<uint32_t> unreferenced;
    for (size_t p = 0; p < passCount; ++p)
        if (passRefs[p] == 0) unreferenced.push_back(static_cast<uint32_t>(p));

    std::vector<bool> culled(passCount, false);
    while (!unreferenced.empty()) {
        const uint32_t p = unreferenced.back();
        unreferenced.pop_back();
        culled[p] = true;
        for (const Access& access : m_passes[p].accesses) {
            if (access.readVersion == kInvalidId || --versionRefs[access.readVersion] != 0) continue;
            const uint32_t writer = m_versions[access.readVersion].writer;
            if (writer != kInvalidId && --passRefs[writer] == 0) unreferenced.push_back(writer);
        }
    }
    return culled;
}

void Graph::computeLifetimes(CompiledGraph& out) const {
    const size_t count = m_resources.size();
    out.firstUse.assign(count, kInvalidId);
    out.lastUse.assign(count, kInvalidId);
    out.imageUsage.assign(count, 0);
    out.bufferUsage.assign(count, 0);
    for (const CompiledPass& compiledPass : out.order) {
        for (const Access& access : m_passes[compiledPass.pass].accesses) {
            const uint32_t r = access.resource;
            if (out.firstUse[r] == kInvalidId) out.firstUse[r] = compiledPass.pass;
            out.lastUse[r] = compiledPass.pass;
            for (Use use : access.uses) {
                if (m_resources[r].isImage)
                    out.imageUsage[r] |= useInfo(use).imageUsage;
                else
                    out.bufferUsage[r] |= useInfo(use).bufferUsage;
            }
        }
    }
}

void Graph::computeBarriers(CompiledGraph& out) const {
    const auto walk = [&](std::vector<SyncState>& states, bool record) {
        for (CompiledPass& compiledPass : out.order) {
            for (const Access& access : m_passes[compiledPass.pass].accesses) {
                const Resource& resource = m_resources[access.resource];
                const Request request{access.stage, access.access, access.layout, access.writes};
                std::optional<Barrier> barrier =
                    synchronise(states[access.resource], request, resource.isImage);
                if (!record || !barrier) continue;
                barrier->resource = access.resource;
                barrier->aspect = resource.isImage ? imageAspect(resource.textureDesc.format) : 0;
                compiledPass.barriers.push_back(*barrier);
            }
        }
    };

    // Transients start each execution from where the previous execution left them, with their
    // contents discarded (UNDEFINED). A pipeline barrier's first scope covers all earlier
    // submissions on the queue, so this also orders a re-execution of the same compiled graph
    // (another frame, or a benchmark loop in one command buffer) after the previous one's
    // accesses to the same objects.
    std::vector<SyncState> states(m_resources.size());
    walk(states, false);
    for (size_t r = 0; r < m_resources.size(); ++r) {
        if (m_resources[r].imported)
            states[r] = importedState(m_resources[r].initial, m_resources[r].isImage);
        else
            states[r].layout = VK_IMAGE_LAYOUT_UNDEFINED;
    }
    walk(states, true);

    for (size_t r = 0; r < m_resources.size(); ++r) {
        const Resource& resource = m_resources[r];
        if (!resource.imported || !resource.final) continue;
        std::optional<Barrier> barrier =
            synchronise(states[r], requestFor(*resource.final), resource.isImage);
        if (!barrier) continue;
        barrier->resource = static_cast<uint32_t>(r);
        barrier->aspect = resource.isImage ? imageAspect(resource.textureDesc.format) : 0;
        out.finalBarriers.push_back(*barrier);
    }
}

void Graph::compile() {
    if (!m_setupError.empty()) throw std::logic_error(m_setupError);
    if (m_isCompiled) return;
    for (const Resource& resource : m_resources)
        if (resource.realised)
            throw std::logic_error("render graph: compile() after the graph changed while transient " +
                                   std::string("'") + resource.name +
                                   "' is still realised; call releaseTransients() first");

    CompiledGraph out;
    const std::vector<bool> culled = cullPasses();
    for (uint32_t p = 0; p < m_passes.size(); ++p) {
        // Setup can only see handles of earlier passes, so declaration order is topological.
        if (culled[p])
            out.culled.push_back(p);
        else
            out.order.push_back(CompiledPass{p, {}});
    }
    computeLifetimes(out);
    computeBarriers(out);
    m_compiled = std::move(out);
    m_isCompiled = true;
}

const CompiledGraph& Graph::compiled() const {
    if (!m_isCompiled) throw std::logic_error("render graph: compiled() before compile()");
    return m_compiled;
}

std::vector<std::string> Graph::executedPassNames() const {
    std::vector<std::string> names;
    for (const CompiledPass& pass : compiled().order)
        names.push_back(m_passes[pass.pass].name);
    return names;
}

std::vector<std::string> Graph::culledPassNames() const {
    std::vector<std::string> names;
    for (uint32_t pass : compiled().culled)
        names.push_back(m_passes[pass].name);
    return names;
}

uint32_t Graph::timestampCount() const {
    return 2 * static_cast<uint32_t>(compiled().order.size());
}

} // namespace eng::rg
