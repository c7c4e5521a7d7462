// SBAA (Salvi and Vidimce 2012) on lavapipe, validation on: the GPU surface selection against its
// CPU twin (agaa/sbaa/surface_selection.cpp) on the same exported prepass, the fill pass's material
// per kept surface against the material of its primitive, the resolve against the CPU weights on
// an emissive-only scene (no lights: each surface's shade is its emissive), the lost coverage the
// stats report, and reruns.

#include "agaa/sbaa/sbaa.h"
#include "agaa/sbaa/surface_selection.h"
#include "engine/frame/frame_constants.h"
#include "engine/frame/frame_runner.h"
#include "engine/frame/readback.h"
#include "engine/io/tone_map.h"
#include "gpu_test_support.h"
#include "shared/sbaa.h"
#include "tests/support/sample_inputs_export.h"
#include "tools/harness/frame_renderer.h"
#include "tools/scenes/adversarial_scenes.h"

#include <glm/gtc/packing.hpp>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

namespace {

namespace vk = eng::vk;

// One frame of SBAA's passes with the prepass exported, the per-surface G-buffer (after the fill),
// the lost samples and the display read back.
struct SbaaFrame {
    shared::FrameConstants constants{};
    std::vector<agaa::SbaaSample> samples;
    std::vector<uint32_t> surfaces, lost;
    std::vector<float> display; // RGBA
};

SbaaFrame renderSbaa(vk::Device& device, const eng::scene::Scene& scene, const agaa::SbaaSettings& settings,
                     uint32_t w, uint32_t h) {
    eng::frame::GpuScene gpuScene(device, scene);
    eng::frame::FrameRunner runner(device);
    agaa::Sbaa sbaa(device, gpuScene, settings);
    agaa::test::SampleInputsExport selectionInputs = agaa::test::sbaaSelectionInputs(device);
    const uint32_t n = settings.samples, S = settings.surfaces;
    eng::frame::ViewSettings view;
    view.width = w;
    view.height = h;
    SbaaFrame f;
    f.constants = eng::frame::makeFrameConstants(scene, view, eng::frame::makeSamplePattern(n));
    std::vector<shared::GpuLight> lights = eng::frame::makeGpuLights(scene, f.constants.view);
    vk::Buffer frameBuf = vk::createBuffer(device, sizeof(f.constants), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                           vk::MemoryUse::Upload, "test.frame");
    vk::Buffer lightBuf =
        vk::createBuffer(device, std::max<size_t>(1, lights.size()) * sizeof(shared::GpuLight),
                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Upload, "test.lights");
    vk::Buffer exportBuf =
        vk::createBuffer(device, VkDeviceSize(w) * h * n * sizeof(agaa::SbaaSample),
                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Readback, "test.export");
    vk::Buffer surfacesHost =
        vk::createBuffer(device, VkDeviceSize(w) * h * S * shared::kSbaaSurfaceWords * 4,
                         VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::Readback, "test.surfaces");
    vk::Buffer lostHost = eng::frame::createReadbackBuffer(device, w, h, VK_FORMAT_R32_UINT, "test.lost");
    vk::Buffer displayHost =
        eng::frame::createReadbackBuffer(device, w, h, VK_FORMAT_R32G32B32A32_SFLOAT, "test.display");
    vk::writeBuffer(device, frameBuf, std::as_bytes(std::span(&f.constants, 1)));
    vk::writeBuffer(device, lightBuf, std::as_bytes(std::span(lights)));
    {
        eng::rg::Graph graph;
        agaa::FrameInputs in;
        in.width = w;
        in.height = h;
        in.frameConstants =
            graph.importBuffer("frame", {frameBuf.buffer, frameBuf.size}, std::nullopt, std::nullopt);
        in.lights =
            graph.importBuffer("lights", {lightBuf.buffer, lightBuf.size}, std::nullopt, std::nullopt);
        eng::rg::Buffer target =
            graph.importBuffer("export", {exportBuf.buffer, exportBuf.size}, std::nullopt, std::nullopt);
        const agaa::SampleGBuffer g = sbaa.addGBuffer(graph, in);
        const agaa::Sbaa::Surfaces s = sbaa.addFill(graph, in, g, sbaa.addSurfaces(graph, in, g));
        const agaa::FrameTargets t = sbaa.addLighting(graph, in, g, s);
        selectionInputs.add(graph, in, {{2, g.depth}, {3, g.geometricNormal}, {11, g.primitive}}, 14, target);
        eng::frame::addBufferReadbackPass(graph, s.surfaces, surfacesHost, "readback.surfaces");
        eng::frame::addReadbackPass(graph, s.lostSamples, lostHost, "readback.lost");
        eng::frame::addReadbackPass(graph, t.display, displayHost, "readback.display");
        runner.run(graph);
    }
    auto copy = [&](const vk::Buffer& b, auto& out, size_t count) {
        vk::invalidateBuffer(device, b);
        out.resize(count);
        std::memcpy(out.data(), b.mapped, count * sizeof(out[0]));
    };
    copy(exportBuf, f.samples, size_t(w) * h * n);
    copy(surfacesHost, f.surfaces, size_t(w) * h * S * shared::kSbaaSurfaceWords);
    copy(lostHost, f.lost, size_t(w) * h);
    copy(displayHost, f.display, size_t(w) * h * 4);
    for (vk::Buffer* b : {&frameBuf, &lightBuf, &exportBuf, &surfacesHost, &lostHost, &displayHost})
        vk::destroyBuffer(device, *b);
    return f;
}

float halfValue(uint32_t word, int which) {
    return glm::unpackHalf2x16(word)[which];
}

// An emissive-only scene: black, non-metallic materials that glow, no lights, no environment, a
// background quad covering the view and, in front, bars 0.3 px to 2 px wide in three colours:
// pixels with up to four primitives on different planes.
eng::scene::Scene emissiveBars() {
    eng::scene::Scene s = agaa::test::emptyScene("sbaa-emissive-bars");
    s.lights.clear();
    s.materials.clear();
    const glm::vec3 glow[4] = {
        {0.2f, 0.3f, 0.4f}, {3.0f, 0.5f, 0.1f}, {0.1f, 2.0f, 0.3f}, {0.6f, 0.2f, 4.0f}};
    for (const glm::vec3& e : glow) {
        eng::scene::Material m;
        m.baseColorFactor = {0.0f, 0.0f, 0.0f, 1.0f};
        m.metallicFactor = 0.0f;
        m.roughnessFactor = 1.0f;
        m.emissiveFactor = e;
        m.doubleSided = true;
        s.materials.push_back(m);
    }
    agaa::test::addRectangle(s, {-50, -50}, {50, 50}, -10.0f, 0);
    // At z = -3 to -1, a 32 px frame with yfov 0.8 covers about 0.84 z wide: a pixel ~ 0.026 z.
    for (int i = 0; i < 24; ++i) {
        const float z = -1.0f - 0.25f * float(i % 3);
        const float x = -0.45f * -z + float(i) * 0.04f * -z;
        const float width = (0.008f + 0.003f * float(i % 5)) * -z;
        agaa::test::addRectangle(s, {x, -0.5f * -z}, {x + width, 0.5f * -z}, z, 1 + uint32_t(i % 3));
    }
    return s;
}

// The material of primitive `id` (scene-wide triangle number + 1), from the scene's draws.
const eng::scene::Material& primitiveMaterial(const eng::scene::Scene& scene, uint32_t id) {
    const uint32_t triangle = id - 1;
    for (const eng::scene::Draw& d : scene.draws)
        if (triangle >= d.firstIndex / 3 && triangle < (d.firstIndex + d.indexCount) / 3)
            return scene.materials.at(d.material);
    throw std::out_of_range("primitive " + std::to_string(id) + " is in no draw");
}

} // namespace

