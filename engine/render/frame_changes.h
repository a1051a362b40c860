// FrameChanges: what changed since the last frame — edited cells, lights, sky, objects, camera,
// image size, settings — worked out once per frame (FrameChangeTracker, in Renderer::render)
// and handed to every technique, which decides from it what to restart, re-trace or invalidate.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "lighting/emitter_list.h"
#include "lighting/lighting_settings.h"
#include "render/gpu_emitter_list.h"
#include "render/gpu_world.h"
#include "world/scene.h"

namespace engine::render {

struct FrameChanges {
    bool newWorld = false;                // the world was uploaded whole (a new or resized world)
    std::vector<glm::ivec3> editedCells;  // 8^3 cells whose voxels changed, in cell coordinates
    bool staticWorldChanged = false;      // bricks or top-grid cells were uploaded
    bool objectsMoved = false;     // the dynamic grid was uploaded: an object moved or appeared
    bool lightsEdited = false;     // an edit added, removed or changed an emitter (not a new world)
    bool lightsUploaded = false;   // emitter slots or the alive list changed on the GPU
    bool skyChanged = false;       // the sun or sky differ from the last frame's (not on a first)
    bool cameraMoved = false;      // the view differs from the last frame's, or there was none
    bool sizeChanged = false;      // the image size differs from the last frame's
    bool settingsChanged = false;  // the lighting settings differ from the last frame's
    // No usable temporal history: a first frame, a new size or new settings, resetHistory(), or
    // an edit of the lights (last frame's reservoirs were resampled from the old set of lights).
    bool historyLost = true;
    // The last frame's camera (this frame's on a first frame): the motion vectors' origin.
    world::CameraPreset previousCamera;

    // Anything the GPU's copy of the world or of the lights received.
    bool worldChanged() const { return staticWorldChanged || objectsMoved || lightsUploaded; }
    // What the estimators that accumulate over still frames restart on (reference, path term,
    // sky reference, accumulation): anything the image depends on, the sun and sky included.
    bool restartsAccumulation() const {
        return historyLost || cameraMoved || skyChanged || worldChanged();
    }
};

// What the tracker compares; read after this frame's uploads were queued and before the grid's
// dirty marks are cleared.
struct FrameObservation {
    const world::Scene& scene;
    const world::CameraPreset& camera;
    glm::uvec2 size;
    const lighting::LightingSettings& lighting;
    const WorldUploadStats& upload;
    const lighting::EmitterUpdateStats& emitterUpdate;
    const EmitterUploadStats& emitterUpload;
};

class FrameChangeTracker {
public:
    // This frame's changes against the last observed one; then this frame is the last one.
    FrameChanges observe(const FrameObservation& frame);
    // Forget the history (Renderer::resetHistory): the next frame has none, and its camera counts
    // as moved.
    void forgetHistory();

private:
    std::optional<world::CameraPreset> mCamera;
    std::optional<world::SkyLight> mSky;
    std::optional<lighting::LightingSettings> mLighting;
    glm::uvec2 mSize{0};
    bool mHistoryValid = false;
};

}  // namespace engine::render
