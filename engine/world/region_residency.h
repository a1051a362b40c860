// RegionResidency: the regions of a world that are in memory, for worlds larger than memory.
// The world's top grid is paged: a region table over the whole world (one pointer per region of
// 16^3 cells: 128 x 4 x 128 = 64 Ki entries for 16 384 x 512 x 16 384 voxels, 576 KiB) points at
// the resident regions (world/resident_region.h: each its own 16^3 cells and exactly its bricks);
// a region not resident has no cells at all. Around an eye position, update() asks a loader
// thread for the regions within a view radius, nearest first, takes in the ones it finished, and
// evicts beyond the radius — farthest first, and inside it too when the memory budget requires
// it, after which it asks for nothing farther than the farthest region it kept until there is
// room again. Loading (reading and decoding a store row, or generating) and freeing run on the
// loader thread; the frame thread only moves pointers.
//
// What a region not yet resident is: empty. get() returns kEmpty there and the region table says
// so (state()), so a traversal over the table skips the whole region in one step as air — never
// reads garbage; a caller that must not walk into unloaded ground (collision) asks state().
//
// Every region is a pure function of its source and key (world/region_source.h), so the voxels
// are the same whether a region was generated directly, streamed in any order, or evicted and
// reloaded (tests/world/region_residency_test.cpp).
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "world/region_source.h"
#include "world/resident_region.h"

namespace engine::world {

struct ResidencySettings {
    float radiusVoxels = 512.0f;  // regions whose box comes within this of the eye are wanted
    std::uint64_t budgetBytes = std::uint64_t(1) << 30;  // resident regions' bytes, at most
};

enum class RegionState : std::uint8_t { Absent, Requested, Resident, Failed };

struct ResidencyReport {
    std::size_t loaded = 0;           // regions taken in by this update
    std::size_t evicted = 0;          // regions evicted by this update
    std::size_t pending = 0;          // regions asked for and not yet loaded
    std::vector<std::string> errors;  // regions that failed to load (seen as empty), one line each
};

class RegionResidency {
public:
    RegionResidency(std::unique_ptr<RegionSource> source, const ResidencySettings& settings);
    ~RegionResidency();  // stops the loader (a load in progress finishes first)
    RegionResidency(const RegionResidency&) = delete;
    RegionResidency& operator=(const RegionResidency&) = delete;

    // Frame thread, once a frame: takes in finished loads, evicts, and asks for what is missing
    // around `eye` (world voxels), nearest first. Never waits for a load.
    ResidencyReport update(glm::vec3 eye);
    // Asks for exactly these regions, in this order, dropping earlier requests (tests and tools:
    // any load order). Finished loads are taken in by the next update() or collect().
    void request(std::span<const RegionKey> keys);
    // Takes in the loads finished so far (update() does this too); returns how many.
    std::size_t collect(std::vector<std::string>* errors = nullptr);
    // Blocks until the loader has nothing left to do, then collects (tests, tools; not the frame).
    std::size_t waitIdle(std::vector<std::string>* errors = nullptr);
    void evict(RegionKey key);
    // Regions the budget must not evict (replaces the previous set): a streamed grid's edited
    // regions until their save commits (world/grid_streaming.h). A pinned region still counts
    // against the budget; the farthest unpinned ones go first.
    void setPinned(std::span<const RegionKey> keys);
    // Hands a resident region's voxels to the caller (a grid that holds them from now on,
    // world/grid_streaming.h): it stays Resident, its bytes counted, until evicted, but get() and
    // region() see it empty. recycle() gives the voxels back to be freed on the loader thread.
    std::unique_ptr<ResidentRegion> release(RegionKey key);
    void recycle(std::unique_ptr<ResidentRegion> region);
    std::span<const RegionKey> residentKeys() const { return mResident; }

    glm::ivec3 worldSizeInCells() const { return mSizeInCells; }
    glm::ivec3 regionCounts() const { return mRegionCounts; }
    RegionState state(RegionKey key) const { return mState[index(key)]; }
    const ResidentRegion* region(RegionKey key) const { return mTable[index(key)].get(); }
    // The material at world voxel `p`: kEmpty outside the world or in a region not resident.
    MaterialId get(glm::ivec3 p) const;
    std::size_t residentRegions() const { return mResident.size(); }
    std::uint64_t residentBytes() const { return mResidentBytes; }
    std::uint64_t tableBytes() const;  // the region table itself
    const ResidencySettings& settings() const { return mSettings; }

private:
    struct Loaded {
        RegionKey key;
        std::unique_ptr<ResidentRegion> region;  // built on the loader thread; null if failed
        std::string error;
    };
    std::size_t index(RegionKey k) const {
        return std::size_t(k.x) + std::size_t(mRegionCounts.x) *
                                      (std::size_t(k.y) + std::size_t(mRegionCounts.y) * k.z);
    }
    float distance(RegionKey key, glm::vec3 eye) const;  // eye to the region's box, voxels
    void take(Loaded loaded, std::vector<std::string>* errors);
    void evictAt(std::size_t i);
    void run();

    std::unique_ptr<RegionSource> mSource;
    ResidencySettings mSettings;
    glm::ivec3 mSizeInCells{0}, mRegionCounts{0};
    // Frame-thread state: the paged top grid (region table) and what it holds.
    std::vector<std::unique_ptr<ResidentRegion>> mTable;
    std::vector<RegionState> mState;
    std::vector<std::uint64_t> mBytes;   // of each resident region, counted while it is resident
    std::vector<std::uint8_t> mPinned;   // setPinned(): not evicted by the budget
    std::vector<RegionKey> mPinnedKeys;  // what mPinned marks, to clear it
    std::vector<RegionKey> mResident;
    std::uint64_t mResidentBytes = 0;
    float mReach = 0.0f;        // how far requests go: the radius, less while the budget is full
    glm::vec3 mReachEye{0.0f};  // where the budget last shrank mReach

    // Shared with the loader thread, under mMutex.
    std::mutex mMutex;
    std::condition_variable mWake, mIdle;
    std::deque<RegionKey> mQueue;
    std::vector<Loaded> mDone;
    std::vector<std::unique_ptr<ResidentRegion>> mToFree;
    bool mLoading = false, mStop = false;
    std::thread mLoader;
};

}  // namespace engine::world
