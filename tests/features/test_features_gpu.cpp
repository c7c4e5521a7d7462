// Issue 8 on lavapipe with validation: the passes and variants each technique runs follow the
// scene's features, and the effects themselves (shadows, alpha-to-coverage, per-sample emissive)
// do what they claim.

#include "engine/io/image.h"
#include "engine/io/metrics.h"
#include "engine/io/tone_map.h"
#include "gpu_test_support.h"
#include "shared/shadow.h"
#include "tools/harness/frame_renderer.h"
#include "tools/scenes/adversarial_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

namespace {

using eng::scene::Scene;

const char* kPerSampleMethods[] = {"reference", "simple-complex", "noaa"};
const char* kMethods[] = {"reference", "simple-complex", "noaa", "agaa"};

std::string prefixOf(const std::string& method) {
    return method;
} // pass names are "<method>.<pass>"

agaa::RenderResult
render(agaa::FrameRenderer& renderer, const std::string& method, uint32_t n, uint32_t size,
       bool forceAll = false,
       agaa::EffectSettings::ShadowFootprint footprint = agaa::EffectSettings{}.shadowFootprint) {
    agaa::RenderRequest r;
    r.method = method;
    r.settings.samples = n;
    r.settings.aggregates = 2;
    r.settings.effects.forceAll = forceAll;
    r.settings.effects.shadowFootprint = footprint;
    r.view.width = r.view.height = size;
    return renderer.render(r);
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}

std::vector<std::string> executed(const agaa::RenderResult& r) {
    std::vector<std::string> names;
    for (const auto& p : r.passes)
        names.push_back(p.name);
    return names;
}

std::string variantOf(const agaa::RenderResult& r, const std::string& effect) {
    for (const agaa::VariantChoice& v : r.variants)
        if (v.effect == effect) return v.variant;
    return "<missing>";
}

std::string describe(const agaa::RenderResult& r) {
    std::string s = "ran:";
    for (const std::string& p : executed(r))
        s += " " + p;
    s += "; culled:";
    for (const std::string& p : r.culledPasses)
        s += " " + p;
    s += "; variants:";
    for (const auto& v : r.variants)
        s += " " + v.effect + "=" + v.variant;
    return s;
}

// A wall at z = -10 facing the camera, an occluder at z = -5 in front of it, the sun travelling
// mostly along -z: the occluder's shadow falls on the wall beside it, in view. One material
// per surface; 0.6 grey, rough, dielectric.
Scene occluderScene(bool castsShadows) {
    Scene s = agaa::test::emptyScene("test:occluder");
    s.lights[0].castsShadows = castsShadows;
    s.lights[0].name = "sun";
    agaa::test::addRectangle(s, {-6, -6}, {6, 6}, -10.0f, 0);
    agaa::test::addRectangle(s, {-1, 0}, {0, 1}, -5.0f, 0);
    s.bounds = {{-6, -6, -10}, {6, 6, -5}};
    return s;
}

// Pixel of the view-space point (x, y, z) for the test camera (origin, yfov 0.8, square image).
glm::ivec2 pixelOf(glm::vec3 p, uint32_t size) {
    float t = std::tan(0.4f);
    float nx = p.x / (-p.z) / t, ny = p.y / (-p.z) / t;
    return {int((nx * 0.5f + 0.5f) * float(size)), int((0.5f - ny * 0.5f) * float(size))};
}

float luminance(const eng::io::ImageF& img, glm::ivec2 p) {
    const float* c = &img.rgba[(size_t(p.y) * img.width + size_t(p.x)) * 4];
    return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
}

eng::io::ImageF encoded(const eng::io::ImageF& display) {
    eng::io::ImageF out = display;
    for (size_t i = 0; i < out.rgba.size(); ++i)
        if (i % 4 != 3) out.rgba[i] = eng::io::linearToSrgb(out.rgba[i]);
    return out;
}

TEST(FeaturesGpu, NoShadowedLightMeansNoShadowPassAnywhere) {
    auto device = agaa::test::makeValidatedDevice();
    Scene scene = occluderScene(false);
    agaa::FrameRenderer renderer(*device, scene);
    for (const char* method : kMethods) {
        agaa::RenderResult r = render(renderer, method, method == std::string("noaa") ? 1 : 8, 32);
        const std::string shadowPass = prefixOf(method) + ".shadow";
        // Guards: the technique does not even add the pass, so it is neither run nor culled.
        EXPECT_FALSE(contains(executed(r), shadowPass)) << method << ": " << describe(r);
        EXPECT_FALSE(contains(r.culledPasses, shadowPass)) << method << ": " << describe(r);
        EXPECT_EQ(variantOf(r, "shadows"), "off") << method;
        EXPECT_EQ(variantOf(r, "alpha"), "opaque only") << method;
        EXPECT_EQ(variantOf(r, "emissive"), "off") << method;
        EXPECT_EQ(variantOf(r, "normal-maps"), "off") << method;
        EXPECT_EQ(variantOf(r, "light-culling"), "off") << method << ": directional light only";
        EXPECT_TRUE(eng::io::allFinite(r.hdr) && eng::io::allFinite(r.display)) << method;
    }
    agaa::test::expectNoValidationErrors(*device);
}

TEST(FeaturesGpu, ShadowedSunAddsTheShadowPassBeforeLightingAndDarkensTheWall) {
    auto device = agaa::test::makeValidatedDevice();
    Scene lit = occluderScene(false), shadowed = occluderScene(true);
    agaa::FrameRenderer litRenderer(*device, lit), shadowRenderer(*device, shadowed);
    const uint32_t size = 64;
    // The occluder's square (x -1..0, y 0..1 at z -5) projects along the sun onto the wall
    // (z -10) shifted by 5 * (d.x, d.y) / -d.z = (1, -1.5): its centre lands at (0.5, -1).
    const glm::ivec2 inShadow = pixelOf({0.5f, -1.0f, -10.0f}, size);
    const glm::ivec2 inLight = pixelOf({-3.0f, -3.0f, -10.0f}, size);
    for (const char* method : kMethods) {
        const uint32_t n = method == std::string("noaa") ? 1 : 8;
        agaa::RenderResult a = render(litRenderer, method, n, size);
        agaa::RenderResult b = render(shadowRenderer, method, n, size);
        const std::vector<std::string> ran = executed(b);
        const std::string shadowPass = prefixOf(method) + ".shadow",
                          lighting = prefixOf(method) + ".lighting";
        ASSERT_TRUE(contains(ran, shadowPass)) << method << ": " << describe(b);
        EXPECT_LT(std::find(ran.begin(), ran.end(), shadowPass), std::find(ran.begin(), ran.end(), lighting))
            << method << ": the shadow map is rendered before lighting reads it";
        EXPECT_EQ(variantOf(b, "shadows").rfind("shadow map x1", 0), 0u)
            << method << ": " << variantOf(b, "shadows");
        // Without shadows the two wall points are lit alike; with them the shadowed one is dark
        // (the sun is the only light: nothing else reaches it).
        EXPECT_NEAR(luminance(a.display, inShadow), luminance(a.display, inLight), 0.05f) << method;
        EXPECT_GT(luminance(b.display, inLight), 0.1f) << method;
        EXPECT_LT(luminance(b.display, inShadow), 0.1f * luminance(b.display, inLight)) << method;
        EXPECT_NEAR(luminance(b.display, inLight), luminance(a.display, inLight), 0.01f)
            << method << ": no shadow acne on the lit wall";
        EXPECT_TRUE(eng::io::allFinite(b.hdr) && eng::io::allFinite(b.display)) << method;
    }
    agaa::test::expectNoValidationErrors(*device);
}

// Every AGAA footprint (statistics along the variance vector, taps at the aggregate's samples,
// adaptive) and every tap count darken the shadowed wall and leave the lit wall lit.
TEST(FeaturesGpu, AgaaShadowFootprintsAndTapCountsAllShadeTheOccluderScene) {
    auto device = agaa::test::makeValidatedDevice();
    Scene scene = occluderScene(true);
    agaa::FrameRenderer renderer(*device, scene);
    const uint32_t size = 64;
    const glm::ivec2 inShadow = pixelOf({0.5f, -1.0f, -10.0f}, size),
                     inLight = pixelOf({-3.0f, -3.0f, -10.0f}, size);
    for (auto footprint :
         {agaa::EffectSettings::ShadowFootprint::Statistics, agaa::EffectSettings::ShadowFootprint::Samples,
          agaa::EffectSettings::ShadowFootprint::Adaptive})
        for (uint32_t taps : {1u, 2u, 3u, 4u, 5u, 8u}) {
            agaa::RenderRequest r;
            r.method = "agaa";
            r.settings.samples = 8;
            r.settings.effects.shadowTaps = taps;
            r.settings.effects.shadowFootprint = footprint;
            r.view.width = r.view.height = size;
            agaa::RenderResult out = renderer.render(r);
            const std::string what =
                "footprint " + std::to_string(uint32_t(footprint)) + ", taps " + std::to_string(taps);
            EXPECT_GT(luminance(out.display, inLight), 0.1f) << what;
            EXPECT_LT(luminance(out.display, inShadow), 0.1f * luminance(out.display, inLight)) << what;
            EXPECT_TRUE(eng::io::allFinite(out.display)) << what;
        }
    agaa::test::expectNoValidationErrors(*device);
}

// The adaptive footprint (the default) changes only the aggregates a shadow edge crosses (its
// penumbra test's taps disagree), and there it gives what per-sample shading gives: every
// sample's own tap. On the occluder scene's flat grey wall, lit by the sun alone, AGAA's shading
// equals the reference's but for the shadow, so the error left on those pixels is the
// footprint's (the shadow's edges run along pixel rows 35 and 43, its outline inside rows 34..44
// and columns 31..40). Measured, accumulate / samples path: 7 / 7 pixels refined, their error
// 0.097 / 0.096 with the statistics alone and 9e-4 / 4e-7 adaptive; over the whole outline the
// adaptive image is 8.3e-4 / 1.6e-7 from the reference. (With Equation 1's distance, 17 / 18
// pixels were refined and the outline's error was the same: a flat pixel is one aggregate with
// the tangent-plane distance, and its footprint's taps agree on more of the edge.)
TEST(FeaturesGpu, AdaptiveShadowFootprintTapsEverySampleWhereAShadowEdgeCrossesTheAggregate) {
    auto device = agaa::test::makeValidatedDevice();
    Scene scene = occluderScene(true);
    agaa::FrameRenderer renderer(*device, scene);
    const uint32_t size = 64, n = 8;
    const agaa::RenderResult ref = render(renderer, "reference", n, size);
    for (const char* method : {"agaa-accumulate", "agaa-samples"}) {
        agaa::RenderResult byFootprint[2];
        int i = 0;
        for (auto footprint : {agaa::EffectSettings::ShadowFootprint::Statistics,
                               agaa::EffectSettings::ShadowFootprint::Adaptive})
            byFootprint[i++] = render(renderer, method, n, size, false, footprint);
        const eng::io::ImageF &statistics = byFootprint[0].hdr, &adaptive = byFootprint[1].hdr;
        size_t changed = 0, onTopEdge = 0, onBottomEdge = 0, awayFromTheOutline = 0;
        double statisticsError = 0.0, adaptiveError = 0.0, outlineError = 0.0;
        uint32_t outlinePixels = 0;
        const auto onOutline = [](uint32_t x, uint32_t y) {
            return y >= 34 && y <= 44 && x >= 31 && x <= 40;
        };
        for (size_t p = 0; p < size_t(size) * size; ++p) {
            const uint32_t x = uint32_t(p % size), y = uint32_t(p / size);
            if (onOutline(x, y)) {
                ++outlinePixels;
                for (size_t ch = 0; ch < 3; ++ch) {
                    const double d = double(adaptive.rgba[4 * p + ch]) - ref.hdr.rgba[4 * p + ch];
                    outlineError += d * d;
                }
            }
            bool same = true;
            for (size_t ch = 0; ch < 3; ++ch)
                same = same && statistics.rgba[4 * p + ch] == adaptive.rgba[4 * p + ch];
            if (same) continue;
            ++changed;
            onTopEdge += y == 35 ? 1 : 0;
            onBottomEdge += y == 43 ? 1 : 0;
            awayFromTheOutline += onOutline(x, y) ? 0 : 1;
            for (size_t ch = 0; ch < 3; ++ch) {
                const double want = ref.hdr.rgba[4 * p + ch];
                statisticsError +=
                    (statistics.rgba[4 * p + ch] - want) * (statistics.rgba[4 * p + ch] - want);
                adaptiveError += (adaptive.rgba[4 * p + ch] - want) * (adaptive.rgba[4 * p + ch] - want);
            }
        }
        statisticsError = changed ? std::sqrt(statisticsError / double(3 * changed)) : 0.0;
        adaptiveError = changed ? std::sqrt(adaptiveError / double(3 * changed)) : 0.0;
        std::printf("%s: %zu of %u pixels changed; their linear RMSE against the reference: statistics %.4g, "
                    "adaptive %.4g\n",
                    method, changed, size * size, statisticsError, adaptiveError);
        outlineError = std::sqrt(outlineError / double(3 * outlinePixels));
        std::printf("%s: the adaptive image's linear RMSE over the shadow's outline %.4g\n", method,
                    outlineError);
        // Refined on both of the square's horizontal edges, and nowhere off its outline.
        EXPECT_GE(onTopEdge, 1u) << method << ": no aggregate on the shadow's top edge was refined";
        EXPECT_GE(onBottomEdge, 1u) << method << ": no aggregate on the shadow's bottom edge was refined";
        EXPECT_EQ(awayFromTheOutline, 0u) << method << ": refined away from the shadow's edge";
        EXPECT_LT(adaptiveError, 0.05 * statisticsError) << method;
        // And the outline is right where nothing was refined too: per-sample shading's answer.
        EXPECT_LT(outlineError, 2.0e-3) << method;
        EXPECT_TRUE(eng::io::allFinite(adaptive)) << method;
    }
    agaa::test::expectNoValidationErrors(*device);
}

TEST(FeaturesGpu, ShadowPassIsCulledByTheGraphWhenNothingReadsIt) {
    auto device = agaa::test::makeValidatedDevice();
    Scene scene = occluderScene(true);
    agaa::FrameRenderer renderer(*device, scene);
    agaa::RenderRequest r;
    r.method = "agaa";
    r.settings.samples = 8;
    r.settings.debug = "aggregates"; // the debug view replaces lighting: nobody reads the map
    r.view.width = r.view.height = 32;
    agaa::RenderResult out = renderer.render(r);
    EXPECT_TRUE(contains(out.culledPasses, "agaa.shadow")) << describe(out);
    EXPECT_FALSE(contains(executed(out), "agaa.shadow")) << describe(out);
    agaa::test::expectNoValidationErrors(*device);
}

// A masked quad whose base-colour alpha is 0 on its left half and 1 on its right half, over a
// dark wall. Every alpha path (discard at n = 1, alpha-to-coverage at n = 8) keeps the right
// half and drops the left one; without alpha handling the left half would show the quad.
TEST(FeaturesGpu, MaskedMaterialsUseAlphaToCoverageWithMsaaAndDiscardAtOneSample) {
    auto device = agaa::test::makeValidatedDevice();
    Scene scene = agaa::test::emptyScene("test:masked");
    scene.materials[0].baseColorFactor = {0.05f, 0.05f, 0.05f, 1.0f}; // wall
    eng::scene::Material leaf;
    leaf.baseColorFactor = {1, 1, 1, 1};
    leaf.metallicFactor = 0.0f;
    leaf.alphaMode = eng::scene::AlphaMode::Mask;
    leaf.alphaCutoff = 0.5f;
    leaf.doubleSided = true;
    leaf.baseColorTexture = 0;
    scene.materials.push_back(leaf);
    eng::scene::Texture t{"halfAlpha", 16, 16, true, {}};
    for (uint32_t y = 0; y < 16; ++y)
        for (uint32_t x = 0; x < 16; ++x)
            for (uint8_t v : {uint8_t(255), uint8_t(255), uint8_t(255), uint8_t(x < 8 ? 0 : 255)})
                t.rgba8.push_back(v);
    scene.textures.push_back(t);
    agaa::test::addRectangle(scene, {-6, -6}, {6, 6}, -10.0f, 0);
    agaa::test::addRectangle(scene, {-2, -2}, {2, 2}, -6.0f, 1);
    // uv across the quad: u = 0 on the left, 1 on the right.
    const size_t quad = scene.vertices.size() - 4;
    const glm::vec2 uvs[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    for (int i = 0; i < 4; ++i)
        scene.vertices[quad + i].uv = uvs[i];
    scene.bounds = {{-6, -6, -10}, {6, 6, -6}};
    agaa::FrameRenderer renderer(*device, scene);
    const uint32_t size = 64;
    const glm::ivec2 left = pixelOf({-1.0f, 0.0f, -6.0f}, size), right = pixelOf({1.0f, 0.0f, -6.0f}, size);
    for (const char* method : kMethods) {
        const uint32_t n = method == std::string("noaa") ? 1 : 8;
        agaa::RenderResult r = render(renderer, method, n, size);
        EXPECT_EQ(variantOf(r, "alpha"), n > 1 ? "alpha-to-coverage" : "discard") << method;
        const float bright = luminance(r.display, right), dark = luminance(r.display, left);
        EXPECT_GT(bright, 4.0f * dark)
            << method << ": the opaque half is drawn, the transparent half shows the dark wall";
        // The alpha edge (u = 0.5, x = 0) runs through pixels of one surface: only alpha-to-coverage
        // gives them partial coverage (discard keeps all samples of a pixel or none).
        uint32_t partial = 0;
        for (int x = left.x; x <= right.x; ++x) {
            float l = luminance(r.display, {x, left.y});
            partial += (l > dark + 0.2f * (bright - dark) && l < dark + 0.8f * (bright - dark)) ? 1u : 0u;
        }
        if (n > 1) {
            EXPECT_GE(partial, 1u) << method << ": alpha-to-coverage anti-aliases the alpha edge";
        } else
            EXPECT_EQ(partial, 0u) << method << ": discard leaves a hard alpha edge";
        EXPECT_TRUE(eng::io::allFinite(r.display)) << method;
    }
    agaa::test::expectNoValidationErrors(*device);
}

// Issue 16: KHR_texture_transform on the GPU. A quad textured red on the left half of its
// texture and green on the right: with offset (0.5, 0) the quad's left half shows green and its
// right half red (the sampler repeats); with scale (1, 1) and rotation pi about the origin,
// uv' = -uv, the halves swap too; reading TEXCOORD_1 that mirrors u swaps them as well. The
// variant is reported only when a material uses a transform or the second set. Vertex colours
// (COLOR_0) multiply the base colour: a blue-tinted quad loses its red.
TEST(FeaturesGpu, TextureTransformMovesTheTextureOnTheGpu) {
    auto device = agaa::test::makeValidatedDevice();
    std::map<std::string, float> untintedRed; // case 0's red at the quad's left half, per method
    for (int c = 0; c < 5; ++c) {
        Scene scene = agaa::test::emptyScene("test:texture-transform");
        eng::scene::Material m;
        m.baseColorFactor = {1, 1, 1, 1};
        m.metallicFactor = 0.0f;
        m.doubleSided = true;
        m.baseColorTexture = 0;
        if (c == 1) m.textureTransforms[0].offset = {0.5f, 0.0f};
        if (c == 2) m.textureTransforms[0].rotation = 3.14159265f;
        if (c == 3) m.textureTransforms[0].texCoord = 1;
        scene.materials.push_back(m);
        eng::scene::Texture t{"halves", 16, 16, true, {}};
        for (uint32_t y = 0; y < 16; ++y)
            for (uint32_t x = 0; x < 16; ++x)
                for (uint8_t v :
                     {uint8_t(x < 8 ? 255 : 0), uint8_t(x < 8 ? 0 : 255), uint8_t(0), uint8_t(255)})
                    t.rgba8.push_back(v);
        scene.textures.push_back(t);
        agaa::test::addRectangle(scene, {-2, -2}, {2, 2}, -6.0f, 1);
        const size_t quad = scene.vertices.size() - 4;
        const glm::vec2 uvs[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
        for (int i = 0; i < 4; ++i) {
            scene.vertices[quad + i].uv = uvs[i];
            scene.vertices[quad + i].uv1 = {1.0f - uvs[i].x, uvs[i].y};
            if (c == 4) scene.vertices[quad + i].color = {0.0f, 1.0f, 1.0f, 1.0f};
        }
        scene.bounds = {{-2, -2, -6}, {2, 2, -6}};
        agaa::FrameRenderer renderer(*device, scene);
        const glm::ivec2 left = pixelOf({-1.0f, 0.0f, -6.0f}, 64), right = pixelOf({1.0f, 0.0f, -6.0f}, 64);
        for (const char* method : kMethods) {
            const agaa::RenderResult r = render(renderer, method, method == std::string("noaa") ? 1 : 8, 64);
            EXPECT_EQ(variantOf(r, "texture-transform"), c == 0 || c == 4 ? "off" : "KHR_texture_transform")
                << method;
            const float red = r.hdr.rgba[(size_t(left.y) * 64 + left.x) * 4];
            if (c == 0) untintedRed[method] = red;
            if (c == 4) {
                // What is left is the white specular (F0 = 0.04), a few % of the diffuse red.
                EXPECT_LT(red, 0.1f * untintedRed[method])
                    << method << ": COLOR_0 = (0, 1, 1) removes the red";
                continue;
            }
            auto redOverGreen = [&](glm::ivec2 p) {
                const float* px = &r.hdr.rgba[(size_t(p.y) * 64 + p.x) * 4];
                return px[0] > 4.0f * px[1];
            };
            const bool swapped = c != 0 && c != 4;
            EXPECT_EQ(redOverGreen(left), !swapped) << method << " case " << c << ": the quad's left half";
            EXPECT_EQ(redOverGreen(right), swapped) << method << " case " << c << ": the quad's right half";
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}

// Issue 16: alphaMode BLEND as translucency by coverage (paper section 3.6). A white quad of
// alpha 0.5 in front of a dark wall: with MSAA every pixel under it resolves to about half the
// quad and half the wall (alpha-to-coverage of the alpha: 2 of each 4x layer's samples); at one
// sample per pixel the ordered dither keeps exactly 8 of each 4x4 block. Without the path the quad
// would be drawn opaque and white.
TEST(FeaturesGpu, BlendedMaterialsAreTranslucentByCoverage) {
    auto device = agaa::test::makeValidatedDevice();
    Scene scene = agaa::test::emptyScene("test:blended");
    scene.materials[0].baseColorFactor = {0.05f, 0.05f, 0.05f, 1.0f}; // wall
    eng::scene::Material glass;
    glass.baseColorFactor = {1, 1, 1, 0.5f};
    glass.metallicFactor = 0.0f;
    glass.alphaMode = eng::scene::AlphaMode::Blend;
    glass.doubleSided = true;
    scene.materials.push_back(glass);
    agaa::test::addRectangle(scene, {-6, -6}, {6, 6}, -10.0f, 0);
    agaa::test::addRectangle(scene, {-2, -2}, {2, 2}, -6.0f, 1);
    scene.bounds = {{-6, -6, -10}, {6, 6, -6}};
    agaa::FrameRenderer renderer(*device, scene);
    const uint32_t size = 64;
    // The quad's opaque luminance, and the wall's, for the expected half-and-half resolve.
    Scene opaque = scene;
    opaque.materials[1].alphaMode = eng::scene::AlphaMode::Opaque;
    agaa::FrameRenderer opaqueRenderer(*device, opaque);
    const glm::ivec2 centre = pixelOf({0.0f, 0.0f, -6.0f}, size),
                     wallPixel = pixelOf({4.0f, 0.0f, -10.0f}, size);
    for (const char* method : kMethods) {
        const uint32_t n = method == std::string("noaa") ? 1 : 8;
        const agaa::RenderResult r = render(renderer, method, n, size);
        const agaa::RenderResult full = render(opaqueRenderer, method, n, size);
        EXPECT_EQ(variantOf(r, "blend"),
                  n > 1 ? "alpha-to-coverage of the alpha" : "4x4 ordered dither of the alpha")
            << method;
        const float wall = luminance(r.hdr, wallPixel), quad = luminance(full.hdr, centre);
        if (n > 1) {
            const float got = luminance(r.hdr, centre), half = 0.5f * (wall + quad);
            EXPECT_NEAR(got, half, 0.15f * (quad - wall)) << method << ": half the samples show the quad";
        } else {
            uint32_t kept = 0;
            for (int y = 0; y < 4; ++y)
                for (int x = 0; x < 4; ++x) {
                    const glm::ivec2 p = {(centre.x & ~3) + x, (centre.y & ~3) + y};
                    kept += luminance(r.hdr, p) > 0.5f * (wall + quad) ? 1u : 0u;
                }
            EXPECT_EQ(kept, 8u) << method << ": the dither keeps alpha x 16 pixels of a 4x4 block";
        }
        EXPECT_TRUE(eng::io::allFinite(r.display)) << method;
    }
    agaa::test::expectNoValidationErrors(*device);
}

// Seed 004: emissive stays per sample and is added after the aggregate resolve. An emissive
// square over a dark wall: AGAA matches the reference's per-sample resolve at its edges too.
TEST(FeaturesGpu, EmissiveIsKeptPerSampleAndMatchesTheReference) {
    auto device = agaa::test::makeValidatedDevice();
    Scene scene = agaa::test::emptyScene("test:emissive");
    scene.lights[0].intensity = 0.2f;
    eng::scene::Material glow = scene.materials[0];
    glow.emissiveFactor = {8.0f, 4.0f, 1.0f};
    scene.materials.push_back(glow);
    agaa::test::addRectangle(scene, {-6, -6}, {6, 6}, -10.0f, 0);
    agaa::test::addRectangle(scene, {-1.3f, -0.7f}, {1.1f, 1.6f}, -6.0f, 1);
    scene.bounds = {{-6, -6, -10}, {6, 6, -6}};
    agaa::FrameRenderer renderer(*device, scene);
    const uint32_t size = 48;
    agaa::RenderResult ref = render(renderer, "reference", 8, size);
    agaa::RenderResult agg = render(renderer, "agaa", 8, size);
    for (const agaa::RenderResult* r : {&ref, &agg})
        EXPECT_EQ(variantOf(*r, "emissive"), "per-sample emissive");
    const glm::ivec2 centre = pixelOf({0.0f, 0.5f, -6.0f}, size);
    EXPECT_GT(luminance(agg.display, centre), 0.8f) << "the emitter is bright";
    const double error = eng::io::rmse(encoded(agg.display), encoded(ref.display));
    std::printf("emissive square, n=8: AGAA c=2 vs reference tone-mapped RMSE %.5f\n", error);
    EXPECT_LT(error, 0.01) << "per-sample emissive: edges resolve like the reference's";
    agaa::test::expectNoValidationErrors(*device);
}

TEST(FeaturesGpu, ForcingEveryEffectAddsThePassesAndVariants) {
    auto device = agaa::test::makeValidatedDevice();
    Scene scene = occluderScene(false);
    agaa::FrameRenderer renderer(*device, scene);
    for (const char* method : {"reference", "agaa"}) {
        agaa::RenderResult r = render(renderer, method, 8, 32, true);
        EXPECT_TRUE(contains(executed(r), std::string(method) + ".shadow")) << describe(r);
        EXPECT_EQ(variantOf(r, "alpha"), "alpha-to-coverage") << method;
        EXPECT_EQ(variantOf(r, "emissive"), "per-sample emissive") << method;
        EXPECT_EQ(variantOf(r, "normal-maps"), "fetch + Toksvig roughness") << method;
        EXPECT_EQ(variantOf(r, "light-culling"), "tiled") << method;
        EXPECT_TRUE(eng::io::allFinite(r.display)) << method;
    }
    agaa::test::expectNoValidationErrors(*device);
}

TEST(FeaturesGpu, BuiltinFoliageRunsShadowsAndAlphaToCoverage) {
    auto device = agaa::test::makeValidatedDevice();
    Scene scene = eng::scene::loadTestScene("foliage");
    agaa::FrameRenderer renderer(*device, scene);
    for (const char* method : kPerSampleMethods) {
        const uint32_t n = method == std::string("noaa") ? 1 : 8;
        agaa::RenderResult r = render(renderer, method, n, 32);
        EXPECT_TRUE(contains(executed(r), std::string(method) + ".shadow")) << describe(r);
        EXPECT_EQ(variantOf(r, "alpha"), n > 1 ? "alpha-to-coverage" : "discard") << method;
        EXPECT_EQ(variantOf(r, "light-culling"), "tiled") << method << ": foliage has point lights";
    }
    agaa::RenderResult r = render(renderer, "agaa", 8, 32);
    EXPECT_TRUE(contains(executed(r), "agaa.shadow")) << describe(r);
    EXPECT_EQ(variantOf(r, "alpha"), "alpha-to-coverage");
    EXPECT_TRUE(eng::io::allFinite(r.hdr) && eng::io::allFinite(r.display));
    agaa::test::expectNoValidationErrors(*device);
}

// Toksvig pre-filtering of the normal-map MIP chain (engine/frame/gpu_scene.cpp, common/
// material.glsl). Two small, far (minified: ~16 texels per pixel) smooth metal quads lit head-on,
// both normal-mapped: one with stripes of normals tilted +-30 degrees texel by texel, one flat.
// Every true normal of the striped quad is 30 degrees off the mirror direction, so it is dark;
// a box-filtered MIP averages its normals to the flat one and would show the same sharp
// highlight as the flat quad. Toksvig's shortened normal raises the roughness instead.
TEST(FeaturesGpu, ToksvigNormalMipsDimTheHighlightOfMinifiedBumps) {
    auto device = agaa::test::makeValidatedDevice();
    Scene scene = agaa::test::emptyScene("test:toksvig");
    scene.lights[0].direction = {0.0f, 0.0f, -1.0f};
    scene.lights[0].intensity = 3.0f;
    scene.materials[0].baseColorFactor = {0.02f, 0.02f, 0.02f, 1.0f}; // dark backdrop
    for (int stripes = 0; stripes < 2; ++stripes) {
        eng::scene::Texture t{stripes ? "stripes" : "flat", 64, 64, false, {}};
        const float s30 = 0.5f, c30 = 0.8660254f;
        for (uint32_t y = 0; y < 64; ++y)
            for (uint32_t x = 0; x < 64; ++x) {
                glm::vec3 n = stripes ? glm::vec3((x % 2) ? s30 : -s30, 0.0f, c30) : glm::vec3(0, 0, 1);
                for (int c = 0; c < 3; ++c)
                    t.rgba8.push_back(uint8_t(std::lround((n[c] * 0.5f + 0.5f) * 255.0f)));
                t.rgba8.push_back(255);
            }
        scene.textures.push_back(t);
        eng::scene::Material m;
        m.baseColorFactor = {1, 1, 1, 1};
        m.metallicFactor = 1.0f;
        m.roughnessFactor = 0.15f;
        m.normalTexture = stripes;
        scene.materials.push_back(m);
    }
    agaa::test::addRectangle(scene, {-6, -6}, {6, 6}, -12.0f, 0);
    agaa::test::addRectangle(scene, {-1.5f, -0.25f}, {-1.0f, 0.25f}, -10.0f, 2); // striped, left
    agaa::test::addRectangle(scene, {1.0f, -0.25f}, {1.5f, 0.25f}, -10.0f, 1);   // flat, right
    for (size_t q = 4; q < scene.vertices.size(); q += 4) {
        const glm::vec2 uvs[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
        for (int i = 0; i < 4; ++i) {
            scene.vertices[q + i].uv = uvs[i];
            scene.vertices[q + i].tangent = {1, 0, 0, 1};
        }
    }
    scene.bounds = {{-6, -6, -12}, {6, 6, -10}};
    agaa::FrameRenderer renderer(*device, scene);
    const uint32_t size = 64;
    for (const char* method : {"reference", "agaa"}) {
        agaa::RenderResult r = render(renderer, method, 8, size);
        EXPECT_EQ(variantOf(r, "normal-maps"), "fetch + Toksvig roughness") << method;
        const glm::ivec2 striped = pixelOf({-1.25f, 0.0f, -10.0f}, size),
                         flat = pixelOf({1.25f, 0.0f, -10.0f}, size);
        // Linear radiance: the tone map saturates the highlight of the flat quad.
        const float bumpy = luminance(r.hdr, striped), smooth = luminance(r.hdr, flat);
        std::printf("%s: minified striped quad radiance %.4f, flat quad %.4f\n", method, bumpy, smooth);
        // Without Toksvig the striped quad's MIP normal is the flat one: it would equal `smooth`.
        EXPECT_GT(smooth, 2.0f) << method
                                << ": the flat smooth metal reflects the light near its mirror direction";
        EXPECT_LT(bumpy, 0.4f * smooth) << method << ": the pre-filtered normal length raised the roughness";
        EXPECT_TRUE(eng::io::allFinite(r.display)) << method;
    }
    agaa::test::expectNoValidationErrors(*device);
}

// Where n is no more than the adaptive footprint's penumbra test taps (5 + shadowTaps), no
// aggregate has more samples than the test, and the adaptive footprint taps every one of them
// outright (agaa/lighting/shadowed_lights.glsl): the image `samples` gives with as many taps as n,
// bit for bit. Above it the test decides, and the two differ. Foliage under the sun: shadow edges
// cross many of its aggregates.
TEST(FeaturesGpu, AdaptiveShadowFootprintTapsEverySampleWhereNIsNoMoreThanItsTest) {
    auto device = agaa::test::makeValidatedDevice();
    Scene scene = eng::scene::loadTestScene("foliage");
    agaa::FrameRenderer renderer(*device, scene);
    for (auto [method, n] :
         {std::pair{"agaa-samples", 8u}, std::pair{"agaa-accumulate", 4u}, std::pair{"agaa-samples", 16u}}) {
        agaa::RenderResult adaptive = render(renderer, method, n, 64);
        agaa::RenderRequest r;
        r.method = method;
        r.settings.samples = n;
        r.settings.aggregates = 2;
        r.settings.effects.shadowFootprint = agaa::EffectSettings::ShadowFootprint::Samples;
        r.settings.effects.shadowTaps = std::min(n, 8u); // min(taps, k) = k: every sample at n <= 8
        r.view.width = r.view.height = 64;
        const agaa::RenderResult everySample = renderer.render(r);
        const std::string variant = variantOf(adaptive, "shadows");
        if (n <= shared::kAdaptiveCornerTaps + agaa::EffectSettings{}.shadowTaps) {
            EXPECT_EQ(adaptive.hdr.rgba, everySample.hdr.rgba) << method << " n=" << n;
            EXPECT_NE(variant.find("every one of the aggregate's samples"), std::string::npos) << variant;
        } else {
            EXPECT_NE(adaptive.hdr.rgba, everySample.hdr.rgba)
                << method << " n=" << n << ": above the test's taps the test decides";
            EXPECT_NE(variant.find("where they disagree"), std::string::npos) << variant;
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}

// Paper section 3.5.3 and the correlation failure mode of section 6: shadowed foliage at n = 8,
// AGAA c = 2 against the reference, with and without the sun's shadows. Measured and printed
// (agaa/common/README.md); the bound is the 1.5x. It holds here (96x96: 1.12 with the
// adaptive footprint, 1.75 with the statistical one) and at 256x256 (1.16; statistical 1.72).
TEST(FeaturesGpu, ShadowedFoliageErrorStaysWithinOneAndAHalfTimesTheUnshadowedError) {
    auto device = agaa::test::makeValidatedDevice();
    Scene shadowed = eng::scene::loadTestScene("foliage");
    Scene unshadowed = shadowed;
    for (auto& light : unshadowed.lights)
        light.castsShadows = false;
    // AGAA_FEATURES_SIZE / AGAA_SHADOW_TAPS re-run the measurement at another size / filter
    // (agaa/common/README.md lists the numbers).
    const char* sizeEnv = std::getenv("AGAA_FEATURES_SIZE");
    const char* tapsEnv = std::getenv("AGAA_SHADOW_TAPS");
    const uint32_t size = sizeEnv ? uint32_t(std::clamp(std::atoi(sizeEnv), 16, 1024)) : 96;
    const uint32_t taps = tapsEnv ? uint32_t(std::clamp(std::atoi(tapsEnv), 1, 4)) : 4;
    // "samples", "statistics" or "adaptive" (the default).
    const std::string footprintEnv =
        std::getenv("AGAA_SHADOW_FOOTPRINT") ? std::getenv("AGAA_SHADOW_FOOTPRINT") : "";
    const auto footprint = footprintEnv == "samples"      ? agaa::EffectSettings::ShadowFootprint::Samples
                           : footprintEnv == "statistics" ? agaa::EffectSettings::ShadowFootprint::Statistics
                                                          : agaa::EffectSettings::ShadowFootprint::Adaptive;
    double errors[2];
    int i = 0;
    for (Scene* scene : {&unshadowed, &shadowed}) {
        agaa::FrameRenderer renderer(*device, *scene);
        agaa::RenderResult ref = render(renderer, "reference", 8, size);
        agaa::RenderRequest r;
        // The accumulate path, for which the bound was set. The samples path measures 1.55 here
        // (unshadowed 0.0100, shadowed 0.0155: its unshadowed error is the lower one; issue 13).
        r.method = "agaa-accumulate";
        r.settings.samples = 8;
        r.settings.aggregates = 2;
        r.settings.effects.shadowTaps = taps;
        r.settings.effects.shadowFootprint = footprint;
        r.view.width = r.view.height = size;
        agaa::RenderResult agg = renderer.render(r);
        errors[i++] = eng::io::rmse(encoded(agg.display), encoded(ref.display));
    }
    std::printf("foliage %ux%u n=8 c=2, %u shadow taps: AGAA vs reference tone-mapped RMSE unshadowed %.5f, "
                "shadowed %.5f (ratio %.3f)\n",
                size, size, taps, errors[0], errors[1], errors[1] / errors[0]);
    EXPECT_GT(errors[0], 0.0);
    EXPECT_LE(errors[1], 1.5 * errors[0]);
    agaa::test::expectNoValidationErrors(*device);
}

} // namespace
