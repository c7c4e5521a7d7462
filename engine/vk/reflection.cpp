#include "engine/vk/reflection.h"

#include <algorithm>
#include <map>

namespace eng::vk {
namespace {

// The SPIR-V words this reader needs (SPIR-V 1.6 specification, sections 2.3 and 3).
constexpr uint32_t kMagic = 0x07230203;
constexpr uint32_t kHeaderWords = 5;

enum Op : uint32_t {
    OpTypeImage = 25,
    OpTypeSampler = 26,
    OpTypeSampledImage = 27,
    OpTypeArray = 28,
    OpTypeRuntimeArray = 29,
    OpTypeStruct = 30,
    OpTypePointer = 32,
    OpConstant = 43,
    OpVariable = 59,
    OpDecorate = 71,
};
enum Decoration : uint32_t {
    DecorationBlock = 2,
    DecorationBufferBlock = 3,
    DecorationBinding = 33,
    DecorationDescriptorSet = 34
};
enum StorageClass : uint32_t { UniformConstant = 0, Uniform = 2, StorageBuffer = 12 };
enum Dim : uint32_t { DimBuffer = 5, DimSubpassData = 6 };

// What an id is, as far as a descriptor's type goes.
struct Id {
    uint32_t opcode = 0;
    uint32_t type = 0; // pointee (pointer), element (array), image (sampled image), variable's pointer
    uint32_t storageClass = 0;     // pointer, variable
    uint32_t lengthId = 0;         // array
    uint32_t value = 0;            // 32-bit constant
    uint32_t dim = 0, sampled = 0; // image
    bool block = false, bufferBlock = false;
    int32_t set = -1, binding = -1;
};

std::string stageName(VkShaderStageFlagBits stage) {
    switch (stage) {
    case VK_SHADER_STAGE_VERTEX_BIT:
        return "vertex";
    case VK_SHADER_STAGE_FRAGMENT_BIT:
        return "fragment";
    case VK_SHADER_STAGE_COMPUTE_BIT:
        return "compute";
    default:
        return "stage " + std::to_string(uint32_t(stage));
    }
}

std::string typeName(VkDescriptorType type) {
    switch (type) {
    case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER:
        return "uniform buffer";
    case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER:
        return "storage buffer";
    case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER:
        return "combined image sampler";
    case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE:
        return "storage image";
    case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE:
        return "sampled image";
    case VK_DESCRIPTOR_TYPE_SAMPLER:
        return "sampler";
    case VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER:
        return "uniform texel buffer";
    case VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER:
        return "storage texel buffer";
    case VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT:
        return "input attachment";
    default:
        return "descriptor type " + std::to_string(int(type));
    }
}

// Reads one module's table of ids; throws ReflectionError on a module it cannot walk.
std::vector<Id> readIds(std::span<const uint32_t> code, const std::string& where) {
    if (code.size() < kHeaderWords || code[0] != kMagic)
        throw ReflectionError(where + ": not a SPIR-V module (" +
                              (code.empty() ? std::string("empty") : "bad magic number or header") + ")");
    const uint32_t bound = code[3];
    if (bound == 0 || bound > (1u << 22))
        throw ReflectionError(where + ": SPIR-V id bound " + std::to_string(bound) + " is out of range");
    std::vector<Id> ids(bound);
    auto id = [&](uint32_t i) -> Id& {
        if (i >= bound)
            throw ReflectionError(where + ": SPIR-V id " + std::to_string(i) + " is past the id bound " +
                                  std::to_string(bound));
        return ids[i];
    };
    for (size_t at = kHeaderWords; at < code.size();) {
        const uint32_t words = code[at] >> 16, opcode = code[at] & 0xFFFFu;
        if (words == 0 || at + words > code.size())
            throw ReflectionError(where + ": SPIR-V instruction at word " + std::to_string(at) +
                                  " runs past the end of the module");
        const uint32_t* w = &code[at];
        auto operands = [&](uint32_t n) {
            if (words < n + 1)
                throw ReflectionError(where + ": SPIR-V opcode " + std::to_string(opcode) + " at word " +
                                      std::to_string(at) + " is too short");
        };
        switch (opcode) {
        case OpDecorate:
            operands(2);
            if (w[2] == DecorationBlock) id(w[1]).block = true;
            if (w[2] == DecorationBufferBlock) id(w[1]).bufferBlock = true;
            if (w[2] == DecorationBinding || w[2] == DecorationDescriptorSet) {
                operands(3);
                (w[2] == DecorationBinding ? id(w[1]).binding : id(w[1]).set) = int32_t(w[3]);
            }
            break;
        case OpTypeImage:
            operands(8);
            id(w[1]).opcode = opcode;
            id(w[1]).dim = w[3];
            id(w[1]).sampled = w[7];
            break;
        case OpTypeSampler:
        case OpTypeStruct:
            operands(1);
            id(w[1]).opcode = opcode;
            break;
        case OpTypeSampledImage:
        case OpTypeRuntimeArray:
            operands(2);
            id(w[1]).opcode = opcode;
            id(w[1]).type = w[2];
            break;
        case OpTypeArray:
            operands(3);
            id(w[1]).opcode = opcode;
            id(w[1]).type = w[2];
            id(w[1]).lengthId = w[3];
            break;
        case OpTypePointer:
            operands(3);
            id(w[1]).opcode = opcode;
            id(w[1]).storageClass = w[2];
            id(w[1]).type = w[3];
            break;
        case OpConstant:
            operands(3);
            id(w[2]).opcode = opcode;
            id(w[2]).type = w[1];
            id(w[2]).value = w[3];
            break;
        case OpVariable:
            operands(3);
            id(w[2]).opcode = opcode;
            id(w[2]).type = w[1];
            id(w[2]).storageClass = w[3];
            break;
        default:
            break;
        }
        at += words;
    }
    return ids;
}

// The descriptor type and count of a variable in a descriptor set.
Binding describe(const std::vector<Id>& ids, const Id& variable, const std::string& where) {
    auto at = [&](uint32_t i) -> const Id& {
        if (i >= ids.size())
            throw ReflectionError(where + ": SPIR-V id " + std::to_string(i) + " is past the id bound");
        return ids[i];
    };
    const std::string name =
        where + ": set " + std::to_string(variable.set) + " binding " + std::to_string(variable.binding);
    const Id& pointer = at(variable.type);
    if (pointer.opcode != OpTypePointer) throw ReflectionError(name + ": its type is not a pointer");
    Binding b;
    b.binding = uint32_t(variable.binding);
    const Id* type = &at(pointer.type);
    if (type->opcode == OpTypeRuntimeArray)
        throw ReflectionError(name +
                              ": a runtime-sized descriptor array (this layer makes fixed-size sets only)");
    if (type->opcode == OpTypeArray) {
        const Id& length = at(type->lengthId);
        if (length.opcode != OpConstant)
            throw ReflectionError(name + ": the array's length is not a constant");
        b.count = length.value;
        type = &at(type->type);
    }
    if (type->opcode == OpTypeStruct) {
        if (variable.storageClass == StorageBuffer || (variable.storageClass == Uniform && type->bufferBlock))
            b.type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        else if (variable.storageClass == Uniform && type->block)
            b.type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        else
            throw ReflectionError(name + ": a struct that is neither a uniform nor a storage block");
    } else if (type->opcode == OpTypeSampledImage) {
        b.type = at(type->type).dim == DimBuffer ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER
                                                 : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    } else if (type->opcode == OpTypeImage) {
        // Sampled 1: used with a sampler; 2: read and written without one (a storage image).
        if (type->dim == DimSubpassData)
            b.type = VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT;
        else if (type->dim == DimBuffer)
            b.type = type->sampled == 2 ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER
                                        : VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
        else
            b.type = type->sampled == 2 ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    } else if (type->opcode == OpTypeSampler) {
        b.type = VK_DESCRIPTOR_TYPE_SAMPLER;
    } else {
        throw ReflectionError(name + ": a type no descriptor holds (opcode " + std::to_string(type->opcode) +
                              ")");
    }
    return b;
}

void add(std::map<uint32_t, Binding>& into, const Binding& b, const std::string& where) {
    auto [it, inserted] = into.emplace(b.binding, b);
    if (inserted) return;
    if (it->second.type != b.type || it->second.count != b.count)
        throw ReflectionError(where + ": binding " + std::to_string(b.binding) + " is a " +
                              typeName(it->second.type) + " [" + std::to_string(it->second.count) +
                              "] in one stage or pipeline and a " + typeName(b.type) + " [" +
                              std::to_string(b.count) + "] in another");
    it->second.stages |= b.stages;
}

} // namespace

std::vector<Binding> reflectBindings(std::initializer_list<ShaderStage> stages, uint32_t set) {
    std::map<uint32_t, Binding> bindings;
    for (const ShaderStage& s : stages) {
        if (s.spirv.empty()) continue; // a depth-only pipeline has no fragment stage
        const std::string where = stageName(s.stage) + " shader";
        const std::vector<Id> ids = readIds(s.spirv, where);
        for (const Id& v : ids) {
            if (v.opcode != OpVariable) continue;
            if (v.binding < 0) {
                // A resource in a set needs its binding number; glslang always writes one.
                if (v.set >= 0)
                    throw ReflectionError(where + ": a variable in set " + std::to_string(v.set) +
                                          " has no binding number");
                continue;
            }
            // GLSL's default set is 0; glslang decorates it anyway.
            if (std::max(v.set, 0) != int32_t(set)) continue;
            if (v.storageClass != UniformConstant && v.storageClass != Uniform &&
                v.storageClass != StorageBuffer)
                continue;
            Binding b = describe(ids, v, where);
            b.stages = s.stage;
            add(bindings, b, where);
        }
    }
    std::vector<Binding> out;
    for (const auto& [number, b] : bindings)
        out.push_back(b);
    return out;
}

std::vector<Binding> mergeBindings(std::span<const Binding> a, std::span<const Binding> b) {
    std::map<uint32_t, Binding> merged;
    for (const Binding& x : a)
        add(merged, x, "shared pipeline layout");
    for (const Binding& x : b)
        add(merged, x, "shared pipeline layout");
    std::vector<Binding> out;
    for (const auto& [number, x] : merged)
        out.push_back(x);
    return out;
}

} // namespace eng::vk
