#include "world/store_region_source.h"

#include <fmt/format.h>

namespace engine::world {

Result<StoreRegionSource> StoreRegionSource::open(const std::filesystem::path& path,
                                                  std::size_t paletteSize) {
    auto store = RegionStore::open(path, /*writable=*/false);
    if (!store) return store.error();
    if (store->info().regionCells != kRegionCells)
        return makeError("{}: regions of {} cells cannot stream (the loader pages regions of {})",
                         path.string(), store->info().regionCells, kRegionCells);
    return StoreRegionSource(std::move(*store), paletteSize);
}

StoreRegionSource::StoreRegionSource(RegionStore store, std::size_t paletteSize)
    : mStore(std::move(store)),
      mPaletteSize(paletteSize),
      mSizeInCells((mStore.info().worldSizeInVoxels + (kBrickDim - 1)) / kBrickDim) {}

Result<RegionSnapshot> StoreRegionSource::load(RegionKey key) {
    const CellRange range = regionCells(key, mSizeInCells);
    if (glm::any(glm::lessThanEqual(range.size(), glm::ivec3(0))))
        return makeError("{}: region ({}, {}, {}) lies outside the world", mStore.path().string(),
                         key.x, key.y, key.z);
    auto blob = mStore.readRegion(key);
    if (!blob) return blob.error();
    if (!*blob) {
        RegionSnapshot empty;
        empty.key = key;
        empty.size = range.size();
        empty.cells.assign(range.count(), shared::CELL_EMPTY);
        return empty;
    }
    return decodeRegion(
        key, **blob, range.size(), mPaletteSize,
        fmt::format("{}: region ({}, {}, {})", mStore.path().string(), key.x, key.y, key.z));
}

}  // namespace engine::world
