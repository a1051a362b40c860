#include "metrics/ssim.h"

#include <array>
#include <cmath>
#include <vector>

namespace engine::metrics {

namespace {

constexpr int kRadius = 5;  // 11 taps: sigma 1.5 truncated at 3.5 sigma
constexpr double kSigma = 1.5;

std::array<double, 2 * kRadius + 1> gaussianTaps() {
    std::array<double, 2 * kRadius + 1> taps{};
    double sum = 0.0;
    for (int i = -kRadius; i <= kRadius; ++i) {
        taps[std::size_t(i + kRadius)] = std::exp(-0.5 * i * i / (kSigma * kSigma));
        sum += taps[std::size_t(i + kRadius)];
    }
    for (double& t : taps) t /= sum;
    return taps;
}

// The Gaussian-weighted mean of `values` around every pixel whose window fits, as an image of
// (width - 2r) x (height - 2r): separable, rows first.
std::vector<double> windowMean(const std::vector<double>& values, int width, int height) {
    static const auto taps = gaussianTaps();
    const int innerW = width - 2 * kRadius, innerH = height - 2 * kRadius;
    std::vector<double> rows(std::size_t(innerW) * std::size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < innerW; ++x) {
            double s = 0.0;
            for (int k = 0; k <= 2 * kRadius; ++k)
                s += taps[std::size_t(k)] *
                     values[std::size_t(y) * std::size_t(width) + std::size_t(x + k)];
            rows[std::size_t(y) * std::size_t(innerW) + std::size_t(x)] = s;
        }
    std::vector<double> out(std::size_t(innerW) * std::size_t(innerH));
    for (int y = 0; y < innerH; ++y)
        for (int x = 0; x < innerW; ++x) {
            double s = 0.0;
            for (int k = 0; k <= 2 * kRadius; ++k)
                s += taps[std::size_t(k)] *
                     rows[std::size_t(y + k) * std::size_t(innerW) + std::size_t(x)];
            out[std::size_t(y) * std::size_t(innerW) + std::size_t(x)] = s;
        }
    return out;
}

}  // namespace

Result<double> ssim(std::span<const float> image, std::span<const float> reference,
                    std::uint32_t width, std::uint32_t height, double dataRange) {
    const std::size_t n = std::size_t(width) * std::size_t(height);
    if (image.size() != n || reference.size() != n)
        return makeError("ssim: images of {} and {} values for {}x{}", image.size(),
                         reference.size(), width, height);
    if (width < 2 * kRadius + 1 || height < 2 * kRadius + 1)
        return makeError("ssim: {}x{} is smaller than the {}x{} window", width, height,
                         2 * kRadius + 1, 2 * kRadius + 1);
    if (!(dataRange > 0.0)) return makeError("ssim: data range {} is not positive", dataRange);
    std::vector<double> a(n), b(n), aa(n), bb(n), ab(n);
    for (std::size_t i = 0; i < n; ++i) {
        a[i] = image[i];
        b[i] = reference[i];
        aa[i] = a[i] * a[i];
        bb[i] = b[i] * b[i];
        ab[i] = a[i] * b[i];
    }
    const int w = int(width), h = int(height);
    const auto ma = windowMean(a, w, h), mb = windowMean(b, w, h);
    const auto maa = windowMean(aa, w, h), mbb = windowMean(bb, w, h), mab = windowMean(ab, w, h);
    const double c1 = (0.01 * dataRange) * (0.01 * dataRange);
    const double c2 = (0.03 * dataRange) * (0.03 * dataRange);
    double sum = 0.0;
    for (std::size_t i = 0; i < ma.size(); ++i) {
        const double va = maa[i] - ma[i] * ma[i], vb = mbb[i] - mb[i] * mb[i];
        const double cov = mab[i] - ma[i] * mb[i];
        sum += (2.0 * ma[i] * mb[i] + c1) * (2.0 * cov + c2) /
               ((ma[i] * ma[i] + mb[i] * mb[i] + c1) * (va + vb + c2));
    }
    return sum / double(ma.size());
}

}  // namespace engine::metrics
