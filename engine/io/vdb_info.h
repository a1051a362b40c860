// What `vox info FILE.vdb` reports: the file's metadata and grids (type, class, voxel size and
// transform, active voxels, bounds, memory), read from the topology only, and what an import with
// the given options would produce (io/vdb_import.h's plan) or why it cannot.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "io/vdb_import.h"
#include "world/brick_grid.h"

namespace engine::io {

struct VdbGridInfo {
    std::string name;
    std::string type;       // value type ("float", "vec3s", ...) or the stored tree type if unknown
    std::string gridClass;  // "level set", "fog volume", "unknown", ...
    std::string transform;  // "uniform scale 0.1", "scale 0.7 x 0.7 x 0.72", or why it is unusable
    glm::dvec3 voxelSize{0.0};
    std::uint64_t activeVoxels = 0, leaves = 0, activeTiles = 0;
    world::Box bounds;  // active voxels, index space (empty if none)
    std::uint64_t memoryBytes =
        0;  // in memory when fully loaded (OpenVDB's file_mem_bytes or an estimate)
    std::vector<std::pair<std::string, std::string>> metadata;
    std::string note;     // e.g. counts taken from metadata
    std::string problem;  // set when the grid could not be read
};

struct VdbFileInfo {
    std::string path;
    std::uint64_t fileBytes = 0;
    std::uint32_t formatVersion = 0;
    std::string libraryVersion;
    bool voxengine = false;
    std::vector<std::pair<std::string, std::string>> metadata;
    std::vector<VdbGridInfo> grids;
    Result<VdbImportPlan> import = Error{"not planned"};
};

Result<VdbFileInfo> describeVdbFile(const std::filesystem::path& path,
                                    const VdbImportOptions& importOptions = {});
std::string formatVdbFileInfo(const VdbFileInfo& info);

}  // namespace engine::io
