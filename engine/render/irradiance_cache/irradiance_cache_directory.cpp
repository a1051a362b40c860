#include "render/irradiance_cache/irradiance_cache_directory.h"

#include <algorithm>
#include <bit>

#include "core/hash.h"

namespace engine::render {

namespace {

glm::uvec2 keyWords(const CacheKey& key) {
    return {static_cast<std::uint32_t>(key.voxel.x) | (static_cast<std::uint32_t>(key.voxel.y) << 16),
            static_cast<std::uint32_t>(key.voxel.z) | (key.set << 31)};
}

}  // namespace

std::uint64_t packCacheKey(const CacheKey& key) {
    glm::uvec2 w = keyWords(key);
    return static_cast<std::uint64_t>(w.x) | (static_cast<std::uint64_t>(w.y) << 32);
}

std::uint32_t cacheKeyHash(const CacheKey& key) {
    glm::uvec2 w = keyWords(key);
    return pcgHash(w.x ^ pcgHash(w.y));
}

IrradianceCacheDirectory::IrradianceCacheDirectory(std::uint32_t maxSlots) : mMaxSlots(std::max(maxSlots, 1u)) {}

void IrradianceCacheDirectory::clear() {
    mSlots.clear();
    mEntries.clear();
    mFree.clear();
    mIndex.clear();
}

std::uint32_t IrradianceCacheDirectory::slotOf(const CacheKey& key) const {
    auto it = mIndex.find(packCacheKey(key));
    return it == mIndex.end() ? ~0u : it->second;
}

void IrradianceCacheDirectory::release(std::uint32_t slot) {
    mIndex.erase(packCacheKey(mSlots[slot].key));
    mSlots[slot].live = false;
    mFree.push_back(slot);
}

std::uint32_t IrradianceCacheDirectory::allocate(const CacheKey& key, std::uint64_t frame, double time,
                                                 CacheFrameLists& lists) {
    std::uint32_t slot;
    if (!mFree.empty()) {
        slot = mFree.back();
        mFree.pop_back();
    } else {
        slot = static_cast<std::uint32_t>(mSlots.size());
        mSlots.emplace_back();
        mEntries.emplace_back();
    }
    Slot& s = mSlots[slot];
    s = Slot{key, true, key.set == shared::CACHE_SET_STATIC, frame, time, frame};
    mEntries[slot] = shared::CacheEntry{glm::ivec4(key.voxel, static_cast<int>(key.set)), glm::vec4(-1.0e9f, 0, 0, 0)};
    mIndex.emplace(packCacheKey(key), slot);
    lists.tableChanged = true;
    return slot;
}

CacheFrameLists IrradianceCacheDirectory::beginFrame(std::span<const CacheKey> visible, double time, float fadeSeconds) {
    CacheFrameLists lists;
    const std::uint64_t frame = ++mFrame;

    // Dynamic entries fade out after their last update; their slots come back.
    for (std::uint32_t slot = 0; slot < mSlots.size(); ++slot) {
        Slot& s = mSlots[slot];
        if (s.live && s.key.set == shared::CACHE_SET_DYNAMIC && time - s.lastUpdate > fadeSeconds) {
            release(slot);
            ++lists.faded;
            lists.tableChanged = true;
        }
    }

    // Known keys are marked seen; new ones wait until we know how many slots they need.
    std::vector<CacheKey> fresh;
    for (const CacheKey& key : visible) {
        auto it = mIndex.find(packCacheKey(key));
        if (it == mIndex.end()) {
            fresh.push_back(key);
            continue;
        }
        Slot& s = mSlots[it->second];
        if (s.lastSeen == frame) continue;  // a duplicate
        s.lastSeen = frame;
    }
    std::sort(fresh.begin(), fresh.end(), [](const CacheKey& a, const CacheKey& b) {
        return packCacheKey(a) < packCacheKey(b);
    });
    fresh.erase(std::unique(fresh.begin(), fresh.end()), fresh.end());

    // Evict the least recently seen (never this frame's) to make room, in one batch.
    const std::size_t available = mFree.size() + (mMaxSlots - mSlots.size());
    if (fresh.size() > available) {
        std::vector<std::uint32_t> candidates;
        for (std::uint32_t slot = 0; slot < mSlots.size(); ++slot) {
            if (mSlots[slot].live && mSlots[slot].lastSeen != frame) candidates.push_back(slot);
        }
        std::size_t want = std::min(candidates.size(), std::max(fresh.size() - available, std::size_t(mMaxSlots / 8)));
        std::partial_sort(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(want), candidates.end(),
                          [&](std::uint32_t a, std::uint32_t b) { return mSlots[a].lastSeen < mSlots[b].lastSeen; });
        for (std::size_t i = 0; i < want; ++i) release(candidates[i]);
        lists.evicted = static_cast<std::uint32_t>(want);
        lists.tableChanged = lists.tableChanged || want > 0;
    }
    for (const CacheKey& key : fresh) {
        if (mFree.empty() && mSlots.size() >= mMaxSlots) {
            ++lists.dropped;
            continue;
        }
        allocate(key, frame, time, lists);
    }

    for (std::uint32_t slot = 0; slot < mSlots.size(); ++slot) {
        Slot& s = mSlots[slot];
        if (!s.live || s.lastSeen != frame) continue;
        lists.update.push_back(slot);
        if (s.needsTrace) lists.trace.push_back(slot);
        s.needsTrace = false;
        s.lastUpdate = time;
        mEntries[slot].time.x = static_cast<float>(time);
        mEntries[slot].time.y = s.born == frame ? 1.0f : 0.0f;  // the GPU forgets the slot's old values
    }
    return lists;
}

std::uint32_t IrradianceCacheDirectory::invalidateStatic(std::span<const glm::ivec3> editedCellMins, float radius) {
    if (editedCellMins.empty()) return 0;
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::ivec3& c : editedCellMins) {
        lo = glm::min(lo, glm::vec3(c));
        hi = glm::max(hi, glm::vec3(c + 8));
    }
    std::uint32_t marked = 0;
    for (Slot& s : mSlots) {
        if (!s.live || s.key.set != shared::CACHE_SET_STATIC || s.needsTrace) continue;
        glm::vec3 p = glm::vec3(s.key.voxel) + 0.5f;
        // Quick reject against the edits' bounds, then the distance to each edited cell.
        glm::vec3 gap = glm::max(glm::max(lo - p, p - hi), glm::vec3(0.0f));
        if (glm::dot(gap, gap) > radius * radius) continue;
        for (const glm::ivec3& c : editedCellMins) {
            glm::vec3 g = glm::max(glm::max(glm::vec3(c) - p, p - glm::vec3(c + 8)), glm::vec3(0.0f));
            if (glm::dot(g, g) <= radius * radius) {
                s.needsTrace = true;
                ++marked;
                break;
            }
        }
    }
    return marked;
}

std::vector<shared::CacheBucket> IrradianceCacheDirectory::buildTable() const {
    const std::uint32_t buckets = std::bit_ceil(std::max<std::uint32_t>(2u * usedSlots(), 64u));
    std::vector<shared::CacheBucket> table(buckets, shared::CacheBucket{glm::uvec4(shared::CACHE_TABLE_EMPTY)});
    for (std::uint32_t slot = 0; slot < mSlots.size(); ++slot) {
        const Slot& s = mSlots[slot];
        if (!s.live) continue;
        glm::uvec2 w = keyWords(s.key);
        std::uint32_t b = cacheKeyHash(s.key) & (buckets - 1);
        while (table[b].keySlot.x != shared::CACHE_TABLE_EMPTY) b = (b + 1) & (buckets - 1);
        table[b].keySlot = glm::uvec4(w.x, w.y, slot, 0);
    }
    return table;
}

}  // namespace engine::render
