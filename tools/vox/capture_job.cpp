#include "capture_job.h"

#include <algorithm>
#include <cstdio>
#include <fmt/format.h>
#include <fstream>
#include <set>
#include <sstream>

#include "commands.h"
#include "core/checksum.h"
#include "core/folder_lock.h"
#include "gpu/context.h"
#include "io/image_io.h"
#include "job_manifest.h"
#include "job_submit.h"
#include "subprocess.h"
#include "tool_gpu.h"

namespace vox {

namespace fs = std::filesystem;
using job::UnitCheck;
using job::UnitState;

namespace {

// An output a record names, on disk: Missing when it is gone, Damaged when its size or checksum
// is not the recorded one.
UnitCheck checkFile(const fs::path& file, const engine::Json& record, const char* sumKey,
                    const char* bytesKey) {
    std::error_code ec;
    if (!fs::exists(file, ec)) return {UnitState::Missing, file.filename().string() + " is gone"};
    if (!fs::is_regular_file(file, ec))
        return {UnitState::Damaged, file.filename().string() + " is not a file"};
    const std::uintmax_t bytes = fs::file_size(file, ec);
    auto sum = engine::fileChecksum(file);
    if (!sum) return {UnitState::Damaged, sum.error().message};
    if (double(bytes) != record.get(bytesKey).number() || *sum != record.get(sumKey).string())
        return {
            UnitState::Damaged,
            fmt::format("{}: {} bytes, {}; recorded {} bytes, {}", file.filename().string(), bytes,
                        *sum, record.get(bytesKey).number(), record.get(sumKey).string())};
    return {UnitState::Done, {}};
}

UnitCheck checkFrameFiles(const fs::path& dir, const engine::Json&, const engine::Json& record) {
    const std::uint32_t frame = std::uint32_t(record.get("frame").number());
    UnitCheck png = checkFile(dir / framePng(frame), record, "png", "png_bytes");
    if (png.state != UnitState::Done || !record.get("exr").isString()) return png;
    return checkFile(dir / frameExr(frame), record, "exr", "exr_bytes");
}

// The same file names the same path in the submitter and in every task.
std::string absolutePath(const fs::path& p) {
    std::error_code ec;
    const fs::path a = fs::weakly_canonical(fs::absolute(p, ec), ec);
    return ec ? p.string() : a.string();
}

std::string checksumOrError(const fs::path& file) {
    auto sum = engine::fileChecksum(file);
    return sum ? *sum : "unreadable: " + sum.error().message;
}

// The command a task runs: this capture's options, with absolute paths so that it runs the same
// from any folder on any host that shares them; `--job-task I` is appended per task.
std::vector<std::string> taskCommandOf(const CaptureOptions& o, const CaptureSetup& setup,
                                       const fs::path& dir) {
    std::vector<std::string> args = {thisExecutable().string(), "capture",
                                     absolutePath(setup.scene.sourcePath)};
    if (!o.path.empty()) args.insert(args.end(), {"--path", absolutePath(setup.pathFile)});
    args.insert(args.end(), {"--out", fs::absolute(dir).string(), "--size", o.size});
    if (o.renderScale != 1.0f)
        args.insert(args.end(), {"--render-scale", fmt::format("{}", o.renderScale)});
    if (o.fps) args.insert(args.end(), {"--fps", fmt::format("{}", *o.fps)});
    args.insert(args.end(),
                {"--frames", fmt::format("{}:{}", setup.first, setup.last), "--warmup",
                 std::to_string(o.warmup), "--exposure", fmt::format("{}", o.exposure)});
    if (o.exr) args.push_back("--exr");
    for (const engine::lighting::KnobValue& v : lightingOverrides(o.lighting))
        args.insert(args.end(), {v.where, v.text});
    return args;
}

}  // namespace

const job::JobKind& captureJobKind() {
    static const job::JobKind kind{"capture", "frame", "frames", checkFrameFiles};
    return kind;
}

engine::Json captureSettings(const CaptureOptions& o, const CaptureSetup& setup) {
    engine::Json s;
    s["world"] = absolutePath(setup.scene.sourcePath);
    s["world_file"] = checksumOrError(setup.scene.sourcePath);
    s["path"] = absolutePath(setup.pathFile);
    s["path_file"] = checksumOrError(setup.pathFile);
    s["size"] = fmt::format("{}x{}", setup.size.x, setup.size.y);
    // Only when set: the settings of jobs submitted before the option stay theirs.
    if (o.renderScale != 1.0f) s["render_scale"] = double(o.renderScale);
    s["fps"] = setup.fps;
    s["frames"] = fmt::format("{}:{}", setup.first, setup.last);
    s["path_frames"] = setup.count;
    s["warmup"] = o.warmup;
    s["exposure"] = double(o.exposure);
    s["exr"] = o.exr;
    std::string lighting;
    for (const engine::lighting::KnobValue& v : lightingOverrides(o.lighting))
        lighting += fmt::format("{}{} {}", lighting.empty() ? "" : " ", v.where, v.text);
    s["lighting"] = lighting;
    return s;
}

int submitCaptureJob(const CaptureOptions& o) {
    if (o.out.empty()) return fail(engine::makeError("--out: give the output folder"));
    auto setup = prepareCapture(o);
    if (!setup) return fail(setup.error());
    const fs::path dir(o.out);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec)
        return fail(engine::makeError("--out {}: cannot create folder: {}", o.out, ec.message()));
    engine::Json manifest = job::newManifest(
        captureJobKind(), captureSettings(o, *setup), setup->first, setup->last, o.job,
        taskCommandOf(o, *setup, dir),
        {thisExecutable().string(), "capture", "--join", fs::absolute(dir).string()});
    engine::Json& outputs = manifest["outputs"];
    outputs["sheet"] = o.sheet;
    outputs["video"] = !o.noVideo;
    // A whole capture's names, or a slice's (docs/CAPTURE.md#outputs).
    const bool whole = setup->first == 0 && setup->last == setup->count - 1;
    outputs["suffix"] = whole ? "" : fmt::format("_{:05}-{:05}", setup->first, setup->last);
    return job::submitJob(dir, manifest, captureJobKind(), o.job);
}

