#include "world/brick_grid.h"

#include <algorithm>

#include "core/check.h"

namespace engine::world {

namespace {
glm::ivec3 cellOf(glm::ivec3 p) { return p >> int(shared::BRICK_SHIFT); }
int localIndex(glm::ivec3 p) { return brickVoxelIndex(p & (kBrickDim - 1)); }
std::uint32_t uniformCellValue(MaterialId m) {
    return m == kEmpty ? shared::CELL_EMPTY : (shared::CELL_HOMOGENEOUS | m);
}
// A cell's marks on its top-grid page.
constexpr std::uint8_t kMarkDirty = 1;    // in mDirtyCells
constexpr std::uint8_t kMarkTouched = 2;  // in mTouchedCells

glm::ivec3 checkedCells(glm::ivec3 sizeInVoxels) {
    CHECK(glm::all(glm::greaterThan(sizeInVoxels, glm::ivec3(0))));
    return (sizeInVoxels + (kBrickDim - 1)) / kBrickDim;
}
}  // namespace

BrickGrid::BrickGrid(glm::ivec3 sizeInVoxels)
    : mSizeInCells(checkedCells(sizeInVoxels)), mTop(mSizeInCells) {
    mSizeInSuperCells = (mSizeInCells + 3) / 4;
    std::size_t supers =
        static_cast<std::size_t>(mSizeInSuperCells.x) * mSizeInSuperCells.y * mSizeInSuperCells.z;
    mSuperCells.assign(supers, shared::SUPER_SKIP_MAX);  // all air
    mSuperCounts.assign(supers, 0);
    mSuperDirty.assign(supers, 0);
    mRegionCount = regionCount(mSizeInCells);
    mRegionStamp.assign(std::size_t(mRegionCount.x) * mRegionCount.y * mRegionCount.z, 0);
}

MaterialId BrickGrid::get(glm::ivec3 p) const {
    if (!contains(p)) return kEmpty;
    std::uint32_t c = cell(cellOf(p));
    if (!cellIsBrick(c)) return cellMaterial(c);
    return mBrickVoxels[cellBrick(c)][localIndex(p)];
}

void BrickGrid::set(glm::ivec3 p, MaterialId material) {
    if (!contains(p)) return;
    glm::ivec3 c = cellOf(p);
    std::uint32_t value = cell(c);
    if (!cellIsBrick(value)) {
        if (cellMaterial(value) == material) return;
        BrickVoxels voxels;
        voxels.fill(cellMaterial(value));
        voxels[localIndex(p)] = material;
        writeCell(c, voxels);
        return;
    }
    std::uint32_t brick = cellBrick(value);
    BrickVoxels& voxels = mBrickVoxels[brick];
    if (voxels[localIndex(p)] == material) return;
    voxels[localIndex(p)] = material;
    if (isUniform(voxels)) {
        freeBrick(brick);
        setCell(c, uniformCellValue(material));
        return;
    }
    mBrickMasks[brick] = BrickMask::build(voxels);
    markBrickDirty(brick);
    touchCell(c);
}

BrickVoxels BrickGrid::readCell(glm::ivec3 c) const {
    std::uint32_t value = cell(c);
    if (cellIsBrick(value)) return mBrickVoxels[cellBrick(value)];
    BrickVoxels voxels;
    voxels.fill(cellMaterial(value));
    return voxels;
}

void BrickGrid::writeCell(glm::ivec3 c, const BrickVoxels& voxels) {
    if (isUniform(voxels)) {
        writeCellUniform(c, voxels[0]);
        return;
    }
    std::uint32_t value = mTop.get(c);
    std::uint32_t brick;
    if (cellIsBrick(value)) {
        brick = cellBrick(value);
        if (mBrickVoxels[brick] == voxels) return;
    } else {
        brick = allocateBrick();
        setCell(c, brick + 1u);
    }
    mBrickVoxels[brick] = voxels;
    mBrickMasks[brick] = BrickMask::build(voxels);
    markBrickDirty(brick);
    touchCell(c);
}

void BrickGrid::writeCellUniform(glm::ivec3 c, MaterialId material) {
    std::uint32_t value = mTop.get(c);
    if (cellIsBrick(value)) freeBrick(cellBrick(value));
    setCell(c, uniformCellValue(material));
}

std::uint32_t BrickGrid::homogeneousCells() const {
    std::uint32_t count = 0;
    mTop.forEachLiveCell(
        [&](std::uint32_t v) { count += (v & shared::CELL_HOMOGENEOUS) != 0 ? 1u : 0u; });
    return count;
}

std::uint64_t BrickGrid::solidVoxels() const {
    std::uint64_t total = 0;
    mTop.forEachLiveCell([&](std::uint32_t v) {
        if (v == shared::CELL_EMPTY) return;
        if (v & shared::CELL_HOMOGENEOUS) {
            total += kBrickVoxels;
            return;
        }
        for (MaterialId m : mBrickVoxels[cellBrick(v)]) total += (m != kEmpty);
    });
    return total;
}

std::vector<std::uint32_t> BrickGrid::denseCells() const {
    std::vector<std::uint32_t> cells(cellCount(), shared::CELL_EMPTY);
    for (int z = 0; z < mSizeInCells.z; ++z)
        for (int y = 0; y < mSizeInCells.y; ++y)
            for (int x = 0; x < mSizeInCells.x; ++x)
                cells[cellIndex({x, y, z})] = mTop.get({x, y, z});
    return cells;
}

void BrickGrid::reserveBricks(std::uint32_t n) {
    mBrickVoxels.reservePages(n);
    mBrickMasks.reservePages(n);
    mBrickDirty.reserve(n);
}

void BrickGrid::clearDirty() {
    for (std::uint32_t b : mDirtyBricks) mBrickDirty[b] = 0;
    for (std::uint32_t c : mDirtyCells) mTop.marks(cellOfIndex(c)) = 0;
    for (std::uint32_t s : mDirtySuperCells) mSuperDirty[s] = 0;
    for (std::uint32_t c : mTouchedCells) mTop.marks(cellOfIndex(c)) = 0;
    mTouchedCells.clear();
    mDirtySuperCells.clear();
    mDirtyBricks.clear();
    mDirtyCells.clear();
    // Every consumer has seen this frame's lists: pages left empty can go (their table entries
    // are then the next sync's changes).
    mTop.clearRegionChanges();
    mTop.releaseEmptyPages();
}

GridMemory BrickGrid::memory() const {
    constexpr std::size_t kBrickBytes = sizeof(BrickVoxels) + sizeof(BrickMask);
    GridMemory m;
    m.topGridBytes = mTop.bytes();
    m.superGridBytes = mSuperCells.size() * sizeof(std::uint32_t) + mSuperCounts.size();
    m.brickPoolBytes = mBrickVoxels.size() * kBrickBytes;
    m.liveBrickBytes = liveBricks() * kBrickBytes;
    m.bookkeepingBytes =
        mFreeBricks.size() * sizeof(std::uint32_t) + mBrickDirty.size() + mSuperDirty.size() +
        mTouchedCells.size() * sizeof(std::uint32_t) +
        (mDirtyBricks.size() + mDirtyCells.size() + mDirtySuperCells.size() + mRegionStamp.size()) *
            sizeof(std::uint32_t);
    return m;
}

bool BrickGrid::operator==(const BrickGrid& other) const {
    if (mSizeInCells != other.mSizeInCells) return false;
    const glm::ivec3 regions = mTop.sizeInRegions();
    for (int rz = 0; rz < regions.z; ++rz)
        for (int ry = 0; ry < regions.y; ++ry)
            for (int rx = 0; rx < regions.x; ++rx) {
                const CellRange range = regionCells({rx, ry, rz}, mSizeInCells);
                if (!mTop.regionHasPage(range.min) && !other.mTop.regionHasPage(range.min))
                    continue;  // both all empty
                for (int z = range.min.z; z < range.max.z; ++z)
                    for (int y = range.min.y; y < range.max.y; ++y)
                        for (int x = range.min.x; x < range.max.x; ++x) {
                            const std::uint32_t a = mTop.get({x, y, z});
                            const std::uint32_t b = other.mTop.get({x, y, z});
                            if (cellIsBrick(a) != cellIsBrick(b)) return false;
                            if (!cellIsBrick(a)) {
                                if (a != b) return false;
                            } else if (mBrickVoxels[cellBrick(a)] !=
                                       other.mBrickVoxels[cellBrick(b)]) {
                                return false;
                            }
                        }
            }
    return true;
}

std::uint32_t BrickGrid::allocateBrick() {
    if (!mFreeBricks.empty()) {
        std::uint32_t brick = mFreeBricks.back();
        mFreeBricks.pop_back();
        return brick;
    }
    CHECK_MSG(mBrickVoxels.size() < 0x7FFFFFF0u, "brick pool exhausted");
    mBrickVoxels.emplace_back();
    mBrickMasks.emplace_back();
    mBrickDirty.push_back(0);
    return static_cast<std::uint32_t>(mBrickVoxels.size() - 1);
}

void BrickGrid::freeBrick(std::uint32_t brick) { mFreeBricks.push_back(brick); }

void BrickGrid::setCell(glm::ivec3 c, std::uint32_t value) {
    const std::uint32_t old = mTop.set(c, value);
    if (old == value) return;
    touchCell(c);
    if ((old == shared::CELL_EMPTY) != (value == shared::CELL_EMPTY)) {
        const glm::ivec3 sc = c >> 2;
        std::uint8_t& count = mSuperCounts[superCellIndex(sc)];
        bool wasEmpty = count == 0;
        count = static_cast<std::uint8_t>(value == shared::CELL_EMPTY ? count - 1 : count + 1);
        if (wasEmpty != (count == 0)) updateSkipDistances(sc, count != 0);
    }
    std::uint8_t& marks = mTop.marks(c);
    if (!(marks & kMarkDirty)) {
        marks |= kMarkDirty;
        mDirtyCells.push_back(static_cast<std::uint32_t>(cellIndex(c)));
    }
}

// A super cell changed between empty and occupied: only skip distances within SUPER_SKIP_MAX - 1
// of it can change (farther ones are capped below that distance already).
void BrickGrid::updateSkipDistances(glm::ivec3 changed, bool nowOccupied) {
    const int reach = int(shared::SUPER_SKIP_MAX) - 1;
    const glm::ivec3 lo = glm::max(changed - reach, glm::ivec3(0));
    const glm::ivec3 hi = glm::min(changed + reach, mSizeInSuperCells - 1);
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
                const glm::ivec3 s(x, y, z);
                const glm::ivec3 d = glm::abs(s - changed);
                const std::uint32_t distance = std::uint32_t(std::max(d.x, std::max(d.y, d.z)));
                const std::size_t i = superCellIndex(s);
                if (nowOccupied) {
                    if (distance < mSuperCells[i]) setSuperCell(i, distance);
                } else if (mSuperCells[i] == distance) {
                    setSuperCell(i, skipDistance(s));  // `changed` was its nearest occupied one
                }
            }
}

