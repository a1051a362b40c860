#include "metrics/display_error.h"

#include <algorithm>
#include <cmath>

#include "metrics/ssim.h"

namespace engine::metrics {

namespace {

double luminance(glm::vec4 p) { return 0.2126 * p.x + 0.7152 * p.y + 0.0722 * p.z; }

glm::dvec3 clamped(glm::vec4 p, double limit) {
    const double y = luminance(p);
    const glm::dvec3 rgb(p.x, p.y, p.z);
    return y > limit ? rgb * (limit / y) : rgb;
}

}  // namespace

Result<DisplayErrors> compareDisplay(ImageView image, ImageView reference) {
    if (Status s = checkComparable(image, reference); !s) return s.error();
    const std::size_t n = reference.pixels.size();
    std::vector<double> lum(n);
    for (std::size_t i = 0; i < n; ++i) lum[i] = luminance(reference.pixels[i]);
    std::vector<double> sorted = lum;
    const std::size_t k = std::min(n - 1, std::size_t(kDisplayClampPercentile * double(n)));
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(k), sorted.end());
    const double limit = std::max(sorted[k], 1e-12);

    double abs = 0.0, sq = 0.0, refSum = 0.0, rawImage = 0.0, rawRef = 0.0;
    std::vector<float> lumA(n), lumB(n);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 a = clamped(image.pixels[i], limit),
                         b = clamped(reference.pixels[i], limit);
        const glm::dvec3 d = a - b;
        abs += std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
        sq += glm::dot(d, d);
        refSum += b.x + b.y + b.z;
        rawImage += double(image.pixels[i].x) + image.pixels[i].y + image.pixels[i].z;
        rawRef += double(reference.pixels[i].x) + reference.pixels[i].y + reference.pixels[i].z;
        lumA[i] = float(0.2126 * a.x + 0.7152 * a.y + 0.0722 * a.z);
        lumB[i] = float(0.2126 * b.x + 0.7152 * b.y + 0.0722 * b.z);
    }
    const double mean = std::max(refSum / double(3 * n), 1e-12);
    DisplayErrors e;
    e.relativeMae = abs / double(3 * n) / mean;
    e.relativeRmse = std::sqrt(sq / double(3 * n)) / mean;
    e.meanRatio = rawImage / std::max(rawRef, 1e-12);
    auto s = ssim(lumA, lumB, reference.width, reference.height, limit);
    if (!s) return s.error();
    e.ssim = *s;
    return e;
}

std::vector<glm::vec4> upscaleNearest(ImageView image, std::uint32_t width, std::uint32_t height) {
    std::vector<glm::vec4> out(std::size_t(width) * height);
    for (std::uint32_t y = 0; y < height; ++y) {
        const std::uint32_t sy =
            std::min(image.height - 1, std::uint32_t((double(y) + 0.5) * image.height / height));
        for (std::uint32_t x = 0; x < width; ++x) {
            const std::uint32_t sx =
                std::min(image.width - 1, std::uint32_t((double(x) + 0.5) * image.width / width));
            out[std::size_t(y) * width + x] = image.pixels[std::size_t(sy) * image.width + sx];
        }
    }
    return out;
}

}  // namespace engine::metrics
