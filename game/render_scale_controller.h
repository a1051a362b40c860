// Dynamic render resolution: keeps the frame's GPU time near a target by scaling the render
// resolution (the passes cost about pixels, pixels go with scale^2). It decides once per window
// of frames, on the window's median (a busy machine's spikes do not count), and only on a clear
// miss (over the target, or well under it): every change of size reallocates the frame buffers and
// restarts temporal reuse, so chasing noise would cost more than it saves. Scripts turn it off
// (their frames must repeat exactly).
#pragma once

#include <cstdint>
#include <vector>

namespace game {

class RenderScaleController {
public:
    RenderScaleController(double targetMs, float minScale, float maxScale,
                          std::uint32_t window = 30)
        : mTargetMs(targetMs), mMinScale(minScale), mMaxScale(maxScale), mWindow(window) {}

    // Records a frame rendered at `scale` that took `gpuMs`; returns the scale for the next one.
    float update(float scale, double gpuMs);
    // Start a new window (after the scale was changed by hand).
    void restart() { mMs.clear(); }
    double targetMs() const { return mTargetMs; }
    // The median of the last complete window.
    double lastMedianMs() const { return mLastMedian; }

private:
    double mTargetMs;
    float mMinScale, mMaxScale;
    std::uint32_t mWindow;
    std::vector<double> mMs;
    double mLastMedian = 0.0;
};

}  // namespace game
