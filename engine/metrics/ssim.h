// Structural similarity (Wang, Bovik, Sheikh and Simoncelli 2004, "Image Quality Assessment: From
// Error Visibility to Structural Similarity"): local means, variances and covariance under an
// 11x11 Gaussian window (sigma 1.5), C1 = (0.01 L)^2, C2 = (0.03 L)^2 for a data range L, averaged
// over the pixels whose window lies inside the image — the paper's parameters, and what
// scikit-image's structural_similarity computes with gaussian_weights=True,
// use_sample_covariance=False (tests/metrics/ssim_test.cpp holds values it gave).
#pragma once

#include <cstdint>
#include <span>

#include "core/error.h"

namespace engine::metrics {

// One channel (e.g. luminance), width * height values, row-major; 1 means identical. Images
// smaller than the window (11 pixels a side) are an error.
Result<double> ssim(std::span<const float> image, std::span<const float> reference,
                    std::uint32_t width, std::uint32_t height, double dataRange);

}  // namespace engine::metrics
