#include "agaa/methods.h"

#include "agaa/reference/reference.h"

#include <stdexcept>

namespace agaa {

const std::vector<MethodInfo>& knownMethods() {
    static const std::vector<MethodInfo> methods = {
        {"reference", "per-sample deferred shading: every covered sample lit (ground truth at the same n)", true, false},
        {"noaa", "one sample, one shading event per pixel", false, false},
    };
    return methods;
}

std::string knownMethodNames() {
    std::string s;
    for (const MethodInfo& m : knownMethods()) s += (s.empty() ? "" : ", ") + m.name;
    return s;
}

bool isKnownMethod(const std::string& name) {
    for (const MethodInfo& m : knownMethods())
        if (m.name == name) return true;
    return false;
}

std::unique_ptr<Technique> createTechnique(const std::string& method, eng::vk::Device& device,
                                           const eng::frame::GpuScene& scene, const MethodSettings& settings) {
    if (method == "reference") return std::make_unique<Reference>(device, scene, ReferenceSettings{settings.samples});
    if (method == "noaa") return std::make_unique<Reference>(device, scene, ReferenceSettings{1}, "noaa");
    throw std::invalid_argument("--method '" + method + "' is unknown (known: " + knownMethodNames() + ")");
}

} // namespace agaa
