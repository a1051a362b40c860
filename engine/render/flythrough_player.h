// FlythroughPlayer: plays a world::Flythrough through a Renderer, one frame at a time. For
// frame i it applies the timeline's events due by then, puts the camera on the spline at
// i / fps, and renders with i as the frame index that seeds the randomness. A capture slice
// (frames A..B after W frames of warm-up) plays frames A-W..B on a freshly loaded scene: the
// events before A-W apply at once, so every frame sees the same world and camera as in the
// whole capture, and only the temporal history is shorter.
#pragma once

#include <cstdint>

#include "lighting/lighting_settings.h"
#include "render/renderer.h"
#include "world/flythrough.h"

namespace engine::render {

class FlythroughPlayer {
public:
    // The flythrough's timeline must already be bound to `scene` (Timeline::bind).
    FlythroughPlayer(Renderer& renderer, world::Scene& scene, world::Flythrough& flythrough,
                     double fps);

    struct Frame {
        std::uint32_t index = 0;
        double time = 0.0;  // seconds
        world::CameraPreset camera;
        std::uint32_t events = 0;  // timeline events applied just before this frame
        FrameResult result;
    };
    // Frame numbers must increase from call to call (gaps are fine: their events still apply).
    Frame render(std::uint32_t frame, const FrameSettings& settings,
                 const lighting::LightingSettings& lighting);

    double fps() const { return mFps; }

private:
    Renderer& mRenderer;
    world::Scene& mScene;
    world::Flythrough& mFlythrough;
    double mFps;
    std::int64_t mLastFrame = -1;
};

}  // namespace engine::render