// Chebyshev distance from s to the nearest occupied super cell, capped at SUPER_SKIP_MAX.
std::uint32_t BrickGrid::skipDistance(glm::ivec3 s) const {
    const int reach = int(shared::SUPER_SKIP_MAX) - 1;
    const glm::ivec3 lo = glm::max(s - reach, glm::ivec3(0));
    const glm::ivec3 hi = glm::min(s + reach, mSizeInSuperCells - 1);
    std::uint32_t best = shared::SUPER_SKIP_MAX;
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
                if (mSuperCounts[superCellIndex({x, y, z})] == 0) continue;
                const glm::ivec3 d = glm::abs(glm::ivec3(x, y, z) - s);
                best = std::min(best, std::uint32_t(std::max(d.x, std::max(d.y, d.z))));
            }
    return best;
}

void BrickGrid::setSuperCell(std::size_t index, std::uint32_t value) {
    if (mSuperCells[index] == value) return;
    mSuperCells[index] = value;
    if (!mSuperDirty[index]) {
        mSuperDirty[index] = 1;
        mDirtySuperCells.push_back(static_cast<std::uint32_t>(index));
    }
}

std::vector<RegionKey> BrickGrid::regionsEditedAfter(std::uint32_t epoch) const {
    std::vector<RegionKey> keys;
    for (std::size_t i = 0; i < mRegionStamp.size(); ++i) {
        if (mRegionStamp[i] <= epoch) continue;
        const int x = int(i % mRegionCount.x), yz = int(i / mRegionCount.x);
        keys.push_back({x, yz % mRegionCount.y, yz / mRegionCount.y});
    }
    return keys;
}

void BrickGrid::markRegionsEdited(std::span<const RegionKey> keys) {
    for (const RegionKey& k : keys) {
        if (glm::any(glm::lessThan(k.vec(), glm::ivec3(0))) ||
            glm::any(glm::greaterThanEqual(k.vec(), mRegionCount)))
            continue;
        mRegionStamp[std::size_t(k.x) + std::size_t(mRegionCount.x) *
                                            (k.y + std::size_t(mRegionCount.y) * k.z)] = mEditEpoch;
    }
}

void BrickGrid::touchCell(glm::ivec3 c) {
    // Stamped on every touch: touchedCells() is cleared each frame by the GPU mirror, the stamps
    // only by a save.
    if (mStampEdits) mRegionStamp[mTop.regionIndex(c)] = mEditEpoch;
    std::uint8_t& marks = mTop.marks(c);
    if (marks & kMarkTouched) return;
    marks |= kMarkTouched;
    mTouchedCells.push_back(static_cast<std::uint32_t>(cellIndex(c)));
}

void BrickGrid::markBrickDirty(std::uint32_t brick) {
    if (mBrickDirty[brick]) return;
    mBrickDirty[brick] = 1;
    mDirtyBricks.push_back(brick);
}

}  // namespace engine::world
