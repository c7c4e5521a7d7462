// Geometric specular anti-aliasing (--curvature-roughness; agaa/common/effects.h
// CurvatureRoughness) as an option of every method's material evaluation, validation on. The
// formula itself is checked against Tokuyoshi and Kaplanyan's in double (tests/hard/
// shader_math_cases.cpp, "curvatureRoughness"); here, that every method takes it:
//  - on a flat square (no curvature) the frame is bit for bit the frame without it;
//  - on a glossy sphere seen from afar the sphere's pixels change, nothing else does, and the
//    frame stays finite (which way the lobe moves: the formula's test, and the exported G-buffer
//    of tests/agaa/test_agaa_samples_gpu.cpp, whose include every method's material evaluation calls);
//  - the converged truth ignores it (it is what the filter approximates).

#include "gpu_test_support.h"
#include "tests/support/curvature_scene.h"
#include "tools/harness/converged_truth.h"
#include "tools/harness/frame_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace {

constexpr uint32_t kSize = 64;

agaa::RenderResult render(agaa::FrameRenderer& renderer, const std::string& method, bool specularAA) {
    agaa::RenderRequest r;
    r.method = method;
    r.settings.samples = 8;
    r.settings.effects.curvatureRoughness.enabled = specularAA;
    r.view.width = r.view.height = kSize;
    r.view.exposure = 1.0f;
    return renderer.render(r);
}

size_t differing(const eng::io::ImageF& a, const eng::io::ImageF& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.rgba.size(); ++i)
        n += a.rgba[i] != b.rgba[i] ? 1 : 0;
    return n;
}

// Values that differ between the two frames, and how many of them lie off the subject (where
// the frame without the option shows the corner's background).
struct Difference {
    size_t values = 0, offSubject = 0;
};
Difference difference(const eng::io::ImageF& off, const eng::io::ImageF& on) {
    Difference d;
    for (size_t i = 0; i < off.rgba.size(); ++i) {
        if (off.rgba[i] == on.rgba[i]) continue;
        ++d.values;
        const size_t pixel = i / 4 * 4;
        d.offSubject += off.rgba[pixel + 1] == off.rgba[1] ? 1 : 0;
    }
    return d;
}

class SpecularAA : public ::testing::TestWithParam<const char*> {};

TEST_P(SpecularAA, LeavesFlatSurfacesBitForBitAndChangesOnlyTheCurvedSubject) {
    auto device = agaa::test::makeValidatedDevice();
    const std::string method = GetParam();
    {
        const eng::scene::Scene flat = agaa::test::curvatureScene(false, 3.0f);
        agaa::FrameRenderer renderer(*device, flat);
        const agaa::RenderResult off = render(renderer, method, false), on = render(renderer, method, true);
        EXPECT_EQ(differing(off.hdr, on.hdr), 0u)
            << method << ": a flat surface keeps its material's roughness";
    }
    const eng::scene::Scene sphere = agaa::test::curvatureScene(true, 12.0f);
    agaa::FrameRenderer renderer(*device, sphere);
    const agaa::RenderResult off = render(renderer, method, false), on = render(renderer, method, true);
    for (float v : on.hdr.rgba)
        ASSERT_TRUE(std::isfinite(v)) << method;
    const Difference d = difference(off.hdr, on.hdr);
    std::printf("[ measured ] %s: sphere at 12 m, %zu of %zu values differ, %zu off the sphere\n",
                method.c_str(), d.values, on.hdr.rgba.size(), d.offSubject);
    EXPECT_GT(d.values, 0u) << method << ": the sphere's curvature must reach the lighting";
    EXPECT_EQ(d.offSubject, 0u) << method << ": only the sphere's pixels change";
    agaa::test::expectNoValidationErrors(*device);
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, SpecularAA,
                         ::testing::Values("reference", "noaa", "fxaa", "simple-complex", "sbaa", "streaming",
                                           "agaa-samples", "agaa-accumulate"),
                         [](const auto& info) {
                             std::string name = info.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

// The truth is the material's own: a request with the option renders the same truth.
TEST(SpecularAATruth, TheConvergedTruthIgnoresIt) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene sphere = agaa::test::curvatureScene(true, 12.0f);
    agaa::FrameRenderer renderer(*device, sphere);
    agaa::RenderRequest r;
    r.method = "agaa";
    r.view.width = r.view.height = 32;
    r.view.exposure = 1.0f;
    agaa::TruthSettings truth;
    truth.supersampling = 2;
    truth.samples = 8;
    const agaa::ConvergedTruth plain = agaa::renderConvergedTruth(renderer, r, truth, nullptr);
    r.settings.effects.curvatureRoughness.enabled = true;
    const agaa::ConvergedTruth filtered = agaa::renderConvergedTruth(renderer, r, truth, nullptr);
    EXPECT_EQ(differing(plain.hdr, filtered.hdr), 0u);
    agaa::test::expectNoValidationErrors(*device);
}

} // namespace
