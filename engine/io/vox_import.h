// MagicaVoxel .vox import (docs/VOX.md): every visible model instance of the file's scene graph
// (io/vox_reader.h) placed into one world.
//
// Axes: MagicaVoxel is Z-up, the engine Y-up. A voxel at MagicaVoxel (x, y, z) goes to
// (x, z, -y) — a rotation about x, the same one the VDB import uses for Z-up files — and the
// whole import is then shifted so that its content's lowest corner lands on `offset`.
// Colours: each colour index in use becomes one material, its RGB read as sRGB and stored as
// linear albedo. A MATL of `_type` `_emit` makes the material emit its own colour with strength
// kVoxEmissionScale * _emit * 2^_flux (so _emit 1 at MagicaVoxel's lowest power is 4).
// Later instances overwrite earlier ones where they overlap, as in the file's order.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.h"
#include "io/vox_reader.h"
#include "world/scene.h"

namespace engine::io {

inline constexpr float kVoxEmissionScale = 4.0f;
inline constexpr std::uint64_t kDefaultVoxMemoryBudget = 4ull << 30;
inline constexpr std::uint64_t kVoxMaxPlacedVoxels = 1ull
                                                     << 31;  // voxels written, overlaps included

// sRGB 8-bit colour (R in the low byte) to linear albedo, and back (rounded to nearest); the pair
// is exact: voxColourFromLinear(voxColourToLinear(c)) == c for every RGB byte triple.
glm::vec3 voxColourToLinear(std::uint32_t rgba);
std::uint32_t voxColourFromLinear(glm::vec3 linear);  // alpha 255

// Emission strength of a MATL, and the _emit/_flux pair that gives a strength back exactly.
float voxEmissionStrength(const VoxMaterial& m);
void voxEmitFlux(float strength, float& emit, float& flux);

struct VoxImportOptions {
    glm::ivec3 offset{0};  // world voxel where the content's lowest corner lands
    std::uint64_t memoryBudgetBytes = kDefaultVoxMemoryBudget;
};

// What an import does (or would do: planVoxImport fills all but solidVoxels).
struct VoxImportReport {
    std::string file;
    int version = 0;
    std::size_t models = 0, instances = 0, graphNodes = 0, layers = 0, hiddenLayers = 0;
    bool defaultPalette = false;
    std::size_t materials = 0, emissiveMaterials = 0;  // colour indices in use
    std::uint64_t placedVoxels = 0;                    // over all instances, overlaps included
    glm::ivec3 contentSize{0};                         // of the placed voxels, engine axes
    glm::ivec3 worldSize{0};
    std::uint64_t estimateBytes = 0, budgetBytes = 0;
    std::uint64_t solidVoxels = 0;       // in the world after the import
    std::uint64_t peakTrackedBytes = 0;  // heap peak seen by the allocation budget
    std::vector<std::string> notes;
};

Result<VoxImportReport> planVoxImport(const std::filesystem::path& path,
                                      const VoxImportOptions& options = {});

// A new scene holding the import; named after the file, voxel size 1.
Result<world::Scene> importVox(const std::filesystem::path& path,
                               const VoxImportOptions& options = {},
                               VoxImportReport* report = nullptr);

// Into an existing scene (the scene-file generator): voxels overwrite the scene's, clipped to its
// bounds; materials merge into its palette by name (the scene's definition wins).
Status importVoxInto(world::Scene& scene, const std::filesystem::path& path,
                     const VoxImportOptions& options = {}, VoxImportReport* report = nullptr);

std::string formatVoxImportReport(const VoxImportReport& report, bool planned);

}  // namespace engine::io
