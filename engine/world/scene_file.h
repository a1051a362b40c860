// Scene files (worlds/*.toml): palette, world size, generators, dynamic objects, camera presets, sky.
// Errors name the file and line: "worlds/city.toml:12: unknown generator 'terain'".
// The format is documented in worlds/README.md.
#pragma once

#include <filesystem>
#include <string_view>

#include "core/error.h"
#include "world/scene.h"
#include "world/world_limits.h"

namespace engine::world {

Result<Scene> loadSceneFile(const std::filesystem::path& path);
// sourceName names the text in messages and is the folder that relative paths in it (a vdb
// generator's source) are resolved against.
Result<Scene> loadSceneText(std::string_view text, std::string_view sourceName);

// A scene file for `scene` without its voxels: [world] (name, size, voxel size), the given
// [[generator]] tables verbatim, cameras and sky. Floats are written in their shortest exact form.
std::string sceneFileText(const Scene& scene, std::string_view comment, std::string_view generators);

// Resolves a world argument: an existing path, or a name in the worlds/ folder
// ("sandbox" -> worlds/sandbox.toml), looked up next to the working directory and the source
// tree the binary was built from.
Result<std::filesystem::path> resolveWorldPath(std::string_view nameOrPath);

}  // namespace engine::world
