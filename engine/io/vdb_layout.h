// The layout of a voxengine .vdb file (docs/VDB.md): grid names and the file metadata that carries
// the palette and the scene's settings. Every value is stored as typed OpenVDB metadata (floats
// as floats), so a re-import is exact, and `vdb_print -m` shows it to anyone. Internal to
// engine/io (it uses OpenVDB's MetaMap).
//
//   grids     material  Int32, background 0, active voxel = solid, value = palette index;
//                       homogeneous bricks are level-1 tiles (one 8^3 tile, not 512 voxels)
//             albedo    Vec3s, linear albedo of each solid voxel (for other tools)
//             emission  Vec3s, emitted radiance (colour x strength) of each emissive voxel
//             density   Float fog volume, 1.0 in every solid voxel (only when asked: for
//                       tools that need a float grid -- Blender, vdb_render, pyopenvdb)
//   transform linear, uniform scale = the scene's voxel size; index (0,0,0) is world voxel 0;
//             for Z-up tools also a quarter turn about +x (gridTransform); index space, and so
//             every voxel and every vox:* value, stays the engine's Y-up either way
//   file metadata (all keys start with "vox:"):
//             vox:format "voxengine.world", vox:format_version 1, vox:up_axis "y" or "z"
//             vox:world.name, vox:world.size (vec3i, voxels), vox:world.voxel_size
//             vox:palette.count; vox:material.NNNNN.{name, albedo, emission, strength}
//             vox:camera.count; vox:camera.NNN.{name, position, target, fov}
//             vox:sky.{sun_direction, sun_radiance, sky_radiance}
#pragma once

#include <openvdb/openvdb.h>
#include <string>
#include <vector>

#include "core/error.h"
#include "world/scene.h"

namespace engine::io::vdb_layout {

inline constexpr char kMaterialGrid[] = "material";
inline constexpr char kAlbedoGrid[] = "albedo";
inline constexpr char kEmissionGrid[] = "emission";
inline constexpr char kDensityGrid[] = "density";
inline constexpr char kFormatKey[] = "vox:format";
inline constexpr char kFormatName[] = "voxengine.world";
inline constexpr int kFormatVersion = 1;

// Everything about a scene except its voxels.
struct WorldHeader {
    std::string name;
    glm::ivec3 size{0};
    float voxelSize = 1.0f;
    world::Palette palette;
    std::vector<world::CameraPreset> cameras;
    world::SkyLight sky;
    bool zUp = false;  // vox:up_axis "z": the grids' transform turns the world Z-up (gridTransform)
};

// zUp: the file's grids carry gridTransform(voxelSize, true).
void writeWorldMetadata(const world::Scene& scene, openvdb::MetaMap& out, bool zUp = false);

// The transform of our grids: index (i, j, k) to world (i, j, k) * voxelSize; with zUp then
// turned a quarter about +x, (x, y, z) -> (x, -z, y), so the engine's +y is the file's +z.
openvdb::math::Transform::Ptr gridTransform(double voxelSize, bool zUp);

// True when the file says it was written by voxengine (any version).
bool isVoxengineFile(const openvdb::MetaMap& meta);

// Reads what writeWorldMetadata() wrote; a missing or wrongly typed key is an Error naming the
// key (prefixed by `file`).
Result<WorldHeader> readWorldMetadata(const openvdb::MetaMap& meta, const std::string& file);

}  // namespace engine::io::vdb_layout
