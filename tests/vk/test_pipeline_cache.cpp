// eng::vk::PipelineCache without a device: fake handles, a counting make and destroy.

#include "engine/vk/pipeline_cache.h"

#include <gtest/gtest.h>

#include <compare>
#include <cstdint>
#include <map>
#include <stdexcept>

namespace {

struct Key {
    uint32_t alpha = 0;
    bool doubleSided = false;
    auto operator<=>(const Key&) const = default;
};

VkPipeline fakeHandle(uintptr_t n) {
    return reinterpret_cast<VkPipeline>(n); // never dereferenced
}

TEST(PipelineCache, MakesEachVariantOnceAndDestroysEachOnce) {
    std::map<VkPipeline, int> destroyed;
    int made = 0;
    {
        eng::vk::PipelineCache<Key> cache(
            [&](const Key& k) {
                ++made;
                return fakeHandle(0x1000 + k.alpha * 2 + (k.doubleSided ? 1 : 0));
            },
            [&](VkPipeline p) { ++destroyed[p]; });
        const VkPipeline a = cache.get({1, false});
        EXPECT_EQ(cache.get({1, false}), a);
        const VkPipeline b = cache.get({1, true});
        const VkPipeline c = cache.get({2, false});
        EXPECT_NE(a, b);
        EXPECT_NE(a, c);
        EXPECT_EQ(made, 3);
        EXPECT_EQ(cache.size(), 3u);
        cache.release();
        EXPECT_EQ(destroyed.size(), 3u);
        EXPECT_EQ(cache.size(), 0u);
        // After a release a variant is made again, and the destructor destroys it.
        EXPECT_EQ(cache.get({1, false}), a);
        EXPECT_EQ(made, 4);
    }
    EXPECT_EQ(destroyed[fakeHandle(0x1002)], 2);
    EXPECT_EQ(destroyed[fakeHandle(0x1003)], 1);
    EXPECT_EQ(destroyed[fakeHandle(0x1004)], 1);
}

// A make that throws (out of memory, a missing feature) keeps nothing, and the next get retries.
TEST(PipelineCache, AFailedMakeKeepsNothing) {
    int destroyed = 0;
    bool fail = true;
    eng::vk::PipelineCache<Key> cache(
        [&](const Key&) {
            if (fail) throw std::runtime_error("no memory");
            return fakeHandle(0x2000);
        },
        [&](VkPipeline) { ++destroyed; });
    EXPECT_THROW(cache.get({}), std::runtime_error);
    EXPECT_EQ(cache.size(), 0u);
    fail = false;
    EXPECT_EQ(cache.get({}), fakeHandle(0x2000));
    cache.release();
    EXPECT_EQ(destroyed, 1);
}

} // namespace
