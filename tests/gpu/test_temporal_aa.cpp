// Temporal AA (--method taa; agaa/temporal/temporal_aa.h), validation on:
//  - the jitter: Halton (2, 3) inside the pixel, and a view jitter out of range refused;
//  - the reprojection: after a pure camera rotation every pixel's reprojected position (--debug
//    motion) is the rotation's own mapping, computed here in double from the two cameras'
//    matrices, whatever the pixel's depth (geometry and sky alike);
//  - the resolve: on a still camera, frame k's HDR is the CPU resolve in double
//    (temporal_resolve_reference.h) of the jittered no-AA frame k and the history frame k - 1 left;
//  - a still camera converges: after 16 frames the frame is far closer to the converged truth than
//    no-AA's.

#include "agaa/temporal/reprojection.h"
#include "engine/frame/frame_constants.h"
#include "engine/io/metrics.h"
#include "engine/io/tone_map.h"
#include "engine/scene/camera_framing.h"
#include "gpu_test_support.h"
#include "temporal_resolve_reference.h"
#include "tools/harness/converged_truth.h"
#include "tools/harness/frame_renderer.h"
#include "tools/scenes/adversarial_scenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

constexpr uint32_t kSize = 64;

TEST(TemporalJitter, HaltonPointsLieInsideThePixelAndRepeatAfterThePhases) {
    EXPECT_DOUBLE_EQ(agaa::radicalInverse(1, 2), 0.5);
    EXPECT_DOUBLE_EQ(agaa::radicalInverse(3, 2), 0.75);
    EXPECT_NEAR(agaa::radicalInverse(5, 3), 7.0 / 9.0, 1e-15); // 5 = 12 in base 3: 2/3 + 1/9
    for (uint64_t f = 0; f < 16; ++f) {
        const glm::vec2 j = agaa::haltonJitter(f, 8);
        EXPECT_GT(j.x, -0.5f);
        EXPECT_LT(j.x, 0.5f);
        EXPECT_GT(j.y, -0.5f);
        EXPECT_LT(j.y, 0.5f);
        EXPECT_EQ(j, agaa::haltonJitter(f + 8, 8)) << "8 phases";
    }
    EXPECT_NE(agaa::haltonJitter(0, 8), agaa::haltonJitter(1, 8));
    eng::scene::Camera camera;
    eng::frame::ViewSettings view;
    view.jitter = {0.6f, 0.0f};
    EXPECT_THROW(
        eng::frame::makeFrameConstants(std::span(&camera, 1), 0, view, eng::frame::makeSamplePattern(1)),
        std::invalid_argument);
}

agaa::RenderRequest taaRequest(const std::string& debug = "", const std::string& method = "taa") {
    agaa::RenderRequest r;
    r.method = method;
    r.settings.debug = debug;
    r.view.width = r.view.height = kSize;
    r.view.exposure = 1.0f;
    return r;
}

// Pixel-space position of a view-space direction through `proj` (Vulkan NDC: y down the rows).
glm::dvec2 projectDirection(const glm::dmat4& proj, const glm::dvec3& direction, double w, double h) {
    const glm::dvec4 clip = proj * glm::dvec4(direction, 0.0);
    return {(clip.x / clip.w * 0.5 + 0.5) * w, (clip.y / clip.w * 0.5 + 0.5) * h};
}

// taa reads one depth per pixel, agaa-taa AGAA's 4x layered per-sample depth (resolve_ms.comp).
class TemporalRotation : public ::testing::TestWithParam<const char*> {};

