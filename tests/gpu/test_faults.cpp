// Faults (issue 19): every device memory allocation of an AGAA frame, and every submission, is
// made to fail in turn (DeviceOptions fault injection). Each must surface as an exception that
// names what failed, and leave nothing behind: the validation layer reports any object still
// alive when the device is destroyed, and the test device's deleter fails the test on it.

#include "engine/vk/check.h"
#include "gpu_test_support.h"
#include "tools/harness/frame_renderer.h"
#include "tools/scenes/adversarial_scenes.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace {

agaa::RenderRequest agaaFrame() {
    agaa::RenderRequest r;
    r.method = "agaa-samples"; // what auto picks on lavapipe
    r.settings.samples = 8;
    r.settings.aggregates = 2;
    r.view.width = r.view.height = 32;
    return r;
}

// Renders an AGAA frame of `scene` on a fresh validated device for k = 1, 2, ... with fault k
// injected by `inject`, until a frame renders; each failure must be a `Fault` exception, checked
// by `onFault`, and leave no validation message (the device deleter checks its destruction).
// Returns the first k that rendered.
template <class Fault, class Inject, class OnFault>
uint32_t sweepFaults(const eng::scene::Scene& scene, uint32_t limit, Inject inject, OnFault onFault) {
    for (uint32_t k = 1; k < limit; ++k) {
        eng::vk::DeviceOptions options;
        inject(options, k);
        auto device = agaa::test::makeValidatedDevice(options);
        bool rendered = false;
        try {
            agaa::FrameRenderer renderer(*device, scene);
            renderer.render(agaaFrame());
            rendered = true;
        } catch (const Fault& e) {
            onFault(std::string(e.what()));
        }
        agaa::test::expectNoValidationErrors(*device);
        if (rendered) return k;
    }
    ADD_FAILURE() << "the sweep must reach a frame with no fault within " << limit;
    return limit;
}

TEST(Faults, EveryAllocationOfAnAgaaFrameFailsCleanlyNamingTheResource) {
    eng::scene::Scene scene = eng::scene::loadTestScene("railings"); // shadow map, point lights
    std::set<std::string> failed;
    const uint32_t k = sweepFaults<eng::vk::OutOfMemory>(
        scene, 200, [](eng::vk::DeviceOptions& o, uint32_t n) { o.failAllocation = n; },
        [&](const std::string& what) {
            EXPECT_NE(what.find("cannot allocate"), std::string::npos) << what;
            EXPECT_NE(what.find("VK_ERROR_OUT_OF_DEVICE_MEMORY"), std::string::npos) << what;
            const size_t open = what.find('\''), close = what.rfind('\'');
            ASSERT_LT(open, close) << "the message must name the resource: " << what;
            failed.insert(what.substr(open + 1, close - open - 1));
        });
    std::printf("[ measured ] an AGAA (8, 2) frame of railings makes %u device memory allocations\n", k - 1);
    EXPECT_GE(failed.size(), 10u) << "the sweep must have failed many distinct resources";
    for (const char* name :
         {"scene.vertices", "frame.lights", "agaa.gbuffer.normal", "agaa.shadow.map", "readback.hdr"})
        EXPECT_TRUE(failed.count(name)) << name << " never failed in the sweep";
}

TEST(Faults, ADeviceLostAtAnySubmissionIsReportedAsSuch) {
    eng::scene::Scene scene = eng::scene::loadTestScene("railings");
    uint32_t losses = 0;
    const uint32_t k = sweepFaults<eng::vk::DeviceLost>(
        scene, 20, [](eng::vk::DeviceOptions& o, uint32_t n) { o.loseDeviceAtSubmit = n; },
        [&](const std::string& what) {
            ++losses;
            EXPECT_NE(what.find("VK_ERROR_DEVICE_LOST"), std::string::npos) << what;
        });
    EXPECT_EQ(losses, k - 1) << "every submission before the first clean frame must have reported the loss";
    EXPECT_GE(k, 2u) << "at least the texture upload and the frame itself are submissions";
}

} // namespace
