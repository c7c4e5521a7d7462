// The shader-math edge cases of the footprints (issue 14): the pixel footprint with the frame's
// own projection, the AGAA shadow footprint's width along a tangent direction, the face normal
// from derivatives, and an aggregate's environment level at the BRDF's alpha floor, each against
// a double twin (shader_math_cases.cpp holds the rest).

#include "engine/frame/frame_constants.h"
#include "engine/frame/sample_pattern.h"
#include "shader_math_checks.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace agaa::hard {

using namespace checks;

void addFootprintCases(std::vector<EdgeCase>& cases) {
    auto add = [&](std::string name, std::vector<std::string> guards, MathCase in,
                   std::function<std::string(const MathResult&)> check) {
        cases.push_back({std::move(name), std::move(guards), in, std::move(check)});
    };

    // Pixel footprint (common/depth.glsl) with the projection the frame really uses: its
    // proj[1][1] is negative (Vulkan's y flip), and the footprint must not be (issue 14).
    {
        eng::scene::Scene scene;
        eng::scene::Camera camera;
        camera.view = glm::mat4(1.0f);
        camera.yfov = 0.8f;
        scene.cameras.push_back(camera);
        eng::frame::ViewSettings view;
        view.width = 96;
        view.height = 64;
        const shared::FrameConstants f =
            eng::frame::makeFrameConstants(scene, view, eng::frame::makeSamplePattern(1));
        for (float t : {0.1f, 2.0f, 500.0f})
            add("pixelFootprint t=" + fmt(t) + " (projParams.y = " + fmt(f.projParams.y) + ")", {},
                op(kOpPixelFootprint, glm::vec4(t, 0, 0, 0), f.extent, f.projParams),
                [t](const MathResult& r) {
                    // One pixel of 64 rows across a 0.8 rad vertical field of view.
                    return near("footprint", r.r0.x, 2.0 * t * std::tan(0.4) / 64.0, 1e-5);
                });
    }

    // The shadow footprint's width along a tangent direction (common/depth.glsl aggregateWidth,
    // issue 14), against the variance of the samples' screen positions along the direction's
    // screen projection, in double: sqrt(12 v) pixels, 1 for a uniform whole pixel.
    {
        struct WidthIn {
            const char* what;
            glm::dvec3 d, S; // direction (view space), covariance (sxx, sxy, syy) in pixel^2
        };
        const double w = 1.0 / 12.0; // a uniform pixel's variance per axis
        const WidthIn widths[] = {
            {"whole pixel, along x", {1, 0, 0}, {w, 0, w}},
            {"whole pixel, diagonal and tilted out of the screen", {0.6, 0.6, 0.52915}, {w, 0, w}},
            {"left half (split along x), across the split", {1, 0, 0}, {w / 4, 0, w}},
            {"left half, along the split", {0, -1, 0}, {w / 4, 0, w}},
            {"a diagonal strip, along it", {0.70710678, 0.70710678, 0}, {w, 0.9 * w, w}},
            {"a diagonal strip, across it", {0.70710678, -0.70710678, 0}, {w, 0.9 * w, w}},
            {"one sample: no spread", {0.3, 0.8, 0.1}, {0, 0, 0}},
            {"cancellation: a slightly negative variance", {1, 0, 0}, {-1e-9, 0, w}},
        };
        for (const WidthIn& k : widths)
            add(std::string("aggregateWidth ") + k.what, {},
                op(kOpAggregateWidth, glm::vec4(glm::vec3(k.d), 0), glm::vec4(glm::vec3(k.S), 0)),
                [k](const MathResult& r) {
                    const double l2 = k.d.x * k.d.x + k.d.y * k.d.y;
                    const double v =
                        (k.d.x * k.d.x * k.S.x + 2.0 * k.d.x * k.d.y * k.S.y + k.d.y * k.d.y * k.S.z) / l2;
                    return near("width", r.r0.x, std::sqrt(12.0 * std::max(v, 0.0)), 1e-5, 1e-6);
                });
        // Guard: a direction along the view ray has no screen direction; the whole pixel.
        for (double xy : {0.0, 0.5e-3, 0.9e-3})
            add("aggregateWidth along the view ray, |xy| = " + fmt(float(xy)), {"kMinScreenDirection2"},
                op(kOpAggregateWidth, glm::vec4(float(xy), 0, 1, 0), glm::vec4(0.001f, 0, 0.001f, 0)),
                [](const MathResult& r) { return near("width", r.r0.x, 1.0, 0.0, 0.0); });
        // Just past the guard: measured along x (|xy|^2 = 1.1e-6 > 1e-6).
        add("aggregateWidth just off the view ray", {"kMinScreenDirection2"},
            op(kOpAggregateWidth, glm::vec4(1.0488e-3f, 0, 1, 0),
               glm::vec4(1.0f / 48.0f, 0, 1.0f / 12.0f, 0)),
            [](const MathResult& r) { return near("width", r.r0.x, 0.5, 1e-4, 0.0); });
    }

    // Face normal from derivatives (common/face_normal.glsl): the guard is on the sine of the angle
    // between dP/dx and dP/dy, so micrometre footprints keep their plane (issue 14) and only
    // parallel derivatives fall back to the camera direction.
    {
        struct FaceIn {
            const char* what;
            glm::vec3 dx, dy, towards;
            bool fallback;
        };
        const glm::vec3 towards(0.6f, 0.0f, 0.8f);
        for (const FaceIn& f : std::vector<FaceIn>{
                 {"a 1 cm footprint", {0.01f, 0, 0}, {0, 0.01f, 0}, towards, false},
                 {"a micrometre footprint (near plane)", {1e-6f, 0, 0}, {0, 1e-6f, 0}, towards, false},
                 {"a 10 nm footprint", {1e-8f, 0, 0}, {0, 0, -1e-8f}, towards, false},
                 {"parallel derivatives (edge-on sliver)", {1e-3f, 0, 0}, {2e-3f, 0, 0}, towards, true},
                 {"nearly parallel, sine 1e-7", {1.0f, 0, 0}, {1.0f, 1e-7f, 0}, towards, true},
                 {"nearly parallel, sine 1e-5", {1.0f, 0, 0}, {1.0f, 1e-5f, 0}, towards, false},
                 {"zero derivatives", {0, 0, 0}, {0, 0, 0}, towards, true},
             })
            add("faceNormal " + std::string(f.what), {"kMinFaceNormalSine"},
                op(kOpFaceNormal, glm::vec4(f.dx, 0), glm::vec4(f.dy, 0), glm::vec4(f.towards, 0)),
                [f](const MathResult& r) -> std::string {
                    D3 n = f.fallback ? D3(f.towards) : glm::normalize(glm::cross(D3(f.dx), D3(f.dy)));
                    if (glm::dot(n, D3(f.towards)) < 0.0) n = -n;
                    return near3("N", glm::vec3(r.r0), n, 1e-5, 1e-5);
                });
    }

    // The environment's level for an aggregate (common/brdf.glsl environmentAggregateRoughness):
    // sqrt(alpha) above the punctual BRDF's floor kMinGgxAlpha; at the floor (within
    // kGgxAlphaFloorRelative, fp32 rounding of sqrt(ax ay) included) the material's own alpha,
    // which may lie below it (issue 14: mirrors read level 0.03 of the chain).
    {
        struct EnvIn {
            const char* what;
            float alpha, material;
            double expected;
        };
        const float floorAlpha = 1.0e-3f;
        const float sggxFloor = std::sqrt(floorAlpha * floorAlpha); // as the lighting pass forms it
        for (const EnvIn& e : std::vector<EnvIn>{
                 {"a mirror at the floor", floorAlpha, 0.0f, 0.0},
                 {"a near-mirror at the floor", floorAlpha, 4.0e-4f, std::sqrt(4.0e-4)},
                 {"an SGGX lobe clamped on both axes", sggxFloor, 0.0f, 0.0},
                 {"just inside the floor's tolerance", floorAlpha * 1.0009f, 0.0f, 0.0},
                 {"just past the floor's tolerance", floorAlpha * 1.0011f, 0.0f, std::sqrt(1.0011e-3)},
                 {"a spread aggregate of mirrors", 0.05f, 0.0f, std::sqrt(0.05)},
                 {"a material above the floor", 0.25f, 0.25f, 0.5},
             })
            add("environmentAggregateRoughness " + std::string(e.what),
                {"kMinGgxAlpha", "kGgxAlphaFloorRelative"},
                op(kOpEnvironmentRoughness, glm::vec4(e.alpha, e.material, 0, 0)),
                [e](const MathResult& r) { return near("roughness", r.r0.x, e.expected, 1e-6, 1e-5); });
    }
}

} // namespace agaa::hard