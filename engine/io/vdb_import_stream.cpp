// Streaming an OpenVDB import: a voxel-for-voxel copy read leaf by leaf in file order, never
// building an OpenVDB tree (io/vdb_tree_stream.h), for planning and for writing the world.
// Solid tiles come first, then each leaf's voxels (io/vdb_import_state.h).
#include <array>
#include <bitset>
#include <climits>
#include <fstream>

#include "io/vdb_import_state.h"
#include "io/vdb_tree_stream.h"

namespace engine::io::vdb_import {

namespace vdb = openvdb;

namespace {

// Calls f with a null pointer to the tree type of `g`, for the types a stream can read.
template <typename F>
Status withStreamableTree(const ImportState& im, F&& f) {
    const vdb::GridBase& g = *im.grids.shapeHeader;
    if (g.isType<vdb::FloatGrid>()) return f(static_cast<vdb::FloatTree*>(nullptr));
    if (g.isType<vdb::DoubleGrid>()) return f(static_cast<vdb::DoubleTree*>(nullptr));
    if (g.isType<vdb::Int32Grid>()) return f(static_cast<vdb::Int32Tree*>(nullptr));
    if (g.isType<vdb::Int64Grid>()) return f(static_cast<vdb::Int64Tree*>(nullptr));
    if (g.isType<vdb::Vec3SGrid>()) return f(static_cast<vdb::Vec3STree*>(nullptr));
    if (g.isType<vdb::Vec3DGrid>()) return f(static_cast<vdb::Vec3DTree*>(nullptr));
    return makeError(
        "{}: truncated, corrupt or unsupported VDB file (grid type cannot be streamed)", im.file);
}

// readShapeTopology() without an OpenVDB tree: the same figures from one walk over the nodes.
template <typename TreeT>
Status readTopologyStreamed(ImportState& im) {
    using Stream = TreeStream<TreeT>;
    using ValueT = typename TreeT::ValueType;
    VdbImportPlan& plan = im.plan;
    const Box crop = cropBox(im.options);
    vdb::GridBase::Ptr header = im.reader.openTree(im.grids.shapeIndex);
    const bool half = header->saveFloatAsHalf();
    std::istream& topology = im.reader.stream();
    Box content;
    auto tile = [&](const vdb::CoordBBox& box, const ValueT& value, bool active) {
        plan.sourceTiles++;
        const Sample s = toSample(value, active);
        if (active) plan.sourceActiveVoxels += volume(toBox(box));
        if (!isSolid(im, s)) return;
        const Box b = toBox(box).intersect(crop);
        if (b.empty()) return;
        content = unite(content, b);
        plan.uniformCells += volume(b) / world::kBrickVoxels;
    };
    const typename Stream::Root root = Stream::walk(topology, im.reader.formatVersion(), half,
                                                    im.reader.fileBytes(), nullptr, tile);
    std::vector<Box>& leaves = im.topology.leaves;
    Stream::stream(topology, nullptr, im.reader.formatVersion(), half, root, tile,
                   [&](const vdb::Coord& origin, const typename Stream::LeafMask& mask) {
                       plan.sourceLeaves++;
                       const std::uint64_t on = mask.countOn();
                       plan.sourceActiveVoxels += on;
                       const glm::ivec3 o(origin.x(), origin.y(), origin.z());
                       Box b;
                       if (im.grids.kind == Kind::LevelSet) {
                           b = Box{o, o + 8};
                       } else if (on) {
                           b = Box{glm::ivec3(INT32_MAX), glm::ivec3(INT32_MIN)};
                           for (auto it = mask.beginOn(); it; ++it) {
                               const vdb::Index i = it.pos();
                               const glm::ivec3 p =
                                   o + glm::ivec3(int(i >> 6), int((i >> 3) & 7), int(i & 7));
                               b.min = glm::min(b.min, p);
                               b.max = glm::max(b.max, p + 1);
                           }
                       }
                       b = b.intersect(crop);
                       if (!b.empty()) {
                           content = unite(content, b);
                           leaves.push_back(b);
                       }
                       return false;  // planning needs no values
                   },
                   {});
    leaves.shrink_to_fit();
    return settleSourceBox(im, content);
}

template <typename TreeT>
Status streamTree(ImportState& im, const std::function<Status(const Box&, const Sample&)>& onTile,
                  const std::function<Status(const vdb::Coord&, const Sample*)>& onLeaf) {
    using Stream = TreeStream<TreeT>;
    using ValueT = typename TreeT::ValueType;
    const Box crop = cropBox(im.options);
    const Box& sourceBox = im.place.sourceBox;
    vdb::GridBase::Ptr header = im.reader.openTree(im.grids.shapeIndex);
    const bool half = header->saveFloatAsHalf();
    std::istream& topology = im.reader.stream();
    // The first callback to fail stops the walk; its error is the result.
    Status failure;
    bool failed = false;
    auto keep = [&](Status s) {
        if (s) return;
        failure = std::move(s);
        failed = true;
    };
    auto tile = [&](const vdb::CoordBBox& box, const ValueT& value, bool active) {
        if (failed) return;
        const Sample s = toSample(value, active);
        if (!isSolid(im, s)) return;
        const Box b = toBox(box).intersect(crop);
        if (!b.empty()) keep(onTile(b, s));
    };
    const typename Stream::Root root = Stream::walk(topology, im.reader.formatVersion(), half,
                                                    im.reader.fileBytes(), nullptr, tile, &failed);
    if (failed) return failure;

    // A second stream over the same file reads the leaf values while the first walks the nodes;
    // it carries the same decoding state (format, compression, grid class and metadata).
    std::ifstream values(im.path, std::ios::in | std::ios::binary);
    if (!values)
        return makeError("{}: truncated or corrupt VDB file (cannot reopen {})", im.file, im.file);
    values.exceptions(std::ios::failbit | std::ios::badbit);
    vdb::io::setVersion(values, vdb::io::getLibraryVersion(topology),
                        vdb::io::getFormatVersion(topology));
    vdb::io::setDataCompression(values, vdb::io::getDataCompression(topology));
    vdb::io::setGridClass(values, vdb::io::getGridClass(topology));
    vdb::io::StreamMetadata::Ptr metadata = vdb::io::getStreamMetadataPtr(topology);
    vdb::io::setStreamMetadataPtr(values, metadata, /*transfer=*/false);
    im.reader.seekToBuffers(im.grids.shapeIndex);
    values.seekg(topology.tellg());

    std::vector<Sample> samples(512);
    Stream::stream(
        topology, &values, im.reader.formatVersion(), half, root, tile,
        [&](const vdb::Coord& origin, const typename Stream::LeafMask&) {
            const glm::ivec3 o(origin.x(), origin.y(), origin.z());
            return !failed && !Box{o, o + 8}.intersect(sourceBox).empty();
        },
        [&](const vdb::Coord& origin, const typename Stream::LeafMask& mask, const ValueT* v) {
            for (int i = 0; i < 512; ++i)
                samples[std::size_t(i)] = toSample(v[i], mask.isOn(vdb::Index(i)));
            keep(onLeaf(origin, samples.data()));
        },
        &failed);
    return failure;
}

// Writes streamed tiles and leaves into the world, cell by cell.
class StreamWriter {
public:
    StreamWriter(ImportState& im, world::BrickGrid& grid) : mIm(im), mGrid(grid) {}

