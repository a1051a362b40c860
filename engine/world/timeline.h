// Timeline: timed events a flythrough applies to the world as it plays — voxel edits (boxes,
// spheres, single voxels, including carving with `empty`), emitters switched on and off, and
// dynamic objects started.
//
// Emitters are just emissive voxels, so switching a light off edits its voxels to a dark twin
// material ("<name>.off": same albedo, no emission) and switching it on edits them back; the
// renderer's emitter list and GPU world pick the edits up incrementally like any other edit.
// A dynamic object named by a start event holds its first pose until the event's time and then
// runs its path (bind sets DynamicObject::startTime; the pose is a function of time, so slices
// of a capture agree).
//
// Frame timing: an event at time t takes effect from the first frame whose time i / fps >= t
// (firstFrame), applied before that frame renders, in file order among events of one frame. So
// the world at frame i depends only on the file, the frame rate and i.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "core/error.h"
#include "world/brick_grid.h"
#include "world/scene.h"

namespace engine::world {

struct TimelineEvent {
    enum class Kind { Box, Sphere, Voxel, Light, DynamicStart };
    Kind kind = Kind::Box;
    double time = 0.0;     // seconds
    std::string where;     // "file:line" of the event, for messages
    std::string material;  // Box, Sphere, Voxel: what to write ("empty" carves); Light: the emitter
                           // material
    std::string materialWhere;  // "file:line" of the material key
    Box box;                    // Box; Light: the region switched (the whole world when not given)
    bool wholeWorld = false;    // Light without a region
    glm::vec3 center{0.0f};     // Sphere
    float radius = 0.0f;        // Sphere
    glm::ivec3 voxel{0};        // Voxel
    bool on = true;             // Light
    std::string object;         // DynamicStart: the object's name

    // Filled in by Timeline::bind.
    MaterialId from = kEmpty, to = kEmpty;
};

class Timeline {
public:
    Timeline() = default;
    // Events in file order; they are kept sorted by time, stably.
    explicit Timeline(std::vector<TimelineEvent> events);

    // Resolves material names against `scene` (adding the ".off" twins that Light events need)
    // and checks the events fit the world. Errors name the event's file and line.
    Status bind(Scene& scene);

    // The first frame an event at time t applies to.
    static std::uint32_t firstFrame(double time, double fps);

    // Applies, in order, every event not yet applied whose first frame is <= frame. Returns how
    // many it applied. Frames must not go backwards (a fresh scene and timeline replay a slice).
    std::uint32_t applyThrough(std::uint32_t frame, double fps, Scene& scene);

    const std::vector<TimelineEvent>& events() const { return mEvents; }

private:
    void apply(const TimelineEvent& e, Scene& scene);

    std::vector<TimelineEvent> mEvents;
    std::size_t mNext = 0;
    bool mBound = false;
};

}  // namespace engine::world
