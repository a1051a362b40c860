// What vox bench display's rows and its reference share (display_bench.h).
#include "display_bench.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "io/image_io.h"
#include "metrics/display_error.h"

namespace vox {

using engine::lighting::Display;
using engine::lighting::LightingSettings;
using engine::render::FrameSettings;

std::string DisplayRow::label() const {
    const char* name = mode == Display::Raw         ? "raw"
                       : mode == Display::Upsampled ? "upsampled"
                                                    : "denoised";
    return fmt::format("{} {:g}", name, scale);
}

std::vector<DisplayRow> displayRows(const std::vector<double>& scales) {
    std::vector<DisplayRow> rows;
    for (double s : scales)
        for (Display m : {Display::Raw, Display::Upsampled, Display::Denoised})
            rows.push_back({m, s});
    rows.push_back({Display::Raw, 1.0});
    return rows;
}

FrameSettings rowFrame(const DisplayRow& row, glm::uvec2 display) {
    FrameSettings f;
    f.width = std::max(1u, std::uint32_t(std::lround(display.x * row.scale)));
    f.height = std::max(1u, std::uint32_t(std::lround(display.y * row.scale)));
    f.displayWidth = row.mode == Display::Raw ? f.width : display.x;
    f.displayHeight = row.mode == Display::Raw ? f.height : display.y;
    return f;
}

LightingSettings rowLighting(const DisplayRow& row, LightingSettings base) {
    base.display.mode = row.mode;
    return base;
}

std::vector<glm::vec4> shownImage(engine::render::Renderer& renderer, glm::uvec2 display) {
    engine::render::FrameImages images = renderer.readback();
    if (images.displayWidth == display.x && images.displayHeight == display.y)
        return std::move(images.display);
    return engine::metrics::upscaleNearest(
        {images.display, images.displayWidth, images.displayHeight}, display.x, display.y);
}

engine::Status writeViewPng(const std::filesystem::path& path, const std::vector<glm::vec4>& image,
                            glm::uvec2 size, float exposure) {
    auto encode = [&](float c) {
        c *= exposure;
        c = c / (1.0f + c);
        const float s = c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
        return std::uint32_t(std::clamp(s, 0.0f, 1.0f) * 255.0f + 0.5f);
    };
    std::vector<std::uint32_t> rgba(image.size());
    for (std::size_t i = 0; i < image.size(); ++i)
        rgba[i] =
            encode(image[i].x) | encode(image[i].y) << 8 | encode(image[i].z) << 16 | 0xff000000u;
    return engine::io::writePng(path, size.x, size.y, rgba);
}

float viewExposure(const std::vector<glm::vec4>& reference) {
    double sum = 0.0;
    for (const glm::vec4& p : reference) sum += 0.2126 * p.x + 0.7152 * p.y + 0.0722 * p.z;
    const double mean = sum / double(std::max<std::size_t>(reference.size(), 1));
    return float(0.18 / std::max(mean, 1e-6));
}

DisplayReference::DisplayReference(engine::gpu::Context& ctx, const LightingSettings& lighting,
                                   std::uint32_t spp)
    : mRenderer(std::make_unique<engine::render::Renderer>(ctx)), mSpp(spp) {
    mLighting = lighting;
    mLighting.method = engine::lighting::Method::Reference;
    mLighting.referenceFilter = engine::lighting::ReferenceFilter::Box;
    mLighting.display.mode = Display::Raw;
    mLighting.bounces = lighting.indirect == engine::lighting::Indirect::None ? 0
                        : lighting.indirect == engine::lighting::Indirect::Path
                            ? lighting.path.bounces
                            : lighting.cache.bounces;
    mLighting.samplesPerFrame = std::min(spp, 32u);
}

std::vector<glm::vec4> DisplayReference::render(engine::world::Scene& scene,
                                                const engine::world::CameraPreset& camera,
                                                glm::uvec2 display, double timeSeconds) {
    FrameSettings f;
    f.width = f.displayWidth = display.x;
    f.height = f.displayHeight = display.y;
    f.timeSeconds = timeSeconds;
    mRenderer->resetHistory();
    for (std::uint32_t done = 0; done < mSpp; done += mLighting.samplesPerFrame)
        mRenderer->render(scene, camera, f, mLighting);
    return std::move(mRenderer->readback().display);
}

}  // namespace vox