namespace {

// What made a task's frames, for their records.
struct FrameMaker {
    std::uint32_t task;
    std::string settingsHash, device, host;
};

// A rendered frame's record in the manifest, once its file reads back as rendered: what made it
// and the checksums that later tell whether its files are intact.
engine::Status recordFrame(const CapturedFrame& f, const FrameMaker& who, const fs::path& dir,
                           bool exr) {
    // The file must hold what was rendered: read back, decoded and compared.
    const fs::path png = dir / framePng(f.index);
    auto back = engine::io::readPng(png);
    if (!back) return back.error();
    if (back->width != f.images.displayWidth || back->height != f.images.displayHeight ||
        back->rgba8 != f.images.rgba8)
        return engine::makeError("{}: reads back other pixels than were rendered", png.string());
    engine::Json record;
    record["frame"] = f.index;
    record["task"] = who.task;
    record["settings"] = who.settingsHash;
    record["engine"] = job::engineVersion();
    record["device"] = who.device;
    record["host"] = who.host;
    auto pngSum = engine::fileChecksum(png);
    if (!pngSum) return pngSum.error();
    std::error_code ec;
    record["png"] = *pngSum;
    record["png_bytes"] = double(fs::file_size(png, ec));
    if (exr) {
        auto exrSum = engine::fileChecksum(dir / frameExr(f.index));
        if (!exrSum) return exrSum.error();
        record["exr"] = *exrSum;
        record["exr_bytes"] = double(fs::file_size(dir / frameExr(f.index), ec));
    }
    record["seconds"] = f.row.wallMs / 1000.0;
    record["csv"] = captureCsvRowJson(f.row);
    return job::updateManifest(dir, [&](engine::Json& m) -> engine::Status {
        job::setUnitRecord(m, captureJobKind().units, f.index, record);
        return {};
    });
}

}  // namespace

int runCaptureTask(const CaptureOptions& o) {
    const std::uint32_t index = *o.jobTask;
    const fs::path dir(o.out);
    auto manifest = job::readManifest(dir);
    if (!manifest) return fail(manifest.error());
    const std::string file = job::manifestPath(dir).string();
    auto setup = prepareCapture(o);
    if (!setup) return fail(setup.error());
    const engine::Json settings = captureSettings(o, *setup);
    if (engine::checksumOf(settings.dump()) != manifest->get("settings_hash").string())
        return fail(engine::makeError(
            "{}: task {}: its settings differ from the job's (did the world or path file "
            "change since the job was submitted?)",
            file, index));
    if (job::engineVersion() != manifest->get("engine").string())
        return fail(engine::makeError(
            "{}: task {}: this vox is {}, the job's is {}: run the job's build here, or "
            "re-run the submitting command with this one",
            file, index, job::engineVersion(), manifest->get("engine").string()));
    if (index >= manifest->get("tasks").items().size())
        return fail(engine::makeError("{}: no task {}", file, index));
    const job::TaskRange range = job::taskRange(job::taskRecord(*manifest, index));

    std::set<std::uint32_t> todo;
    for (std::uint32_t f = range.first; f <= range.last; ++f)
        if (job::checkUnit(captureJobKind(), dir, *manifest, f).state != UnitState::Done)
            todo.insert(f);
    const std::uint32_t count = range.last - range.first + 1;
    if (todo.empty()) {
        std::printf("task %u   frames %u..%u: all %u done and intact, nothing to render\n", index,
                    range.first, range.last, count);
        return 0;
    }
    // Another run writing the same frames would mix them: each task claims its slice.
    auto lock = engine::FolderLock::acquire(dir, "vox capture", range.first, count);
    if (!lock) return fail(lock.error());
    auto ctx = createValidatedGpu();
    if (!ctx) return fail(ctx.error());
    const auto& dev = (*ctx)->info();
    const std::string device = fmt::format("{} ({})", dev.name, dev.driver);
    const std::uint32_t from = *todo.begin() - std::min(*todo.begin(), o.warmup),
                        to = *todo.rbegin();
    std::printf("task %u   frames %u..%u: rendering %zu of %u (%s), playing %u..%u; %s on %s\n",
                index, range.first, range.last, todo.size(), count,
                job::unitRanges({todo.begin(), todo.end()}).c_str(), from, to, device.c_str(),
                job::hostName().c_str());
    std::fflush(stdout);

    const FrameMaker who{index, manifest->get("settings_hash").string(), device, job::hostName()};
    RenderRequest request{from,
                          to,
                          [&](std::uint32_t f) { return todo.count(f) > 0; },
                          dir,
                          o.exr,
                          o.exposure,
                          fmt::format("task {}", index)};
    auto seconds = renderCapture(
        **ctx, *setup, request,
        [&](const CapturedFrame& f) -> engine::Status { return recordFrame(f, who, dir, o.exr); });
    if (!seconds) return fail(seconds.error());
    std::printf(
        "task %u   rendered %zu frame(s) in %.1f s (%u of its %u frames were done already)\n",
        index, todo.size(), *seconds, count - std::uint32_t(todo.size()), count);
    if ((*ctx)->validationErrors() > 0) {
        std::fprintf(stderr, "vox: %u Vulkan validation error(s)\n", (*ctx)->validationErrors());
        return 1;
    }
    return 0;
}

}  // namespace vox
