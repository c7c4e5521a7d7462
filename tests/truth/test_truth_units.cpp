// The converged truth without a device: the tile crop's projection, the accumulation of tiles into
// the output and its halves, the error estimate and the disk cache's refusals.

#include "engine/frame/frame_constants.h"
#include "engine/io/io_error.h"
#include "engine/io/tone_map.h"
#include "tools/harness/converged_truth.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace {

using eng::frame::ViewTile;

// A view-space point's pixel position in a frame of width x height under projection `proj`
// (ndc = 2 p / extent - 1, as the shaders).
glm::vec2 pixelOf(const glm::mat4& proj, glm::vec3 p, uint32_t width, uint32_t height) {
    const glm::vec4 c = proj * glm::vec4(p, 1.0f);
    const glm::vec2 ndc(c.x / c.w, c.y / c.w);
    return (ndc + 1.0f) * 0.5f * glm::vec2(width, height);
}

// Camera-relative frame constants (FrameConstants::eye, viewProjRelative): the eye of a view
// 1e5 m out is exact, (p - eye) through viewProjRelative is viewProj * p, and constants whose
// view or proj changed without setCameraRelative are refused naming the field.
TEST(CameraRelative, EyeAndRelativeTransformFollowFromViewAndProj) {
    const glm::vec3 eye(1.0e5f, 0.0f, 0.15f);
    shared::FrameConstants c{};
    c.view = glm::lookAtRH(eye, eye - glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    c.proj = eng::frame::reversedZPerspective(0.7f, 1.0f, 1.0e-4f, 1.0e7f);
    c.viewProj = c.proj * c.view;
    eng::frame::setCameraRelative(c);
    EXPECT_EQ(glm::vec3(c.eye), eye) << "the eye of a rigid view, recovered exactly";
    EXPECT_NO_THROW(eng::frame::requireCameraRelative(c));
    const glm::vec3 p = eye + glm::vec3(0.01f, -0.02f, -0.15f);
    const glm::dvec4 exact = glm::dmat4(c.proj) * glm::dmat4(c.view) * glm::dvec4(glm::dvec3(p), 1.0);
    const glm::vec4 relative = c.viewProjRelative * glm::vec4(p - glm::vec3(c.eye), 1.0f);
    for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(relative[i], exact[i], 1e-6 * std::max(1.0, std::abs(exact[i]))) << "component " << i;

    shared::FrameConstants moved = c;
    moved.view = glm::translate(c.view, glm::vec3(0.0f, 0.0f, -1.0f));
    try {
        eng::frame::requireCameraRelative(moved);
        ADD_FAILURE() << "a view changed without setCameraRelative was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("FrameConstants::eye"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("setCameraRelative"), std::string::npos) << e.what();
    }
    shared::FrameConstants zoomed = c;
    zoomed.proj = eng::frame::reversedZPerspective(0.35f, 1.0f, 1.0e-4f, 1.0e7f);
    EXPECT_THROW(eng::frame::requireCameraRelative(zoomed), std::invalid_argument) << "proj changed";
    shared::FrameConstants unset = c;
    unset.viewProjRelative = glm::mat4(0.0f);
    EXPECT_THROW(eng::frame::requireCameraRelative(unset), std::invalid_argument) << "never set";
}

TEST(ViewTile, ScaleOneIsTheIdentity) {
    EXPECT_EQ(eng::frame::viewTileCrop({}, 64, 48), glm::mat4(1.0f))
        << "a whole view's projection is unchanged";
}

// A point seen at pixel (X, Y) of the k-times-larger view is at (X - ox, Y - oy) in the tile at
// (ox, oy): the tiles are pieces of one image, which is what makes their average a box filter.
TEST(ViewTile, ATilesPixelsAreThoseOfTheLargerView) {
    const uint32_t w = 40, h = 30, k = 4;
    const glm::mat4 p = eng::frame::reversedZPerspective(0.9f, float(w) / float(h), 0.1f, 100.0f);
    const glm::mat4 whole = eng::frame::reversedZPerspective(0.9f, float(w * k) / float(h * k), 0.1f, 100.0f);
    for (uint32_t ty = 0; ty < k; ++ty)
        for (uint32_t tx = 0; tx < k; ++tx) {
            const ViewTile tile{k, {tx * w, ty * h}};
            const glm::mat4 tileProj = eng::frame::viewTileCrop(tile, w, h) * p;
            for (glm::vec3 q :
                 {glm::vec3(0.3f, -0.2f, -2.0f), glm::vec3(-1.1f, 0.7f, -5.0f), glm::vec3(0, 0, -1)}) {
                const glm::vec2 big = pixelOf(whole, q, w * k, h * k);
                const glm::vec2 inTile = pixelOf(tileProj, q, w, h);
                EXPECT_NEAR(inTile.x, big.x - float(tile.origin.x), 2e-3f) << "tile " << tx << "," << ty;
                EXPECT_NEAR(inTile.y, big.y - float(tile.origin.y), 2e-3f) << "tile " << tx << "," << ty;
            }
            // The shaders' ray (common/depth.glsl viewRayNdc): x_view = (ndc + P'20) t / P'00 returns the
            // point a pixel sees.
            const glm::vec3 q(0.4f, 0.25f, -3.0f);
            const glm::vec2 px = pixelOf(tileProj, q, w, h);
            const glm::vec2 ndc =
                px / glm::vec2(w, h) * 2.0f - 1.0f + glm::vec2(tileProj[2][0], tileProj[2][1]);
            EXPECT_NEAR(ndc.x * 3.0f / tileProj[0][0], q.x, 1e-4f);
            EXPECT_NEAR(ndc.y * 3.0f / tileProj[1][1], q.y, 1e-4f);
        }
}

TEST(ViewTile, OutOfRangeTilesAreRefusedByName) {
    EXPECT_THROW(eng::frame::viewTileCrop({0, {0, 0}}, 8, 8), std::invalid_argument);
    EXPECT_THROW(eng::frame::viewTileCrop({eng::frame::kMaxViewTileScale + 1, {0, 0}}, 8, 8),
                 std::invalid_argument);
    try {
        eng::frame::viewTileCrop({2, {9, 0}}, 8, 8);
        ADD_FAILURE() << "a tile reaching past its view was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("outside its 16x16 view"), std::string::npos) << e.what();
    }
}

eng::io::ImageF constantImage(uint32_t w, uint32_t h, float v) {
    return eng::io::makeImage(w, h, {v, v, v, 1.0f});
}

// Sub-pixel (u, v) of output pixel (x, y) is pixel (k x + u, k y + v) of the k-times-larger image,
// whichever tile holds it; each 2 x 2 block holds 0, 1, 2, 3 here, half 0 the diagonal (0, 3).
TEST(TruthAccumulator, AveragesEachKxKBlockAndSplitsTheCheckerboard) {
    const uint32_t w = 4, h = 2, k = 2;
    agaa::TruthAccumulator acc(w, h, k);
    for (uint32_t ty = 0; ty < k; ++ty)
        for (uint32_t tx = 0; tx < k; ++tx) {
            // The tile's pixel (x, y) is high-res (tx w + x, ty h + y): value = its high-res column parity.
            eng::io::ImageF display = eng::io::makeImage(w, h), hdr = eng::io::makeImage(w, h);
            for (uint32_t y = 0; y < h; ++y)
                for (uint32_t x = 0; x < w; ++x) {
                    const uint32_t X = tx * w + x, Y = ty * h + y;
                    const float v = float((X % 2) + 2 * (Y % 2)); // 0, 1, 2, 3 over each 2x2 block
                    eng::io::setPixel(display, x, y, {v, v, v, 1.0f});
                    eng::io::setPixel(hdr, x, y, {10 * v, 10 * v, 10 * v, 1.0f});
                }
            acc.add({k, {tx * w, ty * h}}, display, hdr);
        }
    const agaa::ConvergedTruth t = acc.finish();
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            EXPECT_FLOAT_EQ(eng::io::pixel(t.display, x, y).r, 1.5f) << "the mean of 0, 1, 2, 3";
            EXPECT_FLOAT_EQ(eng::io::pixel(t.hdr, x, y).g, 15.0f);
            EXPECT_FLOAT_EQ(eng::io::pixel(t.halves[0], x, y).r, 1.5f) << "(0,0) and (1,1): 0 and 3";
            EXPECT_FLOAT_EQ(eng::io::pixel(t.halves[1], x, y).r, 1.5f) << "(1,0) and (0,1): 1 and 2";
        }
    EXPECT_DOUBLE_EQ(t.errorEstimate, 0.0) << "halves that agree estimate no error";
}

