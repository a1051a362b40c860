// Scene files (worlds/*.toml): [world], palette, generators (or a payload), dynamic objects,
// camera presets, [sky], [indirect] and [path]. The format is documented in worlds/README.md.
//
// This layer sits above world/, io/ and lighting/: it reads files into a world::Scene, running
// the generators of scene/generator_registry.h, and writes a Scene back with the same registry.
// Errors name the file and line: "worlds/city.toml:12: unknown generator 'terain'".
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "world/scene.h"
#include "world/world_limits.h"

namespace engine::scene {

// What loading builds. `gridGenerators` false reads the world's generators (checked, recorded in
// scene.generators) without running them, leaving the grid empty: a streamed world
// (world/grid_streaming.h) fills it region by region. Objects' generators always run.
struct SceneLoadOptions {
    bool gridGenerators = true;
};

Result<world::Scene> loadSceneFile(const std::filesystem::path& path,
                                   const SceneLoadOptions& options = {});
// sourceName names the text in messages and is the folder that relative paths in it (a vdb
// generator's source) are resolved against.
Result<world::Scene> loadSceneText(std::string_view text, std::string_view sourceName,
                                   const SceneLoadOptions& options = {});

struct SceneWriteOptions {
    std::string_view headerComment;  // "# " before each line, above everything
    // Write these instead of scene.generators (a save whose grid was edited names a payload).
    const std::vector<world::GeneratorRecord>* generators = nullptr;
    // Write these instead of each object's generators, one list per object in scene order (a
    // save writes each object's model as a payload of its own).
    const std::vector<std::vector<world::GeneratorRecord>>* objectGenerators = nullptr;
};

// The one writer: every table, so that loading the text gives back the same scene (palette,
// voxels, objects, cameras, sky, indirect settings, path). Floats in their shortest exact form.
std::string sceneText(const world::Scene& scene, const SceneWriteOptions& options = {});

// Resolves a world argument: an existing path, or a name in the worlds/ folder
// ("sandbox" -> worlds/sandbox.toml), looked up next to the working directory and the source
// tree the binary was built from.
Result<std::filesystem::path> resolveWorldPath(std::string_view nameOrPath);

}  // namespace engine::scene
