#pragma once
// The render graph: passes declare in a setup callback which resources they read and write, and
// record commands in an execute callback that touches nothing else (Filament's split).
// compile() is CPU-only: it culls, orders and bakes every barrier. execute() is the only code in
// the project that records barriers (Granite's single owner of synchronisation).

#include "engine/graph/compiled.h"
#include "engine/graph/recorder.h"
#include "engine/graph/render_pass.h"
#include "engine/graph/resources.h"
#include "engine/graph/use.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace eng::rg {

class Graph;

// Handed to a pass's setup callback; valid only during that call.
class Builder {
  public:
    Texture create(std::string name, const TextureDesc& desc);
    Buffer create(std::string name, const BufferDesc& desc);
    // Reads return the same handle; the use must not write.
    Texture read(Texture texture, Use use);
    Buffer read(Buffer buffer, Use use);
    // Writes return a new version; later readers must use it. A read-modify-write use
    // (readsPrevious()) also keeps the previous producer alive.
    Texture write(Texture texture, Use use);
    Buffer write(Buffer buffer, Use use);
    // The pass depends on the previous contents and replaces them, e.g. loadOp LOAD, atomics,
    // DepthStencilRead.
    Texture readWrite(Texture texture, Use use);
    Buffer readWrite(Buffer buffer, Use use);
    // Attachments of a graphics pass's render pass, which execute() begins before the pass's
    // callback and ends after it. color() declares ColorAttachment; depthStencil() one of
    // DepthStencilWrite, DepthStencilRead (EQUAL test, stencil written) or DepthReadOnly. A LOAD
    // (or a use that reads the previous contents) keeps the previous producer alive; read-only
    // depth returns the same handle. All attachments of a pass share one width, height and layer
    // count: the render area.
    Texture color(Texture texture, const Attachment& attachment = {});
    Texture depthStencil(Texture texture, Use use, const Attachment& attachment = {});
    // The pass has effects the graph cannot see (host readback, debug output): never culled.
    void sideEffect();

  private:
    friend class Graph;
    Builder(Graph& graph, uint32_t pass) : m_graph(graph), m_pass(pass) {}
    Graph& m_graph;
    uint32_t m_pass;
};

// Handed to a pass's execute callback. Only resources the pass declared can be resolved, so an
// undeclared access (which would have no barrier) fails loudly instead of racing.
class Context {
  public:
    const PhysicalTexture& texture(Texture texture) const;
    const PhysicalBuffer& buffer(Buffer buffer) const;
    VkCommandBuffer cmd() const { return m_cmd; }
    const std::string& passName() const;
    // The layout the graph put a declared texture in for this pass: for copy commands and
    // descriptors that must name it.
    VkImageLayout layout(Texture texture) const;

  private:
    friend class Graph;
    Context(const Graph& graph, uint32_t pass, VkCommandBuffer cmd)
        : m_graph(graph), m_pass(pass), m_cmd(cmd) {}
    const Graph& m_graph;
    uint32_t m_pass;
    VkCommandBuffer m_cmd;
};

// How an imported resource was last used before the graph, for callers that keep it per frame.
struct ImportedState {
    Use lastUse;
};

namespace detail {
struct PassCallback {
    virtual ~PassCallback() = default;
    virtual void run(const Context& context) const = 0;
};

// Heap-allocated so that the Data reference returned by addPass() stays valid as passes are added.
template <class Data> struct PassStorage final : PassCallback {
    explicit PassStorage(std::function<void(const Context&, const Data&)> fn) : execute(std::move(fn)) {}
    void run(const Context& context) const override {
        if (execute) execute(context, data);
    }
    Data data{};
    std::function<void(const Context&, const Data&)> execute;
};
} // namespace detail

