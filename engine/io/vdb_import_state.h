// One OpenVDB import (io/vdb_import.h) as a pipeline of steps over shared state. Each part of
// ImportState is filled by one step, in this order, and only read by the later ones:
//   grids      vdb_import_grids.cpp      the shape grid, the colour grid and the material rule
//   place      vdb_import_placement.cpp  axes, scale and offset: where source voxels land
//   topology   vdb_import_topology.cpp   source leaves and extents, read without voxel values
//   (plan)     vdb_import_plan.cpp       cells to sample, slabs to read, the memory estimate
//   slabs      vdb_import_slabs.cpp      the slabs, planned with the cells
//   palette    vdb_import_palette.cpp    the import's materials and their ids in the scene
// then the world is written: slab by slab (vdb_import_slabs.cpp) or, for voxel-for-voxel copies,
// leaf by leaf straight from the file (vdb_import_stream.cpp). vdb_import_mapping.cpp turns
// source values into solid voxels and materials for both.
//
// Expected failures (a grid that cannot be imported, a world over the limits) come back as
// Status; what OpenVDB, the reader and the allocation budget throw is caught once, at the entry
// points in vdb_import.cpp. Internal to engine/io.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <openvdb/openvdb.h>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/error.h"
#include "io/colour_quantizer.h"
#include "io/vdb_import.h"
#include "io/vdb_import_placement.h"
#include "io/vdb_import_source.h"
#include "io/vdb_layout.h"
#include "io/vdb_reader.h"
#include "world/scene.h"

namespace engine::io::vdb_import {

struct ChosenGrids {
    bool voxengine = false;               // one of our own files (io/vdb_layout.h)
    vdb_layout::WorldHeader worldHeader;  // its world metadata, when voxengine
    std::size_t shapeIndex = 0;           // the grid whose voxels become solid
    openvdb::GridBase::Ptr shapeHeader;
    Kind kind = Kind::Fog;
    MaterialRule rule = MaterialRule::Constant;  // never Auto
    int colourIndex = -1;                        // separate colour grid, or -1
    openvdb::math::Transform::Ptr shapeXform, colourXform;
    bool sameXform = true;  // colour grid voxels line up with the shape's
    int heightBands = 0;
};

// What planning learns from the source's topology, to size the world and the reads.
struct SourceTopology {
    std::vector<Box> leaves;        // source leaf boxes (clipped to the crop box)
    std::vector<Box> colourLeaves;  // colour grid leaf boxes
    std::uint64_t shapeTopologyBytes = 0, colourTopologyBytes = 0;
    std::uint64_t shapeLeafBytes = 0, colourLeafBytes = 0;  // one loaded leaf
};

// World cells in a z range whose source voxels are read together.
struct Slab {
    int cz0, cz1;  // world cell z range
    std::uint64_t leaves;
};

// What the import does with each world cell (8^3 voxels), indexed by cellIndex().
enum CellMark : std::uint8_t { kCellNone = 0, kCellUniform = 1, kCellSample = 2 };

inline std::size_t cellIndex(glm::ivec3 cells, glm::ivec3 c) {
    return std::size_t(c.x) +
           std::size_t(cells.x) * (std::size_t(c.y) + std::size_t(cells.y) * std::size_t(c.z));
}

struct ImportPalette {
    std::vector<world::Material> materials;       // index 0 unused
    std::vector<world::MaterialId> remap;         // materials' ids in the scene's palette
    std::unordered_map<std::int64_t, int> idLut;  // ids rule, foreign grids: value -> material
    std::unique_ptr<ColourMapper> mapper;         // colour rule
    ColourError colourError;
};

struct ImportState {
    ImportState(const std::filesystem::path& source, const VdbImportOptions& importOptions)
        : path(source), file(source.string()), options(importOptions), reader(source) {}

    std::filesystem::path path;
    std::string file;  // names the file in every message
    const VdbImportOptions& options;
    VdbReader reader;
    VdbImportReport report;
    VdbImportPlan& plan = report.plan;

    ChosenGrids grids;
    Placement place;
    bool streaming = false;  // see vdb_import_stream.cpp
    SourceTopology topology;
    std::vector<Slab> slabs;
    std::uint64_t slabLeavesMax = 0;
    ImportPalette palette;

    // Loaded source values, one slab at a time.
    std::unique_ptr<SourceGrid> shape, colour;

