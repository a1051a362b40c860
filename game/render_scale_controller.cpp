#include "game/render_scale_controller.h"

#include <algorithm>
#include <cmath>

namespace game {

namespace {
// Kept while the median is in [kLow, 1] × the target; a step aims at kAim × the target, a little
// short: the model is not exact and overshooting makes it oscillate.
constexpr double kLow = 0.7;
constexpr double kAim = 0.9;
// Two windows whose pixel counts differ by less than this say little about the fixed part.
constexpr double kMinPixelRatio = 1.2;
}  // namespace

// A frame costs fixed + perPixel * scale^2; the window now and the last one at another scale are
// two equations for the two unknowns. A noisy pair (the larger image not the slower) keeps the
// previous estimate.
void RenderScaleController::fit(const Window& now) {
    if (!mPrevious) return;
    double a = double(now.scale) * now.scale, b = double(mPrevious->scale) * mPrevious->scale;
    if (std::max(a, b) < kMinPixelRatio * std::min(a, b)) return;
    double perPixel = (now.medianMs - mPrevious->medianMs) / (a - b);
    if (perPixel <= 0.0) return;
    mFixedMs = std::clamp(now.medianMs - perPixel * a, 0.0, now.medianMs);
}

float RenderScaleController::update(float scale, double frameMs) {
    mMs.push_back(frameMs);
    if (mMs.size() < mWindow) return scale;
    std::nth_element(mMs.begin(), mMs.begin() + mMs.size() / 2, mMs.end());
    double median = mMs[mMs.size() / 2];
    mLastMedian = median;
    restart();
    if (median <= 0.0) return scale;
    Window now{scale, median};
    fit(now);
    if (median <= mTargetMs && median >= kLow * mTargetMs) return scale;
    // The scaled part now and what it may take: the target less the fixed part.
    double scaled = std::max(median - mFixedMs, 1e-3);
    double allowed = kAim * mTargetMs - mFixedMs;
    double step = allowed <= 0.0 ? 0.0 : std::sqrt(allowed / scaled);
    // Down by at most half and up by at most 1.5x per decision: one bad window cannot swing it.
    step = std::clamp(step, 0.5, 1.5);
    float next = std::clamp(static_cast<float>(scale * step), mMinScale, mMaxScale);
    if (next != scale) mPrevious = now;
    return next;
}

}  // namespace game
