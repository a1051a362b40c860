// StoreRegionSource: a world's regions read one at a time from its region store
// (world/region_store.h), for streaming. Material ids stay the store's own (the palette of its
// `material` key); a region without a row is empty. The source holds its own read-only
// connection, used only by the loader thread, so the frame's saves never wait on it (WAL: readers
// and the writer do not block each other).
#pragma once

#include <cstddef>
#include <filesystem>

#include "world/region_source.h"
#include "world/region_store.h"

namespace engine::world {

class StoreRegionSource : public RegionSource {
public:
    // `paletteSize`: ids in the store must be below it (scene/store_world.h reads the palette).
    static Result<StoreRegionSource> open(const std::filesystem::path& path,
                                          std::size_t paletteSize);
    glm::ivec3 worldSizeInCells() const override { return mSizeInCells; }
    Result<RegionSnapshot> load(RegionKey key) override;

private:
    StoreRegionSource(RegionStore store, std::size_t paletteSize);
    RegionStore mStore;
    std::size_t mPaletteSize = 0;
    glm::ivec3 mSizeInCells{0};
};

}  // namespace engine::world
