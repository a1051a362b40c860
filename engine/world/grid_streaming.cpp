#include "world/grid_streaming.h"

#include <algorithm>
#include <chrono>

namespace engine::world {

namespace {
double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}
}  // namespace

GridStreaming::GridStreaming(std::unique_ptr<RegionSource> source,
                             const ResidencySettings& settings, std::size_t regionsPerFrame,
                             std::size_t bricksPerFrame)
    : mResidency(std::move(source), settings),
      mRegionsPerFrame(std::max<std::size_t>(1, regionsPerFrame)),
      mBricksPerFrame(bricksPerFrame) {
    const glm::ivec3 n = mResidency.regionCounts();
    mInGrid.assign(std::size_t(n.x) * n.y * n.z, 0);
}

bool GridStreaming::boxInGrid(const Box& voxels) const {
    const Box world{glm::ivec3(0), mResidency.worldSizeInCells() * kBrickDim};
    const Box b = voxels.intersect(world);
    if (b.empty()) return true;
    const int regionVoxels = kRegionCells * kBrickDim;
    const glm::ivec3 lo = b.min / regionVoxels, hi = (b.max - 1) / regionVoxels;
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x)
                if (!inGrid({x, y, z}) && mResidency.state({x, y, z}) != RegionState::Failed)
                    return false;  // a failed region is empty for good: nothing to wait for
    return true;
}

GridStreamingReport GridStreaming::update(glm::vec3 eye, BrickGrid& grid) {
    GridStreamingReport report;
    ResidencyReport r = mResidency.update(eye);
    report.pending = r.pending;
    report.errors = std::move(r.errors);
    // Streamed writes are not edits: no save writes them (the header).
    grid.setStampingEdits(false);

    // Evicted by the residency: out of the grid, bricks back to the pool.
    auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < mGridKeys.size();) {
        const RegionKey k = mGridKeys[i];
        if (mResidency.state(k) == RegionState::Resident) {
            ++i;
            continue;
        }
        eraseRegion(grid, k);
        mInGrid[index(k)] = 0;
        mGridKeys[i] = mGridKeys.back();
        mGridKeys.pop_back();
        ++report.left;
    }
    report.outMs = msSince(start);

    // Arrived: into the grid, nearest first, within the per-frame limits (the first always).
    start = std::chrono::steady_clock::now();
    std::vector<std::pair<float, RegionKey>> arrived;
    for (RegionKey k : mResidency.residentKeys()) {
        if (mInGrid[index(k)]) continue;
        const CellRange range = regionCells(k, mResidency.worldSizeInCells());
        const glm::vec3 lo(range.min * kBrickDim), hi(range.max * kBrickDim);
        arrived.push_back(
            {glm::length(glm::max(glm::max(lo - eye, eye - hi), glm::vec3(0.0f))), k});
    }
    std::sort(arrived.begin(), arrived.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first < b.first : a.second < b.second;
    });
    for (const auto& [d, k] : arrived) {
        if (report.arrived == mRegionsPerFrame) break;
        const ResidentRegion* loaded = mResidency.region(k);
        const std::size_t bricks = loaded ? loaded->voxels().bricks.size() : 0;
        if (report.arrived > 0 && bricks > mBricksPerFrame - report.bricks) break;
        report.bricks += bricks;
        std::unique_ptr<ResidentRegion> region = mResidency.release(k);
        if (region) writeRegion(region->voxels(), grid);  // null: a failed load, seen as empty
        mResidency.recycle(std::move(region));
        mInGrid[index(k)] = 1;
        mGridKeys.push_back(k);
        ++report.arrived;
    }
    report.waiting = arrived.size() - report.arrived;
    report.inMs = msSince(start);
    grid.setStampingEdits(true);
    return report;
}

}  // namespace engine::world
