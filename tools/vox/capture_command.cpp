// vox capture: plays a world's flythrough (camera path + timed events) headless and writes every
// frame as PNG (and linear EXR on request), a per-frame CSV of GPU pass timings and counts, a
// contact sheet and, when ffmpeg is on PATH, an MP4. `--frames A:B --warmup W` renders a slice
// so a long capture can be split across machines (docs/CAPTURE.md).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <vector>

#include "commands.h"
#include "core/atomic_file.h"
#include "core/folder_lock.h"
#include "core/quoted_string.h"
#include "number_options.h"
#include "ffmpeg_video.h"
#include "frame_rays.h"
#include "gpu/context.h"
#include "io/contact_sheet.h"
#include "io/image_io.h"
#include "lighting_options.h"
#include "progress_line.h"
#include "render/flythrough_player.h"
#include "shared/brick_grid.h"
#include "scene/path_file.h"

namespace vox {

namespace {

namespace fs = std::filesystem;

struct CaptureOptions {
    std::string world;
    std::string path;
    std::string out;
    std::string size = "320x180";
    std::optional<double> fps;  // absent: the path file's
    std::string frames;
    std::uint32_t warmup = 30;
    bool exr = false;
    bool noVideo = false;
    std::uint32_t sheet = 24;
    float exposure = 1.0f;
    LightingOptions lighting;
};

// What one written frame contributes to the CSV.
struct FrameRow {
    engine::render::FlythroughPlayer::Frame frame;
    std::uint64_t primaryRays = 0, surfacePixels = 0, primarySteps = 0;
    std::uint64_t rays = 0;
    bool raysCounted = false;  // counted on the GPU (preview), else the per-pixel bound below
    std::uint64_t visibleCacheVoxels = 0;
    double wallMs = 0.0;
};

// "A:B" (inclusive; B may be left out or run past the end) within frames 0..count-1. Each
// number goes through the one number check (core/number_check.h): "-1" is refused as such, not
// read as 4294967295.
engine::Result<std::pair<std::uint32_t, std::uint32_t>> parseRange(const std::string& text,
                                                                   std::uint32_t count) {
    if (text.empty()) return std::pair<std::uint32_t, std::uint32_t>{0, count - 1};
    const std::size_t colon = text.find(':');
    if (colon == std::string::npos)
        return engine::makeError("--frames: expected A:B (first and last frame, inclusive) or A:, got '{}'",
                                 engine::printableText(text));
    constexpr engine::NumberRange kFrame = engine::wholeRange(0, 1e9, "frames");
    auto a = engine::parseNumber("--frames: the first frame", text.substr(0, colon), kFrame);
    if (!a) return a.error();
    if (*a >= count) return engine::makeError("--frames: frame {} is past the path's last frame ({})", *a, count - 1);
    std::uint32_t last = count - 1;
    if (colon + 1 < text.size()) {
        auto b = engine::parseNumber("--frames: the last frame", text.substr(colon + 1), kFrame);
        if (!b) return b.error();
        if (*b < *a) return engine::makeError("--frames: {}:{} ends before it starts", *a, *b);
        last = std::uint32_t(std::min<double>(*b, count - 1));
    }
    return std::pair<std::uint32_t, std::uint32_t>{std::uint32_t(*a), last};
}

std::string framePng(std::uint32_t i) { return fmt::format("frame_{:05}.png", i); }
std::string frameExr(std::uint32_t i) { return fmt::format("frame_{:05}.exr", i); }

// Columns ending in _ms are timings (they vary from run to run); every other column is a pure
// function of the inputs. Pass columns are the union over frames in first-seen order (ReSTIR's
// temporal pass, for one, does not run on the first frame).
engine::Status writeCsv(const fs::path& file, const std::vector<FrameRow>& rows) {
    std::vector<std::string> passes;
    for (const FrameRow& r : rows)
        for (const auto& [name, ms] : r.frame.result.passMs)
            if (std::find(passes.begin(), passes.end(), name) == passes.end())
                passes.push_back(name);
    std::ostringstream csv;
    csv << "frame,time_s,events,cam_x,cam_y,cam_z,target_x,target_y,target_z,fov_deg,emitters,"
           "primary_rays,"
           "surface_pixels,primary_steps,rays,visible_cache_voxels,rays_how,upload_bricks,upload_cells";
    for (const std::string& p : passes) csv << ",gpu_" << p << "_ms";
    csv << ",gpu_total_ms,cpu_emitter_update_ms,wall_ms\n";
    for (const FrameRow& r : rows) {
        const auto& f = r.frame;
        const auto& c = f.camera;
        csv << fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}", f.index,
                           f.time, f.events, c.position.x, c.position.y, c.position.z, c.target.x,
                           c.target.y, c.target.z, c.fovYDegrees, f.result.emitters, r.primaryRays,
                           r.surfacePixels, r.primarySteps, r.rays, r.visibleCacheVoxels,
                           r.raysCounted ? "counted" : "bound", f.result.upload.bricks,
                           f.result.upload.cells);
        for (const std::string& p : passes) {
            bool ran = false;
            for (const auto& [name, ms] : f.result.passMs) ran |= name == p;
            csv << ",";
            if (ran) csv << fmt::format("{:.4f}", f.result.passMsOf(p));
        }
        csv << fmt::format(",{:.4f},{:.4f},{:.2f}\n", f.result.totalMs(), f.result.emitterUpdateMs,
                           r.wallMs);
    }
    std::string text = csv.str();
    return engine::writeFileAtomically(file, text);
}