// The selection on the GPU equals its CPU twin on the exported prepass: the kept surfaces'
// coverage masks, representative samples, primitive ids and depths bit for bit, and the lost
// samples (the material words are the fill's, tested below). Foliage at n = 8 and S = 2: many
// pixels have more surfaces than they keep. Pixels where a merge test sits within 1e-4 of its
// threshold may differ by fp32 rounding; those are counted, not compared.
TEST(SbaaGpu, SurfaceSelectionMatchesTheCpuTwin) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadTestScene("foliage");
    agaa::SbaaSettings settings;
    settings.samples = 8;
    settings.surfaces = 2;
    const uint32_t w = 48, h = 48, n = settings.samples, S = settings.surfaces;
    const SbaaFrame f = renderSbaa(*device, scene, settings, w, h);
    uint32_t mismatches = 0, nearThreshold = 0, pixelsLosing = 0, twoOrMore = 0;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const size_t p = size_t(y) * w + x;
            const agaa::SbaaSample* px = &f.samples[p * n];
            const agaa::SbaaSelection cpu =
                agaa::selectSurfaces(f.constants, px, int(x), int(y), S, settings.merge);
            pixelsLosing += cpu.lostSamples > 0 ? 1 : 0;
            twoOrMore += cpu.kept.size() >= 2 ? 1 : 0;
            bool same = f.lost[p] == cpu.lostSamples;
            for (uint32_t k = 0; k < S && same; ++k) {
                const uint32_t* gpu = &f.surfaces[(p * S + k) * shared::kSbaaSurfaceWords];
                if (k >= cpu.kept.size()) {
                    same = gpu[shared::kSbaaWordMask] == 0u;
                    continue;
                }
                const std::array<uint32_t, 8> want = agaa::surfaceRecord(cpu.kept[k], px);
                for (uint32_t word :
                     {shared::kSbaaWordMask, shared::kSbaaWordDepth, shared::kSbaaWordSampleAndPrimitive})
                    same = same && gpu[word] == want[word];
            }
            if (same) continue;
            if (cpu.margin < 1e-4f)
                ++nearThreshold;
            else if (++mismatches <= 5)
                ADD_FAILURE() << "pixel " << x << "," << y << ": GPU and CPU selections differ (lost "
                              << f.lost[p] << " vs " << cpu.lostSamples << ")";
        }
    std::printf("[ measured ] selection: %u pixels lose coverage, %u keep 2 surfaces, %u near-threshold "
                "disagreements\n",
                pixelsLosing, twoOrMore, nearThreshold);
    EXPECT_GT(pixelsLosing, 20u) << "foliage at S = 2 must have pixels with more surfaces than kept";
    EXPECT_GT(twoOrMore, 20u) << "and pixels keeping both surfaces";
    EXPECT_EQ(mismatches, 0u);
    EXPECT_LE(nearThreshold, w * h / 200) << "too many near-threshold disagreements for rounding alone";
    agaa::test::expectNoValidationErrors(*device);
}

