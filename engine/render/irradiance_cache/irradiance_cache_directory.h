// The host side of the irradiance cache: which (voxel, set) pairs have a slot, which slots this
// frame updates, and the hash table the shaders look keys up in. Memory follows what the camera
// has seen: slots are handed out as voxels become visible, up to a budget, and the least
// recently seen are evicted when it is full. Slot numbers are stable while an entry lives, so
// the GPU-side data of a slot never moves.
//
// Work follows what changed: each frame spends a budget of rays on the visible entries by
// priority (see CacheWork), so a still, converged view costs little and a change is picked up
// within a bounded number of frames.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

#include "shared/irradiance_cache.h"

namespace engine::render {

struct CacheKey {
    glm::ivec3 voxel{0};
    std::uint32_t set = shared::CACHE_SET_STATIC;
    std::uint32_t coarse =
        0;  // 0: the voxel's entry; 1 + face: one face of an open 2x2 patch (cache_lod.h)
    bool operator==(const CacheKey&) const = default;
};

std::uint64_t packCacheKey(const CacheKey& key);
// The bucket a key starts probing at; the shaders compute the same
// (shaders/irradiance_cache/irradiance_cache.glsl).
std::uint32_t cacheKeyHash(const CacheKey& key);

// How a frame's rays are spent. Visible entries are taken in this order, the most stale first
// within a class, while the budget lasts:
//   1. dynamic entries (moving objects' surroundings), up to half the budget, first; while no
//      object moves (`objectsMoved` false) they are classed as static entries are (2 after the
//      lights changed, else 3, 4) and do not fade;
//   0. new static entries and those an edit invalidated, for their first update: on a moving
//      camera every pixel should find an entry. A static entry traces S directions of its own
//      through the static world per update (twice an update's rays) until all K are cached,
//      K / S updates;
//   1. the dynamic entries left over;
//   2. static entries near a moving object, and every entry once after the lights changed;
//   3. static entries still converging (fewer than `convergedAfter` updates since a reset, or
//      still tracing);
//   4. converged static entries not updated for `refreshFrames` frames.
// Without a budget (rayBudget 0) every visible entry is updated every frame.
//
// An update is charged for the faces it traces: S rays per face. The shaders skip a face whose
// neighbour is static solid, so a static voxel's entry is charged for its open faces when
// `openFaces` is given (a floor voxel traces one face, not six); a coarse entry traces one face;
// a dynamic entry is charged all six (what moves in front of its faces is not known here).
struct CacheWork {
    std::uint64_t rayBudget = 0;        // rays per frame; 0: no limit
    std::uint32_t raysPerUpdate = 96;   // S rays on each of the six faces
    std::uint32_t phases = 8;           // K / S: the updates a (re)trace takes
    std::uint32_t convergedAfter = 33;  // about 1 / alpha
    std::uint32_t refreshFrames = 30;
    glm::ivec3 nearMin{0},
        nearMax{-1};           // voxels near moving objects (class 2); empty when max < min
    bool objectsMoved = true;  // an object moved, appeared or vanished since the last frame
    std::function<std::uint32_t(glm::ivec3)>
        openFaces;  // a static voxel's faces not against static solid; null: six
};

struct CacheFrameLists {
    std::vector<std::uint32_t>
        update;  // slots the GPU updates this frame: static ones first, then dynamic
    std::vector<std::uint32_t>
        trace;  // of them, static slots tracing their phase in the static world first
    std::uint32_t staticUpdates = 0;  // static slots at the front of `update`
    std::uint64_t rays = 0;           // rays the selected updates may trace (the budget's measure)
    std::uint32_t waiting = 0;        // visible entries (or keys) the budget left for later frames
    std::uint32_t dropped =
        0;  // visible keys left out because the memory budget is full of visible keys
    std::uint32_t evicted = 0;  // least recently seen entries dropped to make room
    std::uint32_t faded = 0;    // dynamic entries released after their fade
    bool tableChanged = false;  // entries were added or removed: re-upload the table
};

class IrradianceCacheDirectory {
public:
    explicit IrradianceCacheDirectory(std::uint32_t maxSlots);

    // Registers this frame's visible keys (deduplicated by the caller or not) and returns the
    // slots to update within `work`'s budget. Dynamic entries not updated for `fadeSeconds` are
    // released.
    CacheFrameLists beginFrame(std::span<const CacheKey> visible, double time, float fadeSeconds,
                               const CacheWork& work = {});

    // Static entries within `radius` voxels of an edited 8^3 cell must re-trace their static rays
    // (next time they are updated). Returns how many were marked. Dynamic entries within reach
    // forget their cached static hits too (not counted).
    std::uint32_t invalidateStatic(std::span<const glm::ivec3> editedCellMins, float radius);
    // The lights changed: every entry restarts its running mean at its next update (class 2).
    void relightAll();
    void clear();

    std::uint32_t maxSlots() const { return mMaxSlots; }
    std::uint32_t usedSlots() const {
        return static_cast<std::uint32_t>(mSlots.size());
    }  // high-water mark
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
        bool reset = true;         // the next update restarts the running mean
        std::uint32_t traced = 0;  // updates since its static rays were (re)traced from scratch
        std::uint64_t tracedPhases =
            0;  // a dynamic entry: bit p set when phase p's static hits are cached
        std::uint32_t updates = 0;  // since the last reset
        std::uint64_t lastSeen = 0;
        std::uint64_t lastUpdateFrame = 0;
        double lastUpdate = 0.0;  // scene time
    };
    struct Candidate;

    // beginFrame's steps, in order.
    void fadeDynamicEntries(double time, float fadeSeconds, bool objectsMoved,
                            CacheFrameLists& lists);
    std::vector<std::uint32_t> markSeen(std::span<const CacheKey> visible, std::uint64_t frame,
                                        std::vector<CacheKey>& fresh);
    std::vector<Candidate> rankCandidates(std::span<const std::uint32_t> seen,
                                          std::span<const CacheKey> fresh, std::uint32_t firstFresh,
                                          std::uint64_t frame, const CacheWork& work) const;
    std::optional<Candidate> candidateFor(std::uint32_t slot, std::uint64_t frame,
                                          const CacheWork& work) const;
    static std::vector<bool> chooseWithinBudget(std::span<const Candidate> candidates,
                                                std::uint64_t rayBudget, std::uint64_t& spent);
    std::vector<std::uint32_t> slotsForChosen(std::span<const Candidate> candidates,
                                              const std::vector<bool>& chosen,
                                              std::span<const CacheKey> fresh,
                                              std::uint32_t firstFresh, std::uint64_t frame,
                                              double time, CacheFrameLists& lists);
    void startUpdates(std::vector<std::uint32_t>& selected, std::uint64_t frame, double time,
                      const CacheWork& work, CacheFrameLists& lists);

    std::uint32_t allocate(const CacheKey& key, std::uint64_t frame, double time,
                           CacheFrameLists& lists);
    std::uint32_t makeRoom(std::size_t wanted, std::uint64_t frame, CacheFrameLists& lists);
    void release(std::uint32_t slot);

    std::uint32_t mMaxSlots;
    std::uint64_t mFrame = 0;
    std::vector<Slot> mSlots;
    std::vector<shared::CacheEntry> mEntries;
    std::vector<std::uint32_t> mFree;
    std::unordered_map<std::uint64_t, std::uint32_t> mIndex;
};

}  // namespace engine::render
