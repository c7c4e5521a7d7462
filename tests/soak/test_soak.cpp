// Soak (issue 19): 1,000 frames at 64x64 on one device, switching method and settings every 50
// frames, twice through the same 10 configurations. The first cycle creates every pipeline and
// cached technique; over the second, resident memory and the live buffers and images must stay
// flat (a per-frame or per-switch leak would grow both). The frames run under the validation
// layer, and the device deleter checks its destruction too.

#include "gpu_test_support.h"
#include "tools/harness/frame_renderer.h"
#include "tools/scenes/adversarial_scenes.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <unistd.h>

namespace {

// Resident set size in bytes (/proc/self/statm, second field, in pages).
double residentBytes() {
    std::ifstream statm("/proc/self/statm");
    long size = 0, resident = 0;
    statm >> size >> resident;
    return double(resident) * double(sysconf(_SC_PAGESIZE));
}

// Growth allowed over the second cycle: allocator arenas and the driver's caches settle in steps.
constexpr double kMaxResidentGrowthBytes = 24.0 * 1024 * 1024;

TEST(Soak, AThousandFramesSwitchingSettingsHoldMemoryAndObjectsFlat) {
    auto device = agaa::test::makeValidatedDevice();
    eng::scene::Scene scene = eng::scene::loadTestScene("railings"); // a shadowed sun and 16 point lights
    agaa::FrameRenderer renderer(*device, scene);
    struct Config {
        const char* method;
        uint32_t n, c;
        const char* lighting = "auto";
        const char* routing = "samples";
    };
    const Config configs[] = {{"reference", 4, 1},
                              {"noaa", 1, 1},
                              {"simple-complex", 4, 1},
                              {"fxaa", 1, 1},
                              {"agaa", 8, 2},
                              {"agaa", 4, 4, "compact"},
                              {"agaa", 4, 1},
                              {"agaa", 4, 2, "registers", "fragment"},
                              {"simple-complex-naive", 4, 1},
                              {"agaa", 4, 3}};
    const uint32_t kFramesPerSwitch = 50;
    double residentAfterFirst = 0.0;
    int64_t liveAfterFirst = 0;
    uint32_t frames = 0;
    for (int cycle = 0; cycle < 2; ++cycle) {
        for (const Config& k : configs) {
            agaa::RenderRequest r;
            r.method = k.method;
            r.settings.samples = k.n;
            r.settings.aggregates = k.c;
            r.settings.agaa.shading =
                agaa::namedValue("agaaLighting", k.lighting, agaa::kAggregateShadingNames);
            r.settings.agaa.routing =
                agaa::namedValue("agaaRouting", k.routing, agaa::kAggregateRoutingNames);
            r.view.width = r.view.height = 64;
            r.timedFrames = kFramesPerSwitch;
            agaa::RenderResult result = renderer.render(r);
            frames += kFramesPerSwitch;
            ASSERT_EQ(result.display.width, 64u) << k.method;
        }
        if (cycle == 0) {
            residentAfterFirst = residentBytes();
            liveAfterFirst = device->liveResources();
        }
    }
    const double residentAfterSecond = residentBytes();
    const int64_t liveAfterSecond = device->liveResources();
    std::printf(
        "[ measured ] soak: %u frames; resident %.1f MB after the first cycle, %.1f MB after the second; "
        "live buffers and images %lld, %lld\n",
        frames, residentAfterFirst / 1048576.0, residentAfterSecond / 1048576.0,
        static_cast<long long>(liveAfterFirst), static_cast<long long>(liveAfterSecond));
    EXPECT_EQ(frames, 1000u);
    EXPECT_EQ(liveAfterSecond, liveAfterFirst) << "buffers or images leaked across a cycle of switches";
    EXPECT_LE(residentAfterSecond - residentAfterFirst, kMaxResidentGrowthBytes)
        << "resident memory grew over the second cycle";
    agaa::test::expectNoValidationErrors(*device);
}

} // namespace