// The fill and the resolve, at pixel and at sample rate. Each kept surface's material words are
// its representative primitive's material (found from the scene's draws, not from the GPU): black,
// non-metallic, roughness 1, its emissive, so a slot the fill missed (zeros) or filled from another
// primitive fails. With no light and no environment each surface's shade is its emissive, so the
// display is sum_k w_k ACES(e_k), the weights from the CPU selection (kept coverage over kept +
// sky; lost coverage out of the denominator). Compared to 1e-5 (fp32 order of additions).
TEST(SbaaGpu, FillWritesEachSurfacesMaterialAndTheResolveWeighsThemByCoverage) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene scene = emissiveBars();
    for (auto [S, sampleRate] : {std::pair{1u, false}, std::pair{4u, false}, std::pair{4u, true}}) {
        agaa::SbaaSettings settings;
        settings.samples = 8;
        settings.surfaces = S;
        settings.sampleRateShading = sampleRate;
        const uint32_t w = 32, h = 32, n = settings.samples;
        const SbaaFrame f = renderSbaa(*device, scene, settings, w, h);
        float worst = 0.0f;
        uint32_t losing = 0, multi = 0, wrongMaterial = 0;
        for (uint32_t p = 0; p < w * h; ++p) {
            const agaa::SbaaSample* px = &f.samples[size_t(p) * n];
            const agaa::SbaaSelection sel =
                agaa::selectSurfaces(f.constants, px, int(p % w), int(p / w), S, settings.merge);
            ASSERT_EQ(sel.skySamples, 0u) << "the background covers the view";
            const std::vector<float> weights = agaa::resolveWeights(sel);
            losing += sel.lostSamples > 0 ? 1 : 0;
            multi += sel.kept.size() > 1 ? 1 : 0;
            glm::vec3 want(0.0f);
            for (size_t k = 0; k < sel.kept.size(); ++k) {
                const eng::scene::Material& m = primitiveMaterial(scene, sel.kept[k].primitive);
                const glm::vec3 e = m.emissiveFactor * m.emissiveStrength;
                const uint32_t* rec = &f.surfaces[(size_t(p) * S + k) * shared::kSbaaSurfaceWords];
                const float stored[8] = {halfValue(rec[shared::kSbaaWordAlbedoRg], 0),
                                         halfValue(rec[shared::kSbaaWordAlbedoRg], 1),
                                         halfValue(rec[shared::kSbaaWordAlbedoBMetal], 0),
                                         halfValue(rec[shared::kSbaaWordAlbedoBMetal], 1),
                                         halfValue(rec[shared::kSbaaWordEmissiveRg], 0),
                                         halfValue(rec[shared::kSbaaWordEmissiveRg], 1),
                                         halfValue(rec[shared::kSbaaWordEmissiveBRoughness], 0),
                                         halfValue(rec[shared::kSbaaWordEmissiveBRoughness], 1)};
                const float expected[8] = {0.0f, 0.0f, 0.0f, 0.0f, e.r, e.g, e.b, 1.0f};
                bool ok = true;
                for (int c = 0; c < 8; ++c)
                    ok = ok && std::abs(stored[c] - expected[c]) <= 1e-3f * std::max(1.0f, expected[c]);
                if (!ok && ++wrongMaterial <= 5)
                    ADD_FAILURE() << "S=" << S << " sample rate " << sampleRate << ": pixel " << p
                                  << " surface " << k << " holds emissive " << stored[4] << ", " << stored[5]
                                  << ", " << stored[6] << " roughness " << stored[7] << ", its primitive's "
                                  << e.r << ", " << e.g << ", " << e.b;
                // The shade from the stored (half) emissive, as the lighting pass reads it.
                for (int c = 0; c < 3; ++c)
                    want[c] += weights[k] * eng::io::toneMapAces(stored[4 + c]);
            }
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::abs(f.display[size_t(p) * 4 + c] - want[c]));
        }
        std::printf(
            "[ measured ] fill and resolve S=%u, sample rate %d: max |GPU - CPU| %.3g, %u pixels lose "
            "coverage, %u keep >1, %u wrong materials\n",
            S, int(sampleRate), worst, losing, multi, wrongMaterial);
        EXPECT_EQ(wrongMaterial, 0u);
        EXPECT_LT(worst, 1e-5f) << "S = " << S;
        if (S == 1) {
            EXPECT_GT(losing, 30u) << "one surface per pixel drops the others' coverage";
        } else {
            EXPECT_GT(multi, 30u) << "S = " << S << ": the bars make pixels with several surfaces";
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}

