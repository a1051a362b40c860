#include "metrics/image_metrics.h"

#include <cmath>

namespace engine::metrics {

namespace {

bool finite(glm::vec4 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

}  // namespace

double pixelSquaredError(glm::vec4 a, glm::vec4 b) {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) {
        double d = double(a[c]) - double(b[c]);
        sum += d * d;
    }
    return sum;
}

double pixelAbsoluteError(glm::vec4 a, glm::vec4 b) {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) sum += std::abs(double(a[c]) - double(b[c]));
    return sum;
}

double pixelRelativeError(glm::vec4 a, glm::vec4 reference) {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c)
        sum += std::abs(double(a[c]) - double(reference[c])) /
               (std::abs(double(reference[c])) + kRmaeEpsilon);
    return sum;
}

Status checkComparable(ImageView image, ImageView reference) {
    for (const ImageView* v : {&image, &reference}) {
        if (v->pixels.size() != std::size_t(v->width) * v->height)
            return makeError("{} holds {} pixels, not {}x{}", v == &image ? "image" : "reference",
                             v->pixels.size(), v->width, v->height);
    }
    if (image.width != reference.width || image.height != reference.height)
        return makeError("image is {}x{} but the reference is {}x{}", image.width, image.height,
                         reference.width, reference.height);
    if (image.pixels.empty()) return makeError("the images are empty (0 pixels)");
    return {};
}

Result<ImageErrors> compareImages(ImageView image, ImageView reference) {
    if (Status s = checkComparable(image, reference); !s) return s.error();
    ImageErrors e;
    e.pixels = image.pixels.size();
    double sumSquared = 0.0, sumAbsolute = 0.0, sumRelative = 0.0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        glm::vec4 a = image.pixels[i], b = reference.pixels[i];
        sumSquared += pixelSquaredError(a, b);
        sumAbsolute += pixelAbsoluteError(a, b);
        sumRelative += pixelRelativeError(a, b);
        e.nonFinitePixels += !(finite(a) && finite(b));
    }
    // thesis eqs. 2 and 4: the sums divided by |P| * 3
    const double n = double(e.pixels) * 3.0;
    e.mse = sumSquared / n;
    e.mae = sumAbsolute / n;
    e.rmae = sumRelative / n;
    return e;
}

Result<double> meanSquaredError(ImageView image, ImageView reference) {
    auto e = compareImages(image, reference);
    if (!e) return e.error();
    return e->mse;
}

Result<double> meanAbsoluteError(ImageView image, ImageView reference) {
    auto e = compareImages(image, reference);
    if (!e) return e.error();
    return e->mae;
}

Result<double> relativeMeanAbsoluteError(ImageView image, ImageView reference) {
    auto e = compareImages(image, reference);
    if (!e) return e.error();
    return e->rmae;
}

Result<std::vector<float>> perPixelError(ImageView image, ImageView reference,
                                         PixelErrorKind kind) {
    if (Status s = checkComparable(image, reference); !s) return s.error();
    std::vector<float> out(image.pixels.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        glm::vec4 a = image.pixels[i], b = reference.pixels[i];
        double v = kind == PixelErrorKind::Absolute  ? pixelAbsoluteError(a, b)
                   : kind == PixelErrorKind::Squared ? pixelSquaredError(a, b)
                                                     : pixelRelativeError(a, b);
        out[i] = static_cast<float>(v / 3.0);
    }
    return out;
}

}  // namespace engine::metrics