int runCapture(const CaptureOptions& o) {
    auto size = parseSize(o.size, "--size");
    if (!size) return fail(size.error());
    if (o.out.empty()) return fail(engine::makeError("--out: give the output folder"));

    if (o.lighting.showSettings) return showSettings(o.world, o.lighting);
    auto scene = loadWorld(o.world);
    if (!scene) return fail(scene.error());
    auto lighting = lightingSettings(o.lighting, &*scene);
    if (!lighting) return fail(lighting.error());
    fs::path pathFile = scene->sourcePath;
    if (!o.path.empty()) {
        auto p = resolvePathFile(o.path);
        if (!p) return fail(p.error());
        pathFile = *p;
    }
    auto fly = engine::scene::loadFlythroughFile(pathFile);
    if (!fly) return fail(fly.error());
    const double fps = o.fps.value_or(fly->fps);
    const std::uint32_t count = fly->frameCount(fps);
    auto range = parseRange(o.frames, count);
    if (!range) return fail(range.error());
    const auto [first, last] = *range;
    const std::uint32_t start = first - std::min(first, o.warmup);
    if (engine::Status s = fly->checkFrames(fps); !s) return fail(s.error());
    if (engine::Status s = fly->timeline.bind(*scene); !s) return fail(s.error());

    const fs::path dir(o.out);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec)
        return fail(engine::makeError("--out {}: cannot create folder: {}", o.out, ec.message()));
    const bool whole = first == 0 && last == count - 1;
    const std::string suffix = whole ? "" : fmt::format("_{:05}-{:05}", first, last);
    // Two runs writing the same frames into one folder would mix them (and the MP4 of one would
    // hold the other's frames): each run claims its frames; slices with disjoint frames share it.
    auto lock = engine::FolderLock::acquire(dir, "vox capture", first, std::uint64_t(last) - first + 1);
    if (!lock) return fail(lock.error());

    engine::gpu::ContextOptions ctxOptions;
#ifndef NDEBUG
    ctxOptions.validation = true;
