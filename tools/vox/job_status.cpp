#include "job_status.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <fmt/format.h>
#include <map>
#include <signal.h>

#include "commands.h"
#include "job_kind.h"
#include "job_manifest.h"
#include "progress_line.h"

namespace vox::job {

namespace fs = std::filesystem;

namespace {

// The task's latest run, or null.
const engine::Json& lastRun(const engine::Json& task) {
    static const engine::Json kNone;
    const auto& runs = task.get("runs").items();
    return runs.empty() ? kNone : runs.back();
}

enum class Liveness { Alive, Gone, Unknown };

// A run's process, when it runs on this host.
Liveness liveness(const engine::Json& run) {
    if (run.get("host").string() != hostName() || !run.get("pid").isNumber())
        return Liveness::Unknown;
    const pid_t pid = pid_t(run.get("pid").number());
    return kill(pid, 0) == 0 || errno == EPERM ? Liveness::Alive : Liveness::Gone;
}

}  // namespace

SchedulerView processView(const engine::Json& manifest) {
    SchedulerView v;
    for (const engine::Json& task : manifest.get("tasks").items()) {
        if (task.get("state").string() != "running") continue;
        const std::uint32_t index = std::uint32_t(task.get("index").number());
        const engine::Json& run = lastRun(task);
        const long pid = long(run.get("pid").number());
        switch (liveness(run)) {
            case Liveness::Alive:
                v.tasks[index] = fmt::format("process {} alive", pid);
                v.active.push_back(index);
                v.running.push_back(index);
                break;
            case Liveness::Gone:
                v.tasks[index] = fmt::format("process {} is gone", pid);
                break;
            case Liveness::Unknown:
                v.tasks[index] = fmt::format("process {} on {}, not checked from here", pid,
                                             run.get("host").string());
                break;
        }
    }
    return v;
}

namespace {

// What the units of all tasks add up to.
struct UnitTotals {
    std::uint32_t done = 0, missing = 0, damaged = 0, other = 0, running = 0;
    std::vector<std::uint32_t> missingUnits;
    std::vector<std::string> attention;  // a line per damaged unit or one of other settings
    double seconds = 0.0;                // the timed units' wall time in their tasks
    std::uint32_t timed = 0;
    std::map<std::string, std::vector<std::string>> failures;  // host -> runs
};

// The units of one task, checked on disk: its counts, added to the totals.
struct TaskUnits {
    std::uint32_t done = 0, missing = 0, damaged = 0, other = 0;
};
TaskUnits checkTaskUnits(const JobKind& kind, const fs::path& dir, const engine::Json& m,
                         const TaskRange& r, UnitTotals& totals) {
    TaskUnits t;
    for (std::uint32_t u = r.first; u <= r.last; ++u) {
        const UnitCheck c = checkUnit(kind, dir, m, u);
        switch (c.state) {
            case UnitState::Done: {
                ++t.done;
                const engine::Json& record = unitRecord(m, kind.units, u);
                if (record.get("seconds").isNumber()) {
                    totals.seconds += record.get("seconds").number();
                    ++totals.timed;
                }
                break;
            }
            case UnitState::Missing:
                ++t.missing;
                totals.missingUnits.push_back(u);
                break;
            case UnitState::Damaged:
                ++t.damaged;
                totals.attention.push_back(fmt::format("{} {}: damaged: {}", kind.unit, u, c.why));
                break;
            case UnitState::OtherSettings:
                ++t.other;
                totals.attention.push_back(
                    fmt::format("{} {}: other settings: {}", kind.unit, u, c.why));
                break;
        }
    }
    totals.done += t.done;
    totals.missing += t.missing;
    totals.damaged += t.damaged;
    totals.other += t.other;
    return t;
}

// A task's state: by the manifest (its process alive, where that can be seen), or by the
// scheduler (a task that has not recorded its start yet). Counts it in `totals.running`.
std::string taskState(const engine::Json& task, std::uint32_t index, const SchedulerView& view,
                      UnitTotals& totals) {
    std::string state = task.get("state").string();
    const engine::Json& run = lastRun(task);
    bool isRunning =
        std::find(view.running.begin(), view.running.end(), index) != view.running.end();
    if (state == "running") {
        if (liveness(run) == Liveness::Gone) {
            state = fmt::format("lost (process {} on {} is gone)", long(run.get("pid").number()),
                                run.get("host").string());
        } else {
            state += " on " + run.get("host").string();
            isRunning = true;
        }
    }
    totals.running += isRunning;
    if (auto it = view.tasks.find(index); it != view.tasks.end()) state += " · " + it->second;
    return state;
}

// The task's runs that did not end well, by host.
void addFailures(const engine::Json& task, std::uint32_t index, UnitTotals& totals) {
    for (const engine::Json& each : task.get("runs").items()) {
        const std::string result = each.get("result").string();
        if (!result.empty() && result != "exit 0" && result.rfind("stopped", 0) != 0)
            totals.failures[each.get("host").string()].push_back(
                fmt::format("task {} attempt {}: {} at {}", index, each.get("attempt").number(),
                            result, each.get("ended").string()));
    }
}

// The lines after the tasks: totals, time and ETA, failures, the join and the problems.
void printTotals(const JobKind& kind, const engine::Json& m, const SchedulerView& view,
                 const UnitTotals& t) {
    const std::uint32_t total = std::uint32_t(m.get("last").number() - m.get("first").number()) + 1;
    std::printf("total    %u of %u %s done, %u missing, %u damaged, %u with other settings\n",
                t.done, total, kind.units.c_str(), t.missing, t.damaged, t.other);
    const std::uint32_t remaining = total - t.done;
    if (t.timed == 0) {
        std::printf("time     no %s done yet: ETA unknown\n", kind.unit.c_str());
    } else {
        const double mean = t.seconds / t.timed;
        std::string eta =
            remaining == 0   ? "nothing left"
            : t.running == 0 ? "no task is running"
                             : fmt::format("ETA {} with {} task(s) running",
                                           formatDuration(mean * remaining / t.running), t.running);
        std::printf("time     %.3f s a %s (mean of %u, wall time in the task); %s\n", mean,
                    kind.unit.c_str(), t.timed, eta.c_str());
    }
    for (const auto& [host, runs] : t.failures) {
        std::string list;
        for (const std::string& r : runs) list += (list.empty() ? "" : "; ") + r;
        std::printf("failures %s: %zu (%s)\n", host.c_str(), runs.size(), list.c_str());
    }
    std::string join = m.get("joined").isObject() ? "joined " + m.get("joined").get("time").string()
                                                  : "not joined";
    if (!view.join.empty()) join += " · " + view.join;
    std::printf("join     %s\n", join.c_str());
    if (!t.missingUnits.empty())
        std::printf("missing  %s %s\n", kind.units.c_str(), unitRanges(t.missingUnits).c_str());
    for (std::size_t i = 0; i < t.attention.size() && i < 10; ++i)
        std::printf("problem  %s\n", t.attention[i].c_str());
    if (t.attention.size() > 10) std::printf("problem  … and %zu more\n", t.attention.size() - 10);
}

}  // namespace

int printJobStatus(const fs::path& dir) {
    auto m = readManifest(dir);
    if (!m) return fail(m.error());
    const JobKind* kind = findJobKind(m->get("kind").string());
    if (!kind)
        return fail(engine::makeError("{}: unknown kind of job '{}'", manifestPath(dir).string(),
                                      m->get("kind").string()));
    SchedulerView view;
    if (auto scheduler = makeScheduler(m->get("scheduler").string())) view = (*scheduler)->view(*m);
    const auto& tasks = m->get("tasks").items();
    const auto& submissions = m->get("submissions").items();
    std::printf(
        "job      %s: %s of %s %g..%g in %zu task(s), %s; submitted %zu time(s)%s\n",
        fs::absolute(dir).string().c_str(), kind->name.c_str(), kind->units.c_str(),
        m->get("first").number(), m->get("last").number(), tasks.size(),
        m->get("scheduler").string().c_str(), submissions.size(),
        submissions.empty() ? "" : (", last " + submissions.back().get("time").string()).c_str());
    std::printf("engine   %s\nsettings %s\n", m->get("engine").string().c_str(),
                m->get("settings_hash").string().c_str());
    if (!view.error.empty())
        std::printf("note     the scheduler could not be asked: %s\n", view.error.c_str());

    std::printf("%-5s %-13s %6s %8s %8s %6s %9s  %s\n", "task", kind->units.c_str(), "done",
                "missing", "damaged", "other", "attempts", "state");
    UnitTotals totals;
    for (const engine::Json& task : tasks) {
        const TaskRange r = taskRange(task);
        const TaskUnits u = checkTaskUnits(*kind, dir, *m, r, totals);
        const std::string state = taskState(task, r.index, view, totals);
        std::printf("%-5u %-13s %6u %8u %8u %6u %5g/%-3g  %s\n", r.index,
                    fmt::format("{}..{}", r.first, r.last).c_str(), u.done, u.missing, u.damaged,
                    u.other, task.get("attempts").number(), m->get("max_attempts").number(1),
                    state.c_str());
        addFailures(task, r.index, totals);
    }
    printTotals(*kind, *m, view, totals);
    return 0;
}

}  // namespace vox::job
