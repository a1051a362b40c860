#include "world/player_body.h"

#include <cmath>

#include "world/scene.h"

namespace engine::world {

PlayerBox PlayerBody::boxAt(glm::dvec3 feet, double height) const {
    const double half = 0.5 * mSettings.width * mSettings.scale;
    return {feet - glm::dvec3(half, 0.0, half), feet + glm::dvec3(half, height, half)};
}

glm::dvec3 PlayerBody::eye() const {
    return mFeet + glm::dvec3(0.0,
                              (mCrouching ? mSettings.crouchEyeHeight : mSettings.eyeHeight) *
                                  mSettings.scale,
                              0.0);
}

void PlayerBody::place(const CollisionWorld& world, glm::dvec3 feet) {
    const glm::dvec3 size(world.grid.sizeInVoxels());
    const double half = 0.5 * mSettings.width * mSettings.scale + kSkin;
    // Wherever the camera was -- far out, or nowhere (NaN) -- the body starts inside the world's
    // sides, above its floor and no higher than any position a file may give (kCoordinateRange).
    auto within = [](double v, double lo, double hi, double ifNaN) {
        return std::isnan(v) ? ifNaN : std::clamp(v, lo, hi);
    };
    mFeet.x = within(feet.x, half, std::max(half, size.x - half), 0.5 * size.x);
    mFeet.z = within(feet.z, half, std::max(half, size.z - half), 0.5 * size.z);
    mFeet.y = within(feet.y, kSkin, kCoordinateRange.max, size.y);
    mVelocity = glm::dvec3(0.0);
    mOnGround = false;
    mCrouching = false;
    mSupport.reset();
    mAccumulator = 0.0;
    liftOut(world);
}

glm::dvec3 PlayerBody::moveBy(const CollisionWorld& world, glm::dvec3 delta) {
    PlayerBox b = box();
    glm::dvec3 moved;
    moved.y = sweepAxis(world, b, 1, delta.y);
    moved.x = sweepAxis(world, b, 0, delta.x);
    moved.z = sweepAxis(world, b, 2, delta.z);
    mFeet += moved;
    return moved;
}

glm::dvec2 PlayerBody::moveHorizontally(const CollisionWorld& world, glm::dvec2 delta) {
    PlayerBox flat = box();
    const glm::dvec2 moved(sweepAxis(world, flat, 0, delta.x), sweepAxis(world, flat, 2, delta.y));
    const bool blocked = moved != delta;
    if (blocked && mOnGround && mVelocity.y <= 0.0) {
        // Step up: rise by at most the step height (less under a ceiling), move, come back down
        // onto whatever is there. Taken only if it got further and ended higher: a real step.
        PlayerBox raised = box();
        const double up = sweepAxis(world, raised, 1, mSettings.stepHeight * mSettings.scale);
        const glm::dvec2 across(sweepAxis(world, raised, 0, delta.x),
                                sweepAxis(world, raised, 2, delta.y));
        const double down = sweepAxis(world, raised, 1, -up);
        if (glm::dot(across, across) > glm::dot(moved, moved) && up + down > kSkin) {
            mFeet += glm::dvec3(across.x, up + down, across.y);
            return across;
        }
    }
    mFeet += glm::dvec3(moved.x, 0.0, moved.y);
    return moved;
}

double PlayerBody::liftOut(const CollisionWorld& world) {
    if (!overlapsSolid(world, box())) return 0.0;
    // The lowest whole-voxel height above that is free; above the world's top is always free
    // (inside its sides), unless dynamic objects float there.
    const double start = mFeet.y;
    const int top = world.grid.sizeInVoxels().y + 4096;
    for (int level = voxelFloor(start) + 1; level <= top; ++level) {
        mFeet.y = double(level) + kSkin;
        if (!overlapsSolid(world, box())) break;
    }
    mVelocity.y = 0.0;
    return mFeet.y - start;
}

void PlayerBody::findSupport(const CollisionWorld& world) {
    mSupport.reset();
    if (!mOnGround || !world.dynamic) return;
    Box voxels = overlappedVoxels(box());
    const int below = voxelFloor(box().min.y - 2.0 * kSkin);
    for (int z = voxels.min.z; z < voxels.max.z; ++z)
        for (int x = voxels.min.x; x < voxels.max.x; ++x) {
            const glm::ivec3 v(x, below, z);
            if (!world.dynamicAt(v)) continue;
            // Where objects overlap the first one wins, as in the voxelisation.
            const auto& instances = world.dynamic->instances;
            for (std::size_t i = 0; i < instances.size(); ++i) {
                if (instances[i].bounds.contains(v)) {
                    mSupport = i;
                    return;
                }
            }
        }
}

void PlayerBody::tick(const CollisionWorld& world, const PlayerIntent& intent) {
    const double dt = mSettings.tickSeconds, scale = mSettings.scale;
    // Crouching lowers the top of the box at once; standing up needs the room to.
    if (intent.crouch) {
        mCrouching = true;
    } else if (mCrouching && !overlapsSolid(world, boxAt(mFeet, standingHeight()))) {
        mCrouching = false;
    }
    glm::dvec2 direction = intent.move;
    if (glm::dot(direction, direction) > 1.0) direction = glm::normalize(direction);
    const double speed = (mCrouching   ? mSettings.crouchSpeed
                          : intent.run ? mSettings.runSpeed
                                       : mSettings.walkSpeed) *
                         scale;
    mVelocity.x = direction.x * speed;
    mVelocity.z = direction.y * speed;
    if (intent.jump && mOnGround) {
        mVelocity.y = std::sqrt(2.0 * mSettings.gravity * mSettings.jumpHeight) * scale;
        mOnGround = false;
    }
    mVelocity.y =
        std::max(mVelocity.y - mSettings.gravity * scale * dt, -mSettings.maxFallSpeed * scale);

    moveHorizontally(world, glm::dvec2(mVelocity.x, mVelocity.z) * dt);
    PlayerBox b = box();
    const double fall = mVelocity.y * dt;
    const double moved = sweepAxis(world, b, 1, fall);
    mFeet.y += moved;
    if (moved != fall) {
        mOnGround = fall < 0.0;
        mVelocity.y = 0.0;
    } else {
        mOnGround = false;
    }
    findSupport(world);
}

PlayerFrameReport PlayerBody::advance(const CollisionWorld& world, const PlayerIntent& intent,
                                      double dt) {
    PlayerFrameReport report;
    if (mSupport && world.dynamic && *mSupport < world.dynamic->instances.size()) {
        // Ride along: the feet move as the object's material point under them moved, from its
        // pose last frame to this frame's.
        const DynamicInstance& object = world.dynamic->instances[*mSupport];
        const glm::dmat4 currentFromPrevious =
            object.worldFromModel * glm::inverse(object.prevWorldFromModel);
        const glm::dvec3 to(currentFromPrevious * glm::dvec4(mFeet, 1.0));
        report.carried = moveBy(world, to - mFeet);
    }
    report.liftedBy = liftOut(world);
    mAccumulator += dt;
    while (mAccumulator >= mSettings.tickSeconds) {
        if (report.ticks == mSettings.maxTicksPerFrame) {
            mAccumulator = 0.0;
            break;
        }
        tick(world, intent);
        mAccumulator -= mSettings.tickSeconds;
        ++report.ticks;
    }
    return report;
}

}  // namespace engine::world
