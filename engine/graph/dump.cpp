// Graphviz and JSON views of the graph, for debugging culling and barriers without a capture.
// Both work before compile() (no culling or barriers shown yet) and after it.

#include "engine/graph/graph.h"

#include <nlohmann/json.hpp>

#if __has_include(<vulkan/vk_enum_string_helper.h>)
#include <vulkan/vk_enum_string_helper.h>
#define ENG_RG_HAS_ENUM_STRING_HELPER 1
#endif

#include <set>
#include <sstream>
#include <string>
#include <utility>

namespace eng::rg {
namespace {

struct FlagName {
    uint64_t bit;
    const char* name;
};

constexpr FlagName kStageNames[] = {
    {VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, "VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT"},
    {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, "VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT"},
    {VK_PIPELINE_STAGE_2_VERTEX_INPUT_BIT, "VK_PIPELINE_STAGE_2_VERTEX_INPUT_BIT"},
    {VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, "VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT"},
    {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, "VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT"},
    {VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT, "VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT"},
    {VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT, "VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT"},
    {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, "VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT"},
    {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, "VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT"},
    {VK_PIPELINE_STAGE_2_TRANSFER_BIT, "VK_PIPELINE_STAGE_2_TRANSFER_BIT"},
    {VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, "VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT"},
    {VK_PIPELINE_STAGE_2_HOST_BIT, "VK_PIPELINE_STAGE_2_HOST_BIT"},
    {VK_PIPELINE_STAGE_2_ALL_GRAPHICS_BIT, "VK_PIPELINE_STAGE_2_ALL_GRAPHICS_BIT"},
    {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, "VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT"},
    {VK_PIPELINE_STAGE_2_COPY_BIT, "VK_PIPELINE_STAGE_2_COPY_BIT"},
    {VK_PIPELINE_STAGE_2_RESOLVE_BIT, "VK_PIPELINE_STAGE_2_RESOLVE_BIT"},
    {VK_PIPELINE_STAGE_2_BLIT_BIT, "VK_PIPELINE_STAGE_2_BLIT_BIT"},
    {VK_PIPELINE_STAGE_2_CLEAR_BIT, "VK_PIPELINE_STAGE_2_CLEAR_BIT"},
};

constexpr FlagName kAccessNames[] = {
    {VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT, "VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT"},
    {VK_ACCESS_2_INDEX_READ_BIT, "VK_ACCESS_2_INDEX_READ_BIT"},
    {VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT, "VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT"},
    {VK_ACCESS_2_UNIFORM_READ_BIT, "VK_ACCESS_2_UNIFORM_READ_BIT"},
    {VK_ACCESS_2_INPUT_ATTACHMENT_READ_BIT, "VK_ACCESS_2_INPUT_ATTACHMENT_READ_BIT"},
    {VK_ACCESS_2_SHADER_READ_BIT, "VK_ACCESS_2_SHADER_READ_BIT"},
    {VK_ACCESS_2_SHADER_WRITE_BIT, "VK_ACCESS_2_SHADER_WRITE_BIT"},
    {VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT, "VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT"},
    {VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, "VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT"},
    {VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT, "VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT"},
    {VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, "VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT"},
    {VK_ACCESS_2_TRANSFER_READ_BIT, "VK_ACCESS_2_TRANSFER_READ_BIT"},
    {VK_ACCESS_2_TRANSFER_WRITE_BIT, "VK_ACCESS_2_TRANSFER_WRITE_BIT"},
    {VK_ACCESS_2_HOST_READ_BIT, "VK_ACCESS_2_HOST_READ_BIT"},
    {VK_ACCESS_2_HOST_WRITE_BIT, "VK_ACCESS_2_HOST_WRITE_BIT"},
    {VK_ACCESS_2_MEMORY_READ_BIT, "VK_ACCESS_2_MEMORY_READ_BIT"},
    {VK_ACCESS_2_MEMORY_WRITE_BIT, "VK_ACCESS_2_MEMORY_WRITE_BIT"},
    {VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, "VK_ACCESS_2_SHADER_SAMPLED_READ_BIT"},
    {VK_ACCESS_2_SHADER_STORAGE_READ_BIT, "VK_ACCESS_2_SHADER_STORAGE_READ_BIT"},
    {VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, "VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT"},
};

constexpr FlagName kImageUsageNames[] = {
    {VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "VK_IMAGE_USAGE_TRANSFER_SRC_BIT"},
    {VK_IMAGE_USAGE_TRANSFER_DST_BIT, "VK_IMAGE_USAGE_TRANSFER_DST_BIT"},
    {VK_IMAGE_USAGE_SAMPLED_BIT, "VK_IMAGE_USAGE_SAMPLED_BIT"},
    {VK_IMAGE_USAGE_STORAGE_BIT, "VK_IMAGE_USAGE_STORAGE_BIT"},
    {VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, "VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT"},
    {VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, "VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT"},
    {VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT, "VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT"},
    {VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT, "VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT"},
};

constexpr FlagName kBufferUsageNames[] = {
    {VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "VK_BUFFER_USAGE_TRANSFER_SRC_BIT"},
    {VK_BUFFER_USAGE_TRANSFER_DST_BIT, "VK_BUFFER_USAGE_TRANSFER_DST_BIT"},
    {VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT, "VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT"},
    {VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT, "VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT"},
    {VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, "VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT"},
    {VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "VK_BUFFER_USAGE_STORAGE_BUFFER_BIT"},
    {VK_BUFFER_USAGE_INDEX_BUFFER_BIT, "VK_BUFFER_USAGE_INDEX_BUFFER_BIT"},
    {VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "VK_BUFFER_USAGE_VERTEX_BUFFER_BIT"},
    {VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, "VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT"},
    {VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT, "VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT"},
};

template <size_t N> std::string flagString(uint64_t flags, const FlagName (&names)[N], const char* none) {
    if (flags == 0) return none;
    std::string out;
    for (const FlagName& name : names) {
        if (!(flags & name.bit)) continue;
        if (!out.empty()) out += "|";
        out += name.name;
        flags &= ~name.bit;
    }
    if (flags != 0) {
        // Bits this table does not know stay visible rather than silently dropped.
        std::ostringstream hex;
        hex << std::hex << "0x" << flags;
        if (!out.empty()) out += "|";
        out += hex.str();
    }
    return out;
}

std::string stageString(VkPipelineStageFlags2 flags) {
    return flagString(flags, kStageNames, "VK_PIPELINE_STAGE_2_NONE");
}
std::string accessString(VkAccessFlags2 flags) {
    return flagString(flags, kAccessNames, "VK_ACCESS_2_NONE");
}

std::string layoutString(VkImageLayout layout) {
#ifdef ENG_RG_HAS_ENUM_STRING_HELPER
    return string_VkImageLayout(layout);
#else
    switch (layout) {
    case VK_IMAGE_LAYOUT_UNDEFINED:
        return "VK_IMAGE_LAYOUT_UNDEFINED";
    case VK_IMAGE_LAYOUT_GENERAL:
        return "VK_IMAGE_LAYOUT_GENERAL";
    case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL:
        return "VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL";
    case VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL:
        return "VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL";
    case VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL:
        return "VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL";
    case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL:
        return "VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL";
    case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL:
        return "VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL";
    case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL:
        return "VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL";
    case VK_IMAGE_LAYOUT_PREINITIALIZED:
        return "VK_IMAGE_LAYOUT_PREINITIALIZED";
    case VK_IMAGE_LAYOUT_PRESENT_SRC_KHR:
        return "VK_IMAGE_LAYOUT_PRESENT_SRC_KHR";
    default:
        return "VkImageLayout(" + std::to_string(static_cast<int>(layout)) + ")";
    }
#endif
}

std::string formatString(VkFormat format) {
#ifdef ENG_RG_HAS_ENUM_STRING_HELPER
    return string_VkFormat(format);
#else
    switch (format) {
    case VK_FORMAT_R8_UNORM:
        return "VK_FORMAT_R8_UNORM";
    case VK_FORMAT_R8G8B8A8_UNORM:
        return "VK_FORMAT_R8G8B8A8_UNORM";
    case VK_FORMAT_R8G8B8A8_SRGB:
        return "VK_FORMAT_R8G8B8A8_SRGB";
    case VK_FORMAT_B8G8R8A8_UNORM:
        return "VK_FORMAT_B8G8R8A8_UNORM";
    case VK_FORMAT_B8G8R8A8_SRGB:
        return "VK_FORMAT_B8G8R8A8_SRGB";
    case VK_FORMAT_R16_SFLOAT:
        return "VK_FORMAT_R16_SFLOAT";
    case VK_FORMAT_R16G16_SFLOAT:
        return "VK_FORMAT_R16G16_SFLOAT";
    case VK_FORMAT_R16G16B16A16_SFLOAT:
        return "VK_FORMAT_R16G16B16A16_SFLOAT";
    case VK_FORMAT_R32_UINT:
        return "VK_FORMAT_R32_UINT";
    case VK_FORMAT_R32_SFLOAT:
        return "VK_FORMAT_R32_SFLOAT";
    case VK_FORMAT_R32G32_UINT:
        return "VK_FORMAT_R32G32_UINT";
    case VK_FORMAT_R32G32_SFLOAT:
        return "VK_FORMAT_R32G32_SFLOAT";
    case VK_FORMAT_R32G32B32A32_UINT:
        return "VK_FORMAT_R32G32B32A32_UINT";
    case VK_FORMAT_R32G32B32A32_SFLOAT:
        return "VK_FORMAT_R32G32B32A32_SFLOAT";
    case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
        return "VK_FORMAT_B10G11R11_UFLOAT_PACK32";
    case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
        return "VK_FORMAT_A2B10G10R10_UNORM_PACK32";
    case VK_FORMAT_D16_UNORM:
        return "VK_FORMAT_D16_UNORM";
    case VK_FORMAT_D32_SFLOAT:
        return "VK_FORMAT_D32_SFLOAT";
    case VK_FORMAT_D16_UNORM_S8_UINT:
        return "VK_FORMAT_D16_UNORM_S8_UINT";
    case VK_FORMAT_D24_UNORM_S8_UINT:
        return "VK_FORMAT_D24_UNORM_S8_UINT";
    case VK_FORMAT_D32_SFLOAT_S8_UINT:
        return "VK_FORMAT_D32_SFLOAT_S8_UINT";
    default:
        return "VkFormat(" + std::to_string(static_cast<int>(format)) + ")";
    }
#endif
}

std::string dotEscape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out;
}

std::string usesLabel(const std::vector<Use>& uses) {
    std::string label;
    for (Use use : uses) {
        if (!label.empty()) label += "+";
        label += useName(use);
    }
    return label;
}

} // namespace