// The mean's own error: the k^2 sub-pixel images' means as draws. Sub-pixel (u, v) of every pixel
// holds hdr 1 + u + 2 v (k = 2: 1, 2, 3, 4), whichever tile holds it, so each tile holds all four
// and the tiles' own means agree: standard deviation sqrt(5 / 3) over sqrt(4). Equal sub-pixels
// estimate none; k = 1 measures nothing.
TEST(TruthAccumulator, TheMeansErrorIsTheSubPixelMeansSpreadOverK) {
    const uint32_t w = 2, h = 2, k = 2;
    agaa::TruthAccumulator acc(w, h, k);
    for (uint32_t ty = 0; ty < k; ++ty)
        for (uint32_t tx = 0; tx < k; ++tx) {
            eng::io::ImageF hdr = eng::io::makeImage(w, h);
            for (uint32_t y = 0; y < h; ++y)
                for (uint32_t x = 0; x < w; ++x) {
                    const float v = float(1 + (tx * w + x) % k + 2 * ((ty * h + y) % k));
                    eng::io::setPixel(hdr, x, y, {v, v, v, 1.0f});
                }
            acc.add({k, {tx * w, ty * h}}, constantImage(w, h, 0.5f), hdr);
        }
    const agaa::ConvergedTruth t = acc.finish();
    EXPECT_NEAR(t.meanLuminance, 2.5, 1e-6) << "luma of grey v is v";
    EXPECT_NEAR(t.meanErrorEstimate, std::sqrt(5.0 / 3.0) / 2.0, 1e-6);
    EXPECT_DOUBLE_EQ(agaa::truthMeanErrorEstimate({0.5, 0.5, 0.5, 0.5}), 0.0);
    EXPECT_TRUE(std::isinf(agaa::truthMeanErrorEstimate({0.5}))) << "one sub-pixel (k = 1) measures nothing";
}

