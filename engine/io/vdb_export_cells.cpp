#include "io/vdb_export_cells.h"

namespace engine::io {

using world::BrickGrid;

glm::ivec3 ExportCells::sizeInCells() const {
    return mGrid ? mGrid->sizeInCells() : mSource->worldSizeInCells();
}

bool ExportCells::containsCell(glm::ivec3 c) const {
    return glm::all(glm::greaterThanEqual(c, glm::ivec3(0))) &&
           glm::all(glm::lessThan(c, sizeInCells()));
}

std::uint32_t ExportCells::cell(glm::ivec3 c) {
    if (!containsCell(c)) return shared::CELL_EMPTY;
    if (mGrid) return mGrid->cell(c);
    const world::RegionKey key = world::regionOfCell(c);
    if (!mRegion || mRegion->key != key) {
        mRegion.reset();  // the old region goes before the new one comes
        Result<world::RegionSnapshot> loaded = mSource->load(key);
        if (!loaded) throw ExportReadError{loaded.error().message};
        mRegion = std::move(*loaded);
        mLoads++;
    }
    const glm::ivec3 local = c - key.vec() * world::kRegionCells;
    const glm::ivec3 size = mRegion->size;
    return mRegion->cells[std::size_t(local.x) +
                          std::size_t(size.x) *
                              (std::size_t(local.y) + std::size_t(size.y) * std::size_t(local.z))];
}

const world::BrickVoxels& ExportCells::brickVoxels(std::uint32_t cell) const {
    const std::uint32_t brick = BrickGrid::cellBrick(cell);
    return mGrid ? mGrid->brickVoxels(brick) : mRegion->bricks[brick];
}

}  // namespace engine::io
