#include "capture_join.h"

#include <cstdio>
#include <fmt/format.h>
#include <vector>

#include "capture_csv.h"
#include "capture_job.h"
#include "capture_render.h"
#include "capture_sheet.h"
#include "commands.h"
#include "core/atomic_file.h"
#include "ffmpeg_video.h"
#include "io/image_io.h"
#include "job_manifest.h"

namespace vox {

namespace fs = std::filesystem;
using job::UnitState;

namespace {

// "2 missing (40, 41); 1 damaged (12: frame_00012.png: …)": the frames that stop a join.
std::string problems(const std::vector<std::uint32_t>& frames, const std::vector<std::string>& why,
                     const char* what) {
    if (frames.empty()) return {};
    std::string list;
    if (why.empty()) {
        list = job::unitRanges(frames);
    } else {
        for (std::size_t i = 0; i < frames.size() && i < 5; ++i)
            list += fmt::format("{}{}: {}", list.empty() ? "" : "; ", frames[i], why[i]);
        if (frames.size() > 5) list += fmt::format("; and {} more", frames.size() - 5);
    }
    return fmt::format("{} {} ({})", frames.size(), what, list);
}

}  // namespace

int joinCapture(const fs::path& dir) {
    auto m = job::readManifest(dir);
    if (!m) return fail(m.error());
    const job::JobKind& kind = captureJobKind();
    if (m->get("kind").string() != kind.name)
        return fail(engine::makeError("{}: a {} job, not a capture",
                                      job::manifestPath(dir).string(), m->get("kind").string()));
    const std::uint32_t first = std::uint32_t(m->get("first").number()),
                        last = std::uint32_t(m->get("last").number());
    std::vector<std::uint32_t> missing, damaged, other;
    std::vector<std::string> damagedWhy, otherWhy;
    for (std::uint32_t f = first; f <= last; ++f) {
        const job::UnitCheck c = job::checkUnit(kind, dir, *m, f);
        if (c.state == UnitState::Missing) missing.push_back(f);
        if (c.state == UnitState::Damaged) {
            damaged.push_back(f);
            damagedWhy.push_back(c.why);
        }
        if (c.state == UnitState::OtherSettings) {
            other.push_back(f);
            otherWhy.push_back(c.why);
        }
    }
    if (!missing.empty() || !damaged.empty() || !other.empty()) {
        std::string list;
        for (const std::string& p :
             {problems(missing, {}, "missing"), problems(damaged, damagedWhy, "damaged"),
              problems(other, otherWhy, "made with other settings")})
            if (!p.empty()) list += (list.empty() ? "" : "; ") + p;
        return fail(engine::makeError(
            "{}: cannot join: frames {}; re-run the submitting command to render them",
            dir.string(), list));
    }

    const engine::Json& settings = m->get("settings");
    const engine::Json& outputs = m->get("outputs");
    const std::string suffix = outputs.get("suffix").string();
    auto size = parseSize(settings.get("size").string(), "size");
    if (!size) return fail(size.error());
    std::vector<CaptureCsvRow> rows;
    for (std::uint32_t f = first; f <= last; ++f) {
        auto row = captureCsvRowFrom(job::unitRecord(*m, kind.units, f).get("csv"));
        if (!row)
            return fail(engine::makeError("{}: frame {}: {}", job::manifestPath(dir).string(), f,
                                          row.error().message));
        rows.push_back(std::move(*row));
    }
    const fs::path csv = dir / ("capture" + suffix + ".csv");
    if (engine::Status s = engine::writeFileAtomically(csv, captureCsvText(rows)); !s)
        return fail(s.error());
    std::printf("wrote    %s (%zu frames %u..%u)\n", csv.string().c_str(), rows.size(), first,
                last);

    CaptureSheet sheet(first, last, std::uint32_t(outputs.get("sheet").number(24)), *size);
    for (const auto& [frame, slot] : sheet.slots()) {
        auto png = engine::io::readPng(dir / framePng(frame));
        if (!png) return fail(png.error());
        sheet.place(frame, png->rgba8, png->width, png->height);
    }
    if (engine::Status s = sheet.write(dir / ("contact_sheet" + suffix + ".png")); !s)
        return fail(s.error());

    std::string video;
    if (!outputs.get("video").boolean(true)) {
        std::printf("video    skipped (--no-video)\n");
    } else if (auto ffmpeg = findFfmpeg()) {
        const fs::path mp4 = dir / ("capture" + suffix + ".mp4");
        if (engine::Status s = encodeMp4(*ffmpeg, (dir / "frame_%05d.png").string(), first,
                                         last - first + 1, settings.get("fps").number(30), mp4);
            !s)
            return fail(s.error());
        std::printf("wrote    %s\n", mp4.string().c_str());
        video = mp4.filename().string();
    } else {
        std::printf(
            "video    skipped: ffmpeg is not on PATH (install it for an MP4; frames and CSV are "
            "complete)\n");
    }
    engine::Status recorded =
        job::updateManifest(dir, [&](engine::Json& manifest) -> engine::Status {
            engine::Json& joined = manifest["joined"];
            joined = engine::Json::object();
            joined["time"] = job::utcNow();
            joined["host"] = job::hostName();
            joined["csv"] = csv.filename().string();
            joined["video"] = video;
            return {};
        });
    if (!recorded) return fail(recorded.error());
    return 0;
}

}  // namespace vox
