#pragma once
// Descriptor bindings read from SPIR-V, so that a pipeline layout is declared once, in the GLSL:
// the C++ cannot number a binding differently or give it another type (STYLE.md, "Descriptor
// layouts from one declaration"; niagara reflects its layouts the same way). CPU-only.

#include "engine/vk/pipeline.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <initializer_list>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace eng::vk {

// A module that cannot be read (bad magic, an instruction running past the end, a set-0 binding
// whose type no push descriptor can hold, two stages disagreeing on a binding's type or count).
struct ReflectionError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct ShaderStage {
    std::span<const uint32_t> spirv;
    VkShaderStageFlagBits stage;
};

// The bindings of descriptor set `set` that the modules declare, sorted by binding number, each
// with the stages that declare it. A binding declared in more than one stage must have the same
// type and count in all of them. Every declared resource is returned, used or not: the
// validation layer counts a binding as used whatever the specialisation constants make of it.
std::vector<Binding> reflectBindings(std::initializer_list<ShaderStage> stages, uint32_t set = 0);

// The union of several pipelines' set-0 bindings, for one layout shared by them (the same binding
// in two must agree on type and count; the stages are merged).
std::vector<Binding> mergeBindings(std::span<const Binding> a, std::span<const Binding> b);

} // namespace eng::vk
