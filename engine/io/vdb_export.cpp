#include "io/vdb_export.h"

#include <algorithm>
#include <functional>
#include <memory>
#include <optional>

#include "core/atomic_file.h"
#include "core/progress.h"
#include "io/vdb_export_cells.h"
#include "io/vdb_layout.h"
#include "io/vdb_reader.h"

namespace engine::io {

namespace fs = std::filesystem;
namespace vdb = openvdb;
using world::BrickGrid;
using world::MaterialId;

namespace {

// io::Archive's own write() takes every grid at once and, for each, computes statistics and
// OpenVDB 10's delayed-load tables by walking the grid's in-memory tree. Our grids have no tree
// (BrickGridAsVdb), so this writer asks for each grid when its turn comes and writes the grid
// record itself, in the same layout as Archive::writeGrid(): descriptor, offsets, metadata,
// transform, topology, buffers. Delayed-load tables are optional in the format (files before
// OpenVDB 6.1 have none); statistics come with the grid.
class StreamingVdbWriter : private vdb::io::Archive {
public:
    using GridMaker = std::function<vdb::GridBase::Ptr()>;

    void writeStreamed(std::ostream& os, const vdb::MetaMap& fileMetadata,
                       const std::vector<GridMaker>& makers) const {
        vdb::io::StreamMetadata::Ptr streamMetadata = std::make_shared<vdb::io::StreamMetadata>();
        vdb::io::setStreamMetadataPtr(os, streamMetadata, /*transfer=*/false);
        vdb::io::setDataCompression(os, compression());
        vdb::io::setWriteGridStatsMetadata(os, false);
        writeHeader(os, /*seekable=*/true);
        fileMetadata.writeMeta(os);
        std::int32_t count = std::int32_t(makers.size());
        os.write(reinterpret_cast<const char*>(&count), sizeof(count));
        for (const GridMaker& make : makers) {
            vdb::GridBase::Ptr grid = make();
            grid->insertMeta(vdb::GridBase::META_FILE_COMPRESSION,
                             vdb::StringMetadata(vdb::io::compressionToString(compression())));
            vdb::io::GridDescriptor gd(grid->getName(), grid->type(), grid->saveFloatAsHalf());
            writeGridRecord(os, gd, *grid, streamMetadata);
            vdb::io::setStreamMetadataPtr(os, streamMetadata, false);
            vdb::io::setDataCompression(os, compression());
        }
    }

private:
    void writeGridRecord(std::ostream& os, vdb::io::GridDescriptor& gd, const vdb::GridBase& grid,
                         const vdb::io::StreamMetadata::Ptr& fileLevel) const {
        auto streamMetadata = std::make_shared<vdb::io::StreamMetadata>(*fileLevel);
        streamMetadata->setHalfFloat(grid.saveFloatAsHalf());
        streamMetadata->gridMetadata() = static_cast<const vdb::MetaMap&>(grid);
        vdb::io::setStreamMetadataPtr(os, streamMetadata, /*transfer=*/false);
        gd.writeHeader(os);
        const std::int64_t offsets = std::int64_t(os.tellp());
        gd.writeStreamPos(os);  // placeholders, rewritten below
        gd.setGridPos(os.tellp());
        setGridCompression(os, grid);
        grid.writeMeta(os);
        grid.writeTransform(os);
        grid.writeTopology(os);
        gd.setBlockPos(os.tellp());
        grid.writeBuffers(os);
        gd.setEndPos(os.tellp());
        os.seekp(offsets, std::ios_base::beg);
        gd.writeStreamPos(os);
        gd.seekToEnd(os);
    }
};

// One output grid written straight from the world's cells, never built as an OpenVDB tree: its
// topology and leaf buffers are produced cell by cell while io::Archive writes it, in exactly the
// byte layout Tree::writeTopology()/writeBuffers() would produce (RootNode, InternalNode 5 and 4,
// LeafNode 3; root children sorted by origin, node children in bit order). Our bricks and
// OpenVDB leaves share size and alignment, so an empty cell is nothing, a homogeneous cell one
// tile of an internal node, and a brick one leaf. An Internal4 node is exactly one region, so
// each pass (statistics, topology, buffers) reads the world region by region
// (io/vdb_export_cells.h).
template <typename GridT>
class BrickGridAsVdb final : public GridT {
public:
    using ValueT = typename GridT::ValueType;
    using TreeT = typename GridT::TreeType;
    using Int5T = typename TreeT::RootNodeType::ChildNodeType;
    using Int4T = typename Int5T::ChildNodeType;
    using LeafT = typename Int4T::ChildNodeType;
    using ValueOf = std::function<std::optional<ValueT>(MaterialId)>;

