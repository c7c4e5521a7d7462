// AggregateSettings::programs (agaa/common/program_overrides.h): a build that replaces one of
// AGAA's shipping programs runs in its place, through the layout reflected from it; the shipping
// code handed in as its own replacement changes no bit; a name AGAA does not run is refused by
// name. agaa-timings --breakdown times its part-removed builds this way.

#include "agaa/method_settings.h"
#include "gpu_test_support.h"
#include "shaders/agaa/lighting_gbuffer_shadow_comp.h"
#include "shaders/tests/agaa_lighting_gbuffer_shadow_no_shading_comp.h"
#include "shaders/tests/agaa_lighting_gbuffer_shadow_no_shadow_filter_comp.h"
#include "tools/harness/frame_renderer.h"
#include "tools/scenes/adversarial_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace {

// The plane's sun casts shadows and nothing is emissive: the samples path lights it with
// agaa/lighting_gbuffer_shadow.comp.
agaa::RenderRequest planeRequest() {
    agaa::RenderRequest r;
    r.method = "agaa-samples";
    r.view.width = r.view.height = 64;
    return r;
}

TEST(AgaaProgramOverrides, ReplaceTheShippingProgramAndOnlyIt) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadTestScene("plane");
    agaa::FrameRenderer renderer(*device, scene);
    const agaa::RenderResult shipping = renderer.render(planeRequest());

    agaa::RenderRequest same = planeRequest();
    same.settings.agaa.programs["agaa/lighting_gbuffer_shadow.comp"] = kAgaaLightingGbufferShadowComp;
    const agaa::RenderResult replacedBySelf = renderer.render(same);
    EXPECT_EQ(replacedBySelf.hdr.rgba, shipping.hdr.rgba) << "the shipping build as its own replacement";
    EXPECT_EQ(replacedBySelf.shadingEvents, shipping.shadingEvents);

    agaa::RenderRequest noShading = planeRequest();
    noShading.settings.agaa.programs["agaa/lighting_gbuffer_shadow.comp"] =
        kTestsAgaaLightingGbufferShadowNoShadingComp;
    const agaa::RenderResult replaced = renderer.render(noShading);
    // Step 3 compiled out: no aggregate is lit, so no covered pixel keeps the shipping colour.
    size_t differ = 0, covered = 0;
    for (size_t p = 0; p < shipping.shadingEvents.size(); ++p) {
        if (shipping.shadingEvents[p] == 0) continue;
        ++covered;
        for (int ch = 0; ch < 3; ++ch)
            if (replaced.hdr.rgba[p * 4 + ch] != shipping.hdr.rgba[p * 4 + ch]) {
                ++differ;
                break;
            }
    }
    ASSERT_GT(covered, shipping.shadingEvents.size() / 2) << "the plane must cover most of the frame";
    EXPECT_EQ(differ, covered) << "the replacement must run in place of the shipping lighting";
    agaa::test::expectNoValidationErrors(*device);
}

// agaa-timings --breakdown's build without the shadow footprint (its "shadow-map taps" figure)
// lights every footprint fully: on foliage under the sun, with no pixel left to the per-sample pass
// (whose own taps it keeps), no pixel gets darker and the shadowed ones get brighter.
TEST(AgaaProgramOverrides, TheBuildWithoutTheShadowFootprintLightsEveryAggregateUnshadowed) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadTestScene("foliage");
    agaa::FrameRenderer renderer(*device, scene);
    // The samples path lights it with agaa/lighting_gbuffer_shadow.comp: the sun casts shadows and
    // nothing is emissive.
    agaa::RenderRequest r;
    r.method = "agaa-samples";
    r.view.width = r.view.height = 64;
    r.settings.agaa.tolerance = agaa::kToleranceNever;
    r.settings.agaa.aliasLimit = agaa::kAliasLimitNone;
    const agaa::RenderResult shipping = renderer.render(r);
    r.settings.agaa.programs["agaa/lighting_gbuffer_shadow.comp"] =
        kTestsAgaaLightingGbufferShadowNoShadowFilterComp;
    const agaa::RenderResult unshadowed = renderer.render(r);
    // Pixels with a channel darker, and with a channel brighter, than the shipping pass's.
    size_t darker = 0, brighter = 0;
    const size_t pixels = shipping.hdr.rgba.size() / 4;
    for (size_t p = 0; p < pixels; ++p) {
        bool lower = false, higher = false;
        for (size_t ch = 0; ch < 3; ++ch) {
            const float a = shipping.hdr.rgba[p * 4 + ch], b = unshadowed.hdr.rgba[p * 4 + ch];
            // Visibility 1 only adds irradiance; the rest of the shading is the same code on the
            // same values, up to the order of a sum's rounding.
            lower = lower || b < a - 1e-5f * std::max(1.0f, a);
            higher = higher || b > a + 1e-3f * std::max(1.0f, a);
        }
        darker += lower ? 1 : 0;
        brighter += higher ? 1 : 0;
    }
    EXPECT_EQ(darker, 0u);
    EXPECT_GT(brighter, pixels / 20) << "the sun's shadows cover foliage's ground";
    agaa::test::expectNoValidationErrors(*device);
}

TEST(AgaaProgramOverrides, ANameAgaaDoesNotRunIsRefusedByName) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadTestScene("plane");
    agaa::FrameRenderer renderer(*device, scene);
    agaa::RenderRequest r = planeRequest();
    r.settings.agaa.programs["agaa/lighting_gbufer.comp"] = kAgaaLightingGbufferShadowComp; // misspelt
    try {
        renderer.render(r);
        FAIL() << "a replacement for a program AGAA does not run must be refused";
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("'agaa/lighting_gbufer.comp'"), std::string::npos) << what;
        EXPECT_NE(what.find("agaa/lighting_gbuffer_shadow.comp"), std::string::npos)
            << "the message lists the names AGAA runs: " << what;
    }
    agaa::test::expectNoValidationErrors(*device);
}

} // namespace
