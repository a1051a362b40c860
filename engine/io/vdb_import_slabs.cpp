// Filling the world of an OpenVDB import one slab of cells at a time, reading only the source
// leaves that slab needs, so a large source is never in memory whole (io/vdb_import_state.h).
#include <algorithm>

#include "io/vdb_import_state.h"

namespace engine::io::vdb_import {

void makeSlabs(ImportState& im, const std::vector<std::uint8_t>& marks) {
    // Leaves each cell-z layer needs; slabs of consecutive layers hold about 1/16 of the leaves
    // (at least 1024), so the source's values are read in bounded pieces.
    const Placement& place = im.place;
    const glm::ivec3 cells = (place.worldSize + 7) / 8;
    const std::vector<Box>& leaves = im.topology.leaves;
    std::vector<std::uint64_t> perLayer(std::size_t(cells.z) + 1, 0);
    const double margin =
        place.trilinear ? std::max({place.map.scale.x, place.map.scale.y, place.map.scale.z}) : 0.0;
    for (const Box& leaf : leaves) {
        Box w = place.map.span(place.map.orient(leaf), margin).intersect(place.worldBox);
        if (w.empty()) continue;
        for (int z = w.min.z >> 3; z <= (w.max.z - 1) >> 3; ++z) perLayer[std::size_t(z)]++;
    }
    std::vector<std::uint8_t> layerHasSamples(std::size_t(cells.z), 0);
    const std::size_t layer = std::size_t(cells.x) * std::size_t(cells.y);
    for (std::size_t i = 0; i < marks.size(); ++i)
        if (marks[i] == kCellSample) layerHasSamples[i / layer] = 1;
    const std::uint64_t limit = std::max<std::uint64_t>(1024, (leaves.size() + 15) / 16);
    int start = -1;
    std::uint64_t count = 0;
    for (int z = 0; z <= cells.z; ++z) {
        bool has = z < cells.z && layerHasSamples[std::size_t(z)];
        if (start >= 0 && (!has || count + perLayer[std::size_t(z)] > limit)) {
            im.slabs.push_back({start, z, count});
            start = -1;
            count = 0;
        }
        if (has) {
            if (start < 0) start = z;
            count += perLayer[std::size_t(z)];
        }
    }
    for (const Slab& s : im.slabs) im.slabLeavesMax = std::max(im.slabLeavesMax, s.leaves);
    im.plan.slabs = int(im.slabs.size());
}

Status fillSlabs(ImportState& im, world::BrickGrid& grid, const std::vector<std::uint8_t>& marks,
                 bool intoExisting) {
    const Placement& place = im.place;
    const Box& worldBox = place.worldBox;
    const glm::ivec3 cells = (place.worldSize + 7) / 8;
    const glm::ivec3 lo = worldBox.min >> 3, hi = (worldBox.max - 1) >> 3;
    DirtyListBound dirty(grid);
    for (const Slab& slab : im.slabs) {
        Box worldPart{
            glm::ivec3(worldBox.min.x, worldBox.min.y, std::max(worldBox.min.z, slab.cz0 * 8)),
            glm::ivec3(worldBox.max.x, worldBox.max.y, std::min(worldBox.max.z, slab.cz1 * 8))};
        Box sourcePart = place.map.unorient(place.map.needed(worldPart)).intersect(place.sourceBox);
        if (sourcePart.empty()) continue;
        im.shape->attach(im.reader.readRegion(im.grids.shapeIndex, leafAligned(sourcePart)));
        if (im.colour)
            im.colour->attach(im.reader.readRegion(std::size_t(im.grids.colourIndex),
                                                   leafAligned(colourRegion(im, sourcePart))));
        for (int cz = std::max(slab.cz0, lo.z); cz < std::min(slab.cz1, hi.z + 1); ++cz) {
            for (int cy = lo.y; cy <= hi.y; ++cy) {
                for (int cx = lo.x; cx <= hi.x; ++cx) {
                    const glm::ivec3 c(cx, cy, cz);
                    if (marks[cellIndex(cells, c)] != kCellSample) continue;
                    world::BrickVoxels voxels;
                    if (intoExisting)
                        voxels = grid.readCell(c);
                    else
                        voxels.fill(world::kEmpty);
                    bool any = false;
                    for (int i = 0; i < world::kBrickVoxels; ++i) {
                        const glm::ivec3 t = c * 8 + world::brickVoxelPosition(i);
                        if (!worldBox.contains(t)) continue;
                        Sample s;
                        if (!solidAt(im, t, s)) continue;
                        Result<int> material = materialFor(im, t, s);
                        if (!material) return material.error();
                        voxels[std::size_t(i)] = im.palette.remap[std::size_t(*material)];
                        im.report.solidVoxels++;
                        any = true;
                    }
                    if (any) {
                        grid.writeCell(c, voxels);
                        dirty.noteWrite();
                    }
                }
            }
        }
        // Drop this slab's source values (and the dirty lists) before reading the next.
        im.shape->attach(nullptr);
        if (im.colour) im.colour->attach(nullptr);
        grid.clearDirty();
    }
    return {};
}

}  // namespace engine::io::vdb_import