class Graph {
  public:
    struct ExecuteInfo {
        VkCommandBuffer cmd = VK_NULL_HANDLE;
        Allocator* allocator = nullptr;
        // Timestamps before/after executed pass i at firstQuery + 2i and + 2i + 1; the caller
        // resets the queries (timestampCount() of them).
        VkQueryPool queryPool = VK_NULL_HANDLE;
        uint32_t firstQuery = 0;
        PFN_vkCmdBeginDebugUtilsLabelEXT beginLabel = nullptr;
        PFN_vkCmdEndDebugUtilsLabelEXT endLabel = nullptr;
        CommandRecorder* recorder = nullptr; // barriers and timestamps; nullptr: vulkanRecorder()
    };

    Graph();
    ~Graph();
    Graph(const Graph&) = delete;
    Graph& operator=(const Graph&) = delete;
    Graph(Graph&&) noexcept;
    Graph& operator=(Graph&&) noexcept;

    // Imported resources outlive the graph. initial: the use before the graph (nullopt: contents
    // undefined, layout UNDEFINED, prior accesses unknown). final: the state to leave it in
    // (nullopt: its last use). An imported resource is an output: its writers are never culled.
    Texture importTexture(std::string name, const PhysicalTexture& texture, std::optional<Use> initial,
                          std::optional<Use> final);
    Buffer importBuffer(std::string name, const PhysicalBuffer& buffer, std::optional<Use> initial,
                        std::optional<Use> final);
    // Keeps the pass that produced this version (and everything it depends on) alive.
    void markOutput(Texture texture);
    void markOutput(Buffer buffer);

    // setup runs immediately; misuse inside it throws std::logic_error from here, naming the pass.
    template <class Data>
    const Data& addPass(std::string name, PassKind kind, std::function<void(Builder&, Data&)> setup,
                        std::function<void(const Context&, const Data&)> execute);
    template <class Data>
    const Data& addGraphics(std::string name, std::function<void(Builder&, Data&)> setup,
                            std::function<void(const Context&, const Data&)> execute) {
        return addPass<Data>(std::move(name), PassKind::Graphics, std::move(setup), std::move(execute));
    }
    template <class Data>
    const Data& addCompute(std::string name, std::function<void(Builder&, Data&)> setup,
                           std::function<void(const Context&, const Data&)> execute) {
        return addPass<Data>(std::move(name), PassKind::Compute, std::move(setup), std::move(execute));
    }

    // CPU only. Throws std::logic_error on misuse, or when transients from a previous compile are
    // still realised (their usage flags could change).
    void compile();
    bool isCompiled() const { return m_isCompiled; }
    const CompiledGraph& compiled() const;

    // Acquires every transient an executed pass touches (once; later calls reuse them), all in one
    // Allocator::acquireTransients() call with their lifetimes, so the allocator may alias them.
    // execute() calls it; exposed so allocation can be checked without recording commands.
    void realiseTransients(Allocator& allocator);
    void execute(const ExecuteInfo& info);
    // Returns transients to the allocator they came from. The caller waits for the GPU first.
    void releaseTransients();

    std::vector<std::string> executedPassNames() const; // execution order == timestamp order
    std::vector<std::string> culledPassNames() const;
    uint32_t timestampCount() const; // queries execute() writes when given a pool

    std::string dumpDot() const;
    std::string dumpJson() const;

    // Introspection for tests, dumps and tools.
    uint32_t passCount() const { return static_cast<uint32_t>(m_passes.size()); }
    uint32_t resourceCount() const { return static_cast<uint32_t>(m_resources.size()); }
    const std::string& passName(uint32_t pass) const;
    const std::string& resourceName(uint32_t resource) const;
    uint32_t resourceIndex(Texture texture) const;
    uint32_t resourceIndex(Buffer buffer) const;

  private:
    friend class Builder;
    friend class Context;

    enum class Mode { Read, Write, ReadWrite };