    // Fog volumes: the largest active value isSolid() has seen, to say why nothing was solid.
    // Mutable because isSolid() is asked through const paths (tiles, samples) everywhere.
    mutable double largestFogValue = -std::numeric_limits<double>::infinity();
};

// Clears the world's dirty lists every few thousand cell writes. An imported world is uploaded
// whole, so the lists (which the GPU mirror reads) carry nothing, and unbounded they would be
// allocations the plan does not count: a 2048^3 fog of tiles resampled writes 10^7 uniform
// cells, a 40 MiB list.
class DirtyListBound {
public:
    explicit DirtyListBound(world::BrickGrid& grid) : mGrid(grid) {}
    void noteWrite() {
        if (++mWrites < 4096) return;
        mGrid.clearDirty();
        mWrites = 0;
    }

private:
    world::BrickGrid& mGrid;
    int mWrites = 0;
};

// vdb_import_grids.cpp
Status chooseGrids(ImportState& im);

// vdb_import_placement.cpp
Status orientAndScale(ImportState& im);
Status placeOffset(ImportState& im, const world::Scene* target);

// vdb_import_topology.cpp
Status readShapeTopology(ImportState& im);  // leaves im.shape holding the topology
// Sets the source box from the extent of what is solid, clipped to the crop box.
Status settleSourceBox(ImportState& im, const Box& content);
void readColourTopology(ImportState& im);
// The colour grid's index box covering shape index box `source`.
Box colourRegion(const ImportState& im, const Box& source);
// Solid tiles above leaf level, clipped to the crop box.
Status forEachSolidTile(const ImportState& im, const SourceGrid& topology,
                        const std::function<Status(const Box&, const Sample&)>& f);
// Active voxels of grid `index` inside `region`, reading its leaves in bounded pieces.
Status scanActiveVoxels(ImportState& im, std::size_t index, const std::vector<Box>& leaves,
                        const Box& region, const SourceGrid::VoxelFn& f);

// vdb_import_plan.cpp
std::string mib(std::uint64_t bytes);
// target: the scene an importVdbInto() writes into; null for a new world.
Status planImport(ImportState& im, const world::Scene* target);
// Marks cells to sample (touched by a leaf, or by a tile only in part) and reports cells a solid
// tile covers whole, with a material that cannot vary inside the cell, through onUniform.
Status markCells(ImportState& im, const SourceGrid& topology, std::vector<std::uint8_t>& marks,
                 const std::function<void(glm::ivec3 cell, int material)>& onUniform);

// vdb_import_slabs.cpp
void makeSlabs(ImportState& im, const std::vector<std::uint8_t>& marks);
Status fillSlabs(ImportState& im, world::BrickGrid& grid, const std::vector<std::uint8_t>& marks,
                 bool intoExisting);

// vdb_import_palette.cpp
Status buildPalette(ImportState& im);
// Gives the import's materials ids in the scene's palette (im.palette.remap).
Status addToScenePalette(ImportState& im, world::Scene& scene, bool intoExisting);

// vdb_import_stream.cpp
bool canStream(const ImportState& im);
Status readShapeTopologyStreamed(ImportState& im);  // readShapeTopology() from a walk of the file
// Calls onTile for each solid tile (clipped to the crop box) and onLeaf for each leaf that
// reaches the source box, with its 512 values in OpenVDB's order (z fastest).
Status streamSource(ImportState& im, const std::function<Status(const Box&, const Sample&)>& onTile,
                    const std::function<Status(const openvdb::Coord&, const Sample*)>& onLeaf);
Status streamIntoWorld(ImportState& im, world::BrickGrid& grid);

// vdb_import_mapping.cpp
bool isSolid(const ImportState& im, const Sample& s);
// Whether world voxel t is solid, sampling the loaded shape grid; s receives the value read.
bool solidAt(const ImportState& im, glm::ivec3 t, Sample& s);
// The material (index into im.palette.materials) of solid world voxel t with source value s.
Result<int> materialFor(ImportState& im, glm::ivec3 t, const Sample& s);
// The material of a whole cell inside a solid tile, or kVariesInCell when its voxels must be
// read one by one. Before the palette is built, any material that cannot vary is reported as 0.
inline constexpr int kVariesInCell = -1;
Result<int> uniformMaterial(ImportState& im, const Sample& tile, const Box& cellBox);

}  // namespace engine::io::vdb_import
