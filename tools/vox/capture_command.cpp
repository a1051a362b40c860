// vox capture: plays a world's flythrough (camera path + timed events) headless and writes every
// frame as PNG (and linear EXR on request), a per-frame CSV of GPU pass timings and counts, a
// contact sheet and, when ffmpeg is on PATH, an MP4. `--frames A:B --warmup W` renders a slice;
// `--scheduler slurm|parallel|local --tasks N` splits the capture into a job of slices, resumed
// by the same command, followed with `--status DIR` and joined by `--join DIR` (capture_job.h,
// docs/CAPTURE.md).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <vector>

#include "capture_csv.h"
#include "capture_job.h"
#include "capture_join.h"
#include "capture_options.h"
#include "capture_render.h"
#include "capture_sheet.h"
#include "commands.h"
#include "core/atomic_file.h"
#include "core/folder_lock.h"
#include "ffmpeg_video.h"
#include "gpu/context.h"
#include "job_status.h"
#include "lighting_options.h"
#include "number_options.h"
#include "render/frame_plan.h"
#include "scene/scene_lighting.h"
#include "tool_gpu.h"

namespace vox {

namespace {

namespace fs = std::filesystem;

// One process renders frames first..last (a whole capture or a slice) and writes every output.
int runCapture(const CaptureOptions& o) {
    if (o.out.empty()) return fail(engine::makeError("--out: give the output folder"));
    if (o.lighting.showSettings) return showSettings(o.world, o.lighting);
    auto setup = prepareCapture(o);
    if (!setup) return fail(setup.error());
    const std::uint32_t first = setup->first, last = setup->last, count = setup->count;
    const std::uint32_t start = first - std::min(first, o.warmup);

    const fs::path dir(o.out);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec)
        return fail(engine::makeError("--out {}: cannot create folder: {}", o.out, ec.message()));
    const bool whole = first == 0 && last == count - 1;
    const std::string suffix = whole ? "" : fmt::format("_{:05}-{:05}", first, last);
    // Two runs writing the same frames into one folder would mix them (and the MP4 of one would
    // hold the other's frames): each run claims its frames; slices with disjoint frames share it.
    auto lock =
        engine::FolderLock::acquire(dir, "vox capture", first, std::uint64_t(last) - first + 1);
    if (!lock) return fail(lock.error());

    auto ctx = createValidatedGpu();
    if (!ctx) return fail(ctx.error());
    printDevice(**ctx);
    std::printf("world    %s (%s)\n", setup->scene.name.c_str(), setup->scene.sourcePath.c_str());
    std::printf("path     %s: %u frames at %g fps (%.2f s), %zu keys, %zu events\n",
                setup->pathFile.string().c_str(), count, setup->fps, setup->fly.duration,
                setup->fly.camera.keys().size(), setup->fly.timeline.events().size());
    std::printf("frames   %u..%u of 0..%u, after %u warm-up frame(s); %ux%u", first, last,
                count - 1, first - start, setup->size.x, setup->size.y);
    if (setup->renderSize != setup->size)
        std::printf(", lit at %ux%u (--render-scale %g)", setup->renderSize.x, setup->renderSize.y,
                    o.renderScale);
    std::printf("\n");
    std::printf("lighting %s\n", engine::render::describeLighting(setup->lighting).c_str());
    std::fflush(stdout);  // before the progress line on stderr

    const std::uint32_t written = last - first + 1;
    CaptureSheet sheet(first, last, o.sheet, setup->size);
    std::vector<CaptureCsvRow> rows;
    RenderRequest request{start, last,  [first](std::uint32_t i) { return i >= first; },
                          dir,   o.exr, o.exposure};
    auto seconds =
        renderCapture(**ctx, *setup, request, [&](const CapturedFrame& f) -> engine::Status {
            sheet.place(f.index, f.images.rgba8, f.images.displayWidth, f.images.displayHeight);
            rows.push_back(f.row);
            return {};
        });
    if (!seconds) return fail(seconds.error());

    const fs::path csv = dir / ("capture" + suffix + ".csv");
    if (engine::Status s = engine::writeFileAtomically(csv, captureCsvText(rows)); !s)
        return fail(s.error());
    std::printf("wrote    %u frames %s..%s%s in %s\n", written, framePng(first).c_str(),
                framePng(last).c_str(), o.exr ? " (+ linear EXR)" : "", dir.string().c_str());
    std::printf("wrote    %s\n", csv.string().c_str());
    if (engine::Status s = sheet.write(dir / ("contact_sheet" + suffix + ".png")); !s)
        return fail(s.error());
    if (o.noVideo) {
        std::printf("video    skipped (--no-video)\n");
    } else if (auto ffmpeg = findFfmpeg()) {
        const fs::path mp4 = dir / ("capture" + suffix + ".mp4");
        if (engine::Status s = encodeMp4(*ffmpeg, (dir / "frame_%05d.png").string(), first, written,
                                         setup->fps, mp4);
            !s)
            return fail(s.error());
        std::printf("wrote    %s\n", mp4.string().c_str());
    } else {
        std::printf(
            "video    skipped: ffmpeg is not on PATH (install it for an MP4; frames and CSV are "
            "complete)\n");
    }
    std::printf("time     %.1f s for %u rendered frames (%.0f ms/frame wall, %u warm-up)\n",
                *seconds, last - start + 1, 1000.0 * *seconds / (last - start + 1), first - start);
    if ((*ctx)->validationErrors() > 0) {
        std::fprintf(stderr, "vox: %u Vulkan validation error(s)\n", (*ctx)->validationErrors());
        return 1;
    }
    return 0;
}

int runCaptureCommand(const CaptureOptions& o) {
    if (!o.status.empty()) return job::printJobStatus(o.status);
    if (!o.join.empty()) return joinCapture(o.join);
    if (o.jobTask) {
        if (o.out.empty())
            return fail(engine::makeError("--job-task: give the job's folder with --out"));
        return runCaptureTask(o);
    }
    if (!o.job.scheduler.empty()) return submitCaptureJob(o);
    return runCapture(o);
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
    cmd->add_option("--out", o->out, "Output folder");
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
    addRenderScaleOption(*cmd, o->renderScale);
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
    job::addJobOptions(*cmd, o->job);
    cmd->add_option("--join", o->join,
                    "Join the job in DIR: one CSV, contact sheet and MP4; refuses while frames are "
                    "missing or damaged")
        ->type_name("DIR");
    cmd->add_option("--status", o->status,
                    "Where the job in DIR stands: frames per task, states, failures, ETA")
        ->type_name("DIR");
    // What a scheduler runs for task I (through `vox job run`), not for people: hidden.
    cmd->add_option("--job-task", o->jobTask, "Render task I of the job in --out")->group("");
    cmd->callback([o, &exitCode] { exitCode = runCaptureCommand(*o); });
}

}  // namespace vox