    Status writeTile(const Box& source, const Sample& s) {
        const AxisMap& map = mIm.place.map;
        const std::vector<world::MaterialId>& remap = mIm.palette.remap;
        const Box target = map.span(map.orient(source), 0.0).intersect(mIm.place.worldBox);
        if (target.empty()) return {};
        const glm::ivec3 lo = target.min >> 3, hi = (target.max - 1) >> 3;
        for (int cz = lo.z; cz <= hi.z; ++cz)
            for (int cy = lo.y; cy <= hi.y; ++cy)
                for (int cx = lo.x; cx <= hi.x; ++cx) {
                    const glm::ivec3 c(cx, cy, cz);
                    const Box cellBox{c * 8, c * 8 + 8};
                    const Box part = cellBox.intersect(target);
                    if (part.min == cellBox.min && part.max == cellBox.max) {
                        Result<int> uniform = uniformMaterial(mIm, s, cellBox);
                        if (!uniform) return uniform.error();
                        if (*uniform != kVariesInCell) {
                            mGrid.writeCellUniform(c, remap[std::size_t(*uniform)]);
                            mIm.report.solidVoxels += world::kBrickVoxels;
                            mDirty.noteWrite();
                            continue;
                        }
                    }
                    world::BrickVoxels voxels = mGrid.readCell(c);
                    for (int z = part.min.z; z < part.max.z; ++z)
                        for (int y = part.min.y; y < part.max.y; ++y)
                            for (int x = part.min.x; x < part.max.x; ++x) {
                                Result<int> material = materialFor(mIm, {x, y, z}, s);
                                if (!material) return material.error();
                                voxels[std::size_t(world::brickVoxelIndex(
                                    glm::ivec3(x, y, z) & 7))] = remap[std::size_t(*material)];
                                mIm.report.solidVoxels++;
                            }
                    mGrid.writeCell(c, voxels);
                    mDirty.noteWrite();
                }
        return {};
    }

