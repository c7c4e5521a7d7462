// Bad input reaches the loader (CPU): refused with a SceneError naming the source and the field,
// or repaired with a warning; the adversarial scenes load and report their repairs.

#include "engine/scene/gltf_loader.h"
#include "engine/scene/scenegen.h"
#include "malformed_models.h"
#include "tools/scenes/adversarial_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

using agaa::hard::Corruption;

bool contains(const std::string& s, const std::string& what) {
    return s.find(what) != std::string::npos;
}

bool anyWarning(const eng::scene::Scene& s, const std::string& what) {
    return std::any_of(s.stats.warnings.begin(), s.stats.warnings.end(),
                       [&](const std::string& w) { return contains(w, what); });
}

void expectFiniteUnitNormals(const eng::scene::Scene& s) {
    for (const auto& v : s.vertices) {
        ASSERT_TRUE(std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z))
            << s.source;
        ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-4f)
            << s.source << ": a vertex normal reached the renderer unrepaired";
    }
}

TEST(HardScenes, AllKindsLoadAndStayOutOfTheDefaultList) {
    const auto regular = eng::scene::sceneKinds();
    for (const std::string& kind : eng::scene::hardSceneKinds()) {
        EXPECT_EQ(std::count(regular.begin(), regular.end(), kind), 0)
            << kind << " must not be swept by the benchmark";
        const eng::scene::Scene s = eng::scene::loadTestScene(kind);
        EXPECT_GT(s.triangleCount(), 0u) << kind;
        expectFiniteUnitNormals(s);
    }
    EXPECT_THROW(eng::scene::generateTestScene("hard-nonexistent"), eng::scene::SceneError);
}

TEST(HardScenes, ScenesAreWhatTheyClaim) {
    EXPECT_EQ(eng::scene::loadTestScene("hard-many-lights").lights.size(), 1000u) << "1000 lights";
    EXPECT_TRUE(eng::scene::loadTestScene("hard-no-lights").lights.empty()) << "no lights";
    const eng::scene::Scene emissive = eng::scene::loadTestScene("hard-emissive");
    float strongest = 0.0f;
    for (const auto& m : emissive.materials)
        strongest = std::max(strongest, m.emissiveStrength);
    EXPECT_EQ(strongest, 1.0e4f) << "KHR_materials_emissive_strength 1e4 survives the loader";
    const eng::scene::Scene mirror = eng::scene::loadTestScene("hard-mirror");
    bool zero = false, one = false;
    for (const auto& m : mirror.materials) {
        zero |= m.roughnessFactor == 0.0f;
        one |= m.roughnessFactor == 1.0f;
    }
    EXPECT_TRUE(zero && one) << "roughness exactly 0 and exactly 1";
    const eng::scene::Scene far = eng::scene::loadTestScene("hard-far");
    EXPECT_GT(glm::length(far.bounds.min), 9.9e4f) << "geometry 1e5 m from the origin";
    EXPECT_EQ(far.cameras[0].znear, 1.0e-4f);
    EXPECT_EQ(far.cameras[0].zfar, 1.0e7f);
    // About 90 triangles per covered pixel at 32x32: 24000 triangles in a 0.4 m box seen from
    // 1.2 m with a 0.7 rad fov cover about (0.4 / (2 * 1.2 * tan 0.35) * 32)^2 = 225 pixels.
    EXPECT_GE(eng::scene::loadTestScene("hard-dense").triangleCount(), 225u * 32u)
        << ">= 32 triangles per pixel";
}

TEST(HardInput, DegenerateTrianglesAndZeroNormalsAreRepairedWithWarnings) {
    const eng::scene::Scene s = eng::scene::loadTestScene("hard-degenerate");
    for (const auto& w : s.stats.warnings)
        std::printf("[ warning  ] %s\n", w.c_str());
    EXPECT_GE(s.stats.degenerateTrianglesDropped, 64u * 2u) << "collinear and point triangles are dropped";
    EXPECT_TRUE(anyWarning(s, "degenerate triangles dropped")) << "the drop is logged";
    EXPECT_TRUE(anyWarning(s, "NORMAL")) << "the normal repair is logged naming the attribute";
    expectFiniteUnitNormals(s);
}

TEST(HardInput, MalformedFilesAreRefusedNamingTheField) {
    struct Case {
        Corruption corruption;
        const char* field;
    };
    for (const Case& c :
         {Case{Corruption::NanPosition, "POSITION"}, Case{Corruption::InfPosition, "POSITION"},
          Case{Corruption::IndexOutOfRange, "indices"}}) {
        try {
            eng::scene::loadGltfModel(agaa::hard::malformedModel(c.corruption), "broken.gltf");
            ADD_FAILURE() << c.field << ": the corrupted model was accepted";
        } catch (const eng::scene::SceneError& e) {
            EXPECT_TRUE(contains(e.what(), "broken.gltf")) << "names the file: " << e.what();
            EXPECT_TRUE(contains(e.what(), c.field)) << "names the field " << c.field << ": " << e.what();
        }
    }
}

TEST(HardInput, ZeroAndNanNormalsAreRepairedWithAWarning) {
    for (Corruption c : {Corruption::ZeroNormals, Corruption::NanNormals}) {
        const eng::scene::Scene s = eng::scene::loadGltfModel(agaa::hard::malformedModel(c), "normals.gltf");
        EXPECT_TRUE(anyWarning(s, "NORMAL")) << "the repair is logged naming the attribute";
        expectFiniteUnitNormals(s);
    }
}

} // namespace