    BrickGridAsVdb(ExportCells& cells, ValueOf value)
        : GridT(vdb::zeroVal<ValueT>()),
          mCells(cells),
          mValue(std::move(value)),
          mBackground(vdb::zeroVal<ValueT>()) {
        static_assert(LeafT::DIM == world::kBrickDim, "bricks must be OpenVDB leaves");
        static_assert(kCells4 == world::kRegionCells, "an Internal4 node must be one region");
        mRegions = world::regionCount(cells.sizeInCells());
        computeStats();
        // The Internal5 nodes (512^3 cells) with anything in them, in root-table order.
        const glm::ivec3 nodes = (mRegions + (kRegions5 - 1)) / kRegions5;
        for (int x = 0; x < nodes.x; ++x)
            for (int y = 0; y < nodes.y; ++y)
                for (int z = 0; z < nodes.z; ++z)
                    if (nodeHasContent(glm::ivec3(x, y, z) * kRegions5))
                        mRootChildren.emplace_back(x, y, z);
    }

    std::uint64_t tiles() const { return mTiles; }
    std::uint64_t leaves() const { return mLeaves; }
    std::uint64_t activeVoxels() const { return mActive; }

    void writeTopology(std::ostream& os) const override {
        const std::int32_t buffers = 1;  // TreeBase::writeTopology()
        os.write(reinterpret_cast<const char*>(&buffers), sizeof(buffers));
        os.write(reinterpret_cast<const char*>(&mBackground), sizeof(ValueT));
        vdb::io::setGridBackgroundValuePtr(os, &mBackground);
        const vdb::Index tiles = 0, children = vdb::Index(mRootChildren.size());
        os.write(reinterpret_cast<const char*>(&tiles), sizeof(tiles));
        os.write(reinterpret_cast<const char*>(&children), sizeof(children));
        for (const glm::ivec3& node : mRootChildren) {
            const int dim = int(Int5T::DIM);
            const std::int32_t origin[3] = {node.x * dim, node.y * dim, node.z * dim};
            os.write(reinterpret_cast<const char*>(origin), sizeof(origin));
            writeInternal5(os, node * kCells5, /*topology=*/true);
        }
    }

    void writeBuffers(std::ostream& os) const override {
        vdb::io::setGridBackgroundValuePtr(os, &mBackground);
        mProgressTask = "writing VDB grid '" + this->getName() + "' (128^3 nodes)";
        mWrittenInt4 = 0;
        for (const glm::ivec3& node : mRootChildren)
            writeInternal5(os, node * kCells5, /*topology=*/false);
        reportProgress(mProgressTask, mInt4, mInt4);
    }

private:
    static constexpr int kCells4 = Int4T::DIM / LeafT::DIM;  // 16 cells per Internal4 axis
    static constexpr int kCells5 = Int5T::DIM / LeafT::DIM;  // 512 cells per Internal5 axis
    static constexpr int kRegions5 = kCells5 / kCells4;      // 32 regions per Internal5 axis
    enum class Kind { Empty, Tile, Leaf };
    static constexpr const char* kStatsTask = "counting VDB grid content (regions)";