    Status writeLeaf(const vdb::Coord& origin, const Sample* samples) {
        // A leaf lands in one cell when the offset is leaf-aligned, else in up to eight.
        struct Part {
            glm::ivec3 cell;
            world::BrickVoxels voxels;
            std::bitset<512> set;
        };
        std::array<Part, 8> parts;
        int used = 0;
        for (int i = 0; i < 512; ++i) {
            const glm::ivec3 src(origin.x() + (i >> 6), origin.y() + ((i >> 3) & 7),
                                 origin.z() + (i & 7));
            if (!mIm.place.sourceBox.contains(src) || !isSolid(mIm, samples[i])) continue;
            const glm::ivec3 t = mIm.place.map.exactTarget(src);
            if (!mIm.place.worldBox.contains(t)) continue;
            const glm::ivec3 cell = t >> 3;
            int p = 0;
            while (p < used && parts[std::size_t(p)].cell != cell) ++p;
            if (p == used) {
                parts[std::size_t(used)].cell = cell;
                parts[std::size_t(used)].set.reset();
                ++used;
            }
            Result<int> material = materialFor(mIm, t, samples[i]);
            if (!material) return material.error();
            const int local = world::brickVoxelIndex(t & 7);
            parts[std::size_t(p)].voxels[std::size_t(local)] =
                mIm.palette.remap[std::size_t(*material)];
            parts[std::size_t(p)].set.set(std::size_t(local));
            mIm.report.solidVoxels++;
        }
        for (int p = 0; p < used; ++p) {
            Part& part = parts[std::size_t(p)];
            world::BrickVoxels voxels = mGrid.readCell(part.cell);
            for (std::size_t v = 0; v < 512; ++v)
                if (part.set.test(v)) voxels[v] = part.voxels[v];
            mGrid.writeCell(part.cell, voxels);
            mDirty.noteWrite();
        }
        return {};
    }

private:
    ImportState& mIm;
    world::BrickGrid& mGrid;
    DirtyListBound mDirty{mGrid};
};

}  // namespace

bool canStream(const ImportState& im) {
    const vdb::GridBase& g = *im.grids.shapeHeader;
    const bool type = g.isType<vdb::FloatGrid>() || g.isType<vdb::DoubleGrid>() ||
                      g.isType<vdb::Int32Grid>() || g.isType<vdb::Int64Grid>() ||
                      g.isType<vdb::Vec3SGrid>() || g.isType<vdb::Vec3DGrid>();
    return im.place.map.scale == glm::dvec3(1.0) && im.grids.colourIndex < 0 && type &&
           im.grids.kind != Kind::Mask &&
           im.reader.formatVersion() >= vdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION &&
           im.reader.grids()[im.grids.shapeIndex].parent.empty();
}

Status readShapeTopologyStreamed(ImportState& im) {
    return withStreamableTree(im, [&](auto* tree) {
        return readTopologyStreamed<std::remove_pointer_t<decltype(tree)>>(im);
    });
}

Status streamSource(ImportState& im, const std::function<Status(const Box&, const Sample&)>& onTile,
                    const std::function<Status(const vdb::Coord&, const Sample*)>& onLeaf) {
    return withStreamableTree(im, [&](auto* tree) {
        return streamTree<std::remove_pointer_t<decltype(tree)>>(im, onTile, onLeaf);
    });
}

Status streamIntoWorld(ImportState& im, world::BrickGrid& grid) {
    StreamWriter writer(im, grid);
    return streamSource(
        im, [&](const Box& tile, const Sample& value) { return writer.writeTile(tile, value); },
        [&](const vdb::Coord& origin, const Sample* samples) {
            return writer.writeLeaf(origin, samples);
        });
}

}  // namespace engine::io::vdb_import