TEST(TruthAccumulator, MissingOrRepeatedTilesAreRefused) {
    agaa::TruthAccumulator acc(2, 2, 2);
    const eng::io::ImageF img = constantImage(2, 2, 0.5f);
    acc.add({2, {0, 0}}, img, img);
    acc.add({2, {2, 0}}, img, img);
    acc.add({2, {0, 2}}, img, img);
    EXPECT_THROW(acc.finish(), std::logic_error) << "one tile of four is missing";
    acc.add({2, {0, 2}}, img, img);
    EXPECT_THROW(acc.finish(), std::logic_error) << "one tile twice, one never";
    EXPECT_THROW(acc.add({2, {1, 0}}, img, img), std::logic_error) << "not on the tile grid";
    EXPECT_THROW(acc.add({2, {0, 0}}, constantImage(3, 2, 0.5f), img), std::logic_error) << "wrong size";
}

// Halves whose errors are equal and opposite: the full truth is exact, and the estimate reads the
// size of one half's error (|A - B| / 2), the conservative side.
TEST(TruthErrorEstimate, HalfTheHalvesDisplayRmse) {
    const eng::io::ImageF a = constantImage(8, 8, 0.25f), b = constantImage(8, 8, 0.25f);
    EXPECT_DOUBLE_EQ(agaa::truthErrorEstimate(a, b), 0.0);
    const double ea = eng::io::linearToSrgb(0.3f), eb = eng::io::linearToSrgb(0.2f);
    EXPECT_NEAR(agaa::truthErrorEstimate(constantImage(8, 8, 0.3f), constantImage(8, 8, 0.2f)),
                0.5 * std::abs(ea - eb), 1e-6);
    EXPECT_THROW(agaa::truthErrorEstimate(a, constantImage(4, 8, 0.25f)), eng::io::IoError);
}

TEST(TruthSettings, OutOfRangeValuesAreRefusedByName) {
    EXPECT_THROW(agaa::validate(agaa::TruthSettings{0, 32}), std::invalid_argument);
    EXPECT_THROW(agaa::validate(agaa::TruthSettings{agaa::kMaxTruthSupersampling + 1, 32}),
                 std::invalid_argument);
    EXPECT_THROW(agaa::validate(agaa::TruthSettings{4, 6}), std::invalid_argument);
    EXPECT_NO_THROW(agaa::validate(agaa::TruthSettings{4, 32}));
}

// The cache trusts only a whole file under its own key: a truncated or foreign file is a miss.
TEST(TruthCache, StoresLoadsAndIgnoresDamagedFiles) {
    const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "agaa_truth_cache_units";
    std::filesystem::remove_all(dir);
    agaa::TruthAccumulator acc(3, 2, 1);
    acc.add({1, {0, 0}}, constantImage(3, 2, 0.5f), constantImage(3, 2, 2.0f));
    agaa::ConvergedTruth t = acc.finish();
    t.key = "0123456789abcdef";
    t.exposure = 0.25f;
    const agaa::TruthCache cache(dir);
    EXPECT_FALSE(cache.load(t.key)) << "an empty cache holds nothing";
    cache.store(t);
    const std::optional<agaa::ConvergedTruth> back = cache.load(t.key);
    ASSERT_TRUE(back);
    EXPECT_TRUE(back->fromCache);
    EXPECT_EQ(back->display.rgba, t.display.rgba);
    EXPECT_EQ(back->hdr.rgba, t.hdr.rgba);
    EXPECT_EQ(back->exposure, 0.25f);
    EXPECT_EQ(back->meanErrorEstimate, t.meanErrorEstimate) << "infinite at k = 1, kept as such";
    EXPECT_FALSE(cache.load("fedcba9876543210")) << "another key is another truth";
    const std::filesystem::path file = dir / (t.key + ".truth");
    std::filesystem::resize_file(file, std::filesystem::file_size(file) - 4);
    EXPECT_FALSE(cache.load(t.key)) << "a truncated file is not trusted";
    std::filesystem::remove_all(dir);
}

} // namespace