TEST_P(TemporalRotation, APureCameraRotationReprojectsEveryPixelExactly) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadTestScene("chainlink");
    agaa::FrameRenderer renderer(*device, scene);
    agaa::RenderRequest r = taaRequest("motion", GetParam());
    const glm::mat4 viewA = scene.cameras.at(0).view;
    // About the camera's own centre: yaw 1.3 degrees and pitch 0.4 (view-space axes).
    const glm::mat4 turn = glm::rotate(glm::rotate(glm::mat4(1.0f), glm::radians(1.3f), glm::vec3(0, 1, 0)),
                                       glm::radians(0.4f), glm::vec3(1, 0, 0));
    const glm::mat4 viewB = turn * viewA;
    r.view.viewOverride = viewA;
    const agaa::RenderResult first = renderer.render(r); // frame 0: the history
    r.view.viewOverride = viewB;
    const agaa::RenderResult motion = renderer.render(r);

    const eng::scene::Camera& cam = scene.cameras.at(0);
    const glm::dmat4 proj(eng::frame::reversedZPerspective(cam.yfov, 1.0f, cam.znear, cam.zfar));
    const glm::dmat4 bToA = glm::dmat4(viewA) * glm::inverse(glm::dmat4(viewB));
    uint32_t checked = 0, inside = 0, wrong = 0, skyWrong = 0, geometry = 0, seenByA = 0;
    double worst = 0.0, worstDistance = 0.0;
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
            // The pixel centre's ray in B's view space, then in A's.
            const glm::dvec2 ndc((x + 0.5) / kSize * 2.0 - 1.0, (y + 0.5) / kSize * 2.0 - 1.0);
            const glm::dvec3 rayB(ndc.x / proj[0][0], ndc.y / proj[1][1], -1.0);
            const glm::dvec2 expected =
                projectDirection(proj, glm::dvec3(bToA * glm::dvec4(rayB, 0.0)), kSize, kSize);
            const bool expectInside =
                expected.x >= 0.0 && expected.y >= 0.0 && expected.x <= kSize && expected.y <= kSize;
            const float* m = &motion.hdr.rgba[(size_t(y) * kSize + x) * 4];
            ++checked;
            if (expectInside) ++inside;
            // A pixel within a thousandth of a pixel of the border may fall either side.
            const bool nearBorder =
                std::min({std::abs(expected.x), std::abs(expected.y), std::abs(expected.x - kSize),
                          std::abs(expected.y - kSize)}) < 1e-3;
            if (!nearBorder && (m[2] == 1.0f) != expectInside) ++wrong;
            if (m[2] == 1.0f && expectInside)
                worst = std::max(worst, glm::length(glm::dvec2(m[0], m[1]) - expected));
            // The depths (the bench's ghosting mask, tools/agaa_bench/disocclusion.h): this camera's
            // distance in the display, the point's distance from A in w; 0 for the sky.
            const double distanceB = motion.display.rgba[(size_t(y) * kSize + x) * 4];
            if (distanceB == 0.0) {
                if (m[3] != 0.0f) ++skyWrong;
            } else if (m[2] == 1.0f) {
                ++geometry;
                const double distanceA = -(bToA * glm::dvec4(rayB * distanceB, 1.0)).z;
                worstDistance = std::max(worstDistance, std::abs(double(m[3]) - distanceA) / distanceA);
                // A rotation hides nothing: frame A's own distances hold the point within a pixel of
                // where it lands, but where one sample a pixel missed a thin rod.
                bool seen = false;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int ax = int(m[0]) + dx, ay = int(m[1]) + dy;
                        if (ax < 0 || ay < 0 || ax >= int(kSize) || ay >= int(kSize)) continue;
                        const double d = first.display.rgba[(size_t(ay) * kSize + ax) * 4];
                        seen = seen || std::abs(d - distanceA) <= 0.02 * distanceA;
                    }
                if (seen) ++seenByA;
            }
        }
    std::printf(
        "[ measured ] %s, rotation: %u of %u pixels reproject inside the previous frame; worst position "
        "error %.2e pixels\n",
        GetParam(), inside, checked, worst);
    EXPECT_GT(inside, checked / 2);
    EXPECT_EQ(wrong, 0u) << "a pixel found where the rotation leaves the frame, or lost inside it";
    EXPECT_LT(worst, 2e-3) << "a rotation's reprojection does not depend on depth: it must be exact";
    std::printf("[ measured ] %s: %u geometry pixels, worst relative error of the distance from the previous "
                "camera %.2e; frame A saw %u of their points within a pixel\n",
                GetParam(), geometry, worstDistance, seenByA);
    EXPECT_GT(geometry, 0u);
    EXPECT_LT(worstDistance, 1e-4) << "w must be the point's distance along the previous camera's axis";
    EXPECT_EQ(skyWrong, 0u) << "the sky has no distance";
    EXPECT_GT(seenByA, geometry * 97 / 100) << "frame A's distances (display) must be what it saw";
    agaa::test::expectNoValidationErrors(*device);
}

