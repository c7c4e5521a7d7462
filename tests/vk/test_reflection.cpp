// Descriptor bindings reflected from SPIR-V (engine/vk/reflection.h): the shipped shaders' layouts,
// and hand-assembled modules for what the shipped shaders do not exercise and for bad input.

#include "engine/vk/reflection.h"

#include "shaders/agaa/generation_int64_frag.h"
#include "shaders/agaa/lighting_comp.h"
#include "shaders/agaa/lighting_gbuffer_comp.h"
#include "shaders/agaa/lighting_gbuffer_shadow_comp.h"
#include "shaders/agaa/scene_vert.h"
#include "shaders/agaa/visibility_frag.h"
#include "shaders/glsl/shared/frame.h"
#include "shaders/tests/agaa_generation_record_frag.h"
#include "shaders/tests/agaa_lighting_export_comp.h"

#include <gtest/gtest.h>

#include <optional>

namespace {
using eng::vk::Binding;
using eng::vk::reflectBindings;
using eng::vk::ReflectionError;
constexpr auto kCs = VK_SHADER_STAGE_COMPUTE_BIT;
constexpr auto kVs = VK_SHADER_STAGE_VERTEX_BIT;
constexpr auto kFs = VK_SHADER_STAGE_FRAGMENT_BIT;

std::optional<Binding> find(const std::vector<Binding>& bindings, uint32_t number) {
    for (const Binding& b : bindings)
        if (b.binding == number) return b;
    return std::nullopt;
}

// The shipped lighting variants: each path's binding 6, the shading rate's 18 in both, the
// G-buffer's albedo at 13 on the samples path only, the accumulate path's kept material at 20 on
// it only, and the test export's 14 only in its test build
// (agaa_test_shaders, not the shipping library).
TEST(Reflection, LightingVariantsDeclareTheirPathsBindings) {
    const std::vector<Binding> accumulate = reflectBindings({{kAgaaLightingComp, kCs}});
    const std::vector<Binding> samples = reflectBindings({{kAgaaLightingGbufferComp, kCs}});
    const std::vector<Binding> exporting = reflectBindings({{kTestsAgaaLightingExportComp, kCs}});
    ASSERT_TRUE(find(accumulate, 6) && find(samples, 6));
    EXPECT_EQ(find(accumulate, 6)->type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);      // the AG-buffer
    EXPECT_EQ(find(samples, 6)->type, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER); // the G-buffer's normals
    EXPECT_FALSE(find(accumulate, 13));
    // The accumulate path's kept per-sample material, which its shading rate reads
    // (shared/sample_material.h); the samples path reads its G-buffer instead.
    ASSERT_TRUE(find(accumulate, 20));
    EXPECT_EQ(find(accumulate, 20)->type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    EXPECT_FALSE(find(samples, 20));
    ASSERT_TRUE(find(samples, 13));
    EXPECT_EQ(find(samples, 13)->type, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
    for (const auto* v : {&accumulate, &samples}) {
        ASSERT_TRUE(find(*v, 18));
        EXPECT_EQ(find(*v, 18)->type, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
        EXPECT_EQ(find(*v, 18)->stages, VkShaderStageFlags(kCs));
        EXPECT_FALSE(find(*v, 14)) << "the test export's binding is in a shipping variant";
        ASSERT_TRUE(find(*v, 0));
        EXPECT_EQ(find(*v, 0)->type, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
    }
    ASSERT_TRUE(find(exporting, 14));
    EXPECT_EQ(find(exporting, 14)->type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    EXPECT_EQ(exporting.size(), samples.size() + 1);
    // Sorted by binding number, no duplicates.
    for (size_t i = 1; i < samples.size(); ++i)
        EXPECT_LT(samples[i - 1].binding, samples[i].binding);
}

TEST(Reflection, ShadowBindingsOnlyInTheShadowedVariant) {
    const std::vector<Binding> plain = reflectBindings({{kAgaaLightingGbufferComp, kCs}});
    const std::vector<Binding> shadowed = reflectBindings({{kAgaaLightingGbufferShadowComp, kCs}});
    EXPECT_FALSE(find(plain, 11));
    EXPECT_FALSE(find(plain, 12));
    ASSERT_TRUE(find(shadowed, 11));
    ASSERT_TRUE(find(shadowed, 12));
    EXPECT_EQ(find(shadowed, 11)->type, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
    EXPECT_EQ(find(shadowed, 12)->type, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
}

// A graphics pipeline's stages merge: the frame constants are read by both, the materials by the
// fragment stage only; set 1 (the scene's textures) is kept apart from set 0, with its array's count.
TEST(Reflection, GraphicsStagesMergeAndSetsStayApart) {
    const std::vector<Binding> set0 = reflectBindings({{kAgaaSceneVert, kVs}, {kAgaaVisibilityFrag, kFs}});
    ASSERT_TRUE(find(set0, 0) && find(set0, 2));
    EXPECT_FALSE(find(set0, 1)) << "the scene's materials are in its own set 1 (common/scene_materials.glsl)";
    EXPECT_EQ(find(set0, 0)->stages, VkShaderStageFlags(kVs | kFs));
    EXPECT_EQ(find(set0, 2)->type, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
    const std::vector<Binding> set1 = reflectBindings({{kAgaaSceneVert, kVs}, {kAgaaVisibilityFrag, kFs}}, 1);
    ASSERT_EQ(set1.size(), 2u);
    ASSERT_TRUE(find(set1, 0) && find(set1, 1));
    EXPECT_EQ(find(set1, 0)->type, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
    EXPECT_EQ(find(set1, 0)->count, shared::kMaxSceneTextures);
    EXPECT_EQ(find(set1, 1)->type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    EXPECT_EQ(find(set1, 1)->stages, VkShaderStageFlags(kFs));

    // The generation variants: the test record's buffer (5) and the 64-bit view of the AG-buffer (6).
    const std::vector<Binding> record =
        reflectBindings({{kAgaaSceneVert, kVs}, {kTestsAgaaGenerationRecordFrag, kFs}});
    const std::vector<Binding> int64 =
        reflectBindings({{kAgaaSceneVert, kVs}, {kAgaaGenerationInt64Frag, kFs}});
    EXPECT_TRUE(find(record, 5));
    EXPECT_FALSE(find(record, 6));
    EXPECT_FALSE(find(int64, 5));
    EXPECT_TRUE(find(int64, 6));
}

// ---- hand-assembled modules -------------------------------------------------------------------

// A minimal module builder: the header, then instructions as given.
struct Module {
    std::vector<uint32_t> words{0x07230203u, 0x00010000u, 0u, 64u, 0u};
    Module& op(uint32_t opcode, std::initializer_list<uint32_t> operands) {
        words.push_back(uint32_t(operands.size() + 1) << 16 | opcode);
        words.insert(words.end(), operands.begin(), operands.end());
        return *this;
    }
};
// Opcodes and enums (SPIR-V 1.6 specification, section 3).
constexpr uint32_t OpTypeFloat = 22, OpTypeImage = 25, OpTypeSampledImage = 27, OpTypeArray = 28,
                   OpTypeRuntimeArray = 29, OpTypeStruct = 30, OpTypePointer = 32, OpTypeInt = 21,
                   OpConstant = 43, OpVariable = 59, OpDecorate = 71;
constexpr uint32_t kBlock = 2, kBinding = 33, kSet = 34, kUniformConstant = 0, kUniform = 2,
                   kStorageBuffer = 12;

// `sampler2D t[4]` at set 0, binding 3, as a compute stage would declare it.
Module samplerArray(uint32_t lengthOp = OpConstant) {
    Module m;
    m.op(OpDecorate, {10, kBinding, 3}).op(OpDecorate, {10, kSet, 0});
    m.op(OpTypeFloat, {1, 32}).op(OpTypeInt, {2, 32, 0});
    m.op(lengthOp, {2, 3, 4});
    m.op(OpTypeImage, {4, 1, 1, 0, 0, 0, 1, 0}); // 2D, sampled
    m.op(OpTypeSampledImage, {5, 4});
    m.op(OpTypeArray, {6, 5, 3});
    m.op(OpTypePointer, {7, kUniformConstant, 6});
    m.op(OpVariable, {7, 10, kUniformConstant});
    return m;
}

TEST(Reflection, ArrayCountsAndStorageImages) {
    const Module m = samplerArray();
    const std::vector<Binding> b = reflectBindings({{m.words, kCs}});
    ASSERT_EQ(b.size(), 1u);
    EXPECT_EQ(b[0].binding, 3u);
    EXPECT_EQ(b[0].count, 4u);
    EXPECT_EQ(b[0].type, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);

    Module storage; // image2D (sampled = 2) at binding 1
    storage.op(OpDecorate, {10, kBinding, 1}).op(OpDecorate, {10, kSet, 0});
    storage.op(OpTypeFloat, {1, 32}).op(OpTypeImage, {4, 1, 1, 0, 0, 0, 2, 1});
    storage.op(OpTypePointer, {7, kUniformConstant, 4}).op(OpVariable, {7, 10, kUniformConstant});
    const std::vector<Binding> s = reflectBindings({{storage.words, kCs}});
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ(s[0].type, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
    EXPECT_TRUE(reflectBindings({{storage.words, kCs}}, 1).empty());
}

TEST(Reflection, StagesThatDisagreeOnABindingAreRefused) {
    auto block = [](uint32_t storageClass) {
        Module m; // a block at binding 2 in `storageClass`
        m.op(OpDecorate, {10, kBinding, 2}).op(OpDecorate, {10, kSet, 0}).op(OpDecorate, {5, kBlock});
        m.op(OpTypeFloat, {1, 32}).op(OpTypeStruct, {5, 1});
        m.op(OpTypePointer, {7, storageClass, 5}).op(OpVariable, {7, 10, storageClass});
        return m;
    };
    const Module ubo = block(kUniform), ssbo = block(kStorageBuffer);
    ASSERT_EQ(reflectBindings({{ubo.words, kVs}})[0].type, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
    ASSERT_EQ(reflectBindings({{ssbo.words, kFs}})[0].type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    try {
        reflectBindings({{ubo.words, kVs}, {ssbo.words, kFs}});
        FAIL() << "a uniform and a storage buffer at one binding were merged";
    } catch (const ReflectionError& e) {
        EXPECT_NE(std::string(e.what()).find("binding 2"), std::string::npos) << e.what();
    }
    const std::vector<Binding> a = reflectBindings({{ubo.words, kVs}});
    const std::vector<Binding> b = reflectBindings({{ssbo.words, kFs}});
    EXPECT_THROW(eng::vk::mergeBindings(a, b), ReflectionError);
    const std::vector<Binding> merged = eng::vk::mergeBindings(a, reflectBindings({{ubo.words, kFs}}));
    ASSERT_EQ(merged.size(), 1u);
    EXPECT_EQ(merged[0].stages, VkShaderStageFlags(kVs | kFs));
}

// What cannot be read says so, naming the stage, and never reads past the module's end.
TEST(Reflection, MalformedModulesAreRefused) {
    auto refused = [](std::span<const uint32_t> code, const char* expected) {
        try {
            reflectBindings({{code, kFs}});
            ADD_FAILURE() << "accepted; expected: " << expected;
        } catch (const ReflectionError& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("fragment shader"), std::string::npos) << e.what();
        }
    };
    Module good = samplerArray();
    std::vector<uint32_t> badMagic = good.words;
    badMagic[0] = 0x12345678u;
    refused(badMagic, "not a SPIR-V module");
    refused(std::span<const uint32_t>(good.words.data(), 3), "not a SPIR-V module");
    std::vector<uint32_t> truncated(good.words.begin(), good.words.end() - 1);
    refused(truncated, "runs past the end");
    std::vector<uint32_t> zeroWords = good.words;
    zeroWords[5] = 0; // the first instruction claims 0 words
    refused(zeroWords, "runs past the end");
    std::vector<uint32_t> pastBound = good.words;
    pastBound[3] = 8; // id 10 is past a bound of 8
    refused(pastBound, "past the id bound");
    refused(samplerArray(50 /* OpSpecConstant */).words, "not a constant");

    Module runtime; // sampler2D t[] at binding 0
    runtime.op(OpDecorate, {10, kBinding, 0}).op(OpTypeFloat, {1, 32});
    runtime.op(OpTypeImage, {4, 1, 1, 0, 0, 0, 1, 0}).op(OpTypeSampledImage, {5, 4});
    runtime.op(OpTypeRuntimeArray, {6, 5}).op(OpTypePointer, {7, kUniformConstant, 6});
    runtime.op(OpVariable, {7, 10, kUniformConstant});
    refused(runtime.words, "runtime-sized");
    Module noBinding; // a storage image in set 0 without a binding number
    noBinding.op(OpDecorate, {10, kSet, 0}).op(OpTypeFloat, {1, 32});
    noBinding.op(OpTypeImage, {4, 1, 1, 0, 0, 0, 2, 1}).op(OpTypePointer, {7, kUniformConstant, 4});
    noBinding.op(OpVariable, {7, 10, kUniformConstant});
    refused(noBinding.words, "has no binding number");
    // An empty stage (a depth-only pipeline's fragment) declares nothing.
    EXPECT_TRUE(reflectBindings({{std::span<const uint32_t>(), kFs}}).empty());
}

} // namespace
