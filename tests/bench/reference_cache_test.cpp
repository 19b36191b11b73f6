// Converged references are computed once per content: the cache returns what it stored, keys
// change with every input byte, and a damaged entry is recomputed.
#include "reference_cache.hpp"

#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace iblkit::bench {
namespace {

TEST(ReferenceCache, ComputesOnceThenReads) {
    testing::TempFolder scratch;
    const ReferenceCache cache(scratch.path());
    const auto key = ReferenceCache::key("test v1", {});
    int computed = 0;
    const auto compute = [&] {
        ++computed;
        return std::vector<double>{1.5, -2.25, 1e300};
    };
    bool hit = true;
    EXPECT_EQ(cache.getOrCompute(key, 3, compute, &hit), (std::vector<double>{1.5, -2.25, 1e300}));
    EXPECT_FALSE(hit);
    EXPECT_EQ(cache.getOrCompute(key, 3, compute, &hit), (std::vector<double>{1.5, -2.25, 1e300}));
    EXPECT_TRUE(hit);
    EXPECT_EQ(computed, 1);
}

TEST(ReferenceCache, KeysFollowTheContent) {
    const std::byte a[] = {std::byte{1}, std::byte{2}}, b[] = {std::byte{1}, std::byte{3}};
    EXPECT_NE(ReferenceCache::key("x", a), ReferenceCache::key("x", b));
    EXPECT_NE(ReferenceCache::key("x", a), ReferenceCache::key("y", a));
    EXPECT_EQ(ReferenceCache::key("x", a), ReferenceCache::key("x", a));
}

TEST(ReferenceCache, ADamagedEntryIsComputedAgain) {
    testing::TempFolder scratch;
    const ReferenceCache cache(scratch.path());
    const auto key = ReferenceCache::key("test v1", {});
    cache.getOrCompute(key, 3, [] { return std::vector<double>{1, 2, 3}; });
    std::ofstream(scratch.path() / "references" / (key + ".bin"), std::ios::trunc) << "IBLKREF1 truncated";
    bool hit = true;
    EXPECT_EQ(cache.getOrCompute(key, 1, [] { return std::vector<double>{4}; }, &hit), std::vector<double>{4});
    EXPECT_FALSE(hit);
    // An entry of another length, under a key that a bug made collide: computed again.
    EXPECT_EQ(cache.getOrCompute(key, 2, [] { return std::vector<double>{5, 6}; }, &hit), (std::vector<double>{5, 6}));
    EXPECT_FALSE(hit);
}

} // namespace
} // namespace iblkit::bench
