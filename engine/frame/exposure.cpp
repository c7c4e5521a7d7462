#include "engine/frame/exposure.h"

#include "engine/scene/default_lighting.h"

#include <algorithm>
#include <cmath>

namespace eng::frame {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kIsoSpeed = 100.0;        // S
constexpr double kMeterCalibration = 12.5; // K, reflected light
constexpr double kLensAttenuation = 1.2;   // 78 / (100 q), q = 0.65
constexpr double kMinIlluminance = 1.0e-6; // lux: below it the scene has no light to meter by

} // namespace

float exposureFromEv100(double ev100) {
    return float(1.0 / (kLensAttenuation * std::exp2(ev100)));
}

double ev100FromLuminance(double averageLuminance) {
    return std::log2(std::max(averageLuminance, kMinMeteredLuminance) * kIsoSpeed / kMeterCalibration);
}

double logAverageLuminance(std::span<const float> rgba, std::span<const uint32_t> covered, float exposure) {
    const size_t pixels = rgba.size() / 4;
    bool any = false;
    for (size_t i = 0; i < pixels && i < covered.size(); ++i)
        any = any || covered[i] > 0;
    double sum = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < pixels; ++i) {
        if (any && (i >= covered.size() || covered[i] == 0)) continue;
        const float* p = &rgba[i * 4];
        const double y = (0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]) / double(exposure);
        sum += std::log(std::max(y, kMinMeteredLuminance));
        ++count;
    }
    return count ? std::exp(sum / double(count)) : kMinMeteredLuminance;
}

float meteringExposure(const scene::Scene& scene) {
    double illuminance = scene::lightIlluminanceAt(scene, (scene.bounds.min + scene.bounds.max) * 0.5f);
    // The environment's brightest texel stands for what it can add (a bright sky or sun).
    double environmentPeak = 0.0;
    for (const glm::vec3& r : scene.environment.radiance)
        environmentPeak = std::max({environmentPeak, double(r.x), double(r.y), double(r.z)});
    illuminance += environmentPeak * kPi;
    return illuminance > kMinIlluminance ? float(kPi / illuminance) : 1.0f;
}

} // namespace eng::frame
