#include "sweep_job.h"

#include <chrono>
#include <cstdio>
#include <fmt/format.h>
#include <set>

#include "commands.h"
#include "core/atomic_file.h"
#include "core/checksum.h"
#include "gpu/context.h"
#include "job_manifest.h"
#include "job_submit.h"
#include "scene/scene_file.h"
#include "subprocess.h"
#include "tool_gpu.h"

namespace vox {

namespace fs = std::filesystem;
using job::UnitState;

namespace {

// The file a world argument names (a scene file, a .vdb or .vox), absolute: what is hashed and
// what the tasks load.
engine::Result<std::string> worldFile(const std::string& world) {
    const std::string ext = fs::path(world).extension().string();
    fs::path file = world;
    if (ext != ".vdb" && ext != ".vox") {
        auto p = engine::scene::resolveWorldPath(world.empty() ? "sandbox" : world);
        if (!p) return p.error();
        file = *p;
    }
    std::error_code ec;
    const fs::path a = fs::weakly_canonical(fs::absolute(file, ec), ec);
    if (ec || !fs::is_regular_file(a, ec))
        return engine::makeError("{}: no such world file", world);
    return a.string();
}

// Every input that changes a point: the worlds (by checksum) and the sweep's options.
engine::Result<engine::Json> sweepSettings(const SweepOptions& o) {
    engine::Json s;
    engine::Json worlds = engine::Json::array(), sums = engine::Json::array();
    for (const std::string& w : o.worlds) {
        auto file = worldFile(w);
        if (!file) return file.error();
        auto sum = engine::fileChecksum(*file);
        if (!sum) return sum.error();
        worlds.push(*file);
        sums.push(*sum);
    }
    s["worlds"] = std::move(worlds);
    s["world_files"] = std::move(sums);
    s["methods"] = o.methods;
    s["candidates"] = o.candidates;
    s["modes"] = o.modes;
    s["brick_lights"] = o.brickLights;
    s["rays"] = o.rays;
    s["size"] = o.size;
    s["frames"] = o.frames;
    s["reference_spp"] = o.referenceSpp;
    s["indirect"] = o.indirect;
    s["indirect_bounces"] = o.indirectBounces;
    s["indirect_reference_spp"] = o.indirectReferenceSpp;
    return s;
}

std::uint32_t pointCount(const SweepOptions& o, const SweepPlan& plan) {
    return plan.pointsPerWorld() * std::uint32_t(o.worlds.size());
}

}  // namespace

const job::JobKind& sweepJobKind() {
    static const job::JobKind kind{"sweep", "point", "points",
                                   nullptr};  // the records are the outputs
    return kind;
}

int submitSweepJob(const SweepOptions& o) {
    auto plan = planSweep(o);
    if (!plan) return fail(plan.error());
    const std::uint32_t total = pointCount(o, *plan);
    if (total == 0) return fail(engine::makeError("bench sweep: no points to measure"));
    auto settings = sweepSettings(o);
    if (!settings) return fail(settings.error());
    const fs::path dir = fs::absolute(o.output);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec)
        return fail(
            engine::makeError("--output {}: cannot create folder: {}", o.output, ec.message()));
    std::vector<std::string> task = {thisExecutable().string(), "bench", "sweep"};
    for (const engine::Json& w : settings->get("worlds").items()) task.push_back(w.string());
    for (const auto& [option, value] : std::vector<std::pair<const char*, std::string>>{
             {"--methods", o.methods},
             {"--candidates", o.candidates},
             {"--modes", o.modes},
             {"--brick-lights", o.brickLights},
             {"--rays", o.rays},
             {"--size", o.size},
             {"--frames", std::to_string(o.frames)},
             {"--seeds", std::to_string(o.seeds)},
             {"--cost-drift", std::to_string(o.costDrift)},
             {"--ref-spp", std::to_string(o.referenceSpp)},
             {"--indirect", o.indirect},
             {"--indirect-bounces", std::to_string(o.indirectBounces)},
             {"--indirect-ref-spp", std::to_string(o.indirectReferenceSpp)},
             {"--output", dir.string()}})
        task.insert(task.end(),
                    {option, value});  // an empty list is an empty word, not a missing value
    engine::Json manifest =
        job::newManifest(sweepJobKind(), *settings, 0, total - 1, o.job, task,
                         {thisExecutable().string(), "bench", "sweep", "--join", dir.string()});
    return job::submitJob(dir, manifest, sweepJobKind(), o.job);
}

