#include "game/walk_controller.h"

#include <GLFW/glfw3.h>
#include <chrono>
#include <cmath>
#include <fmt/format.h>

#include "world/dynamic_grid.h"

namespace game {

namespace world = engine::world;

std::string WalkController::toggle(const world::Scene& scene, CameraController& camera) {
    mActive = !mActive;
    if (!mActive) {
        mLastTime.reset();
        return "fly mode (F walks)";
    }
    placeAtCamera(scene, camera);
    const world::PlayerSettings& s = mBody.settings();
    return fmt::format(
        "walk mode: a {:.2g} x {:.2g} x {:.2g} voxel body (Space jumps, Q crouches, Shift runs; F "
        "flies)",
        s.width * s.scale, s.height * s.scale, s.width * s.scale);
}

void WalkController::placeAtCamera(const world::Scene& scene, CameraController& camera) {
    const world::CollisionWorld collision{scene.grid, &scene.dynamic};
    const world::PlayerSettings& s = mBody.settings();
    mBody.place(collision,
                glm::dvec3(camera.position()) - glm::dvec3(0.0, s.eyeHeight * s.scale, 0.0));
    camera.setPosition(glm::vec3(mBody.eye()));
}

std::string WalkController::update(const InputState& input, double dt, double time, bool mouseLook,
                                   world::Scene& scene, CameraController& camera) {
    camera.look(input, mouseLook);
    // This frame's poses; the previous frame's time gives each object's motion to ride along.
    world::updateDynamicObjects(scene.objects, scene.dynamic, time, mLastTime.value_or(time));
    mLastTime = time;

    world::PlayerIntent intent;
    if (!input.ctrl()) {  // Ctrl+key is a command
        const double yaw = glm::radians(double(camera.yawDegrees()));
        const glm::dvec2 forward(std::sin(yaw), std::cos(yaw)),
            right(-std::cos(yaw), std::sin(yaw));
        if (input.held(GLFW_KEY_W)) intent.move += forward;
        if (input.held(GLFW_KEY_S)) intent.move -= forward;
        if (input.held(GLFW_KEY_D)) intent.move += right;
        if (input.held(GLFW_KEY_A)) intent.move -= right;
        if (glm::dot(intent.move, intent.move) > 0.0) intent.move = glm::normalize(intent.move);
        intent.run = input.shift();
        intent.jump = input.held(GLFW_KEY_SPACE) || input.held(GLFW_KEY_E);
        intent.crouch = input.held(GLFW_KEY_Q);
    }
    const auto start = std::chrono::steady_clock::now();
    const world::CollisionWorld collision{scene.grid, &scene.dynamic};
    mLastReport = mBody.advance(collision, intent, dt);
    mCollisionMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    camera.setPosition(glm::vec3(mBody.eye()));

    auto support = mBody.supportObject();
    mSupportName = support && *support < scene.objects.size() ? scene.objects[*support].name : "";
    if (mLastReport.liftedBy > 0.0)
        return fmt::format("walk: lifted {:.2f} voxels up out of solid voxels",
                           mLastReport.liftedBy);
    return {};
}

std::string WalkController::refusal(const EditOp& op, const world::BrickGrid& grid) const {
    if (!mActive || op.tool != Tool::Place)
        return {};  // removing and painting never add solid voxels
    // The same edit applied to an empty scratch grid over the voxels the body overlaps: any voxel
    // it fills there (inside the world) would enclose the body.
    const world::Box under = world::overlappedVoxels(mBody.box());
    world::BrickGrid scratch(glm::max(under.size(), glm::ivec3(1)));
    EditOp local = op;
    local.box.min -= under.min;
    local.box.max -= under.min;
    local.center -= glm::vec3(under.min);
    applyEdit(scratch, local);
    for (int z = under.min.z; z < under.max.z; ++z)
        for (int y = under.min.y; y < under.max.y; ++y)
            for (int x = under.min.x; x < under.max.x; ++x) {
                const glm::ivec3 v(x, y, z);
                if (grid.contains(v) && scratch.get(v - under.min) != world::kEmpty)
                    return fmt::format(
                        "it would enclose the player at ({}, {}, {}) (walk mode; F flies)", x, y,
                        z);
            }
    return {};
}

std::string WalkController::hudText() const {
    if (!mActive) return "fly (F: walk)";
    std::string state = !mBody.onGround()       ? "in the air"
                        : !mSupportName.empty() ? "on " + mSupportName
                                                : "on the ground";
    if (mBody.crouching()) state += ", crouching";
    const glm::dvec3 f = mBody.feet();
    return fmt::format(
        "walk (F: fly): {} at ({:.1f}, {:.1f}, {:.1f}); collision {:.3f} ms, {} ticks", state, f.x,
        f.y, f.z, mCollisionMs, mLastReport.ticks);
}

const char* WalkController::logHeader() {
    return "frame,time,mode,min_x,min_y,min_z,max_x,max_y,max_z,on_ground,crouching,support,ticks,"
           "collision_ms";
}

std::string WalkController::logRow(std::uint64_t frame, double time) const {
    if (!mActive) return fmt::format("{},{},fly,,,,,,,,,,,", frame, time);
    // Shortest round-trip form, so a checker reads back the very doubles the body had.
    const world::PlayerBox b = mBody.box();
    return fmt::format("{},{},walk,{},{},{},{},{},{},{},{},{},{},{:.4f}", frame, time, b.min.x,
                       b.min.y, b.min.z, b.max.x, b.max.y, b.max.z, int(mBody.onGround()),
                       int(mBody.crouching()), mSupportName, mLastReport.ticks, mCollisionMs);
}

}  // namespace game