std::string Graph::dumpDot() const {
    std::vector<bool> culled(m_passes.size(), false);
    if (m_isCompiled)
        for (uint32_t pass : m_compiled.culled)
            culled[pass] = true;
    std::vector<uint32_t> orderOf(m_passes.size(), kInvalidId);
    if (m_isCompiled)
        for (uint32_t i = 0; i < m_compiled.order.size(); ++i)
            orderOf[m_compiled.order[i].pass] = i;

    std::ostringstream dot;
    dot << "digraph render_graph {\n  rankdir=LR;\n  node [fontname=\"Helvetica\", fontsize=10];\n"
        << "  edge [fontname=\"Helvetica\", fontsize=9];\n";

    std::set<uint32_t> versions; // only versions some pass touches, plus outputs
    for (const Pass& pass : m_passes)
        for (const Access& access : pass.accesses)
            for (uint32_t version : {access.readVersion, access.writeVersion})
                if (version != kInvalidId) versions.insert(version);
    for (uint32_t v = 0; v < m_versions.size(); ++v)
        if (m_versions[v].output) versions.insert(v);

    for (uint32_t p = 0; p < m_passes.size(); ++p) {
        const Pass& pass = m_passes[p];
        dot << "  pass" << p << " [shape=box, label=\"" << dotEscape(pass.name) << "\\n"
            << passKindName(pass.kind);
        if (orderOf[p] != kInvalidId) dot << " #" << orderOf[p];
        if (culled[p])
            dot << " (culled)\", style=\"filled,dashed\", fillcolor=\"grey90\", fontcolor=\"grey50\", "
                   "color=\"grey60\"];\n";
        else
            dot << (pass.sideEffect ? " (side effect)" : "") << "\", style=filled, fillcolor=\""
                << (pass.kind == PassKind::Compute ? "orange" : "lightskyblue") << "\"];\n";
    }
    for (uint32_t v : versions) {
        const Version& version = m_versions[v];
        const Resource& resource = m_resources[version.resource];
        dot << "  res" << v << " [shape=ellipse, label=\"" << dotEscape(resource.name) << "\\nv"
            << version.version << "\", style=filled, ";
        if (resource.imported)
            dot << "fillcolor=\"gold\", peripheries=2";
        else
            dot << "fillcolor=\"" << (resource.isImage ? "palegreen" : "lightyellow") << "\"";
        if (version.output) dot << ", penwidth=2";
        dot << "];\n";
    }
    for (uint32_t p = 0; p < m_passes.size(); ++p) {
        const char* color = culled[p] ? ", color=\"grey70\", fontcolor=\"grey60\"" : "";
        for (const Access& access : m_passes[p].accesses) {
            const std::string label = usesLabel(access.uses);
            if (access.readVersion != kInvalidId)
                dot << "  res" << access.readVersion << " -> pass" << p << " [label=\"" << label << "\""
                    << color << "];\n";
            if (access.writeVersion != kInvalidId)
                dot << "  pass" << p << " -> res" << access.writeVersion << " [label=\"" << label << "\""
                    << color << "];\n";
        }
    }
    dot << "}\n";
    return dot.str();
}

