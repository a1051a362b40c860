#include "capture_render.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fmt/format.h>

#include "commands.h"
#include "core/number_check.h"
#include "core/quoted_string.h"
#include "frame_rays.h"
#include "gpu/context.h"
#include "io/image_io.h"
#include "progress_line.h"
#include "render/flythrough_player.h"
#include "scene/path_file.h"
#include "shared/brick_grid.h"

namespace vox {

namespace {

// "A:B" (inclusive; B may be left out or run past the end) within frames 0..count-1. Each
// number goes through the one number check (core/number_check.h): "-1" is refused as such, not
// read as 4294967295.
engine::Result<std::pair<std::uint32_t, std::uint32_t>> parseRange(const std::string& text,
                                                                   std::uint32_t count) {
    if (text.empty()) return std::pair<std::uint32_t, std::uint32_t>{0, count - 1};
    const std::size_t colon = text.find(':');
    if (colon == std::string::npos)
        return engine::makeError(
            "--frames: expected A:B (first and last frame, inclusive) or A:, got '{}'",
            engine::printableText(text));
    constexpr engine::NumberRange kFrame = engine::wholeRange(0, 1e9, "frames");
    auto a = engine::parseNumber("--frames: the first frame", text.substr(0, colon), kFrame);
    if (!a) return a.error();
    if (*a >= count)
        return engine::makeError("--frames: frame {} is past the path's last frame ({})", *a,
                                 count - 1);
    std::uint32_t last = count - 1;
    if (colon + 1 < text.size()) {
        auto b = engine::parseNumber("--frames: the last frame", text.substr(colon + 1), kFrame);
        if (!b) return b.error();
        if (*b < *a) return engine::makeError("--frames: {}:{} ends before it starts", *a, *b);
        last = std::uint32_t(std::min<double>(*b, count - 1));
    }
    return std::pair<std::uint32_t, std::uint32_t>{std::uint32_t(*a), last};
}

// The CSV row of a frame: counts from the G-buffer and the ray statistics (docs/CAPTURE.md).
CaptureCsvRow csvRow(const engine::render::FlythroughPlayer::Frame& f,
                     const engine::render::FrameImages& images, const CaptureSetup& setup) {
    const engine::lighting::LightingSettings& l = setup.lighting;
    const std::uint64_t primaryRays = std::uint64_t(images.width) * images.height;  // one per pixel
    std::uint64_t surfacePixels = 0, primarySteps = 0, rays = 0, visibleCacheVoxels = 0;
    for (const auto& g : images.gbuffer) {
        surfacePixels += std::uint32_t(g.voxel.w) != shared::FACE_NONE;
        primarySteps += g.data.z;
    }
    // The preview shading counts its rays (primary + sun shadow) on the GPU; the other methods'
    // rays are bounded from their per-pixel counts (rayBound).
    const auto& result = f.result;
    const bool counted = l.method == engine::lighting::Method::Preview;
    if (counted) {
        for (const auto& s : images.rayStats) rays += s.z;
        if (result.cacheUsed) rays += result.cache.raysTraced;
    } else {
        rays = rayBound(l, setup.scene, result, primaryRays, surfacePixels);
    }
    if (result.cacheUsed)
        visibleCacheVoxels = result.cache.visibleStatic + result.cache.visibleDynamic;
    const auto& c = f.camera;
    CaptureCsvRow row;
    auto add = [&](const char* name, std::string value) {
        row.fields.emplace_back(name, std::move(value));
    };
    add("frame", fmt::format("{}", f.index));
    add("time_s", fmt::format("{}", f.time));
    add("events", fmt::format("{}", f.events));
    add("cam_x", fmt::format("{}", c.position.x));
    add("cam_y", fmt::format("{}", c.position.y));
    add("cam_z", fmt::format("{}", c.position.z));
    add("target_x", fmt::format("{}", c.target.x));
    add("target_y", fmt::format("{}", c.target.y));
    add("target_z", fmt::format("{}", c.target.z));
    add("fov_deg", fmt::format("{}", c.fovYDegrees));
    add("emitters", fmt::format("{}", result.emitters));
    add("primary_rays", fmt::format("{}", primaryRays));
    add("surface_pixels", fmt::format("{}", surfacePixels));
    add("primary_steps", fmt::format("{}", primarySteps));
    add("rays", fmt::format("{}", rays));
    add("visible_cache_voxels", fmt::format("{}", visibleCacheVoxels));
    add("rays_how", counted ? "counted" : "bound");
    add("upload_bricks", fmt::format("{}", result.upload.bricks));
    add("upload_cells", fmt::format("{}", result.upload.cells));
    for (const auto& [name, ms] : result.passMs) {
        const bool seen = std::any_of(row.passMs.begin(), row.passMs.end(),
                                      [&](const auto& p) { return p.first == name; });
        if (!seen) row.passMs.emplace_back(name, ms);
    }
    row.gpuTotalMs = result.totalMs();
    row.cpuEmitterUpdateMs = result.emitterUpdateMs;
    return row;
}

}  // namespace

std::string framePng(std::uint32_t frame) { return fmt::format("frame_{:05}.png", frame); }
std::string frameExr(std::uint32_t frame) { return fmt::format("frame_{:05}.exr", frame); }

engine::Result<CaptureSetup> prepareCapture(const CaptureOptions& o) {
    CaptureSetup s;
    auto size = parseSize(o.size, "--size");
    if (!size) return size.error();
    s.size = *size;
    s.renderSize = renderSizeOf(s.size, o.renderScale);
    auto scene = loadWorld(o.world);
    if (!scene) return scene.error();
    s.scene = std::move(*scene);
    auto lighting = lightingSettings(o.lighting, &s.scene);
    if (!lighting) return lighting.error();
    s.lighting = *lighting;
    s.pathFile = s.scene.sourcePath;
    if (!o.path.empty()) {
        auto p = resolvePathFile(o.path);
        if (!p) return p.error();
        s.pathFile = *p;
    }
    auto fly = engine::scene::loadFlythroughFile(s.pathFile);
    if (!fly) return fly.error();
    s.fly = std::move(*fly);
    s.fps = o.fps.value_or(s.fly.fps);
    s.count = s.fly.frameCount(s.fps);
    auto range = parseRange(o.frames, s.count);
    if (!range) return range.error();
    std::tie(s.first, s.last) = *range;
    if (engine::Status st = s.fly.checkFrames(s.fps); !st) return st.error();
    if (engine::Status st = s.fly.timeline.bind(s.scene); !st) return st.error();
    return s;
}

engine::Result<double> renderCapture(
    engine::gpu::Context& ctx, CaptureSetup& setup, const RenderRequest& request,
    const std::function<engine::Status(const CapturedFrame&)>& onFrame) {
    engine::render::Renderer renderer(ctx);
    engine::render::FlythroughPlayer player(renderer, setup.scene, setup.fly, setup.fps);
    engine::render::FrameSettings settings;
    settings.width = setup.renderSize.x;
    settings.height = setup.renderSize.y;
    settings.displayWidth = setup.size.x;
    settings.displayHeight = setup.size.y;
    settings.exposure = request.exposure;
    ProgressLine progress(request.progressLabel, request.to - request.from + 1);
    for (std::uint32_t i = request.from; i <= request.to; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        engine::render::FlythroughPlayer::Frame frame = player.render(i, settings, setup.lighting);
        const bool written = request.written(i);
        if (written) {
            engine::render::FrameImages images = renderer.readback();
            CaptureCsvRow row = csvRow(frame, images, setup);
            engine::Status s = engine::io::writePng(request.dir / framePng(i), images.displayWidth,
                                                    images.displayHeight, images.rgba8);
            if (s && request.exr)
                s = engine::io::writeExr(request.dir / frameExr(i), images.displayWidth,
                                         images.displayHeight, images.display);
            if (!s) return s.error();
            row.wallMs =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                    .count();
            if (engine::Status handed = onFrame({i, images, row}); !handed) return handed.error();
        }
        progress.update(i - request.from + 1,
                        written ? fmt::format("frame {}", i) : fmt::format("warm-up, frame {}", i));
    }
    return progress.finish();
}

}  // namespace vox
