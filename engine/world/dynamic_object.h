// Dynamic objects: small voxel models moved by a rigid transform along a scripted path.
//
// A model is a BrickGrid of palette material ids spanning [0, modelSize); it turns about its
// centre (the pivot) and the path places that centre in the world. Paths are keyframes (time,
// position, rotation) joined by a cubic Hermite spline with Catmull–Rom tangents over key times
// (positions) and slerp (rotations); a looping path wraps time into [first key, last key).
// Everything is a pure function of the time, so a frame renders the same wherever it is rendered.
// Each frame the objects are re-voxelised into one world-aligned grid (world/dynamic_grid.h).
//
// The model is shared, never copied: copies of an object (undo steps, a drag's start) hold the
// same grid, whose brick pool takes a whole page however few bricks it holds. Built once, it
// is const from then on.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "world/brick_grid.h"
#include "world/generator_record.h"

namespace engine::world {

struct ObjectKey {
    double time = 0.0;         // seconds
    glm::dvec3 position{0.0};  // world position of the model centre, voxel units
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    // The rotation as the scene file gave it, so a writer gives back the very same quaternion:
    // none, yaw/pitch/roll degrees in `angles`, or an axis in `angles` and `angle` degrees.
    enum class Given { None, YawPitchRoll, AxisAngle };
    Given given = Given::None;
    glm::dvec3 angles{0.0};
    double angle = 0.0;
};

// Yaw about +Y, then pitch about +X, then roll about +Z (applied roll first), in degrees.
glm::dquat rotationFromYawPitchRoll(glm::dvec3 degrees);
glm::dquat rotationFromAxisAngle(glm::dvec3 axis, double degrees);

struct RigidTransform {
    glm::dvec3 position{0.0};  // where the pivot goes
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    bool operator==(const RigidTransform&) const = default;
};

class ObjectPath {
public:
    ObjectPath() = default;
    // Keys sorted by strictly increasing time, at least one. A looping path should end on its
    // first pose for a seamless loop; the tangents at its ends then wrap around.
    ObjectPath(std::vector<ObjectKey> keys, bool loop);

    RigidTransform at(double t) const;
    const std::vector<ObjectKey>& keys() const { return mKeys; }
    bool loop() const { return mLoop; }
    double period() const { return mKeys.empty() ? 0.0 : mKeys.back().time - mKeys.front().time; }

private:
    glm::dvec3 tangent(std::size_t k) const;
    std::vector<ObjectKey> mKeys{ObjectKey{}};
    bool mLoop = false;
};

struct DynamicObject {
    std::string name;
    std::shared_ptr<const BrickGrid> model = std::make_shared<const BrickGrid>(glm::ivec3(8));
    std::vector<GeneratorRecord> generators;  // what built `model`, for writing the scene back
    glm::ivec3 modelSize{8};  // the model's extent in voxels (the grid rounds it up to bricks)
    ObjectPath path;
    // Set when a flythrough's timeline has a `dynamic` start event for this object
    // (Timeline::bind): the object holds its first pose until then and runs its path from that
    // moment.
    std::optional<double> startTime;
    // Set by updateDynamicObjects (world/dynamic_grid.h): the poses of this frame and the last.
    RigidTransform current, previous;

    // Where the object is at scene time t: its path, shifted to start at startTime if set.
    RigidTransform poseAt(double t) const;

    glm::dvec3 pivot() const { return glm::dvec3(modelSize) * 0.5; }
    // world = position + rotation * (model - pivot)
    glm::dmat4 worldFromModel(const RigidTransform& t) const;
    // The voxels the model can cover under `t`: its transformed box, rounded outwards.
    Box worldBounds(const RigidTransform& t) const;
};

}  // namespace engine::world
