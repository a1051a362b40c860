// The host side of the irradiance cache: which (voxel, set) pairs have a slot, which slots this
// frame updates, and the hash table the shaders look keys up in. Memory follows what the camera
// has seen: slots are handed out as voxels become visible, up to a budget, and the least
// recently seen are evicted when it is full. Slot numbers are stable while an entry lives, so
// the GPU-side data of a slot never moves.
#pragma once

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "shared/irradiance_cache.h"

namespace engine::render {

struct CacheKey {
    glm::ivec3 voxel{0};
    std::uint32_t set = shared::CACHE_SET_STATIC;
    bool operator==(const CacheKey&) const = default;
};

std::uint64_t packCacheKey(const CacheKey& key);
// The bucket a key starts probing at; the shaders compute the same (shaders/irradiance_cache/irradiance_cache.glsl).
std::uint32_t cacheKeyHash(const CacheKey& key);

struct CacheFrameLists {
    std::vector<std::uint32_t> update;  // slots the GPU updates this frame (visible ones)
    std::vector<std::uint32_t> trace;   // static slots whose rays must be traced in the static world first
    std::uint32_t dropped = 0;          // visible keys left out because the budget is full of visible keys
    std::uint32_t evicted = 0;          // least recently seen entries dropped to make room
    std::uint32_t faded = 0;            // dynamic entries released after their fade
    bool tableChanged = false;          // entries were added or removed: re-upload the table
};

class IrradianceCacheDirectory {
public:
    explicit IrradianceCacheDirectory(std::uint32_t maxSlots);

    // Registers this frame's visible keys (deduplicated by the caller or not) and returns the
    // slots to update. Dynamic entries not seen for `fadeSeconds` are released.
    CacheFrameLists beginFrame(std::span<const CacheKey> visible, double time, float fadeSeconds);

    // Static entries within `radius` voxels of an edited 8^3 cell must re-trace their static rays
    // (next time they are updated). Returns how many were marked.
    std::uint32_t invalidateStatic(std::span<const glm::ivec3> editedCellMins, float radius);
    void clear();

    std::uint32_t maxSlots() const { return mMaxSlots; }
    std::uint32_t usedSlots() const { return static_cast<std::uint32_t>(mSlots.size()); }  // high-water mark
    std::uint32_t liveEntries() const { return static_cast<std::uint32_t>(mIndex.size()); }
    const shared::CacheEntry& entry(std::uint32_t slot) const { return mEntries[slot]; }
    std::span<const shared::CacheEntry> entries() const { return mEntries; }
    std::uint32_t slotOf(const CacheKey& key) const;  // ~0u when absent

    // The open-addressing table (linear probing) over the live entries, sized to a power of two
    // at least twice `usedSlots()`.
    std::vector<shared::CacheBucket> buildTable() const;

private:
    struct Slot {
        CacheKey key;
        bool live = false;
        bool needsTrace = false;
        std::uint64_t lastSeen = 0;
        double lastUpdate = 0.0;
        std::uint64_t born = 0;
    };
    std::uint32_t allocate(const CacheKey& key, std::uint64_t frame, double time, CacheFrameLists& lists);
    void release(std::uint32_t slot);

    std::uint32_t mMaxSlots;
    std::uint64_t mFrame = 0;
    std::vector<Slot> mSlots;
    std::vector<shared::CacheEntry> mEntries;
    std::vector<std::uint32_t> mFree;
    std::unordered_map<std::uint64_t, std::uint32_t> mIndex;
};

}  // namespace engine::render