#endif
    auto ctx = engine::gpu::Context::create(ctxOptions);
    if (!ctx) return fail(ctx.error());
    const auto& dev = (*ctx)->info();
    const engine::lighting::LightingSettings l = *lighting;
    std::printf("device   %s (%s, %s)\n", dev.name.c_str(), dev.type.c_str(), dev.driver.c_str());
    std::printf("world    %s (%s)\n", scene->name.c_str(), scene->sourcePath.c_str());
    std::printf("path     %s: %u frames at %g fps (%.2f s), %zu keys, %zu events\n",
                pathFile.string().c_str(), count, fps, fly->duration, fly->camera.keys().size(),
                fly->timeline.events().size());
    std::printf("frames   %u..%u of 0..%u, after %u warm-up frame(s); %ux%u\n", first, last,
                count - 1, first - start, (*size).x, (*size).y);
    std::printf("lighting %s\n", l.describe().c_str());
    std::fflush(stdout);  // before the progress line on stderr

    // Thumbnails: `sheet` frames spread evenly over the written ones, first and last included.
    const std::uint32_t written = last - first + 1;
    const std::uint32_t thumbs = std::min(o.sheet, written);
    std::map<std::uint32_t, std::uint32_t> thumbSlot;  // frame -> slot
    for (std::uint32_t s = 0; s < thumbs; ++s)
        thumbSlot[first + (thumbs > 1 ? std::uint32_t(
                                            std::llround(double(s) * (written - 1) / (thumbs - 1)))
                                      : 0)] = s;
    const std::uint32_t thumbWidth = std::min<std::uint32_t>((*size).x, 160);
    const std::uint32_t thumbHeight =
        std::max<std::uint32_t>(1, (*size).y * thumbWidth / (*size).x);
    std::optional<engine::io::ContactSheet> sheet;
    if (thumbs > 0) sheet.emplace(thumbs, 6, thumbWidth, thumbHeight);

    engine::render::Renderer renderer(**ctx);
    engine::render::FlythroughPlayer player(renderer, *scene, *fly, fps);
    engine::render::FrameSettings settings;
    settings.width = (*size).x;
    settings.height = (*size).y;
    settings.exposure = o.exposure;

    std::vector<FrameRow> rows;
    ProgressLine progress("capture", last - start + 1);
    for (std::uint32_t i = start; i <= last; ++i) {
        auto t0 = std::chrono::steady_clock::now();
        FrameRow row;
        row.frame = player.render(i, settings, l);
        if (i >= first) {
            engine::render::FrameImages images = renderer.readback();
            row.primaryRays = std::uint64_t(images.width) * images.height;  // one per pixel
            for (const auto& g : images.gbuffer) {
                row.surfacePixels += std::uint32_t(g.voxel.w) != shared::FACE_NONE;
                row.primarySteps += g.data.z;
            }
            // The preview shading counts its rays (primary + sun shadow) on the GPU; the other
            // methods' rays are bounded from their per-pixel counts (rayBound).
            const auto& result = row.frame.result;
            if (l.method == engine::lighting::Method::Preview) {
                for (const auto& s : images.rayStats) row.rays += s.z;
                if (result.cacheUsed) row.rays += result.cache.raysTraced;
                row.raysCounted = true;
            } else {
                row.rays = rayBound(l, *scene, result, row.primaryRays, row.surfacePixels);
            }
            if (result.cacheUsed)
                row.visibleCacheVoxels = result.cache.visibleStatic + result.cache.visibleDynamic;
            engine::Status s =
                engine::io::writePng(dir / framePng(i), images.width, images.height, images.rgba8);
            if (s && o.exr)
                s = engine::io::writeExr(dir / frameExr(i), images.width, images.height,
                                         images.radiance);
            if (!s) return fail(s.error());
            if (auto it = thumbSlot.find(i); it != thumbSlot.end())
                sheet->place(it->second, images.rgba8, images.width, images.height);
            row.wallMs =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                    .count();
            rows.push_back(std::move(row));
        }
        progress.update(i - start + 1, i < first ? fmt::format("warm-up, frame {}", i)
                                                 : fmt::format("frame {}", i));
    }
    const double seconds = progress.finish();

    const fs::path csv = dir / ("capture" + suffix + ".csv");
    if (engine::Status s = writeCsv(csv, rows); !s) return fail(s.error());
    std::printf("wrote    %u frames %s..%s%s in %s\n", written, framePng(first).c_str(),
                framePng(last).c_str(), o.exr ? " (+ linear EXR)" : "", dir.string().c_str());
    std::printf("wrote    %s\n", csv.string().c_str());
    if (sheet) {
        const fs::path sheetFile = dir / ("contact_sheet" + suffix + ".png");
        if (engine::Status s =
                engine::io::writePng(sheetFile, sheet->width(), sheet->height(), sheet->pixels());
            !s)
            return fail(s.error());
        std::string frames;
        for (const auto& [frame, slot] : thumbSlot)
            frames += (frames.empty() ? "" : " ") + std::to_string(frame);
        std::printf("wrote    %s (%u thumbnails, frames %s)\n", sheetFile.string().c_str(), thumbs,
                    frames.c_str());
    }
    if (o.noVideo) {
        std::printf("video    skipped (--no-video)\n");
    } else if (auto ffmpeg = findFfmpeg()) {
        const fs::path mp4 = dir / ("capture" + suffix + ".mp4");
        if (engine::Status s =
                encodeMp4(*ffmpeg, (dir / "frame_%05d.png").string(), first, written, fps, mp4);
            !s)
            return fail(s.error());
        std::printf("wrote    %s\n", mp4.string().c_str());
    } else {
        std::printf(
            "video    skipped: ffmpeg is not on PATH (install it for an MP4; frames and CSV are "
            "complete)\n");
    }
    std::printf("time     %.1f s for %u rendered frames (%.0f ms/frame wall, %u warm-up)\n",
                seconds, last - start + 1, 1000.0 * seconds / (last - start + 1), first - start);
    if ((*ctx)->validationErrors() > 0) {
        std::fprintf(stderr, "vox: %u Vulkan validation error(s)\n", (*ctx)->validationErrors());
        return 1;
    }
    return 0;
}

}  // namespace

void addCaptureCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand(
        "capture", "Render a world's flythrough headless: PNG frames, CSV, contact sheet, MP4");
    auto o = std::make_shared<CaptureOptions>();
    cmd->add_option("world", o->world,
                    "World name (worlds/NAME.toml) or scene file; default: sandbox");
    cmd->add_option("--path", o->path,
                    "Path file or name in worlds/paths/ (default: the world's own [path])");
    cmd->add_option("--out", o->out, "Output folder")->required();
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("--fps", o->fps, "Frames per second (default: the path's fps, else 30)")
        ->check(numberIn(engine::world::kFpsRange));
    cmd->add_option("--frames", o->frames,
                    "Only frames A..B (inclusive; A: = to the end), e.g. 40:79");
    cmd->add_option("--warmup", o->warmup, "Frames of history rendered, not written, before A")
        ->capture_default_str()
        ->check(numberIn(kWarmupRange));
    cmd->add_flag("--exr", o->exr, "Also write linear radiance as frame_NNNNN.exr");
    cmd->add_flag("--no-video", o->noVideo, "Do not encode an MP4 even when ffmpeg is present");
    cmd->add_option("--sheet", o->sheet, "Thumbnails on the contact sheet (0 = none)")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(0, 1000, "thumbnails")));
    cmd->add_option("--exposure", o->exposure, "Exposure multiplier before tonemapping")
        ->capture_default_str()
        ->check(numberIn(kExposureRange));
    addLightingOptions(*cmd, o->lighting);
    cmd->callback([o, &exitCode] { exitCode = runCapture(*o); });
}

}  // namespace vox
