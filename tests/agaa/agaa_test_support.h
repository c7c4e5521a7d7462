#pragma once
// Constants for CPU tests of the AGAA kernels: a 64x64 view from the origin down -Z.

#include "agaa/aggregate/agaa_constants.h"
#include "engine/frame/frame_constants.h"
#include "engine/frame/sample_pattern.h"
#include "tools/harness/frame_renderer.h"

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

} // namespace agaa::test