    struct Resource {
        std::string name;
        bool isImage = false;
        bool imported = false;
        TextureDesc textureDesc;
        BufferDesc bufferDesc;
        std::optional<Use> initial, final; // imported only
        uint32_t latest = kInvalidId;      // newest version id
        uint32_t versionCount = 0;
        PhysicalTexture texture; // imported, or realised transient
        PhysicalBuffer buffer;
        bool realised = false; // transient acquired from m_allocator
        // Accesses of the other transients placed over the same memory: the first barrier of
        // this one also waits on them (it starts from UNDEFINED, but the bytes were in use).
        VkPipelineStageFlags2 aliasStage = VK_PIPELINE_STAGE_2_NONE;
        VkAccessFlags2 aliasAccess = VK_ACCESS_2_NONE;
    };

    struct Version {
        uint32_t resource = kInvalidId;
        uint32_t version = 0;
        uint32_t writer = kInvalidId; // pass that produced it; none for imports and fresh creates
        bool output = false;
    };

    // Everything one pass does to one resource, merged: one barrier per resource per pass.
    struct Access {
        uint32_t resource = kInvalidId;
        uint32_t readVersion = kInvalidId;  // version whose contents the pass depends on
        uint32_t writeVersion = kInvalidId; // version the pass produces
        std::vector<Use> uses;
        VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_NONE;
        VkAccessFlags2 access = VK_ACCESS_2_NONE;
        VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
        bool writes = false;
    };

    struct Pass {
        std::string name;
        PassKind kind = PassKind::Graphics;
        bool sideEffect = false;
        std::vector<Access> accesses;
        RenderTargets targets; // declared attachments; empty: no render pass
        std::unique_ptr<detail::PassCallback> callback;
    };

    uint32_t beginPass(std::string name, PassKind kind, std::unique_ptr<detail::PassCallback> callback);
    void failSetup(uint32_t pass, const std::string& what);
    uint32_t createResource(std::string name, bool isImage, const TextureDesc* textureDesc,
                            const BufferDesc* bufferDesc);
    uint32_t declare(uint32_t pass, uint32_t handle, bool isImage, Use use, Mode mode);
    uint32_t declareAttachment(uint32_t pass, uint32_t handle, Use use, const Attachment& attachment);
    void recordPass(CommandRecorder& recorder, VkCommandBuffer cmd, uint32_t pass) const;
    const Version& checkHandle(uint32_t handle, bool isImage, const std::string& where) const;
    void invalidate();
    std::vector<bool> cullPasses() const;
    void computeLifetimes(CompiledGraph& out) const;
    void computeBarriers(CompiledGraph& out) const;
    const Access* findAccess(uint32_t pass, uint32_t resource) const;
    void recordBarriers(CommandRecorder& recorder, VkCommandBuffer cmd,
                        const std::vector<Barrier>& barriers) const;
    void computeAliasWaits(const std::vector<uint32_t>& resources,
                           const std::vector<TransientAllocation>& allocations);
    std::vector<Barrier> barriersWithAliasing(const CompiledPass& pass) const;

    std::vector<Pass> m_passes;
    std::vector<Resource> m_resources;
    std::vector<Version> m_versions;
    CompiledGraph m_compiled;
    bool m_isCompiled = false;
    std::string m_setupError; // a setup threw: the graph is incomplete and must not compile
    Allocator* m_allocator = nullptr;
};

template <class Data>
const Data& Graph::addPass(std::string name, PassKind kind, std::function<void(Builder&, Data&)> setup,
                           std::function<void(const Context&, const Data&)> execute) {
    auto storage = std::make_unique<detail::PassStorage<Data>>(std::move(execute));
    Data& data = storage->data;
    const uint32_t pass = beginPass(std::move(name), kind, std::move(storage));
    Builder builder(*this, pass);
    try {
        if (setup) setup(builder, data);
    } catch (const std::exception& error) {
        failSetup(pass, error.what());
        throw;
    } catch (...) {
        failSetup(pass, "a non-standard exception");
        throw;
    }
    return data;
}

} // namespace eng::rg
