// The irradiance cache's host-side directory: stable slots, LRU eviction within a budget, fading
// dynamic entries, invalidation by distance, and a hash table the shaders can probe.
#include "render/irradiance_cache/irradiance_cache_directory.h"

#include <gtest/gtest.h>
#include <set>

using engine::render::CacheKey;
using engine::render::CacheWork;
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
        if ((std::uint64_t(table[b].keySlot.y) << 32 | table[b].keySlot.x) == packed)
            return table[b].keySlot.z;
    }
    return ~0u;
}

}  // namespace

// One update traces all of a new entry's directions (K = S), no budget.
CacheWork oneTrace() {
    CacheWork w;
    w.phases = 1;
    return w;
}

TEST(IrradianceCacheDirectory, SlotsAreStableAndNewStaticEntriesTrace) {
    IrradianceCacheDirectory dir(100);
    auto first = dir.beginFrame(row(0, 10), 0.0, 0.3f, oneTrace());
    EXPECT_EQ(first.update.size(), 10u);
    EXPECT_EQ(first.trace.size(), 10u);
    std::uint32_t slot = dir.slotOf({{3, 1, 2}, 0});
    auto again = dir.beginFrame(row(0, 12), 0.1, 0.3f, oneTrace());
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
    for (const CacheKey& k : row(20, 40))
        EXPECT_NE(dir.slotOf(k), ~0u) << "seen more recently than the evicted ones";
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

// While no object moves, the dynamic entries around objects hold what is true: they converge and
// refresh like static entries instead of taking the budget every frame, and they do not fade.
// After a change of light they restart at once. When an object moves again they are updated
// every frame again.
TEST(IrradianceCacheDirectory, DynamicEntriesOfObjectsAtRestConvergeLikeStaticOnes) {
    IrradianceCacheDirectory dir(100);
    const std::vector<CacheKey> keys = row(0, 5, shared::CACHE_SET_DYNAMIC);
    CacheWork moving;
    moving.rayBudget = 1000000;  // ample; a budget of 0 would update every entry every frame
    moving.convergedAfter = 4;
    moving.refreshFrames = 10;
    CacheWork resting = moving;
    resting.objectsMoved = false;
    EXPECT_EQ(dir.beginFrame(keys, 0.0, 0.3f, moving).update.size(), 5u);
    // At rest: three more updates converge them (4 in all), then nothing until the refresh.
    std::vector<std::size_t> updated;
    double t = 0.0;
    for (int frame = 1; frame <= 12; ++frame) {
        t = frame / 30.0;
        updated.push_back(dir.beginFrame(keys, t, 0.3f, resting).update.size());
    }
    EXPECT_EQ(updated, (std::vector<std::size_t>{5, 5, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0}))
        << "12 frames = 0.4 s, past the fade";
    EXPECT_EQ(dir.liveEntries(), 5u) << "entries of objects at rest must not fade";
    // The lights changed: every one restarts at once (class 2), at rest or not.
    dir.relightAll();
    t += 1.0 / 30.0;
    EXPECT_EQ(dir.beginFrame(keys, t, 0.3f, resting).update.size(), 5u);
    // Nothing visible but still at rest: kept alive.
    EXPECT_EQ(dir.beginFrame({}, t + 1.0, 0.3f, resting).faded, 0u);
    // Moving again: every frame, and they fade once unseen for the fade time.
    EXPECT_EQ(dir.beginFrame(keys, t + 1.1, 0.3f, moving).update.size(), 5u);
    EXPECT_EQ(dir.beginFrame(keys, t + 1.2, 0.3f, moving).update.size(), 5u);
    EXPECT_EQ(dir.beginFrame({}, t + 1.6, 0.3f, moving).faded, 5u);
}

TEST(IrradianceCacheDirectory, InvalidationReachesOnlyEntriesWithinTheRayLength) {
    IrradianceCacheDirectory dir(1000);
    dir.beginFrame(row(0, 100), 0.0, 0.3f, oneTrace());
    // An edited cell at x in [40, 48): entries within 10 voxels are x in [30, 58].
    EXPECT_EQ(dir.invalidateStatic(std::vector<glm::ivec3>{{40, 0, 0}}, 10.0f), 28u);
    auto lists = dir.beginFrame(row(0, 100), 0.1, 0.3f, oneTrace());
    EXPECT_EQ(lists.trace.size(), 28u);
}

// The ray budget: never exceeded; dynamic entries first with at most half of it, then new
// entries; each (re)trace spreads over K / S updates; converged entries refresh only now and then.
TEST(IrradianceCacheDirectory, RayBudgetIsSpentByPriorityAndNeverExceeded) {
    IrradianceCacheDirectory dir(1000);
    CacheWork work;
    work.rayBudget = 40 * 96;  // 40 plain updates, or 20 updates that also trace
    work.phases = 2;
    work.convergedAfter = 3;
    work.refreshFrames = 10;
    auto first = dir.beginFrame(row(0, 100), 0.0, 0.3f, work);
    EXPECT_LE(first.rays, work.rayBudget);
    EXPECT_EQ(first.update.size(), 20u);  // all new: twice the rays each
    EXPECT_EQ(first.waiting, 80u);
    EXPECT_EQ(dir.liveEntries(), 20u) << "keys the budget leaves out get no slot yet";

    // Dynamic entries join: they come first, up to half the budget (50 here would want 4800
    // rays: 20 fit), then new static entries before the 20 still tracing.
    std::vector<CacheKey> keys = row(0, 100);
    auto dynamic = row(0, 50, shared::CACHE_SET_DYNAMIC);
    keys.insert(keys.end(), dynamic.begin(), dynamic.end());
    auto second = dir.beginFrame(keys, 0.1, 0.3f, work);
    EXPECT_LE(second.rays, work.rayBudget);
    EXPECT_EQ(second.update.size() - second.staticUpdates, 20u)
        << "dynamic entries: half the budget";
    EXPECT_EQ(second.staticUpdates, 10u);
    for (std::uint32_t i = 0; i < second.staticUpdates; ++i)
        EXPECT_GE(dir.entry(second.update[i]).voxel.x, 20)
            << "new keys before entries already traced once";
    EXPECT_EQ(second.trace.size(), second.staticUpdates);

    // Run until nothing waits: every entry is then traced (2 phases) and converged (3 updates).
    std::uint32_t frames = 2;
    for (; frames < 100; ++frames) {
        auto lists = dir.beginFrame(row(0, 100), 0.01 * frames, 100.0f, work);
        EXPECT_LE(lists.rays, work.rayBudget);
        if (lists.waiting == 0 && lists.update.empty()) break;
    }
    EXPECT_LT(frames, 100u);
    // Converged and nothing changed: 100 entries each refresh every 10 frames at most.
    std::uint64_t updates = 0;
    for (std::uint32_t i = 0; i < 20; ++i)
        updates += dir.beginFrame(row(0, 100), 2.0 + 0.01 * i, 100.0f, work).update.size();
    EXPECT_LE(updates, 200u);
    EXPECT_GT(updates, 0u);

    // After the lights change every entry restarts once, most stale first, within the budget.
    dir.relightAll();
    std::uint32_t restarted = 0;
    for (std::uint32_t i = 0; i < 3; ++i) {
        auto lists = dir.beginFrame(row(0, 100), 3.0 + 0.01 * i, 100.0f, work);
        EXPECT_LE(lists.rays, work.rayBudget);
        for (std::uint32_t slot : lists.update)
            restarted += (dir.entry(slot).flags & shared::CACHE_ENTRY_RESET) != 0u;
    }
    EXPECT_EQ(restarted, 100u) << "40 per frame: all within ceil(100 / 40) = 3 frames";
}

// An update is charged for the faces the shaders trace: a floor voxel (one open face) costs a
// sixth of an entry with six, so the same budget admits six times the new floor entries.
TEST(IrradianceCacheDirectory, RayBudgetChargesOnlyOpenFaces) {
    CacheWork work;
    work.rayBudget = 40 * 96;  // 20 new entries with six faces each (a first update costs twice)
    work.phases = 2;
    IrradianceCacheDirectory sixFaces(1000), floor(1000);
    EXPECT_EQ(sixFaces.beginFrame(row(0, 200), 0.0, 0.3f, work).update.size(), 20u);
    work.openFaces = [](glm::ivec3) { return 1u; };
    auto lists = floor.beginFrame(row(0, 200), 0.0, 0.3f, work);
    EXPECT_EQ(lists.update.size(), 120u);
    EXPECT_EQ(lists.rays, work.rayBudget);
    // Dynamic keys are charged six faces whatever is around them (objects move in front of them).
    auto dynamic = floor.beginFrame(row(0, 50, shared::CACHE_SET_DYNAMIC), 0.1, 0.3f, work);
    EXPECT_EQ(dynamic.update.size(), 40u)
        << "the whole budget (nothing else waits) at 96 rays each";
}

TEST(IrradianceCacheDirectory, WithoutABudgetEveryVisibleEntryUpdatesEveryFrame) {
    IrradianceCacheDirectory dir(1000);
    CacheWork work;
    work.convergedAfter = 1;
    for (int i = 0; i < 20; ++i)
        EXPECT_EQ(dir.beginFrame(row(0, 50), 0.01 * i, 100.0f, work).update.size(), 50u);
}
