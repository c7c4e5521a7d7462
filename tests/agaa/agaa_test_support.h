#pragma once
// Constants for CPU tests of the AGAA kernels: a 64x64 view from the origin down -Z.

#include "agaa/aggregate/agaa_constants.h"
#include "engine/frame/frame_constants.h"
#include "engine/frame/sample_pattern.h"
#include "tools/harness/frame_renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace agaa::test {

struct KernelConstants {
    shared::FrameConstants frame;
    shared::AgaaConstants agaa;
};

inline KernelConstants kernelConstants(uint32_t n, uint32_t c, uint32_t size = 64) {
    eng::scene::Scene scene;
    eng::scene::Camera camera;
    camera.view = glm::mat4(1.0f);
    camera.yfov = 0.8f;
    camera.znear = 0.05f;
    camera.zfar = 100.0f;
    scene.cameras.push_back(camera);
    eng::frame::ViewSettings view;
    view.width = view.height = size;
    KernelConstants k;
    k.frame = eng::frame::makeFrameConstants(scene, view, eng::frame::makeSamplePattern(n));
    AggregateSettings s;
    s.samples = n;
    s.aggregates = c;
    k.agaa = makeAgaaConstants(s, k.frame, false);
    return k;
}

// A square frame of `method` at n samples and c aggregates.
inline RenderRequest request(const std::string& method, uint32_t n, uint32_t c, uint32_t size) {
    RenderRequest r;
    r.method = method;
    r.settings.samples = n;
    r.settings.aggregates = c;
    r.view.width = r.view.height = size;
    return r;
}

// Reversed-Z depth of a point at view distance t (common/depth.glsl).
inline float depthAt(float t, const shared::FrameConstants& f) {
    float n = f.depthParams.x, far = f.depthParams.y;
    return n * (far - t) / (t * (far - n));
}

// Octahedral decoding (Cigolle et al. 2014) of a packSnorm2x16 word, in double: the accumulate
// path's kept normal (shared/sample_material.h), decoded apart from the shaders.
inline std::array<double, 3> decodeOctahedralSnorm(uint32_t word) {
    auto snorm = [](uint16_t v) { return std::max(-1.0, double(int16_t(v)) / 32767.0); };
    double x = snorm(uint16_t(word & 0xFFFF)), y = snorm(uint16_t(word >> 16));
    const double z = 1.0 - std::abs(x) - std::abs(y);
    if (z < 0.0) {
        const double ox = (1.0 - std::abs(y)) * (x >= 0.0 ? 1.0 : -1.0);
        const double oy = (1.0 - std::abs(x)) * (y >= 0.0 ? 1.0 : -1.0);
        x = ox;
        y = oy;
    }
    const double length = std::sqrt(x * x + y * y + z * z);
    return {x / length, y / length, z / length};
}

// The low half of a packUnorm2x16 word.
inline double unorm16Low(uint32_t word) {
    return double(word & 0xFFFF) / 65535.0;
}

} // namespace agaa::test
