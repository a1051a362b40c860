// The source's topology for an OpenVDB import: leaves, tiles and extents read without voxel
// values, for planning; and scans of a grid's active voxels in bounded pieces, for the palette
// (io/vdb_import_state.h).
#include <algorithm>
#include <climits>
#include <cmath>

#include "io/vdb_import_state.h"

namespace engine::io::vdb_import {

namespace vdb = openvdb;

Status settleSourceBox(ImportState& im, const Box& content) {
    const std::optional<Box>& crop = im.options.crop;
    Box& sourceBox = im.place.sourceBox;
    sourceBox = content.intersect(cropBox(im.options));
    if (sourceBox.empty() && im.grids.voxengine && !crop)
        sourceBox = Box{glm::ivec3(0), glm::ivec3(1)};  // an all-air world of ours: keep it
    if (sourceBox.empty()) {
        if (crop)
            return makeError("{}: nothing of grid '{}' lies inside the crop box", im.file,
                             im.plan.grid);
        return makeError("{}: grid '{}' is empty (no active voxels)", im.file, im.plan.grid);
    }
    im.plan.sourceBox = sourceBox;
    return {};
}

Status readShapeTopology(ImportState& im) {
    const ChosenGrids& grids = im.grids;
    im.shape = makeSource(*grids.shapeHeader);
    im.shape->attach(im.reader.readTopology(grids.shapeIndex));
    vdb::GridBase::ConstPtr g = im.shape->base();
    im.plan.sourceActiveVoxels = g->activeVoxelCount();
    im.topology.shapeTopologyBytes = g->memUsage();

    // Extent of what is solid: active voxels, and for level sets every leaf and inside tile.
    Box content;
    vdb::CoordBBox active = g->evalActiveVoxelBoundingBox();
    if (!active.empty()) content = toBox(active);
    const Box crop = cropBox(im.options);
    std::uint64_t leafCount = 0;
    std::vector<Box>& leaves = im.topology.leaves;
    im.shape->forEachLeaf([&](const vdb::CoordBBox& node, std::uint64_t on) {
        ++leafCount;
        if (grids.kind != Kind::LevelSet && on == 0) return;
        Box b = toBox(node).intersect(crop);
        if (b.empty()) return;
        if (grids.kind == Kind::LevelSet) content = unite(content, b);
        leaves.push_back(b);
    });
    (void)im.shape->forEachTile([&](const vdb::CoordBBox&, const Sample&) {
        im.plan.sourceTiles++;
        return Status{};
    });
    (void)forEachSolidTile(im, *im.shape, [&](const Box& b, const Sample&) {
        content = unite(content, b);
        return Status{};
    });
    im.plan.sourceLeaves = leafCount;
    leaves.shrink_to_fit();
    // Bytes of one loaded leaf: values plus the node (mask, origin, buffer header).
    const vdb::GridBase& header = *grids.shapeHeader;
    std::uint64_t valueBytes = grids.kind == Kind::Colour ? 12 : 4;
    if (header.isType<vdb::DoubleGrid>() || header.isType<vdb::Int64Grid>()) valueBytes = 8;
    if (header.isType<vdb::Vec3DGrid>()) valueBytes = 24;
    if (grids.kind == Kind::Mask) valueBytes = 0;
    im.topology.shapeLeafBytes = 512 * valueBytes + 128;
    return settleSourceBox(im, content);
}

void readColourTopology(ImportState& im) {
    if (im.grids.colourIndex < 0) return;
    const std::size_t index = std::size_t(im.grids.colourIndex);
    im.colour = makeSource(*im.reader.readHeader(index));
    im.colour->attach(im.reader.readTopology(index));
    im.topology.colourTopologyBytes = im.colour->base()->memUsage();
    im.colour->forEachLeaf([&](const vdb::CoordBBox& node, std::uint64_t on) {
        if (on) im.topology.colourLeaves.push_back(toBox(node));
    });
    im.topology.colourLeafBytes =
        512 * (im.colour->base()->isType<vdb::Vec3DGrid>() ? 24 : 12) + 128;
    im.colour->attach(nullptr);
}

Box colourRegion(const ImportState& im, const Box& source) {
    if (im.grids.sameXform) return source;
    vdb::BBoxd index =
        im.grids.colourXform->worldToIndex(im.grids.shapeXform->indexToWorld(toCoordBBox(source)));
    // Widened by a voxel (two above: max is exclusive) so rounding never misses a neighbour.
    return Box{glm::ivec3(int(std::floor(index.min().x())), int(std::floor(index.min().y())),
                          int(std::floor(index.min().z()))) -
                   1,
               glm::ivec3(int(std::ceil(index.max().x())), int(std::ceil(index.max().y())),
                          int(std::ceil(index.max().z()))) +
                   2};
}

Status forEachSolidTile(const ImportState& im, const SourceGrid& topology,
                        const std::function<Status(const Box&, const Sample&)>& f) {
    const Box crop = cropBox(im.options);
    return topology.forEachTile([&](const vdb::CoordBBox& box, const Sample& s) -> Status {
        if (!isSolid(im, s)) return {};
        Box b = toBox(box).intersect(crop);
        if (b.empty()) return {};
        return f(b, s);
    });
}

Status scanActiveVoxels(ImportState& im, std::size_t index, const std::vector<Box>& leaves,
                        const Box& region, const SourceGrid::VoxelFn& f) {
    auto source = makeSource(*im.reader.readHeader(index));
    // Leaf-aligned z ranges of about 1/8 of the leaves each; a leaf belongs to exactly one.
    std::vector<int> zs;
    for (const Box& b : leaves) zs.push_back(floorDiv(b.min.z, 8));
    std::sort(zs.begin(), zs.end());
    const std::size_t limit = std::max<std::size_t>(2048, (zs.size() + 7) / 8);
    std::size_t i = 0;
    while (i < zs.size()) {
        std::size_t j = std::min(zs.size(), i + limit);
        while (j < zs.size() && zs[j] == zs[j - 1]) ++j;
        const int z0 = zs[i] * 8, z1 = zs[j - 1] * 8 + 8;
        Box piece{glm::ivec3(region.min.x, region.min.y, std::max(region.min.z, z0)),
                  glm::ivec3(region.max.x, region.max.y, std::min(region.max.z, z1))};
        if (!piece.empty()) {
            source->attach(im.reader.readRegion(index, leafAligned(piece)));
            vdb::CoordBBox origins(vdb::Coord(INT32_MIN / 2, INT32_MIN / 2, z0),
                                   vdb::Coord(INT32_MAX / 2, INT32_MAX / 2, z1 - 1));
            Status s = source->forEachActiveLeafVoxel(origins, toCoordBBox(piece), f);
            source->attach(nullptr);
            if (!s) return s;
        }
        i = j;
    }
    return {};
}

}  // namespace engine::io::vdb_import
