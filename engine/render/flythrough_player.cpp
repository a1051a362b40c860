#include "render/flythrough_player.h"

#include "core/check.h"

namespace engine::render {

FlythroughPlayer::FlythroughPlayer(Renderer& renderer, world::Scene& scene,
                                   world::Flythrough& flythrough, double fps)
    : mRenderer(renderer), mScene(scene), mFlythrough(flythrough), mFps(fps) {
    CHECK(fps > 0.0);
}

FlythroughPlayer::Frame FlythroughPlayer::render(std::uint32_t frame, const FrameSettings& settings,
                                                 const lighting::LightingSettings& lighting) {
    CHECK_MSG(std::int64_t(frame) > mLastFrame, "frame %u after frame %lld", frame,
              static_cast<long long>(mLastFrame));
    mLastFrame = frame;
    Frame out;
    out.index = frame;
    out.time = world::Flythrough::frameTime(frame, mFps);
    out.events = mFlythrough.timeline.applyThrough(frame, mFps, mScene);
    out.camera = mFlythrough.camera.at(out.time, "path");
    FrameSettings s = settings;
    s.timeSeconds = out.time;  // dynamic objects follow the same clock as the camera and events
    mRenderer.setFrameIndex(frame);
    out.result = mRenderer.render(mScene, out.camera, s, lighting);
    return out;
}

}  // namespace engine::render
