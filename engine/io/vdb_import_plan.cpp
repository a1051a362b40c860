// Planning an OpenVDB import from the source's topology alone: which world cells need voxels
// read and which fill whole from tiles, and the memory the import will need, refused before
// anything is built when over the budget (io/vdb_import_state.h).
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "core/memory_budget.h"
#include "io/vdb_import_state.h"

namespace engine::io::vdb_import {

namespace {

// A streamed import has no topology in memory: its leaves give the cells that need voxels, and
// its tiles were counted while walking the file.
void countStreamedCells(ImportState& im) {
    const Placement& place = im.place;
    const glm::ivec3 cells = (place.worldSize + 7) / 8;
    std::vector<std::uint8_t> marks(std::size_t(volume(Box{glm::ivec3(0), cells})), kCellNone);
    for (const Box& leaf : im.topology.leaves) {
        Box w = place.map.span(place.map.orient(leaf), 0.0).intersect(place.worldBox);
        if (w.empty()) continue;
        for (int z = w.min.z >> 3; z <= (w.max.z - 1) >> 3; ++z)
            for (int y = w.min.y >> 3; y <= (w.max.y - 1) >> 3; ++y)
                for (int x = w.min.x >> 3; x <= (w.max.x - 1) >> 3; ++x) {
                    std::uint8_t& m = marks[cellIndex(cells, {x, y, z})];
                    im.plan.sampledCells += (m == kCellNone);
                    m = kCellSample;
                }
    }
    im.topology.leaves = {};  // the import streams the leaves again
}

Status estimate(ImportState& im, const world::Scene* target) {
    VdbImportPlan& plan = im.plan;
    const SourceTopology& topology = im.topology;
    const glm::u64vec3 cells = glm::u64vec3((im.place.worldSize + 7) / 8);
    const std::uint64_t cellCount = cells.x * cells.y * cells.z;
    // Top grid with its dirty and touched flags, and the super cells (4^3 cells: skip, count,
    // flag).
    const glm::u64vec3 supers = (cells + std::uint64_t(3)) / std::uint64_t(4);
    std::uint64_t worldBytes =
        target ? 0 : cellCount * (4 + 1 + 1) + supers.x * supers.y * supers.z * (4 + 1 + 1);
    worldBytes += cellCount;                  // the marks
    worldBytes += cells.x * cells.y * 8 * 2;  // per-slab dirty lists
    std::uint64_t existing = target ? target->grid.liveBricks() : 0;
    worldBytes +=
        world::BrickGrid::poolBytesFor(existing + plan.sampledCells);  // the pool, in whole pages
    // Each slab read rebuilds the source's topology (nodes, masks, tiles) next to that slab's leaf
    // values; malloc adds a header to every node, hence the 1.25.
    std::uint64_t source = (topology.shapeTopologyBytes * 5) / 4 +
                           im.slabLeavesMax * topology.shapeLeafBytes +
                           topology.leaves.capacity() * sizeof(Box);
    if (im.colour) {
        const std::uint64_t colourLeaves =
            std::min<std::uint64_t>(topology.colourLeaves.size(), 2 * im.slabLeavesMax);
        source += (topology.colourTopologyBytes * 5) / 4 + topology.colourLeafBytes * colourLeaves +
                  topology.colourLeaves.capacity() * sizeof(Box);
    }
    if (im.grids.rule == MaterialRule::Colour) source += 65536 * 96;  // histogram and mapper memo
    source += 1 << 20;  // the reader: stream buffer, descriptors, file metadata
    if (im.streaming) {
        // No OpenVDB tree is built, neither for planning nor for the import.
        source = 2 << 20;  // node masks on one path, one leaf's values, two stream buffers
    }
    plan.worldBytes = worldBytes;
    plan.sourceBytes = source;
    plan.estimateBytes = worldBytes + source;
    const std::uint64_t budget = im.options.memoryBudgetBytes;
    if (plan.estimateBytes > budget)
        return makeError(
            "{}: importing grid '{}' would need about {} (world {}x{}x{}: {} for the grid and up "
            "to {} "
            "bricks; {} for the source), over the memory budget of {} ({})",
            im.file, plan.grid, mib(plan.estimateBytes), plan.worldSize.x, plan.worldSize.y,
            plan.worldSize.z, mib(worldBytes), plan.sampledCells, mib(source), mib(budget),
            memoryBudgetAdvice(budget));
    return {};
}

}  // namespace

std::string mib(std::uint64_t bytes) {
    return fmt::format("{:.1f} MiB", double(bytes) / (1 << 20));
}

Status planImport(ImportState& im, const world::Scene* target) {
    im.plan.file = im.file;
    im.plan.budgetBytes = im.options.memoryBudgetBytes;
    if (!(im.options.voxelSize >= 0.0) || std::isinf(im.options.voxelSize))
        return makeError("{}: the voxel size must be positive (got {})", im.file,
                         im.options.voxelSize);
    if (Status s = chooseGrids(im); !s) return s;
    if (Status s = orientAndScale(im); !s) return s;
    im.streaming = canStream(im);
    im.plan.streamed = im.streaming;
    if (Status s = im.streaming ? readShapeTopologyStreamed(im) : readShapeTopology(im); !s)
        return s;
    if (Status s = placeOffset(im, target); !s) return s;
    if (im.streaming) {
        countStreamedCells(im);
    } else {
        std::vector<std::uint8_t> marks(
            std::size_t(volume(Box{glm::ivec3(0), (im.place.worldSize + 7) / 8})), kCellNone);
        // Counting pass: which cells need voxels, which fill whole from tiles.
        if (Status s = markCells(im, *im.shape, marks, [](glm::ivec3, int) {}); !s) return s;
        for (std::uint8_t m : marks) {
            im.plan.sampledCells += (m == kCellSample);
            im.plan.uniformCells += (m == kCellUniform);
        }
        im.shape->attach(nullptr);
        readColourTopology(im);
        makeSlabs(im, marks);
    }
    return estimate(im, target);
}

Status markCells(ImportState& im, const SourceGrid& topology, std::vector<std::uint8_t>& marks,
                 const std::function<void(glm::ivec3 cell, int material)>& onUniform) {
    const Placement& place = im.place;
    const AxisMap& map = place.map;
    const glm::ivec3 cells = (place.worldSize + 7) / 8;
    const double margin = place.trilinear ? std::max({map.scale.x, map.scale.y, map.scale.z}) : 0.0;
    auto cellRange = [&](const Box& w, glm::ivec3& lo, glm::ivec3& hi) {
        Box clipped = w.intersect(place.worldBox);
        if (clipped.empty()) return false;
        lo = clipped.min >> 3;
        hi = (clipped.max - 1) >> 3;
        return true;
    };
    for (const Box& leaf : im.topology.leaves) {
        glm::ivec3 lo, hi;
        if (!cellRange(map.span(map.orient(leaf), margin), lo, hi)) continue;
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) marks[cellIndex(cells, {x, y, z})] = kCellSample;
    }
    return forEachSolidTile(
        im, topology, [&](const Box& tileBox, const Sample& tileValue) -> Status {
            Box oriented = map.orient(tileBox);
            Box inside = map.centresInside(oriented, margin);
            glm::ivec3 lo, hi;
            if (!cellRange(map.span(oriented, margin), lo, hi)) return {};
            for (int z = lo.z; z <= hi.z; ++z) {
                for (int y = lo.y; y <= hi.y; ++y) {
                    for (int x = lo.x; x <= hi.x; ++x) {
                        const glm::ivec3 c(x, y, z);
                        std::uint8_t& m = marks[cellIndex(cells, c)];
                        if (m == kCellSample) continue;
                        Box cellBox{c * 8, c * 8 + 8};
                        // Whole cell inside the tile and inside the world box: no voxel to read.
                        const Box& worldBox = place.worldBox;
                        bool whole = glm::all(glm::greaterThanEqual(
                                         cellBox.min, glm::max(inside.min, worldBox.min))) &&
                                     glm::all(glm::lessThanEqual(
                                         cellBox.max, glm::min(inside.max, worldBox.max)));
                        int material = kVariesInCell;
                        if (whole) {
                            Result<int> uniform = uniformMaterial(im, tileValue, cellBox);
                            if (!uniform) return uniform.error();
                            material = *uniform;
                        }
                        if (material != kVariesInCell) {
                            m = kCellUniform;
                            onUniform(c, material);
                        } else {
                            m = kCellSample;
                        }
                    }
                }
            }
            return {};
        });
}

}  // namespace engine::io::vdb_import
