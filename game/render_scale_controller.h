// Dynamic render resolution: keeps the frame's wall time near a target by scaling the render
// resolution while the display stays the window's size. A frame's time is modelled as a fixed
// part (host work, the passes at the window's size: resolve, tonemap, present; the irradiance
// cache's ray budget) plus a part that goes with the render's pixels, scale^2. Two windows at
// different scales give both parts, so one step lands near the target even when the fixed part
// is most of it; until then the whole frame is taken to scale. It decides once per window of
// frames, on the window's median (a busy machine's spikes do not count), and only on a clear
// miss (over the target, or well under it): a change of size restarts the lighting's temporal
// reuse, so chasing noise would cost more than it saves. Scripts turn it off (their frames must
// repeat exactly).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace game {

class RenderScaleController {
public:
    RenderScaleController(double targetMs, float minScale, float maxScale,
                          std::uint32_t window = 30)
        : mTargetMs(targetMs), mMinScale(minScale), mMaxScale(maxScale), mWindow(window) {}

    // Records a frame rendered at `scale` that took `frameMs` (wall time, host work included);
    // returns the scale for the next one.
    float update(float scale, double frameMs);
    // Start a new window (after the scale was changed by hand).
    void restart() { mMs.clear(); }
    double targetMs() const { return mTargetMs; }
    // The median of the last complete window.
    double lastMedianMs() const { return mLastMedian; }
    // The fixed part of a frame as last estimated from two scales (0 until then).
    double fixedMs() const { return mFixedMs; }

private:
    struct Window {
        float scale;
        double medianMs;
    };
    void fit(const Window& now);

    double mTargetMs;
    float mMinScale, mMaxScale;
    std::uint32_t mWindow;
    std::vector<double> mMs;
    double mLastMedian = 0.0;
    std::optional<Window> mPrevious;  // the last window at another scale
    double mFixedMs = 0.0;
};

}  // namespace game
