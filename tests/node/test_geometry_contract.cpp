// Issue 50, the geometry and material contract (agaa/common/raster_pass.h): a host's drawer is
// handed every raster pass of a method, prepares it before anything records and draws it inside the
// pass. A drawer that draws the scene as this project's own does (it delegates to an
// agaa::SceneDrawer of its own, with its own pipelines) gets the image the technique makes without
// one, bit for bit, validation-clean, on every path: the per-sample G-buffer and the shadow maps,
// SBAA's prepass and fill, AGAA's visibility prepass and accumulation kernel.

#include "agaa/common/scene_drawer.h"
#include "agaa/methods.h"
#include "engine/scene/scenegen.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/node/node_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace agaa::test {
namespace {

// A host's drawer: what it was asked, and this project's scene drawn by a SceneDrawer of its own.
class HostDrawer final : public GeometryDrawer {
  public:
    HostDrawer(eng::vk::Device& device, const eng::frame::GpuScene& scene,
               const eng::scene::SceneFeatures& features)
        : m_scene(device, scene, features) {}
    void prepare(const RasterPass& pass) override {
        prepared.push_back(pass);
        m_scene.prepare(pass);
    }
    void recordDraws(VkCommandBuffer cmd, const RasterPass& pass, const PushModuleSet& push) const override {
        ++recorded;
        m_scene.recordDraws(cmd, pass, push);
    }
    std::vector<RasterPass> prepared;
    mutable int recorded = 0;

  private:
    SceneDrawer m_scene;
};

struct Case {
    const char* method;
    AggregateGeneration generation;
    std::vector<RasterOutput> outputs; // what the drawer must be handed, sorted
};

void PrintTo(const Case& c, std::ostream* os) {
    *os << c.method << (c.generation == AggregateGeneration::Accumulate ? " accumulate" : "");
}

class GeometryContract : public ::testing::TestWithParam<Case> {};

TEST_P(GeometryContract, AHostDrawerDrawsEveryRasterPassAndGetsTheSceneDrawersImageBitForBit) {
    auto device = makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadBuiltin("railings");
    eng::frame::GpuScene gpuScene(*device, scene);
    MethodSettings settings;
    settings.agaa.generation = GetParam().generation;
    std::unique_ptr<Technique> technique = createTechnique(GetParam().method, *device, gpuScene, settings);
    const std::vector<float> own = renderFrame(*device, gpuScene, *technique, nullptr);

    HostDrawer host(*device, gpuScene, effectiveFeatures(sceneTraits(scene), settings.effects));
    const std::vector<float> hosts = renderFrame(*device, gpuScene, *technique, &host);
    std::vector<RasterOutput> outputs;
    for (const RasterPass& p : host.prepared)
        outputs.push_back(p.output);
    std::sort(outputs.begin(), outputs.end());
    EXPECT_EQ(outputs, GetParam().outputs);
    EXPECT_EQ(host.recorded, int(host.prepared.size())) << "each prepared pass is drawn once";
    for (const RasterPass& p : host.prepared) {
        EXPECT_FALSE(p.moduleSet.empty()) << p.name << ": set 0 is the module's";
        if (p.output == RasterOutput::ShadowDepth) {
            EXPECT_TRUE(p.bothFaces) << p.name;
            EXPECT_EQ(p.samples, VK_SAMPLE_COUNT_1_BIT) << p.name;
        } else {
            EXPECT_EQ(p.layers, technique->samples() / 4) << p.name << ": one layer per 4 samples";
            EXPECT_EQ(p.samples, VK_SAMPLE_COUNT_4_BIT) << p.name;
        }
    }
    EXPECT_EQ(countDifferentBits(hosts, own), 0u);
    expectNoValidationErrors(*device);
}

using O = RasterOutput;
INSTANTIATE_TEST_SUITE_P(
    Node, GeometryContract,
    ::testing::Values(
        Case{"reference", AggregateGeneration::Auto, {O::SampleGBuffer, O::ShadowDepth}},
        Case{"agaa", AggregateGeneration::Samples, {O::SampleGBuffer, O::ShadowDepth}},
        Case{"agaa",
             AggregateGeneration::Accumulate,
             {O::ShadowDepth, O::AggregateVisibility, O::AggregateAccumulation}},
        Case{"sbaa", AggregateGeneration::Auto, {O::SurfaceVisibility, O::SurfaceFill, O::ShadowDepth}},
        Case{"streaming", AggregateGeneration::Auto, {O::SampleGBufferPrimitive, O::ShadowDepth}}),
    [](const auto& info) {
        return std::string(info.param.method) +
               (info.param.generation == AggregateGeneration::Accumulate ? "_accumulate" : "");
    });

} // namespace
} // namespace agaa::test
