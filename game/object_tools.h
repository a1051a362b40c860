// The sandbox's object tool (key 4): dynamic objects (world/dynamic_object.h) placed, moved,
// turned, animated and deleted from `vox play`.
//
// A model comes from a world scene file, a `.vdb` or a `.vox` (`vox play --model FILE`, loaded
// like `vox play FILE`), cropped to its solid voxels; at most kMaxModelVoxels solid voxels and
// kMaxObjectExtent voxels a side, so an object stays cheap to re-voxelise every frame; a bigger
// model is refused with a message naming the cap. Placing copies its materials into the world's
// palette by name.
//
// Poses snap to voxels: an object turned by whole quarter turns covers whole voxels, so it shows
// its model exactly. An object with one key is static: moving or turning it changes that key.
// Setting a key (K) at the current scene time adds a key with the pose shown now (a second key
// makes a looping path); moving or turning an object that has a path sets the key at the current
// time the same way, so a path is recorded by moving the object as time runs. Every command is one
// undo step (UndoHistory::recordObject).
#pragma once

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "game/edit_tools.h"
#include "game/undo_history.h"
#include "world/scene.h"

namespace game {

class InputState;

inline constexpr std::uint64_t kMaxModelVoxels = 16384;  // solid voxels of one model
inline constexpr std::uintmax_t kMaxModelFileBytes = 64u
                                                     << 20;  // a .vdb or .vox larger is not opened
inline constexpr double kKeyTolerance = 1.0 / 60.0;  // s: a key this close to the time is replaced
inline constexpr double kFreeTurnDegrees = 5.0;

struct ObjectModel {
    std::string name;                // the file's stem
    engine::world::Palette palette;  // the source's materials; `voxels` holds their ids
    engine::world::BrickGrid voxels{glm::ivec3(8)};  // the solid voxels' box, from (0, 0, 0)
    glm::ivec3 size{0};
    std::uint64_t solidVoxels = 0;
};

// Loads a model from a scene file, .vdb or .vox (refused beyond the caps above, or empty).
engine::Result<ObjectModel> loadObjectModel(const std::filesystem::path& path);

// The outcome of one object command: whether the objects changed, and the HUD's message line.
struct ObjectResult {
    bool changed = false;
    std::string message;
};

// Places `model` on the face under the crosshair (its lowest corner on the voxel in front of the
// face, centred across it), as a static object keyed at `time`. Appends it to scene.objects.
ObjectResult placeObject(engine::world::Scene& scene, UndoHistory& undo, const ObjectModel& model,
                         const Pick& target, double time);
// Moves by whole voxels along world axes.
ObjectResult moveObject(engine::world::Scene& scene, UndoHistory& undo, std::size_t index,
                        glm::ivec3 delta, double time);
// Turns about +Y (world up) by `degrees` about the object's centre.
ObjectResult turnObject(engine::world::Scene& scene, UndoHistory& undo, std::size_t index,
                        double degrees, double time);
// Sets a key at `time` with the pose shown at that time.
ObjectResult setObjectKey(engine::world::Scene& scene, UndoHistory& undo, std::size_t index,
                          double time);
// Keeps one key, the pose shown at `time`: the object stops there.
ObjectResult clearObjectPath(engine::world::Scene& scene, UndoHistory& undo, std::size_t index,
                             double time);
// A path with two keys or more loops, or stops at its last key.
ObjectResult toggleObjectLoop(engine::world::Scene& scene, UndoHistory& undo, std::size_t index,
                              double time);
ObjectResult deleteObject(engine::world::Scene& scene, UndoHistory& undo, std::size_t index,
                          double time);

// The object an editing command starts from at `time`: the path's pose, held at the last key
// after a path's end (recording continues from there), snapped to voxels; yaw in degrees.
struct ObjectPose {
    glm::dvec3 position{0.0};
    double yawDegrees = 0.0;
};
ObjectPose editPose(const engine::world::DynamicObject& object, double time);

// Drags the object over the ground: its box's lowest corner follows the voxel in front of the face
// under the crosshair along X and Z (centred on it, height kept), changing the key at `time` as
// a move does. No undo step (ObjectTools records one per drag). False if it did not move.
bool dragObject(engine::world::DynamicObject& object, const Pick& target, double time);

// The object whose voxel the view ray hits first (static voxels in front hide it).
std::optional<std::size_t> pickObject(const engine::world::Scene& scene, glm::vec3 origin,
                                      glm::vec3 direction);

// Re-voxelises the objects at `time` so picks and the next frame see a change at once.
void refreshObjects(engine::world::Scene& scene, double time);

// The tool's state and keys; the sandbox calls handle() each frame while it is active.
class ObjectTools {
public:
    bool active = false;
    std::optional<std::size_t> selected;
    std::vector<ObjectModel> models;
    std::size_t model = 0;

    // Clicks only when `mouseLook`: left places, or, pressed on the selected object, drags it
    // until the release (one undo step); right selects. Returns what the frame did.
    ObjectResult handle(const InputState& input, bool mouseLook, const Pick& target,
                        glm::vec3 origin, glm::vec3 direction, engine::world::Scene& scene,
                        UndoHistory& undo, double time);
    // Ends a drag as one undo step (at the release; the sandbox calls it before undo and redo).
    ObjectResult finishDrag(engine::world::Scene& scene, UndoHistory& undo);
    // After undo/redo: drops a selection that no longer exists.
    void objectsChanged(const engine::world::Scene& scene);
    // One line for the HUD: model, selection, keys.
    std::string status(const engine::world::Scene& scene) const;

private:
    struct Drag {
        std::size_t index = 0;
        engine::world::DynamicObject before;  // for the undo step
        double time = 0.0;                    // the key a drag changes: at its press
    };
    std::optional<Drag> mDrag;
};

}  // namespace game
