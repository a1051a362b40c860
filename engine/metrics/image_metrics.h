// Image error metrics: how far a rendering is from a reference, as the thesis measures it (§3.3)
// and as Bitterli et al. 2020 report it. Images are linear RGB radiance (EXR), row-major; alpha is
// ignored. The reference is always the second argument. Sums run in double so that million-pixel
// images of small errors keep their digits.
//
//   PSE(p1, p2) = sum_c (p1c - p2c)^2                               thesis eq. 1
//   MSE(P1, P2) = 1 / (|P1| * 3) * sum_p PSE(p1, p2)                thesis eq. 2
//   PAE(p1, p2) = sum_c |p1c - p2c|                                 thesis eq. 3
//   MAE(P1, P2) = 1 / (|P1| * 3) * sum_p PAE(p1, p2)                thesis eq. 4
//   RMAE(P, R)  = 1 / (|P| * 3) * sum_p sum_c |pc - rc| / (|rc| + eps),  eps = kRmaeEpsilon
//
// RMAE is relative to the reference only (not symmetric); eps = 0.01 (linear radiance units) keeps
// black reference pixels from dominating, as in the relative MSE of Rousselle et al. 2011. A
// NaN or infinity in either image propagates into the metrics (it is a bug to see, not to hide)
// and is counted in ImageErrors::nonFinitePixels.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "core/error.h"

namespace engine::metrics {

inline constexpr double kRmaeEpsilon = 1.0e-2;

struct ImageView {
    std::span<const glm::vec4> pixels;  // width * height, row-major
    std::uint32_t width = 0;
    std::uint32_t height = 0;
};

struct ImageErrors {
    double mae = 0.0;   // thesis eq. 4
    double mse = 0.0;   // thesis eq. 2
    double rmae = 0.0;  // relative MAE, see above
    std::uint64_t pixels = 0;
    std::uint64_t nonFinitePixels = 0;  // pixels with a NaN or infinite channel in either image
};

// thesis eq. 1
double pixelSquaredError(glm::vec4 a, glm::vec4 b);
// thesis eq. 3
double pixelAbsoluteError(glm::vec4 a, glm::vec4 b);
// The RMAE summand of one pixel: sum_c |ac - bc| / (|bc| + kRmaeEpsilon); b is the reference.
double pixelRelativeError(glm::vec4 a, glm::vec4 reference);

// Fails (with both sizes in the message) unless both images are the same, non-empty size and
// each holds width * height pixels.
Status checkComparable(ImageView image, ImageView reference);

Result<ImageErrors> compareImages(ImageView image, ImageView reference);
Result<double> meanSquaredError(ImageView image, ImageView reference);           // thesis eq. 2
Result<double> meanAbsoluteError(ImageView image, ImageView reference);          // thesis eq. 4
Result<double> relativeMeanAbsoluteError(ImageView image, ImageView reference);  // RMAE

enum class PixelErrorKind { Absolute, Squared, Relative };
// Per-pixel error for heat maps, divided by 3 (the channels) so that the mean over all pixels
// is exactly MAE, MSE or RMAE respectively.
Result<std::vector<float>> perPixelError(ImageView image, ImageView reference, PixelErrorKind kind);

}  // namespace engine::metrics
