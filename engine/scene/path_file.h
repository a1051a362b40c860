// Path files: the [path] table (camera keys and timed events) that `vox capture` plays. It
// lives either in a scene file next to the world it flies through (the scene loader keeps it in
// world::Scene::path), or alone in a path file (a TOML file holding only [path]). Unknown keys
// are errors; every error names the file and line: "worlds/sandbox.toml:130: unknown event type
// 'lamp'". Format: worlds/README.md.
#pragma once

#include <filesystem>
#include <string_view>

#include "core/error.h"
#include "world/flythrough.h"

namespace engine::scene {

// A path file, or a scene file's [path] table (a file with a [world] table is a scene file:
// its other tables belong to the scene and are left to the scene loader).
Result<world::Flythrough> loadFlythroughFile(const std::filesystem::path& path);
Result<world::Flythrough> loadFlythroughText(std::string_view text, std::string_view sourceName);

}  // namespace engine::scene