// Through the frame renderer: the stats' lost coverage is the share of samples lost (it shrinks as
// S grows and is 0 where S covers every surface), the shading events are the kept surfaces, and a
// rerun is bit-identical.
TEST(SbaaGpu, LostCoverageStatsShadingEventsAndReruns) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadTestScene("furball");
    agaa::FrameRenderer renderer(*device, scene);
    double previous = 2.0;
    for (uint32_t S : {1u, 2u, 4u, 6u}) {
        agaa::RenderRequest r;
        r.method = "sbaa";
        r.settings.samples = 8;
        r.settings.surfaces = S;
        r.view.width = r.view.height = 32;
        const agaa::RenderResult a = renderer.render(r);
        const agaa::RenderResult b = renderer.render(r);
        ASSERT_TRUE(a.lostCoverageFraction) << "SBAA reports its lost coverage";
        std::printf(
            "[ measured ] furball S=%u: lost %.4f of the samples in %llu pixels, events mean %.3f max %u\n",
            S, *a.lostCoverageFraction, static_cast<unsigned long long>(a.pixelsWithLostCoverage),
            a.shadingEventsMean, a.shadingEventsMax);
        EXPECT_LE(a.shadingEventsMax, S) << "at most S shading events per pixel";
        EXPECT_LE(*a.lostCoverageFraction, previous) << "more surfaces lose less";
        if (S == 1) {
            EXPECT_GT(*a.lostCoverageFraction, 0.0) << "the furball has pixels with several surfaces";
        }
        previous = *a.lostCoverageFraction;
        EXPECT_EQ(a.hdr.rgba, b.hdr.rgba) << "S = " << S << ": reruns differ";
        EXPECT_EQ(a.display.rgba, b.display.rgba) << "S = " << S << ": reruns differ";
        EXPECT_TRUE(eng::io::allFinite(a.hdr));
    }
    agaa::RenderRequest ref;
    ref.method = "reference";
    ref.view.width = ref.view.height = 32;
    EXPECT_FALSE(renderer.render(ref).lostCoverageFraction) << "methods that keep every sample report none";
    agaa::test::expectNoValidationErrors(*device);
}

