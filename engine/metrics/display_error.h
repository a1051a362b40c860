// How far a displayed image is from its converged reference, as `vox bench display` reports it
// (docs/DISPLAY.md). Both images are linear radiance at the display's size. The brightest pixels
// — emitters, sun glints — would dominate any sum, and a tone curve squeezes them anyway, so
// every pixel of both images is first scaled down to the reference's 98th-percentile luminance
// when brighter. Then:
//   relative MAE  = MAE / mean of the clamped reference (thesis eq. 4 over the mean),
//   relative RMSE = sqrt(MSE) / the same mean,
//   SSIM          = metrics/ssim.h on the clamped luminance, data range = the clamp,
//   mean ratio    = mean image / mean reference, unclamped (energy: is the image biased?).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "core/error.h"
#include "metrics/image_metrics.h"

namespace engine::metrics {

struct DisplayErrors {
    double relativeMae = 0.0;
    double relativeRmse = 0.0;
    double ssim = 1.0;
    double meanRatio = 1.0;
};

inline constexpr double kDisplayClampPercentile = 0.98;

Result<DisplayErrors> compareDisplay(ImageView image, ImageView reference);

// The image blown up to width x height by nearest neighbour — what the presenter's blit shows of a
// raw image rendered below the window's size. The size must be a whole multiple or not: each
// target pixel takes the source pixel under its centre.
std::vector<glm::vec4> upscaleNearest(ImageView image, std::uint32_t width, std::uint32_t height);

}  // namespace engine::metrics
