// Walk mode (F toggles it): the camera rides at the eye of a player body that walks with
// collision instead of flying (physics: engine/world/player_body.h). W A S D walk along the
// view's heading, Space or E jumps, Q crouches, Shift runs; the mouse looks around as in fly
// mode. Each frame the scene's dynamic objects are posed at the frame's time first, so the body
// collides with (and rides on) what this frame draws; the renderer's own update then finds them
// posed already. Place edits that would put solid voxels inside the body are refused.
#pragma once

#include <optional>
#include <string>

#include "game/camera_controller.h"
#include "game/edit_tools.h"
#include "game/input.h"
#include "world/player_body.h"
#include "world/scene.h"

namespace game {

class WalkController {
public:
    explicit WalkController(engine::world::PlayerSettings settings = {}) : mBody(settings) {}

    bool active() const { return mActive; }
    // Enters walk mode with the body's eye at the camera (lifted out of anything solid), or
    // leaves it (the camera flies on from the eye). Returns the message for the HUD.
    std::string toggle(const engine::world::Scene& scene, CameraController& camera);
    // Puts the body's eye at the camera (a camera preset was chosen while walking).
    void placeAtCamera(const engine::world::Scene& scene, CameraController& camera);
    // One frame of walk mode at scene time `time`: poses the objects, moves the body with the
    // held keys over `dt` seconds and puts the camera at its eye (the mouse turns it). Returns a
    // message when the body had to be lifted out of solid voxels (an undo, an object), else "".
    std::string update(const InputState& input, double dt, double time, bool mouseLook,
                       engine::world::Scene& scene, CameraController& camera);
    // Why `op` must not be applied in walk mode (it would put solid voxels inside the body), or
    // "" when it may.
    std::string refusal(const EditOp& op, const engine::world::BrickGrid& grid) const;

    const engine::world::PlayerBody& body() const { return mBody; }
    // One HUD line: the mode, the body's state, the collision cost.
    std::string hudText() const;
    // The walk log (`vox play --walk-log`): one CSV row per frame, the body's box in voxels.
    static const char* logHeader();
    std::string logRow(std::uint64_t frame, double time) const;

private:
    engine::world::PlayerBody mBody;
    bool mActive = false;
    std::optional<double> mLastTime;  // the scene time of the last walk frame
    double mCollisionMs = 0.0;
    engine::world::PlayerFrameReport mLastReport;
    std::string mSupportName;  // the object under the feet
};

}  // namespace game
