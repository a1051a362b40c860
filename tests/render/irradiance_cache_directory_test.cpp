// The irradiance cache's host-side directory: stable slots, LRU eviction within a budget, fading
// dynamic entries, invalidation by distance, and a hash table the shaders can probe.
#include <gtest/gtest.h>

#include <set>

#include "render/irradiance_cache/irradiance_cache_directory.h"

using engine::render::CacheKey;
using engine::render::IrradianceCacheDirectory;

namespace {

std::vector<CacheKey> row(int from, int to, std::uint32_t set = shared::CACHE_SET_STATIC) {
    std::vector<CacheKey> keys;
    for (int x = from; x < to; ++x) keys.push_back({{x, 1, 2}, set});
    return keys;
}

// The probe the shaders do (shaders/irradiance_cache/irradiance_cache.glsl).
std::uint32_t probe(const std::vector<shared::CacheBucket>& table, const CacheKey& key) {
    std::uint64_t packed = engine::render::packCacheKey(key);
    auto mask = static_cast<std::uint32_t>(table.size() - 1);
    std::uint32_t b = engine::render::cacheKeyHash(key) & mask;
    for (std::uint32_t i = 0; i <= mask; ++i, b = (b + 1) & mask) {
        if (table[b].keySlot.x == shared::CACHE_TABLE_EMPTY) return ~0u;
        if ((std::uint64_t(table[b].keySlot.y) << 32 | table[b].keySlot.x) == packed) return table[b].keySlot.z;
    }
    return ~0u;
}

}  // namespace

TEST(IrradianceCacheDirectory, SlotsAreStableAndNewStaticEntriesTrace) {
    IrradianceCacheDirectory dir(100);
    auto first = dir.beginFrame(row(0, 10), 0.0, 0.3f);
    EXPECT_EQ(first.update.size(), 10u);
    EXPECT_EQ(first.trace.size(), 10u);
    std::uint32_t slot = dir.slotOf({{3, 1, 2}, 0});
    auto again = dir.beginFrame(row(0, 12), 0.1, 0.3f);
    EXPECT_EQ(again.update.size(), 12u);
    EXPECT_EQ(again.trace.size(), 2u);  // only the new ones
    EXPECT_EQ(dir.slotOf({{3, 1, 2}, 0}), slot);
    auto table = dir.buildTable();
    for (const CacheKey& k : row(0, 12)) EXPECT_EQ(probe(table, k), dir.slotOf(k));
    EXPECT_EQ(probe(table, {{50, 1, 2}, 0}), ~0u);
    EXPECT_EQ(probe(table, {{3, 1, 2}, 1}), ~0u);  // the other set
}

TEST(IrradianceCacheDirectory, EvictsLeastRecentlySeenWithinBudget) {
    IrradianceCacheDirectory dir(40);
    dir.beginFrame(row(0, 20), 0.0, 0.3f);   // oldest
    dir.beginFrame(row(20, 40), 0.1, 0.3f);  // full now
    auto lists = dir.beginFrame(row(40, 50), 0.2, 0.3f);
    EXPECT_GE(lists.evicted, 10u);
    EXPECT_EQ(lists.dropped, 0u);
    EXPECT_LE(dir.usedSlots(), 40u);
    for (const CacheKey& k : row(40, 50)) EXPECT_NE(dir.slotOf(k), ~0u);
    for (const CacheKey& k : row(20, 40)) EXPECT_NE(dir.slotOf(k), ~0u) << "seen more recently than the evicted ones";
    EXPECT_EQ(dir.slotOf({{0, 1, 2}, 0}), ~0u);
    // More visible keys than the budget: the rest are dropped, nothing visible is evicted.
    auto over = dir.beginFrame(row(100, 150), 0.3, 0.3f);
    EXPECT_EQ(over.update.size(), 40u);
    EXPECT_EQ(over.dropped, 10u);
}

TEST(IrradianceCacheDirectory, DynamicEntriesFadeAndStaticOnesStay) {
    IrradianceCacheDirectory dir(100);
    std::vector<CacheKey> keys = row(0, 5, shared::CACHE_SET_DYNAMIC);
    auto more = row(0, 5);
    keys.insert(keys.end(), more.begin(), more.end());
    dir.beginFrame(keys, 0.0, 0.3f);
    EXPECT_EQ(dir.liveEntries(), 10u);
    EXPECT_EQ(dir.beginFrame({}, 0.2, 0.3f).faded, 0u);
    EXPECT_EQ(dir.beginFrame({}, 0.31, 0.3f).faded, 5u);
    EXPECT_EQ(dir.liveEntries(), 5u);
}

TEST(IrradianceCacheDirectory, InvalidationReachesOnlyEntriesWithinTheRayLength) {
    IrradianceCacheDirectory dir(1000);
    dir.beginFrame(row(0, 100), 0.0, 0.3f);
    // An edited cell at x in [40, 48): entries within 10 voxels are x in [30, 58].
    EXPECT_EQ(dir.invalidateStatic(std::vector<glm::ivec3>{{40, 0, 0}}, 10.0f), 28u);
    auto lists = dir.beginFrame(row(0, 100), 0.1, 0.3f);
    EXPECT_EQ(lists.trace.size(), 28u);
}
