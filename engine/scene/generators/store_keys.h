// The `store` generator (scene/generators/store_keys.cpp): a world store's regions as the grid
// (scene/store_world.h). Saves of `vox play` and `vox import ... -o W.toml` write a scene file
// whose only generator is one of these.
#pragma once

#include <filesystem>
#include <string>

#include "world/generator_record.h"
#include "world/scene.h"

namespace engine::scene {

// `source` relative to the scene file's folder (or absolute).
world::GeneratorRecord storeGenerator(std::string source);
// The store a scene's grid came from whole — its only generator is a `store` one, or the scene
// was read from a store — resolved against the scene file's folder; empty otherwise.
std::filesystem::path storeOfScene(const world::Scene& scene);

}  // namespace engine::scene