int runSweepTask(const SweepOptions& o) {
    const std::uint32_t index = *o.jobTask;
    const fs::path dir(o.output);
    auto manifest = job::readManifest(dir);
    if (!manifest) return fail(manifest.error());
    const std::string file = job::manifestPath(dir).string();
    auto plan = planSweep(o);
    if (!plan) return fail(plan.error());
    auto settings = sweepSettings(o);
    if (!settings) return fail(settings.error());
    if (engine::checksumOf(settings->dump()) != manifest->get("settings_hash").string())
        return fail(engine::makeError(
            "{}: task {}: its settings differ from the job's (did a world file change since "
            "the job was submitted?)",
            file, index));
    if (job::engineVersion() != manifest->get("engine").string())
        return fail(engine::makeError("{}: task {}: this vox is {}, the job's is {}", file, index,
                                      job::engineVersion(), manifest->get("engine").string()));
    if (index >= manifest->get("tasks").items().size())
        return fail(engine::makeError("{}: no task {}", file, index));
    const job::TaskRange range = job::taskRange(job::taskRecord(*manifest, index));
    std::set<std::uint32_t> todo;
    for (std::uint32_t k = range.first; k <= range.last; ++k)
        if (job::checkUnit(sweepJobKind(), dir, *manifest, k).state != UnitState::Done)
            todo.insert(k);
    if (todo.empty()) {
        std::printf("task %u   points %u..%u: all measured, nothing to do\n", index, range.first,
                    range.last);
        return 0;
    }
    auto ctx = createBenchGpu();
    if (!ctx) return fail(ctx.error());
    const std::string device = fmt::format("{} ({})", (*ctx)->info().name, (*ctx)->info().driver);
    std::printf("task %u   points %u..%u: measuring %zu (%s) on %s\n", index, range.first,
                range.last, todo.size(), job::unitRanges({todo.begin(), todo.end()}).c_str(),
                job::hostName().c_str());
    std::fflush(stdout);
    const std::string settingsHash = manifest->get("settings_hash").string();
    auto since = std::chrono::steady_clock::now();
    engine::Status measured = measureSweepPoints(
        **ctx, o, *plan, *todo.begin(), *todo.rbegin(),
        [&](std::uint32_t k) { return todo.count(k) > 0; },
        [&](std::uint32_t k, const std::string& line) -> engine::Status {
            const auto now = std::chrono::steady_clock::now();
            engine::Json record;
            record["point"] = k;
            record["task"] = index;
            record["settings"] = settingsHash;
            record["engine"] = job::engineVersion();
            record["device"] = device;
            record["host"] = job::hostName();
            record["seconds"] = std::chrono::duration<double>(now - since).count();
            record["line"] = line;  // empty: the point does not apply to its world
            since = now;
            return job::updateManifest(dir, [&](engine::Json& m) -> engine::Status {
                job::setUnitRecord(m, sweepJobKind().units, k, record);
                return {};
            });
        });
    if (!measured) return fail(measured.error());
    std::printf("task %u   measured %zu point(s)\n", index, todo.size());
    return 0;
}

int joinSweep(const fs::path& dir) {
    auto m = job::readManifest(dir);
    if (!m) return fail(m.error());
    const job::JobKind& kind = sweepJobKind();
    if (m->get("kind").string() != kind.name)
        return fail(engine::makeError("{}: a {} job, not a sweep", job::manifestPath(dir).string(),
                                      m->get("kind").string()));
    const std::uint32_t first = std::uint32_t(m->get("first").number()),
                        last = std::uint32_t(m->get("last").number());
    std::vector<std::uint32_t> missing, other;
    std::string csv = kSweepCsvHeader;
    for (std::uint32_t k = first; k <= last; ++k) {
        const job::UnitCheck c = job::checkUnit(kind, dir, *m, k);
        if (c.state == UnitState::Missing) missing.push_back(k);
        if (c.state == UnitState::OtherSettings || c.state == UnitState::Damaged)
            other.push_back(k);
        if (c.state == UnitState::Done)
            csv += job::unitRecord(*m, kind.units, k).get("line").string();
    }
    if (!missing.empty() || !other.empty()) {
        std::string list;
        if (!missing.empty())
            list = fmt::format("{} missing ({})", missing.size(), job::unitRanges(missing));
        if (!other.empty())
            list += fmt::format("{}{} measured with other settings ({})", list.empty() ? "" : "; ",
                                other.size(), job::unitRanges(other));
        return fail(engine::makeError(
            "{}: cannot join: points {}; re-run the submitting command to measure them",
            dir.string(), list));
    }
    if (engine::Status s = engine::writeFileAtomically(dir / "sweep.csv", csv); !s)
        return fail(s.error());
    std::printf("wrote    %s (%u points)\n", (dir / "sweep.csv").string().c_str(),
                last - first + 1);
    drawSweepCharts(dir.string());
    engine::Status recorded =
        job::updateManifest(dir, [&](engine::Json& manifest) -> engine::Status {
            engine::Json& joined = manifest["joined"];
            joined = engine::Json::object();
            joined["time"] = job::utcNow();
            joined["host"] = job::hostName();
            joined["csv"] = "sweep.csv";
            return {};
        });
    if (!recorded) return fail(recorded.error());
    return 0;
}

}  // namespace vox
