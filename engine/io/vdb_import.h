// OpenVDB import (docs/VDB.md).
//
// Our own files (io/vdb_layout.h) come back exactly: same voxels, palette, name, size, voxel
// size, cameras and sky. Foreign grids become solid voxels by kind:
//   level set (float/double, class level set)  inside (value < 0) = solid
//   fog volume (other float/double grids)       active and density >= fogThreshold = solid
//   integer grid (int32/int64)                  active = solid, one material per distinct value
//   bool/mask grid                              active = solid
//   vec3 grid                                   active = solid, colour quantised to <= maxColours
// and a material rule: constant, by height (bands), from a colour grid, or the ids themselves.
//
// How: the chosen grid's topology is read first (no voxel values) to place the import, count
// the cells that need voxels and estimate the memory; an estimate over the budget is refused
// before anything is built. Then the world is filled one slab of cells at a time, reading only
// the source leaves that slab needs (io/vdb_reader.h), so a large source is never in memory
// whole. Source tiles that cover a whole cell become homogeneous cells without touching voxels.
// The whole import runs under an AllocationBudget, so a damaged file that asks for absurd memory
// fails with a message instead of exhausting the machine.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "world/scene.h"

namespace engine::io {

inline constexpr std::uint64_t kDefaultVdbMemoryBudget = 4ull << 30;

enum class UpAxis { Auto, Y, Z };  // Auto: Z for Blender's files ("creator" says so), else Y
enum class MaterialRule { Auto, Constant, Height, Colour, Ids };

struct VdbImportOptions {
    std::string grid;  // shape grid by name; empty: ours, else the first usable non-empty one
    std::string
        colourGrid;  // vec3 grid for the colour rule; empty: one named color/colour/Cd/albedo/rgb
    MaterialRule rule = MaterialRule::Auto;  // Auto: ids for id grids, colour when there is a
                                             // colour grid, else constant
    float fogThreshold = 0.5f;
    int maxColours = 16;  // colour rule: palette size, 1..65534
    world::Material material{"imported", glm::vec3(0.7f), glm::vec3(0.0f), 0.0f};  // constant rule
    std::vector<world::Material>
        heightMaterials;  // height rule, bottom to top; empty: 4 default bands
    double voxelSize =
        0.0;  // target voxel size in file units; 0: the file's (smallest axis if non-uniform)
    std::optional<glm::ivec3> offset;  // world voxel where source voxel (0,0,0) lands; none: auto
    std::optional<world::Box>
        crop;  // import only this source index box (min inclusive, max exclusive)
    UpAxis up = UpAxis::Auto;
    std::uint64_t memoryBudgetBytes = kDefaultVdbMemoryBudget;
};

// What an import would do, worked out from the topology alone.
struct VdbImportPlan {
    std::string file;
    std::string grid, gridType, gridClass;
    std::string
        kind;  // "voxengine world", "level set", "fog volume", "integer ids", "mask", "colour"
    std::string rule;  // the material rule, in words
    std::string colourGrid;
    bool voxengine = false;
    bool upZ = false;
    glm::dvec3 sourceVoxelSize{1.0};
    double voxelSize = 1.0;  // of the imported world
    glm::dvec3 scale{1.0};   // world voxels per source voxel, per world axis
    glm::dvec3 offset{0.0};  // world position of source voxel (0,0,0)'s corner
    world::Box sourceBox;    // source index box imported
    world::Box worldBox;     // where it lands (clipped to the world)
    glm::ivec3 worldSize{0};
    std::uint64_t sourceActiveVoxels = 0, sourceLeaves = 0, sourceTiles = 0;
    std::uint64_t sampledCells = 0;  // cells whose voxels are read: an upper bound on new bricks
    std::uint64_t uniformCells = 0;  // cells filled whole from tiles
    std::uint64_t worldBytes = 0;    // top grid, bookkeeping, bricks (upper bound)
    std::uint64_t sourceBytes = 0;   // source topology and the largest slab of leaf values
    std::uint64_t estimateBytes = 0;
    std::uint64_t budgetBytes = 0;
    bool streamed = false;  // voxel for voxel, leaf by leaf, no OpenVDB tree; else in `slabs` slabs
    int slabs = 0;
    std::vector<std::string> notes;
};

struct VdbImportReport {
    VdbImportPlan plan;
    std::uint64_t solidVoxels = 0;  // written by this import
    std::size_t materials = 0;      // palette entries the import used
    int colours = 0;                // colour rule: palette size
    std::uint64_t colouredVoxels = 0;
    double meanColourError = 0.0;  // Euclidean distance in linear RGB, per voxel
    double maxColourError = 0.0;
    std::uint64_t peakTrackedBytes = 0;  // heap peak seen by the allocation budget
};

Result<VdbImportPlan> planVdbImport(const std::filesystem::path& path,
                                    const VdbImportOptions& options = {});

// A new scene holding the import.
Result<world::Scene> importVdb(const std::filesystem::path& path,
                               const VdbImportOptions& options = {},
                               VdbImportReport* report = nullptr);

// Into an existing scene (the scene-file generator): solid voxels overwrite the scene's, clipped
// to its bounds; materials merge into its palette by name (the scene's definition wins).
Status importVdbInto(world::Scene& scene, const std::filesystem::path& path,
                     const VdbImportOptions& options = {}, VdbImportReport* report = nullptr);

std::string formatVdbImportPlan(const VdbImportPlan& plan);
std::string formatVdbImportReport(const VdbImportReport& report);

}  // namespace engine::io
