#include "job_submit.h"

#include <cstdio>
#include <fmt/format.h>

#include "commands.h"
#include "core/checksum.h"
#include "job_manifest.h"
#include "subprocess.h"

namespace vox::job {

namespace fs = std::filesystem;

namespace {

engine::Json stringArray(const std::vector<std::string>& items) {
    engine::Json out = engine::Json::array();
    for (const std::string& s : items) out.push(s);
    return out;
}

// "size: 160x90 in the job, 64x36 here; world_file: …": the settings that differ.
std::string settingsDifference(const engine::Json& job, const engine::Json& here) {
    std::string out;
    auto text = [](const engine::Json& v) {
        std::string t = v.dump(0);
        return t.substr(0, t.size() - 1);
    };
    for (const auto& [key, value] : here.members())
        if (!(job.get(key) == value))
            out += fmt::format("{}{}: {} in the job, {} here", out.empty() ? "" : "; ", key,
                               text(job.get(key)), text(value));
    for (const auto& [key, value] : job.members())
        if (!here.find(key))
            out += fmt::format("{}{}: {} in the job, none here", out.empty() ? "" : "; ", key,
                               text(value));
    return out;
}

}  // namespace

engine::Json newManifest(const JobKind& kind, const engine::Json& settings, std::uint32_t first,
                         std::uint32_t last, const JobOptions& options,
                         const std::vector<std::string>& taskCommand,
                         const std::vector<std::string>& joinCommand) {
    engine::Json m;
    m["format"] = kManifestFormat;
    m["kind"] = kind.name;
    m["engine"] = engineVersion();
    m["settings_hash"] = engine::checksumOf(settings.dump());
    m["settings"] = settings;
    m["first"] = first;
    m["last"] = last;
    m["scheduler"] = options.scheduler;
    m["max_attempts"] = options.maxAttempts;
    m["task_command"] = stringArray(taskCommand);
    m["join_command"] = stringArray(joinCommand);
    m["submissions"] = engine::Json::array();
    engine::Json tasks = engine::Json::array();
    for (const TaskRange& r : splitUnits(first, last, options.tasks)) {
        engine::Json t;
        t["index"] = r.index;
        t["first"] = r.first;
        t["last"] = r.last;
        t["state"] = "queued";
        t["attempts"] = 0;
        t["runs"] = engine::Json::array();
        tasks.push(std::move(t));
    }
    m["tasks"] = std::move(tasks);
    m[kind.units] = engine::Json::array();
    return m;
}

int submitJob(const fs::path& dir, const engine::Json& fresh, const JobKind& kind,
              const JobOptions& options) {
    auto scheduler = makeScheduler(options.scheduler);
    if (!scheduler) return fail(scheduler.error());
    std::vector<std::uint32_t> toRun;
    std::vector<std::string> lines;
    bool resumed = false;
    std::uint32_t otherEngine = 0;
    const std::string file = manifestPath(dir).string();
    engine::Status updated = updateManifest(dir, [&](engine::Json& m) -> engine::Status {
        if (m.isNull()) {
            m = fresh;
        } else {
            resumed = true;
            if (m.get("kind").string() != kind.name)
                return engine::makeError(
                    "{}: a {} job is in this folder, not a {} job; use another folder", file,
                    m.get("kind").string(), kind.name);
            if (m.get("settings_hash").string() != fresh.get("settings_hash").string())
                return engine::makeError(
                    "{}: the job in this folder has other settings ({}); use another folder, or "
                    "delete {} to start over",
                    file, settingsDifference(m.get("settings"), fresh.get("settings")), file);
            const std::size_t taskCount = m.get("tasks").items().size();
            if (m.get("first").number() != fresh.get("first").number() ||
                m.get("last").number() != fresh.get("last").number() ||
                taskCount != fresh.get("tasks").items().size())
                return engine::makeError(
                    "{}: the job in this folder is {} {}..{} in {} tasks, this command asks for "
                    "{}..{} in {} tasks; "
                    "give the job's --tasks, or use another folder",
                    file, kind.units, m.get("first").number(), m.get("last").number(), taskCount,
                    fresh.get("first").number(), fresh.get("last").number(),
                    fresh.get("tasks").items().size());
            if (auto previous = makeScheduler(m.get("scheduler").string())) {
                SchedulerView view = (*previous)->view(m);
                if (!view.active.empty())
                    return engine::makeError(
                        "{}: task(s) {} of this job are still pending or running under {}; wait, "
                        "or cancel them, before resuming (--status shows them)",
                        file, unitRanges(view.active), m.get("scheduler").string());
            }
            if (m.get("engine").string() != fresh.get("engine").string()) {
                for (const engine::Json& r : m.get(kind.units).items())
                    otherEngine +=
                        !r.isNull() && r.get("engine").string() != fresh.get("engine").string();
            }
            for (const char* key :
                 {"engine", "scheduler", "max_attempts", "task_command", "join_command", "outputs"})
                if (fresh.find(key)) m[key] = fresh.get(key);
        }
        for (engine::Json& task : m["tasks"].items()) {
            const TaskRange r = taskRange(task);
            std::uint32_t missing = 0, damaged = 0, other = 0;
            for (std::uint32_t u = r.first; u <= r.last; ++u) {
                const UnitCheck c = checkUnit(kind, dir, m, u);
                missing += c.state == UnitState::Missing;
                damaged += c.state == UnitState::Damaged;
                other += c.state == UnitState::OtherSettings;
            }
            const std::uint32_t count = r.last - r.first + 1, redo = missing + damaged + other;
            std::string line =
                fmt::format("task {:<3} {} {}..{}: ", r.index, kind.units, r.first, r.last);
            if (redo == 0) {
                task["state"] = "done";
                line += "complete";
            } else {
                toRun.push_back(r.index);
                task["state"] = "queued";
                task["attempts"] = 0;
                line +=
                    redo == count
                        ? fmt::format("{} to render", count)
                        : fmt::format(
                              "{} of {} to render ({} missing, {} damaged, {} with other settings)",
                              redo, count, missing, damaged, other);
            }
            lines.push_back(line);
        }
        if (!toRun.empty()) m.erase("joined");  // the join is made again after them
        return {};
    });
    if (!updated) return fail(updated.error());
    const engine::Json& f = fresh;
    std::printf("job      %s: %s of %s %g..%g in %zu task(s), %s\n", file.c_str(),
                kind.name.c_str(), kind.units.c_str(), f.get("first").number(),
                f.get("last").number(), f.get("tasks").items().size(), resumed ? "resumed" : "new");
    if (otherEngine > 0)
        std::printf("engine   %u %s made by another build of vox are made again by this one (%s)\n",
                    otherEngine, kind.units.c_str(), engineVersion().c_str());
    for (const std::string& line : lines) std::printf("%s\n", line.c_str());
    if (toRun.empty()) std::printf("all %s are done: joining\n", kind.units.c_str());
    std::fflush(stdout);
    if (engine::Status s = (*scheduler)->run(dir, toRun, options); !s) return fail(s.error());
    return 0;
}

engine::Status recordSubmission(const fs::path& dir, const std::string& scheduler,
                                const std::vector<std::uint32_t>& tasks, const engine::Json& ids) {
    return updateManifest(dir, [&](engine::Json& m) -> engine::Status {
        engine::Json s;
        s["time"] = utcNow();
        s["scheduler"] = scheduler;
        engine::Json list = engine::Json::array();
        for (std::uint32_t t : tasks) list.push(t);
        s["tasks"] = std::move(list);
        for (const auto& [key, value] : ids.members()) s[key] = value;
        m["submissions"].push(std::move(s));
        return {};
    });
}

engine::Status runJoin(const fs::path& dir) {
    auto m = readManifest(dir);
    if (!m) return m.error();
    const std::vector<std::string> command = joinCommand(*m);
    if (command.empty())
        return engine::makeError("{}: no join_command", manifestPath(dir).string());
    std::fflush(stdout);
    auto pid = startProgram(command);
    if (!pid) return pid.error();
    auto exit = waitForProgram(*pid);
    if (!exit) return exit.error();
    if (!exit->ok())
        return engine::makeError("{}: the join ended with {}", dir.string(), describeExit(*exit));
    return {};
}

}  // namespace vox::job
