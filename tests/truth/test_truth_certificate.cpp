// The converged truth's certificate against a measurement (label `measure`: a measurement like
// the quality tests, left out of the sanitizer stage, where its 300 frames took six minutes).

#include "engine/io/metrics.h"
#include "engine/io/tone_map.h"
#include "gpu_test_support.h"
#include "tools/harness/converged_truth.h"
#include "tools/scenes/adversarial_scenes.h"
#include "truth_request.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace {

// The certificate is a measurement, so it is checked against one: each truth's estimated error
// against its measured distance from a truth at twice the k (k = 8 standing in for the limit
// of k = 2 and 4). On thin glossy metal (spikes, glints) and the default scene.
TEST(ConvergedTruthGpu, TheEstimateTracksTheDistanceToAFinerTruth) {
    auto device = agaa::test::makeValidatedDevice();
    for (const char* name : {"default", "spikes", "glints"}) {
        eng::scene::Scene scene = eng::scene::loadTestScene(name);
        agaa::FrameRenderer renderer(*device, scene);
        const agaa::ConvergedTruth fine =
            agaa::renderConvergedTruth(renderer, agaa::test::truthView(32, 32), {8, 32});
        const eng::io::ImageF limit = eng::io::srgbEncoded(fine.display);
        for (uint32_t k : {2u, 4u}) {
            const agaa::ConvergedTruth t =
                agaa::renderConvergedTruth(renderer, agaa::test::truthView(32, 32), {k, 32});
            const double distance = eng::io::rmse(eng::io::srgbEncoded(t.display), limit);
            std::printf("[ measured ] %-8s k=%u: estimate %.5f, display RMSE to k=8 %.5f (ratio %.2f); k=8's "
                        "estimate %.5f\n",
                        name, k, t.errorEstimate, distance, distance > 0 ? t.errorEstimate / distance : 0.0,
                        fine.errorEstimate);
            // Measured at 32x32: the estimate is 1.07 to 1.45 times the distance (k = 8's own error is
            // in the distance too). Below 0.8 it would flatter the truth; above 2 waste its samples.
            EXPECT_GE(t.errorEstimate, 0.8 * distance)
                << name << " k=" << k << ": the truth claims too little error";
            EXPECT_LE(t.errorEstimate, 2.0 * distance)
                << name << " k=" << k << ": the estimate is far too wide";
            // The linear mean's own estimate (its k^2 sub-pixel images' spread): one number, so the
            // distance to k = 8's mean is one draw of that error. It must lie within three of the
            // estimated standard deviations (with k = 8's own beside it), or the estimate flatters.
            const double meanDistance = std::abs(t.meanLuminance - fine.meanLuminance);
            std::printf("[ measured ] %-8s k=%u: the mean %.5f, its estimate +-%.5f, distance to k=8's %.5f "
                        "(k=8's own +-%.5f)\n",
                        name, k, t.meanLuminance, t.meanErrorEstimate, meanDistance, fine.meanErrorEstimate);
            EXPECT_LE(meanDistance, 3.0 * t.meanErrorEstimate + fine.meanErrorEstimate)
                << name << " k=" << k << ": the truth's mean claims too little error";
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}

} // namespace
