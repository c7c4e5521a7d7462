// Building the graph: resources, versions and the accesses passes declare in setup.
// Misuse is refused here, while the offending pass is still known by name.

#include "engine/graph/graph.h"

#include <stdexcept>

namespace eng::rg {
namespace {

std::string quoted(const std::string& name) {
    return "'" + name + "'";
}

// Depth test plus sampling the same depth image in one pass is legal in the read-only depth
// layout; any other pair of different layouts would be a feedback loop.
std::optional<VkImageLayout> mergeLayouts(VkImageLayout a, VkImageLayout b) {
    if (a == b) return a;
    const auto isPair = [&](VkImageLayout x, VkImageLayout y) {
        return (a == x && b == y) || (a == y && b == x);
    };
    if (isPair(VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL))
        return VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
    return std::nullopt;
}

void checkDesc(const std::string& name, const TextureDesc& desc) {
    if (desc.format == VK_FORMAT_UNDEFINED)
        throw std::logic_error("render graph: texture " + quoted(name) + " has format VK_FORMAT_UNDEFINED");
    if (desc.width == 0 || desc.height == 0 || desc.layers == 0)
        throw std::logic_error("render graph: texture " + quoted(name) +
                               " has a zero width, height or layers (" + std::to_string(desc.width) + "x" +
                               std::to_string(desc.height) + "x" + std::to_string(desc.layers) + ")");
}

void checkDesc(const std::string& name, const BufferDesc& desc) {
    if (desc.size == 0) throw std::logic_error("render graph: buffer " + quoted(name) + " has size 0");
}

} // namespace

Graph::Graph() = default;
Graph::~Graph() = default; // transients still realised belong to the allocator (see releaseTransients)
Graph::Graph(Graph&&) noexcept = default;
Graph& Graph::operator=(Graph&&) noexcept = default;

void Graph::invalidate() {
    m_isCompiled = false;
    m_compiled = CompiledGraph{};
}

uint32_t Graph::beginPass(std::string name, PassKind kind, std::unique_ptr<detail::PassCallback> callback) {
    if (!m_setupError.empty()) throw std::logic_error(m_setupError);
    invalidate();
    Pass pass;
    pass.name = std::move(name);
    pass.kind = kind;
    pass.callback = std::move(callback);
    m_passes.push_back(std::move(pass));
    return static_cast<uint32_t>(m_passes.size() - 1);
}

void Graph::failSetup(uint32_t pass, const std::string& what) {
    // Half-declared passes would compile into wrong barriers; refuse everything from here on.
    if (m_setupError.empty())
        m_setupError = "render graph: setup of pass " + quoted(m_passes[pass].name) +
                       " threw, so the graph is incomplete: " + what;
}

uint32_t Graph::createResource(std::string name, bool isImage, const TextureDesc* textureDesc,
                               const BufferDesc* bufferDesc) {
    invalidate();
    Resource resource;
    resource.name = std::move(name);
    resource.isImage = isImage;
    if (textureDesc) {
        checkDesc(resource.name, *textureDesc);
        resource.textureDesc = *textureDesc;
    }
    if (bufferDesc) {
        checkDesc(resource.name, *bufferDesc);
        resource.bufferDesc = *bufferDesc;
    }
    const auto index = static_cast<uint32_t>(m_resources.size());
    Version first;
    first.resource = index;
    resource.latest = static_cast<uint32_t>(m_versions.size());
    resource.versionCount = 1;
    m_versions.push_back(first);
    m_resources.push_back(std::move(resource));
    return m_resources.back().latest;
}

const Graph::Version& Graph::checkHandle(uint32_t handle, bool isImage, const std::string& where) const {
    const char* kind = isImage ? "texture" : "buffer";
    if (handle == kInvalidId)
        throw std::logic_error("render graph: " + where + " was given an invalid " + kind +
                               " handle (default-constructed or never created)");
    if (handle >= m_versions.size())
        throw std::logic_error("render graph: " + where + " was given " + kind + " handle " +
                               std::to_string(handle) + ", which this graph never created");
    const Version& version = m_versions[handle];
    const Resource& resource = m_resources[version.resource];
    if (resource.isImage != isImage)
        throw std::logic_error("render graph: " + where + " was given " + quoted(resource.name) + " as a " +
                               kind + ", but it is a " + (resource.isImage ? "texture" : "buffer"));
    return version;
}

uint32_t Graph::declare(uint32_t passIndex, uint32_t handle, bool isImage, Use use, Mode mode) {
    const std::string where = "pass " + quoted(m_passes[passIndex].name);
    const Version version = checkHandle(handle, isImage, where);
    Resource& resource = m_resources[version.resource];
    Pass& pass = m_passes[passIndex];
    const UseInfo& info = useInfo(use);
    const std::string subject =
        where + " using " + quoted(resource.name) + " as " + std::string(useName(use));

    if (!appliesTo(use, isImage))
        throw std::logic_error("render graph: " + subject + ": that use is for " +
                               (isImage ? "buffers" : "textures") + " only");
    if (!allowedIn(use, pass.kind))
        throw std::logic_error("render graph: " + subject + ": not available in a " +
                               std::string(passKindName(pass.kind)) + " pass");
    if (mode == Mode::Read && info.writes)
        throw std::logic_error("render graph: " + subject +
                               ": that use writes, so declare it with write() or "
                               "readWrite(), which return the new version");
    if (mode != Mode::Read && !info.writes)
        throw std::logic_error("render graph: " + subject +
                               ": that use only reads, so declare it with read()");

    const bool isLatest = resource.latest == handle;
    const auto staleMessage = [&](const char* verb) {
        const Version& newest = m_versions[resource.latest];
        return "render graph: " + where + " " + verb + " version " + std::to_string(version.version) +
               " of " + quoted(resource.name) + ", but pass " + quoted(m_passes[newest.writer].name) +
               " has since written version " + std::to_string(newest.version) +
               "; use the handle that write() returned";
    };
    const bool dependsOnContents = mode != Mode::Write || info.readsPrevious;
    const bool ownOutput = version.writer == passIndex;
    if (mode == Mode::Read) {
        if (!isLatest) throw std::logic_error(staleMessage("reads old"));
        if (version.writer == kInvalidId && !resource.imported)
            throw std::logic_error("render graph: " + subject + " before any pass wrote it");
    } else {
        if (!isLatest) throw std::logic_error(staleMessage("writes old"));
        if (ownOutput)
            throw std::logic_error("render graph: " + where + " writes " + quoted(resource.name) +
                                   " twice; declare one write with the combined use");
    }

    Access* access = nullptr;
    for (Access& existing : pass.accesses)
        if (existing.resource == version.resource) access = &existing;
    if (!access) {
        pass.accesses.push_back(Access{});
        access = &pass.accesses.back();
        access->resource = version.resource;
        access->layout = info.layout;
    } else if (isImage) {
        const std::optional<VkImageLayout> merged = mergeLayouts(access->layout, info.layout);
        if (!merged)
            throw std::logic_error("render graph: " + where + " uses " + quoted(resource.name) + " as " +
                                   std::string(useName(access->uses.front())) + " and as " +
                                   std::string(useName(use)) + ", which need different image layouts");
        access->layout = *merged;
    }
    access->uses.push_back(use);
    access->stage |= stagesIn(use, pass.kind);
    access->access |= info.access;
    access->writes = access->writes || info.writes;
    if (dependsOnContents && !ownOutput) access->readVersion = handle;

    if (mode == Mode::Read) return handle;
    invalidate();
    Version next;
    next.resource = version.resource;
    next.version = resource.versionCount++;
    next.writer = passIndex;
    resource.latest = static_cast<uint32_t>(m_versions.size());
    m_versions.push_back(next);
    access->writeVersion = resource.latest;
    return resource.latest;
}

uint32_t Graph::declareAttachment(uint32_t passIndex, uint32_t handle, Use use,
                                  const Attachment& attachment) {
    const std::string where = "pass " + quoted(m_passes[passIndex].name);
    const Version version = checkHandle(handle, true, where);
    const Resource& resource = m_resources[version.resource];
    const std::string subject =
        where + " attaching " + quoted(resource.name) + " as " + std::string(useName(use));
    if (m_passes[passIndex].kind != PassKind::Graphics)
        throw std::logic_error("render graph: " + subject + ": only graphics passes have attachments");
    const bool isDepth = use != Use::ColorAttachment;
    if (isDepth && use != Use::DepthStencilWrite && use != Use::DepthStencilRead && use != Use::DepthReadOnly)
        throw std::logic_error(
            "render graph: " + subject +
            ": a depth attachment is DepthStencilWrite, DepthStencilRead or DepthReadOnly");
    if (isDepth != isDepthFormat(resource.textureDesc.format))
        throw std::logic_error("render graph: " + subject + ": its format is " +
                               (isDepth ? "not a depth format" : "a depth format; use depthStencil()"));
    const bool keepsContents = attachment.load == VK_ATTACHMENT_LOAD_OP_LOAD;
    if ((use == Use::DepthStencilRead || use == Use::DepthReadOnly) && !keepsContents)
        throw std::logic_error("render graph: " + subject +
                               ": that use tests against the previous depth, so its load op must be LOAD");

    RenderTargets& targets = m_passes[passIndex].targets;
    if (isDepth && targets.depth.resource != kInvalidId)
        throw std::logic_error("render graph: " + subject + ": the pass already has depth attachment " +
                               quoted(m_resources[targets.depth.resource].name));
    for (const RenderTargets::Target& target : targets.colors)
        if (target.resource == version.resource)
            throw std::logic_error("render graph: " + subject + ": already attached");
    const TextureDesc& desc = resource.textureDesc;
    if (!targets.empty() &&
        (desc.width != targets.width || desc.height != targets.height || desc.layers != targets.layers))
        throw std::logic_error("render graph: " + subject + ": its size " + std::to_string(desc.width) + "x" +
                               std::to_string(desc.height) + "x" + std::to_string(desc.layers) +
                               " differs from the render area " + std::to_string(targets.width) + "x" +
                               std::to_string(targets.height) + "x" + std::to_string(targets.layers) +
                               " of the attachments before it");

    const Mode mode = use == Use::DepthReadOnly             ? Mode::Read
                      : keepsContents || readsPrevious(use) ? Mode::ReadWrite
                                                            : Mode::Write;
    const uint32_t result = declare(passIndex, handle, true, use, mode);
    targets.width = desc.width;
    targets.height = desc.height;
    targets.layers = desc.layers;
    const RenderTargets::Target target{version.resource, attachment};
    if (isDepth)
        targets.depth = target;
    else
        targets.colors.push_back(target);
    return result;
}

Texture Graph::importTexture(std::string name, const PhysicalTexture& texture, std::optional<Use> initial,
                             std::optional<Use> final) {
    for (const std::optional<Use>& use : {initial, final})
        if (use && !appliesTo(*use, true))
            throw std::logic_error("render graph: imported texture " + quoted(name) + " given buffer use " +
                                   std::string(useName(*use)));
    if (initial == Use::Present)
        throw std::logic_error("render graph: imported texture " + quoted(name) +
                               " cannot start in Present (import an acquired swapchain image with nullopt)");
    if (texture.image == VK_NULL_HANDLE)
        throw std::logic_error("render graph: imported texture " + quoted(name) + " has no VkImage");
    const uint32_t handle = createResource(std::move(name), true, &texture.desc, nullptr);
    Resource& resource = m_resources[m_versions[handle].resource];
    resource.imported = true;
    resource.initial = initial;
    resource.final = final;
    resource.texture = texture;
    return Texture{handle};
}

Buffer Graph::importBuffer(std::string name, const PhysicalBuffer& buffer, std::optional<Use> initial,
                           std::optional<Use> final) {
    for (const std::optional<Use>& use : {initial, final})
        if (use && !appliesTo(*use, false))
            throw std::logic_error("render graph: imported buffer " + quoted(name) + " given texture use " +
                                   std::string(useName(*use)));
    if (buffer.buffer == VK_NULL_HANDLE)
        throw std::logic_error("render graph: imported buffer " + quoted(name) + " has no VkBuffer");
    BufferDesc desc;
    desc.size = buffer.size;
    const uint32_t handle = createResource(std::move(name), false, nullptr, &desc);
    Resource& resource = m_resources[m_versions[handle].resource];
    resource.imported = true;
    resource.initial = initial;
    resource.final = final;
    resource.buffer = buffer;
    return Buffer{handle};
}

void Graph::markOutput(Texture texture) {
    checkHandle(texture.id, true, "markOutput");
    invalidate();
    m_versions[texture.id].output = true;
}

void Graph::markOutput(Buffer buffer) {
    checkHandle(buffer.id, false, "markOutput");
    invalidate();
    m_versions[buffer.id].output = true;
}

const std::string& Graph::passName(uint32_t pass) const {
    if (pass >= m_passes.size()) throw std::out_of_range("render graph: no pass " + std::to_string(pass));
    return m_passes[pass].name;
}

const std::string& Graph::resourceName(uint32_t resource) const {
    if (resource >= m_resources.size())
        throw std::out_of_range("render graph: no resource " + std::to_string(resource));
    return m_resources[resource].name;
}

uint32_t Graph::resourceIndex(Texture texture) const {
    return checkHandle(texture.id, true, "resourceIndex").resource;
}

uint32_t Graph::resourceIndex(Buffer buffer) const {
    return checkHandle(buffer.id, false, "resourceIndex").resource;
}

const Graph::Access* Graph::findAccess(uint32_t pass, uint32_t resource) const {
    for (const Access& access : m_passes[pass].accesses)
        if (access.resource == resource) return &access;
    return nullptr;
}

Texture Builder::create(std::string name, const TextureDesc& desc) {
    return Texture{m_graph.createResource(std::move(name), true, &desc, nullptr)};
}

Buffer Builder::create(std::string name, const BufferDesc& desc) {
    return Buffer{m_graph.createResource(std::move(name), false, nullptr, &desc)};
}

Texture Builder::read(Texture texture, Use use) {
    return Texture{m_graph.declare(m_pass, texture.id, true, use, Graph::Mode::Read)};
}

Buffer Builder::read(Buffer buffer, Use use) {
    return Buffer{m_graph.declare(m_pass, buffer.id, false, use, Graph::Mode::Read)};
}

Texture Builder::write(Texture texture, Use use) {
    return Texture{m_graph.declare(m_pass, texture.id, true, use, Graph::Mode::Write)};
}

Buffer Builder::write(Buffer buffer, Use use) {
    return Buffer{m_graph.declare(m_pass, buffer.id, false, use, Graph::Mode::Write)};
}

Texture Builder::readWrite(Texture texture, Use use) {
    return Texture{m_graph.declare(m_pass, texture.id, true, use, Graph::Mode::ReadWrite)};
}

Buffer Builder::readWrite(Buffer buffer, Use use) {
    return Buffer{m_graph.declare(m_pass, buffer.id, false, use, Graph::Mode::ReadWrite)};
}

Texture Builder::color(Texture texture, const Attachment& attachment) {
    return Texture{m_graph.declareAttachment(m_pass, texture.id, Use::ColorAttachment, attachment)};
}

Texture Builder::depthStencil(Texture texture, Use use, const Attachment& attachment) {
    return Texture{m_graph.declareAttachment(m_pass, texture.id, use, attachment)};
}

void Builder::sideEffect() {
    m_graph.invalidate();
    m_graph.m_passes[m_pass].sideEffect = true;
}

} // namespace eng::rg
