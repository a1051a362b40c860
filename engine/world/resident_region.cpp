#include "world/resident_region.h"

#include "core/check.h"

namespace engine::world {

ResidentRegion::ResidentRegion(RegionSnapshot voxels)
    : mVoxels(std::move(voxels)), mOriginVoxel(mVoxels.key.vec() * (kRegionCells * kBrickDim)) {
    mMasks.reserve(mVoxels.bricks.size());
    for (const BrickVoxels& b : mVoxels.bricks) mMasks.push_back(BrickMask::build(b));
}

MaterialId ResidentRegion::get(glm::ivec3 p) const {
    const glm::ivec3 local = p - mOriginVoxel;
    const glm::ivec3 c = local / kBrickDim;
    DCHECK(glm::all(glm::greaterThanEqual(local, glm::ivec3(0))) &&
           glm::all(glm::lessThan(c, mVoxels.size)));
    const std::uint32_t cell =
        mVoxels
            .cells[std::size_t(c.x) + std::size_t(mVoxels.size.x) *
                                          (std::size_t(c.y) + std::size_t(mVoxels.size.y) * c.z)];
    if (cell == shared::CELL_EMPTY) return kEmpty;
    if (cell & shared::CELL_HOMOGENEOUS)
        return static_cast<MaterialId>(cell & shared::CELL_MATERIAL_MASK);
    return mVoxels.bricks[cell - 1][brickVoxelIndex(local - c * kBrickDim)];
}

std::size_t ResidentRegion::bytes() const {
    return sizeof(*this) + mVoxels.cells.capacity() * sizeof(std::uint32_t) +
           mVoxels.bricks.capacity() * sizeof(BrickVoxels) + mMasks.capacity() * sizeof(BrickMask);
}

}  // namespace engine::world