    Kind kind(glm::ivec3 c, ValueT* tile = nullptr) const {
        const std::uint32_t cell = mCells.cell(c);
        if (cell == shared::CELL_EMPTY) return Kind::Empty;
        if (!BrickGrid::cellIsBrick(cell)) {
            std::optional<ValueT> v = mValue(BrickGrid::cellMaterial(cell));
            if (!v) return Kind::Empty;
            if (tile) *tile = *v;
            return Kind::Tile;
        }
        for (MaterialId m : mCells.brickVoxels(cell))
            if (m != world::kEmpty && mValue(m)) return Kind::Leaf;
        return Kind::Empty;
    }

    std::size_t regionIndex(glm::ivec3 r) const {
        return std::size_t(r.x) +
               std::size_t(mRegions.x) * (std::size_t(r.y) + std::size_t(mRegions.y) * r.z);
    }
    bool regionHasContent(glm::ivec3 r) const {
        return glm::all(glm::lessThan(r, mRegions)) && mRegionHasContent[regionIndex(r)];
    }
    bool nodeHasContent(glm::ivec3 firstRegion) const {
        const glm::ivec3 last = glm::min(firstRegion + kRegions5, mRegions);
        for (int z = firstRegion.z; z < last.z; ++z)
            for (int y = firstRegion.y; y < last.y; ++y)
                for (int x = firstRegion.x; x < last.x; ++x)
                    if (mRegionHasContent[regionIndex({x, y, z})]) return true;
        return false;
    }

    // A leaf's values in OpenVDB's order (x slowest, z fastest) and its active mask.
    void leaf(glm::ivec3 c, ValueT* values, typename LeafT::NodeMaskType& mask) const {
        const world::BrickVoxels& voxels = mCells.brickVoxels(mCells.cell(c));
        mask.setOff();
        for (vdb::Index i = 0; i < LeafT::SIZE; ++i) {
            const MaterialId m = voxels[std::size_t(
                world::brickVoxelIndex(glm::ivec3(int(i >> 6), int((i >> 3) & 7), int(i & 7))))];
            std::optional<ValueT> v = m != world::kEmpty ? mValue(m) : std::nullopt;
            values[i] = v ? *v : mBackground;
            if (v) mask.setOn(i);
        }
    }

    template <typename NodeT>
    static glm::ivec3 childCell(vdb::Index pos, int cellsPerChild) {
        vdb::Coord local;
        NodeT::offsetToLocalCoord(pos, local);
        return glm::ivec3(local.x(), local.y(), local.z()) * cellsPerChild;
    }

    void writeInternal5(std::ostream& os, glm::ivec3 first, bool topology) const {
        typename Int5T::NodeMaskType childMask, valueMask;
        for (vdb::Index pos = 0; pos < Int5T::NUM_VALUES; ++pos)
            if (regionHasContent((first + childCell<Int5T>(pos, kCells4)) / kCells4))
                childMask.setOn(pos);
        if (topology) {
            childMask.save(os);
            valueMask.save(os);
            std::unique_ptr<ValueT[]> values(new ValueT[Int5T::NUM_VALUES]);
            std::fill(values.get(), values.get() + Int5T::NUM_VALUES, mBackground);
            vdb::io::writeCompressedValues(os, values.get(), Int5T::NUM_VALUES, valueMask,
                                           childMask, false);
        }
        for (auto it = childMask.beginOn(); it; ++it) {
            writeInternal4(os, first + childCell<Int5T>(it.pos(), kCells4), topology);
            if (!topology && ++mWrittenInt4 < mInt4)
                reportProgress(mProgressTask, mWrittenInt4, mInt4);
        }
    }

