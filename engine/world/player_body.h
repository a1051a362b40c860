// The walking player's body: an axis-aligned box moved by fixed-step physics against the
// world's voxels (world/player_collision.h) — gravity, jump, automatic step-up of one voxel,
// crouch — and carried by the dynamic object it stands on.
//
// advance() runs whole ticks of PlayerSettings::tickSeconds (120 Hz) and keeps the remainder
// for the next frame, so the same inputs and frame times give the same path on every machine
// and every run (a script's replay). Each frame, before its ticks, the body rides along with
// the object under its feet (the object's pose change from the last frame to this one, from the
// DynamicGrid's instances) and, if anything solid overlaps it (an undo, an object moving into
// it), is lifted to the nearest free height above.
#pragma once

#include <algorithm>
#include <glm/glm.hpp>
#include <optional>

#include "world/player_collision.h"

namespace engine::world {

// Lengths in voxels and speeds in voxels per second, all multiplied by `scale` (a world of
// smaller voxels wants a larger player). Proportions after Minecraft's player.
struct PlayerSettings {
    double scale = 1.0;
    double width = 0.6;  // x and z
    double height = 1.8;
    double crouchHeight = 1.5;
    double eyeHeight = 1.62;  // above the feet
    double crouchEyeHeight = 1.32;
    double stepHeight = 1.0;  // climbed without a jump; one voxel, never two
    double walkSpeed = 4.3;
    double runSpeed = 8.6;
    double crouchSpeed = 1.3;
    double jumpHeight = 1.25;    // the apex of a jump above the ground
    double gravity = 32.0;       // voxels / s^2
    double maxFallSpeed = 78.4;  // terminal speed: the fastest the body ever moves
    double tickSeconds = 1.0 / 120.0;
    int maxTicksPerFrame = 12;  // a frame longer than this drops the rest (a stall is not a leap)

    double maxSpeed() const { return std::max(maxFallSpeed, runSpeed) * scale; }
};

// What the player wants this tick: a horizontal direction (world x and z, length <= 1), run,
// jump (held: jumps again on landing), crouch (held).
struct PlayerIntent {
    glm::dvec2 move{0.0};
    bool run = false;
    bool jump = false;
    bool crouch = false;
};

struct PlayerFrameReport {
    int ticks = 0;
    glm::dvec3 carried{0.0};  // moved by the object it stood on
    double liftedBy = 0.0;    // pushed up out of solid voxels
};

class PlayerBody {
public:
    explicit PlayerBody(PlayerSettings settings = {}) : mSettings(settings) {}

    // Puts the feet (centre of the box's bottom face) at `feet`, at rest and standing, inside the
    // world's sides, then lifts the body out of anything solid.
    void place(const CollisionWorld& world, glm::dvec3 feet);

    // One frame of `dt` seconds: carried, lifted out of solid, then whole ticks.
    PlayerFrameReport advance(const CollisionWorld& world, const PlayerIntent& intent, double dt);
    // One fixed step of tickSeconds.
    void tick(const CollisionWorld& world, const PlayerIntent& intent);

    PlayerBox box() const { return boxAt(mFeet, crouching() ? crouchHeight() : standingHeight()); }
    glm::dvec3 feet() const { return mFeet; }
    glm::dvec3 eye() const;
    glm::dvec3 velocity() const { return mVelocity; }
    bool onGround() const { return mOnGround; }
    bool crouching() const { return mCrouching; }
    // The dynamic object (index into DynamicGrid::instances) under the feet, if any.
    std::optional<std::size_t> supportObject() const { return mSupport; }
    const PlayerSettings& settings() const { return mSettings; }

private:
    PlayerBox boxAt(glm::dvec3 feet, double height) const;
    double standingHeight() const { return mSettings.height * mSettings.scale; }
    double crouchHeight() const { return mSettings.crouchHeight * mSettings.scale; }
    // Moves by `delta` one axis at a time (y first); returns the distance moved on each.
    glm::dvec3 moveBy(const CollisionWorld& world, glm::dvec3 delta);
    glm::dvec2 moveHorizontally(const CollisionWorld& world, glm::dvec2 delta);
    double liftOut(const CollisionWorld& world);
    void findSupport(const CollisionWorld& world);

    PlayerSettings mSettings;
    glm::dvec3 mFeet{0.0};
    glm::dvec3 mVelocity{0.0};
    bool mOnGround = false;
    bool mCrouching = false;
    std::optional<std::size_t> mSupport;
    double mAccumulator = 0.0;  // seconds not yet simulated
};

}  // namespace engine::world
