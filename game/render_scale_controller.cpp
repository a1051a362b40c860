#include "game/render_scale_controller.h"

#include <algorithm>
#include <cmath>

namespace game {

float RenderScaleController::update(float scale, double gpuMs) {
    mMs.push_back(gpuMs);
    if (mMs.size() < mWindow) return scale;
    std::nth_element(mMs.begin(), mMs.begin() + mMs.size() / 2, mMs.end());
    double median = mMs[mMs.size() / 2];
    mLastMedian = median;
    restart();
    if (median <= 0.0) return scale;
    double ratio = mTargetMs / median;
    // Down promptly when over budget; up only when well under it, and a little short of the
    // estimate: time is not quite proportional to pixels, and overshooting makes it oscillate.
    if (ratio >= 0.8 && ratio <= 1.6) return scale;
    double step =
        ratio < 0.8 ? std::max(std::sqrt(ratio), 0.5) : std::min(0.9 * std::sqrt(ratio), 1.5);
    return std::clamp(static_cast<float>(scale * step), mMinScale, mMaxScale);
}

}  // namespace game