    void writeInternal4(std::ostream& os, glm::ivec3 first, bool topology) const {
        typename Int4T::NodeMaskType childMask, valueMask;
        std::unique_ptr<ValueT[]> values(new ValueT[Int4T::NUM_VALUES]);
        for (vdb::Index pos = 0; pos < Int4T::NUM_VALUES; ++pos) {
            values[pos] = mBackground;
            switch (kind(first + childCell<Int4T>(pos, 1), &values[pos])) {
                case Kind::Tile:
                    valueMask.setOn(pos);
                    break;
                case Kind::Leaf:
                    childMask.setOn(pos);
                    values[pos] = vdb::zeroVal<ValueT>();
                    break;
                case Kind::Empty:
                    values[pos] = mBackground;
                    break;
            }
        }
        if (topology) {
            childMask.save(os);
            valueMask.save(os);
            vdb::io::writeCompressedValues(os, values.get(), Int4T::NUM_VALUES, valueMask,
                                           childMask, false);
        }
        typename LeafT::NodeMaskType mask;
        for (auto it = childMask.beginOn(); it; ++it) {
            leaf(first + childCell<Int4T>(it.pos(), 1), values.get(), mask);
            mask.save(os);  // LeafNode::writeTopology(), and the start of LeafNode::writeBuffers()
            if (!topology)
                vdb::io::writeCompressedValues(os, values.get(), LeafT::SIZE, mask,
                                               typename LeafT::NodeMaskType(), false);
        }
    }

    // Which regions hold anything for this grid, and the statistics io::Archive would have added
    // (file_bbox_min/max, file_voxel_count, file_mem_bytes; it would compute them from an empty
    // tree): one pass, region by region.
    void computeStats() {
        glm::ivec3 lo(INT32_MAX), hi(INT32_MIN);
        const glm::ivec3 size = mCells.sizeInCells();
        std::unique_ptr<ValueT[]> values(new ValueT[LeafT::SIZE]);
        typename LeafT::NodeMaskType mask;
        mRegionHasContent.assign(std::size_t(mRegions.x) * mRegions.y * mRegions.z, false);
        for (int rz = 0; rz < mRegions.z; ++rz)
            for (int ry = 0; ry < mRegions.y; ++ry)
                for (int rx = 0; rx < mRegions.x; ++rx) {
                    const world::CellRange range = world::regionCells({rx, ry, rz}, size);
                    bool content = false;
                    for (int z = range.min.z; z < range.max.z; ++z)
                        for (int y = range.min.y; y < range.max.y; ++y)
                            for (int x = range.min.x; x < range.max.x; ++x) {
                                const glm::ivec3 c(x, y, z);
                                const Kind k = kind(c);
                                if (k == Kind::Empty) continue;
                                content = true;
                                if (k == Kind::Tile) {
                                    mTiles++;
                                    mActive += LeafT::SIZE;
                                    lo = glm::min(lo, c * 8);
                                    hi = glm::max(hi, c * 8 + 7);
                                    continue;
                                }
                                mLeaves++;
                                leaf(c, values.get(), mask);
                                mActive += mask.countOn();
                                for (auto it = mask.beginOn(); it; ++it) {
                                    const vdb::Index i = it.pos();
                                    const glm::ivec3 p =
                                        c * 8 +
                                        glm::ivec3(int(i >> 6), int((i >> 3) & 7), int(i & 7));
                                    lo = glm::min(lo, p);
                                    hi = glm::max(hi, p);
                                }
                            }
                    mRegionHasContent[regionIndex({rx, ry, rz})] = content;
                    mInt4 += content;
                    const std::size_t done = regionIndex({rx, ry, rz}) + 1;
                    if (done < mRegionHasContent.size())
                        reportProgress(kStatsTask, done, mRegionHasContent.size());
                }
        reportProgress(kStatsTask, mRegionHasContent.size(), mRegionHasContent.size());
        if (mActive == 0) lo = hi = glm::ivec3(0);
        this->insertMeta(vdb::GridBase::META_FILE_BBOX_MIN,
                         vdb::Vec3IMetadata(vdb::Vec3i(lo.x, lo.y, lo.z)));
        this->insertMeta(vdb::GridBase::META_FILE_BBOX_MAX,
                         vdb::Vec3IMetadata(vdb::Vec3i(hi.x, hi.y, hi.z)));
        this->insertMeta(vdb::GridBase::META_FILE_VOXEL_COUNT,
                         vdb::Int64Metadata(std::int64_t(mActive)));
        std::uint64_t int5 = 0;
        const glm::ivec3 nodes = (mRegions + (kRegions5 - 1)) / kRegions5;
        for (int x = 0; x < nodes.x; ++x)
            for (int y = 0; y < nodes.y; ++y)
                for (int z = 0; z < nodes.z; ++z)
                    int5 += nodeHasContent(glm::ivec3(x, y, z) * kRegions5);
        const std::uint64_t memory = int5 * sizeof(Int5T) + mInt4 * sizeof(Int4T) +
                                     mLeaves * (sizeof(LeafT) + LeafT::SIZE * sizeof(ValueT));
        this->insertMeta(vdb::GridBase::META_FILE_MEM_BYTES,
                         vdb::Int64Metadata(std::int64_t(memory)));
    }