// MERGE mode: a tilted plane tessellated into triangles about 2 px across. With merge every pixel
// is one surface (its triangles lie on one plane: same normal, depths within the plane's slope),
// so S = 1 loses nothing; without merge each triangle is a surface and pixels on the triangle edges
// lose the coverage of all but one. The same plane without vertex normals (all zero: the prepass's
// kMinNormalLength guard hands over to the face normal) is one surface too.
TEST(SbaaGpu, MergeKeepsATessellatedPlaneOneSurface) {
    auto device = agaa::test::makeValidatedDevice();
    const glm::vec3 planeNormal = glm::normalize(glm::vec3(0.6f, 0.0f, 1.0f));
    auto tessellatedPlane = [&](glm::vec3 vertexNormal) {
        eng::scene::Scene scene = agaa::test::emptyScene("sbaa-tessellated-plane");
        const int cells = 24;
        for (int j = 0; j <= cells; ++j)
            for (int i = 0; i <= cells; ++i) {
                eng::scene::Vertex v;
                const float x = -1.2f + 2.4f * float(i) / cells, y = -1.2f + 2.4f * float(j) / cells;
                v.position = {x, y, -2.0f - 0.6f * x}; // tilted: the depth changes along x
                v.normal = vertexNormal;
                scene.vertices.push_back(v);
            }
        for (int j = 0; j < cells; ++j)
            for (int i = 0; i < cells; ++i) {
                const uint32_t a = uint32_t(j * (cells + 1) + i), b = a + 1, c = a + cells + 1, d = c + 1;
                for (uint32_t k : {a, b, d, a, d, c})
                    scene.indices.push_back(k);
            }
        scene.draws.push_back({0, uint32_t(scene.indices.size()), 0});
        return scene;
    };
    const uint32_t w = 32, h = 32;
    std::vector<agaa::SbaaSample> withNormals;
    for (glm::vec3 vertexNormal : {planeNormal, glm::vec3(0.0f)}) {
        const eng::scene::Scene scene = tessellatedPlane(vertexNormal);
        uint32_t lostWith = 0, lostWithout = 0, pixelsWithout = 0;
        for (bool merge : {true, false}) {
            agaa::SbaaSettings settings;
            settings.samples = 8;
            settings.surfaces = 1;
            settings.merge.merge = merge;
            const SbaaFrame f = renderSbaa(*device, scene, settings, w, h);
            for (uint32_t l : f.lost) {
                (merge ? lostWith : lostWithout) += l;
                if (!merge) pixelsWithout += l > 0 ? 1 : 0;
            }
            for (float v : f.display)
                ASSERT_TRUE(std::isfinite(v));
            if (!merge) continue;
            if (vertexNormal == planeNormal) {
                withNormals = f.samples;
                continue;
            }
            // Without vertex normals the stored normal is the face normal: the plane's, as its
            // vertex normals gave it (8-bit octahedral: within about 1 degree).
            float worst = 1.0f;
            for (size_t i = 0; i < f.samples.size(); ++i)
                if (f.samples[i].x > 0.0f)
                    worst = std::min(worst, glm::dot(agaa::storedGeometricNormal(f.samples[i]),
                                                     agaa::storedGeometricNormal(withNormals[i])));
            EXPECT_GT(worst, 0.999f) << "the face normal stands in for a zero vertex normal";
        }
        const bool zero = vertexNormal == glm::vec3(0.0f);
        std::printf("[ measured ] tessellated plane%s, S=1: lost samples %u with merge, %u in %u pixels "
                    "without\n",
                    zero ? " without vertex normals" : "", lostWith, lostWithout, pixelsWithout);
        EXPECT_EQ(lostWith, 0u) << "one plane is one surface under MERGE" << (zero ? " (face normals)" : "");
        EXPECT_GT(pixelsWithout, 50u) << "without MERGE the triangle edges split pixels into surfaces";
    }
    agaa::test::expectNoValidationErrors(*device);
}

TEST(SbaaGpu, RefusesSettingsOutOfRange) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadTestScene("plane");
    eng::frame::GpuScene gpuScene(*device, scene);
    for (auto [n, S, what] : {std::tuple{1u, 4u, "--samples 1"}, std::tuple{8u, 0u, "--surfaces 0"},
                              std::tuple{8u, 7u, "--surfaces 7"}}) {
        agaa::SbaaSettings s;
        s.samples = n;
        s.surfaces = S;
        try {
            agaa::Sbaa sbaa(*device, gpuScene, s);
            ADD_FAILURE() << what << " was accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}