INSTANTIATE_TEST_SUITE_P(Methods, TemporalRotation, ::testing::Values("taa", "agaa-taa"),
                         [](const auto& info) {
                             std::string name = info.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

TEST(TemporalAA, OnAStillCameraEachFrameIsTheCpuResolveOfItsInputs) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadTestScene("chainlink");
    agaa::FrameRenderer renderer(*device, scene);
    agaa::RenderRequest taa = taaRequest();
    agaa::RenderRequest noaa = taaRequest();
    noaa.method = "noaa";
    agaa::RenderResult history = renderer.render(taa); // frame 0: the jittered no-AA frame alone
    double worst = 0.0;
    const auto compare = [&](const eng::io::ImageF& frame, const eng::io::ImageF& expected) {
        for (size_t i = 0; i < frame.rgba.size(); ++i)
            if (i % 4 != 3)
                worst = std::max(worst, std::abs(double(frame.rgba[i]) - expected.rgba[i]) /
                                            std::max(1.0, std::abs(double(expected.rgba[i]))));
    };
    for (uint64_t k = 1; k <= 4; ++k) {
        noaa.view.jitter = agaa::haltonJitter(k, 8);
        const agaa::RenderResult current = renderer.render(noaa);
        const agaa::RenderResult frame = renderer.render(taa);
        const double alpha = std::max(1.0 / double(k + 1), 0.1);
        compare(frame.hdr, agaa::test::temporalResolveStill(current.hdr, history.hdr, alpha, 1.0, true));
        compare(frame.display,
                agaa::test::temporalResolveStill(current.display, history.display, alpha, 1.0, false));
        double moved = 0.0;
        for (size_t i = 0; i < frame.hdr.rgba.size(); ++i)
            moved = std::max(moved, double(std::abs(frame.hdr.rgba[i] - current.hdr.rgba[i])));
        EXPECT_GT(moved, 1e-3) << "frame " << k << " must blend a history";
        history = frame;
    }
    std::printf(
        "[ measured ] resolve (HDR and display) against its CPU twin over 4 frames: worst relative error "
        "%.2e\n",
        worst);
    // Float against double: the box's sigma comes from E[x^2] - E[x]^2, whose float rounding leaves
    // up to sqrt(1.2e-7) |x|, 3.5e-4 |x|, where the neighbourhood is flat (the clip moves by that);
    // and the reprojected centre is off by ~1e-5 pixels, which mixes that much of a neighbour in.
    EXPECT_LT(worst, 1e-3);
    agaa::test::expectNoValidationErrors(*device);
}

TEST(TemporalAA, AStillCameraConvergesTowardsTheTruth) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadTestScene("chainlink");
    agaa::FrameRenderer renderer(*device, scene);
    agaa::RenderRequest taa = taaRequest();
    taa.timedFrames = 16;
    agaa::RenderRequest noaa = taaRequest();
    noaa.method = "noaa";
    agaa::TruthSettings settings;
    settings.supersampling = 4;
    const agaa::ConvergedTruth truth = agaa::renderConvergedTruth(renderer, noaa, settings, nullptr);
    const auto error = [&](const agaa::RenderResult& r) {
        return eng::io::rmse(eng::io::srgbEncoded(r.display), eng::io::srgbEncoded(truth.display));
    };
    const double noaaError = error(renderer.render(noaa)), taaError = error(renderer.render(taa));
    std::printf(
        "[ measured ] chainlink %ux%u, display RMSE against the truth (its own %.4f): no-AA %.4f, TAA "
        "after 16 frames %.4f\n",
        kSize, kSize, truth.errorEstimate, noaaError, taaError);
    EXPECT_LT(taaError, 0.6 * noaaError);
    agaa::test::expectNoValidationErrors(*device);
}

// AGAA + TAA (the Unreal talk's combination): AGAA's resolve through the same temporal pass. On a
// still camera its 8th frame is at least as close to the truth as AGAA's own frame, within the
// truth's own error, and it is not AGAA's frame (the jitter and the history moved it).
TEST(TemporalAA, AgaaThroughTheTemporalPassIsNoWorseThanAgaa) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadTestScene("chainlink");
    agaa::FrameRenderer renderer(*device, scene);
    agaa::RenderRequest combined = taaRequest("", "agaa-taa");
    combined.timedFrames = 8;
    agaa::RenderRequest agaaAlone = taaRequest("", "agaa");
    agaa::TruthSettings settings;
    settings.supersampling = 4;
    const agaa::ConvergedTruth truth = agaa::renderConvergedTruth(renderer, agaaAlone, settings, nullptr);
    const auto error = [&](const agaa::RenderResult& r) {
        return eng::io::rmse(eng::io::srgbEncoded(r.display), eng::io::srgbEncoded(truth.display));
    };
    const agaa::RenderResult a = renderer.render(agaaAlone), c = renderer.render(combined);
    const double agaaError = error(a), combinedError = error(c);
    std::printf(
        "[ measured ] chainlink %ux%u, display RMSE against the truth (its own %.4f): AGAA (8, 2) %.4f, "
        "AGAA + TAA after 8 frames %.4f\n",
        kSize, kSize, truth.errorEstimate, agaaError, combinedError);
    EXPECT_LE(combinedError, agaaError + truth.errorEstimate);
    EXPECT_NE(a.hdr.rgba, c.hdr.rgba);
    for (float v : c.hdr.rgba)
        ASSERT_TRUE(std::isfinite(v));
    agaa::test::expectNoValidationErrors(*device);
}

} // namespace
