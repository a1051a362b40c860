// Writes a Scene back as a scene file (the format of scene_file.h, documented in
// worlds/README.md): world name, size and voxel size, palette, the given generators, camera
// presets and sky. Voxels are not generated from a description any more once edited, so a
// saved world's generator list is usually one payload generator (see game/world_store.h).
#pragma once

#include <string>
#include <string_view>

#include "world/scene.h"

namespace engine::world {

// A TOML basic string, quoted and escaped.
std::string tomlString(std::string_view text);

// `generators` is TOML text inserted as is (zero or more [[generator]] tables). Numbers are
// written so that loading the text gives back the same floats.
std::string sceneTextWithPalette(const Scene& scene, std::string_view generators, std::string_view headerComment = {});

}  // namespace engine::world
