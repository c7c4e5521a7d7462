#include "engine/vk/capabilities.h"

#include <sstream>

namespace eng::vk {
namespace {

std::string sampleCounts(VkSampleCountFlags flags) {
    std::string s;
    for (uint32_t n = 1; n <= 64; n *= 2)
        if (flags & n) s += (s.empty() ? "" : " ") + std::to_string(n);
    return s.empty() ? "none" : s;
}

const char* yesNo(bool b) {
    return b ? "yes" : "no";
}

const char* deviceTypeName(VkPhysicalDeviceType t) {
    switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return "CPU";
    default:
        return "other";
    }
}

std::string stageNames(VkShaderStageFlags s) {
    std::string out;
    auto add = [&](VkShaderStageFlags bit, const char* name) {
        if (s & bit) out += (out.empty() ? "" : " ") + std::string(name);
    };
    add(VK_SHADER_STAGE_VERTEX_BIT, "vertex");
    add(VK_SHADER_STAGE_FRAGMENT_BIT, "fragment");
    add(VK_SHADER_STAGE_COMPUTE_BIT, "compute");
    add(VK_SHADER_STAGE_GEOMETRY_BIT, "geometry");
    return out.empty() ? "none" : out;
}

std::string subgroupOpNames(VkSubgroupFeatureFlags s) {
    std::string out;
    auto add = [&](VkSubgroupFeatureFlags bit, const char* name) {
        if (s & bit) out += (out.empty() ? "" : " ") + std::string(name);
    };
    add(VK_SUBGROUP_FEATURE_BASIC_BIT, "basic");
    add(VK_SUBGROUP_FEATURE_VOTE_BIT, "vote");
    add(VK_SUBGROUP_FEATURE_ARITHMETIC_BIT, "arithmetic");
    add(VK_SUBGROUP_FEATURE_BALLOT_BIT, "ballot");
    add(VK_SUBGROUP_FEATURE_SHUFFLE_BIT, "shuffle");
    add(VK_SUBGROUP_FEATURE_SHUFFLE_RELATIVE_BIT, "shuffle-relative");
    add(VK_SUBGROUP_FEATURE_CLUSTERED_BIT, "clustered");
    add(VK_SUBGROUP_FEATURE_QUAD_BIT, "quad");
    return out.empty() ? "none" : out;
}

} // namespace

std::string Capabilities::describe() const {
    std::ostringstream o;
    o << "device                 " << deviceName << " (" << deviceTypeName(deviceType) << ")\n"
      << "driver                 " << driverName << "\n"
      << "api                    " << VK_API_VERSION_MAJOR(apiVersion) << "."
      << VK_API_VERSION_MINOR(apiVersion) << "." << VK_API_VERSION_PATCH(apiVersion) << "\n"
      << "sample counts          colour " << sampleCounts(colorSampleCounts) << "; depth "
      << sampleCounts(depthSampleCounts) << " (higher rates are emulated by layered 4x passes)\n"
      << "sample-rate shading    " << yesNo(sampleRateShading) << "\n"
      << "post-depth coverage    " << yesNo(postDepthCoverage) << "\n"
      << "float atomics          buffer add " << yesNo(bufferFloatAtomicAdd) << ", image add "
      << yesNo(imageFloatAtomicAdd) << "\n"
      << "int64 atomics          buffer " << yesNo(bufferInt64Atomics)
      << " (AGAA generation: --agaa-atomics 64)\n"
      << "subgroups              size " << subgroupSize << ", stages " << stageNames(subgroupStages) << "\n"
      << "subgroup operations    " << subgroupOpNames(subgroupOperations) << "\n"
      << "fragment interlock     " << yesNo(fragmentShaderInterlock) << "\n"
      << "mixed samples          " << yesNo(mixedSamples) << "\n"
      << "coverage override      " << yesNo(coverageOverride) << "\n"
      << "sample locations       " << yesNo(sampleLocations) << "\n"
      << "multiview              " << yesNo(multiview) << "\n"
      << "layered output         " << yesNo(layeredOutput) << " (gl_Layer from the vertex shader)\n"
      << "multi-viewport         " << yesNo(multiViewport) << "\n"
      << "push descriptors       " << yesNo(pushDescriptors) << "\n"
      << "timestamps             period " << timestampPeriodNs << " ns, " << timestampValidBits
      << " valid bits" << (calibratedTimestamps ? ", calibrated" : "") << "\n"
      << "compute shared memory  " << maxComputeSharedMemory << " bytes\n";
    return o.str();
}

} // namespace eng::vk
