#include "io/vdb_export.h"

#include <fstream>
#include <functional>
#include <optional>

#include "io/image_io.h"
#include "io/vdb_layout.h"
#include "io/vdb_reader.h"

namespace engine::io {

namespace fs = std::filesystem;
namespace vdb = openvdb;
using world::BrickGrid;
using world::MaterialId;

namespace {

// io::Archive's own write() takes every grid at once; this one asks for each grid when its turn
// comes, so only one is alive at a time. Same stream set-up and order as Archive::write().
class StreamingVdbWriter : private vdb::io::Archive {
public:
    using GridMaker = std::function<vdb::GridBase::Ptr()>;

    void writeStreamed(std::ostream& os, const vdb::MetaMap& fileMetadata, const std::vector<GridMaker>& makers) const {
        vdb::io::StreamMetadata::Ptr streamMetadata = std::make_shared<vdb::io::StreamMetadata>();
        vdb::io::setStreamMetadataPtr(os, streamMetadata, /*transfer=*/false);
        vdb::io::setDataCompression(os, compression());
        vdb::io::setWriteGridStatsMetadata(os, isGridStatsMetadataEnabled());
        writeHeader(os, /*seekable=*/true);
        fileMetadata.writeMeta(os);
        std::int32_t count = std::int32_t(makers.size());
        os.write(reinterpret_cast<const char*>(&count), sizeof(count));
        for (const GridMaker& make : makers) {
            vdb::GridBase::ConstPtr grid = make();
            vdb::io::GridDescriptor gd(grid->getName(), grid->type(), grid->saveFloatAsHalf());
            writeGrid(gd, grid, os, /*seekable=*/true);
            vdb::io::setDataCompression(os, compression());
        }
    }
};

vdb::Coord toCoord(glm::ivec3 v) { return vdb::Coord(v.x, v.y, v.z); }

// Builds one grid from the brick grid: value(m) gives the voxel value of material m, or nullopt
// to leave the voxel inactive. Homogeneous cells become level-1 tiles (exactly one 8^3 leaf's
// extent, since our bricks and OpenVDB leaves share size and alignment).
template <typename GridT, typename ValueOf>
typename GridT::Ptr buildGrid(const world::Scene& scene, const char* name, const typename GridT::ValueType& background,
                              ValueOf value, VdbExportReport* counts) {
    using LeafT = typename GridT::TreeType::LeafNodeType;
    auto grid = GridT::create(background);
    grid->setName(name);
    grid->setTransform(vdb::math::Transform::createLinearTransform(double(scene.voxelSize)));
    grid->setCreator("voxengine");
    auto& tree = grid->tree();
    const BrickGrid& g = scene.grid;
    const glm::ivec3 cells = g.sizeInCells();
    for (int z = 0; z < cells.z; ++z) {
        for (int y = 0; y < cells.y; ++y) {
            for (int x = 0; x < cells.x; ++x) {
                const glm::ivec3 c(x, y, z);
                const std::uint32_t cell = g.cell(c);
                if (cell == shared::CELL_EMPTY) continue;
                const vdb::Coord origin = toCoord(c * world::kBrickDim);
                if (!BrickGrid::cellIsBrick(cell)) {
                    std::optional<typename GridT::ValueType> v = value(BrickGrid::cellMaterial(cell));
                    if (!v) continue;
                    tree.addTile(1, origin, *v, true);
                    if (counts) {
                        counts->tiles++;
                        counts->solidVoxels += world::kBrickVoxels;
                    }
                    continue;
                }
                const world::BrickVoxels& voxels = g.brickVoxels(BrickGrid::cellBrick(cell));
                LeafT* leaf = nullptr;
                for (int i = 0; i < world::kBrickVoxels; ++i) {
                    if (voxels[i] == world::kEmpty) continue;
                    std::optional<typename GridT::ValueType> v = value(voxels[i]);
                    if (!v) continue;
                    if (!leaf) leaf = tree.touchLeaf(origin);
                    // Ours is x fastest, OpenVDB's leaf offset is z fastest.
                    const vdb::Coord local(i & 7, (i >> 3) & 7, i >> 6);
                    leaf->setValueOn(LeafT::coordToOffset(local), *v);
                    if (counts) counts->solidVoxels++;
                }
                if (leaf && counts) counts->leaves++;
            }
        }
    }
    return grid;
}

}  // namespace

Status exportVdb(const world::Scene& scene, const fs::path& path, const VdbExportOptions& options,
                 VdbExportReport* report) {
    initializeOpenVdb();
    const world::Palette& palette = scene.palette;
    bool anyEmissive = false;
    for (const world::Material& m : palette.materials()) anyEmissive |= m.emissive();

    std::vector<StreamingVdbWriter::GridMaker> makers;
    VdbExportReport local;
    makers.push_back([&] {
        auto grid = buildGrid<vdb::Int32Grid>(scene, vdb_layout::kMaterialGrid, 0,
                                             [](MaterialId m) { return std::optional<std::int32_t>(m); }, &local);
        grid->insertMeta("vox:role", vdb::StringMetadata("material index into the vox:material.* palette"));
        return grid;
    });
    local.grids.push_back(vdb_layout::kMaterialGrid);
    if (options.colourGrids) {
        makers.push_back([&] {
            auto grid = buildGrid<vdb::Vec3SGrid>(scene, vdb_layout::kAlbedoGrid, vdb::Vec3s(0.0f), [&](MaterialId m) {
                glm::vec3 a = palette[m].albedo;
                return std::optional<vdb::Vec3s>(vdb::Vec3s(a.x, a.y, a.z));
            }, nullptr);
            grid->setVectorType(vdb::VEC_INVARIANT);
            grid->insertMeta("vox:role", vdb::StringMetadata("linear albedo"));
            return grid;
        });
        local.grids.push_back(vdb_layout::kAlbedoGrid);
        if (anyEmissive) {
            makers.push_back([&] {
                auto grid =
                    buildGrid<vdb::Vec3SGrid>(scene, vdb_layout::kEmissionGrid, vdb::Vec3s(0.0f), [&](MaterialId m) {
                        if (!palette[m].emissive()) return std::optional<vdb::Vec3s>();
                        glm::vec3 e = palette[m].emittedRadiance();
                        return std::optional<vdb::Vec3s>(vdb::Vec3s(e.x, e.y, e.z));
                    }, nullptr);
                grid->setVectorType(vdb::VEC_INVARIANT);
                grid->insertMeta("vox:role", vdb::StringMetadata("emitted radiance (colour x strength)"));
                return grid;
            });
            local.grids.push_back(vdb_layout::kEmissionGrid);
        }
    }

    vdb::MetaMap fileMetadata;
    fileMetadata.insertMeta("creator", vdb::StringMetadata("voxengine"));
    vdb_layout::writeWorldMetadata(scene, fileMetadata);

    Status written = writeAtomically(path, [&](const fs::path& temp) -> Status {
        try {
            std::ofstream os(temp, std::ios::out | std::ios::binary | std::ios::trunc);
            if (!os) return makeError("{}: cannot create file", path.string());
            os.exceptions(std::ios::failbit | std::ios::badbit);
            StreamingVdbWriter().writeStreamed(os, fileMetadata, makers);
            os.close();
        } catch (const std::ios_base::failure&) {
            return makeError("{}: write failed (disk full or not writable?)", path.string());
        } catch (const std::exception& e) {
            return makeError("{}: cannot write VDB file: {}", path.string(), e.what());
        }
        return {};
    });
    if (!written) return written;
    std::error_code ec;
    local.fileBytes = fs::file_size(path, ec);
    if (report) *report = local;
    return {};
}

}  // namespace engine::io
