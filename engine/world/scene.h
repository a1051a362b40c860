// A scene: the world grid with its palette, plus what a scene file says about viewing and
// lighting it (camera presets, sun and sky), and the dynamic objects moving through it.
#pragma once

#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/number_check.h"
#include "world/brick_grid.h"
#include "world/dynamic_grid.h"
#include "world/dynamic_object.h"
#include "world/generator_record.h"
#include "world/material.h"

namespace engine::world {

struct Flythrough;

// Vertical field of view a camera accepts wherever it comes from (scene and path files, --fov).
inline constexpr NumberRange kFovRange = openRange(1.0, 179.0, "degrees");
// Positions (cameras, sphere centres, object keys): far beyond any world, and floats still hold
// whole voxels there.
inline constexpr NumberRange kCoordinateRange = closedRange(-1e7, 1e7, "voxels");
// The other numbers a world holds, checked by these ranges wherever they come from: a scene
// file's keys, a .vdb file's metadata and its grid's transform.
inline constexpr NumberRange kVoxelSizeRange = aboveRange(0.0, 1e6, "m");
inline constexpr NumberRange kAlbedoRange = closedRange(0.0, 1.0);
inline constexpr NumberRange kRadianceRange =
    closedRange(0.0, 1e6);  // emission, its strength, sun and sky
inline constexpr NumberRange kDirectionRange =
    closedRange(-1e6, 1e6);  // the sun's, not yet normalised

struct CameraPreset {
    std::string name;
    glm::vec3 position{0.0f};
    glm::vec3 target{0.0f, 0.0f, 1.0f};
    float fovYDegrees = 60.0f;
};

// The camera's numbers within kCoordinateRange and kFovRange, and its target apart from its
// position; the message names the camera.
Status checkCamera(const CameraPreset& camera);

struct SkyLight {
    glm::vec3 sunDirection = glm::normalize(glm::vec3(0.4f, 1.0f, 0.3f));  // towards the sun
    glm::vec3 sunRadiance{3.0f, 2.85f, 2.6f};
    glm::vec3 skyRadiance{0.35f, 0.45f, 0.6f};
    // [sky] sky_light: how the real-time methods get sky light, as the `sky` lighting knob's text
    // ("none", "dvf", "reference"; empty = the scene does not say). Read through the knob
    // (scene/scene_lighting.h); the command line overrides it.
    std::string lightMode;
};

struct Scene {
    std::string name = "untitled";
    std::string sourcePath;  // the file it came from, for messages
    float voxelSize =
        1.0f;  // edge of a voxel in world units (metres); exported as the VDB transform
    Palette palette;
    BrickGrid grid{glm::ivec3(8)};
    std::vector<CameraPreset> cameras;
    SkyLight sky;
    // [indirect]: how the world wants its indirect light, as key = value text in the form the
    // lighting knobs read (scene/indirect_keys.h checks them on load; the command line
    // overrides them, scene/scene_lighting.h). The world layer does not interpret them.
    std::vector<std::pair<std::string, std::string>> indirect;
    // Moving objects and this frame's voxelisation of them (world/dynamic_grid.h), posed by
    // updateDynamicObjects from the frame's scene time.
    std::vector<DynamicObject> objects;
    DynamicGrid dynamic;
    // What the scene file said, kept so it can be written back (engine/scene/scene_file.h): the
    // generators that built `grid`, in order, and the file's [path] (camera keys and events), if
    // any. An edited grid no longer matches its generators; a save writes a payload instead.
    std::vector<GeneratorRecord> generators;
    std::shared_ptr<const Flythrough> path;

    // The named preset, the first one for an empty name, or a view of the whole world.
    CameraPreset camera(std::string_view name = {}) const;
    std::uint64_t emissiveVoxels() const;
};

}  // namespace engine::world