    ExportCells& mCells;
    ValueOf mValue;
    ValueT mBackground;
    glm::ivec3 mRegions{0};               // regions along each axis
    std::vector<bool> mRegionHasContent;  // x fastest
    std::vector<glm::ivec3> mRootChildren;
    std::uint64_t mTiles = 0, mLeaves = 0, mActive = 0;
    std::uint64_t mInt4 = 0;  // Internal4 nodes (regions) with content: the unit of progress
    mutable std::uint64_t mWrittenInt4 = 0;
    mutable std::string mProgressTask;
};

template <typename GridT>
std::shared_ptr<BrickGridAsVdb<GridT>> gridOf(ExportCells& cells, const world::Scene& scene,
                                              const char* name, bool zUp,
                                              typename BrickGridAsVdb<GridT>::ValueOf value) {
    auto grid = std::make_shared<BrickGridAsVdb<GridT>>(cells, std::move(value));
    grid->setName(name);
    grid->setTransform(vdb_layout::gridTransform(double(scene.voxelSize), zUp));
    grid->setCreator("voxengine");
    return grid;
}

}  // namespace

Result<VdbExportOptions> vdbExportOptionsFor(const std::string& tool) {
    VdbExportOptions o;
    o.densityGrid = true;
    if (tool == "blender")
        o.zUp = true;  // Blender ignores vox:up_axis: the transform must say it
    else if (tool != "houdini")
        return makeError("unknown tool '{}' (known: blender, houdini)", tool);
    return o;
}

Status exportVdbFrom(ExportCells& cells, const world::Scene& scene, const fs::path& path,
                     const VdbExportOptions& options, VdbExportReport* report) {
    initializeOpenVdb();
    const world::Palette& palette = scene.palette;
    bool anyEmissive = false;
    for (const world::Material& m : palette.materials()) anyEmissive |= m.emissive();

    std::vector<StreamingVdbWriter::GridMaker> makers;
    VdbExportReport local;
    if (options.densityGrid) {
        // First, for tools that show or read "the first grid".
        makers.push_back([&] {
            auto grid =
                gridOf<vdb::FloatGrid>(cells, scene, vdb_layout::kDensityGrid, options.zUp,
                                       [](MaterialId) { return std::optional<float>(1.0f); });
            grid->setGridClass(vdb::GRID_FOG_VOLUME);
            grid->insertMeta(
                "vox:role", vdb::StringMetadata("fog volume, 1 in solid voxels (for other tools)"));
            return grid;
        });
        local.grids.push_back(vdb_layout::kDensityGrid);
    }
    makers.push_back([&] {
        auto grid =
            gridOf<vdb::Int32Grid>(cells, scene, vdb_layout::kMaterialGrid, options.zUp,
                                   [](MaterialId m) { return std::optional<std::int32_t>(m); });
        grid->insertMeta("vox:role",
                         vdb::StringMetadata("material index into the vox:material.* palette"));
        local.tiles = grid->tiles();
        local.leaves = grid->leaves();
        local.solidVoxels = grid->activeVoxels();
        return grid;
    });
    local.grids.push_back(vdb_layout::kMaterialGrid);
    if (options.colourGrids) {
        makers.push_back([&] {
            auto grid = gridOf<vdb::Vec3SGrid>(
                cells, scene, vdb_layout::kAlbedoGrid, options.zUp, [&](MaterialId m) {
                    glm::vec3 a = palette[m].albedo;
                    return std::optional<vdb::Vec3s>(vdb::Vec3s(a.x, a.y, a.z));
                });
            grid->setVectorType(vdb::VEC_INVARIANT);
            grid->insertMeta("vox:role", vdb::StringMetadata("linear albedo"));
            return grid;
        });
        local.grids.push_back(vdb_layout::kAlbedoGrid);
        if (anyEmissive) {
            makers.push_back([&] {
                auto grid = gridOf<vdb::Vec3SGrid>(
                    cells, scene, vdb_layout::kEmissionGrid, options.zUp, [&](MaterialId m) {
                        if (!palette[m].emissive()) return std::optional<vdb::Vec3s>();
                        glm::vec3 e = palette[m].emittedRadiance();
                        return std::optional<vdb::Vec3s>(vdb::Vec3s(e.x, e.y, e.z));
                    });
                grid->setVectorType(vdb::VEC_INVARIANT);
                grid->insertMeta("vox:role",
                                 vdb::StringMetadata("emitted radiance (colour x strength)"));
                return grid;
            });
            local.grids.push_back(vdb_layout::kEmissionGrid);
        }
    }

    vdb::MetaMap fileMetadata;
    fileMetadata.insertMeta("creator", vdb::StringMetadata("voxengine"));
    vdb_layout::writeWorldMetadata(scene, fileMetadata, options.zUp);

    Status written = writeFileAtomically(path, [&](AtomicFile& file) -> Status {
        try {
            std::ostream& os = file.stream();
            os.exceptions(std::ios::failbit | std::ios::badbit);
            StreamingVdbWriter().writeStreamed(os, fileMetadata, makers);
            os.flush();
        } catch (const ExportReadError& e) {
            return makeError("{}", e.message);  // a region the source could not give
        } catch (const std::ios_base::failure&) {
            if (Status s = file.status(); !s) return s;  // the write's own error: path and reason
            return makeError("{}: cannot write VDB file", path.string());
        } catch (const std::exception& e) {
            return makeError("{}: cannot write VDB file: {}", path.string(), e.what());
        }
        return {};
    });
    if (!written) return written;
    std::error_code ec;
    local.fileBytes = fs::file_size(path, ec);
    local.regionLoads = cells.regionLoads();
    if (report) *report = local;
    return {};
}

Status exportVdb(const world::Scene& scene, const fs::path& path, const VdbExportOptions& options,
                 VdbExportReport* report) {
    ExportCells cells(scene.grid);
    return exportVdbFrom(cells, scene, path, options, report);
}

Status exportVdb(const world::Scene& scene, world::RegionSource& source, const fs::path& path,
                 const VdbExportOptions& options, VdbExportReport* report) {
    if (source.worldSizeInCells() != scene.grid.sizeInCells())
        return makeError(
            "{}: cannot export: the world's regions span {}x{}x{} cells, its scene {}x{}x{}",
            path.string(), source.worldSizeInCells().x, source.worldSizeInCells().y,
            source.worldSizeInCells().z, scene.grid.sizeInCells().x, scene.grid.sizeInCells().y,
            scene.grid.sizeInCells().z);
    ExportCells cells(source);
    return exportVdbFrom(cells, scene, path, options, report);
}

}  // namespace engine::io