std::string Graph::dumpJson() const {
    using nlohmann::json;
    const auto barrierJson = [&](const Barrier& barrier) {
        json out = {{"resource", m_resources[barrier.resource].name},
                    {"srcStage", stageString(barrier.srcStage)},
                    {"dstStage", stageString(barrier.dstStage)},
                    {"srcAccess", accessString(barrier.srcAccess)},
                    {"dstAccess", accessString(barrier.dstAccess)}};
        if (barrier.isImage) {
            out["oldLayout"] = layoutString(barrier.oldLayout);
            out["newLayout"] = layoutString(barrier.newLayout);
        }
        return out;
    };
    const auto passNameOrNull = [&](uint32_t pass) {
        return pass == kInvalidId ? json() : json(m_passes[pass].name);
    };

    std::vector<const CompiledPass*> compiledOf(m_passes.size(), nullptr);
    std::vector<json> orderOf(m_passes.size());
    if (m_isCompiled)
        for (uint32_t i = 0; i < m_compiled.order.size(); ++i) {
            compiledOf[m_compiled.order[i].pass] = &m_compiled.order[i];
            orderOf[m_compiled.order[i].pass] = i;
        }

    const auto loadName = [](VkAttachmentLoadOp op) {
        switch (op) {
        case VK_ATTACHMENT_LOAD_OP_LOAD:
            return "LOAD";
        case VK_ATTACHMENT_LOAD_OP_CLEAR:
            return "CLEAR";
        case VK_ATTACHMENT_LOAD_OP_DONT_CARE:
            return "DONT_CARE";
        default:
            return "other";
        }
    };
    const auto storeName = [](VkAttachmentStoreOp op) {
        switch (op) {
        case VK_ATTACHMENT_STORE_OP_STORE:
            return "STORE";
        case VK_ATTACHMENT_STORE_OP_DONT_CARE:
            return "DONT_CARE";
        default:
            return "other";
        }
    };
    // The render pass execute() begins around the pass: null for passes without attachments.
    const auto renderPassJson = [&](const RenderTargets& targets) {
        if (targets.empty()) return json();
        const auto target = [&](const RenderTargets::Target& t) {
            return json{{"resource", m_resources[t.resource].name},
                        {"load", loadName(t.attachment.load)},
                        {"store", storeName(t.attachment.store)}};
        };
        json colors = json::array();
        for (const RenderTargets::Target& t : targets.colors)
            colors.push_back(target(t));
        return json{{"colors", colors},
                    {"depth", targets.depth.resource == kInvalidId ? json() : target(targets.depth)},
                    {"width", targets.width},
                    {"height", targets.height},
                    {"layers", targets.layers}};
    };

    json passes = json::array();
    for (uint32_t p = 0; p < m_passes.size(); ++p) {
        const Pass& pass = m_passes[p];
        json reads = json::array(), writes = json::array(), barriers = json::array();
        for (const Access& access : pass.accesses) {
            const std::string& name = m_resources[access.resource].name;
            const std::string uses = usesLabel(access.uses);
            if (access.readVersion != kInvalidId)
                reads.push_back(
                    {{"resource", name}, {"version", m_versions[access.readVersion].version}, {"use", uses}});
            if (access.writeVersion != kInvalidId)
                writes.push_back({{"resource", name},
                                  {"version", m_versions[access.writeVersion].version},
                                  {"use", uses}});
        }
        if (compiledOf[p])
            for (const Barrier& barrier : compiledOf[p]->barriers)
                barriers.push_back(barrierJson(barrier));
        passes.push_back({{"name", pass.name},
                          {"kind", std::string(passKindName(pass.kind))},
                          {"culled", m_isCompiled && !compiledOf[p]},
                          {"sideEffect", pass.sideEffect},
                          {"order", orderOf[p]},
                          {"reads", reads},
                          {"writes", writes},
                          {"renderPass", renderPassJson(pass.targets)},
                          {"barriers", barriers}});
    }

    json resources = json::array();
    for (uint32_t r = 0; r < m_resources.size(); ++r) {
        const Resource& resource = m_resources[r];
        json entry = {{"name", resource.name},
                      {"kind", resource.isImage ? "texture" : "buffer"},
                      {"imported", resource.imported}};
        if (m_isCompiled) {
            entry["firstPass"] = passNameOrNull(m_compiled.firstUse[r]);
            entry["lastPass"] = passNameOrNull(m_compiled.lastUse[r]);
            entry["usage"] = resource.isImage ? flagString(m_compiled.imageUsage[r], kImageUsageNames, "0")
                                              : flagString(m_compiled.bufferUsage[r], kBufferUsageNames, "0");
        }
        if (resource.isImage)
            entry["desc"] = {{"format", formatString(resource.textureDesc.format)},
                             {"width", resource.textureDesc.width},
                             {"height", resource.textureDesc.height},
                             {"layers", resource.textureDesc.layers},
                             {"samples", static_cast<uint32_t>(resource.textureDesc.samples)}};
        else
            entry["desc"] = {{"size", resource.bufferDesc.size}};
        if (resource.imported) {
            entry["initial"] = resource.initial ? json(std::string(useName(*resource.initial))) : json();
            entry["final"] = resource.final ? json(std::string(useName(*resource.final))) : json();
        }
        resources.push_back(std::move(entry));
    }

    json culled = json::array(), finalBarriers = json::array();
    if (m_isCompiled) {
        for (uint32_t pass : m_compiled.culled)
            culled.push_back(m_passes[pass].name);
        for (const Barrier& barrier : m_compiled.finalBarriers)
            finalBarriers.push_back(barrierJson(barrier));
    }
    json out = {{"compiled", m_isCompiled},
                {"passes", passes},
                {"resources", resources},
                {"culled", culled},
                {"finalBarriers", finalBarriers}};
    return out.dump(2);
}

} // namespace eng::rg
