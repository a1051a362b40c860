#include "slurm_scheduler.h"

#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <set>
#include <sstream>
#include <sys/stat.h>

#include "core/atomic_file.h"
#include "job_kind.h"
#include "job_manifest.h"
#include "job_submit.h"
#include "subprocess.h"

namespace vox::job {

namespace fs = std::filesystem;

namespace {

// 'text' for a shell script, whatever it holds.
std::string shellQuote(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// A script that runs `command`, then `tail` as the shell reads it ("$SLURM_ARRAY_TASK_ID").
engine::Status writeScript(const fs::path& file, const std::string& comment,
                           const std::vector<std::string>& command, const std::string& tail = {}) {
    std::string line = "exec";
    for (const std::string& a : command) line += " " + shellQuote(a);
    if (!tail.empty()) line += " " + tail;
    const std::string text = fmt::format("#!/bin/bash\n# {}\n{}\n", comment, line);
    if (engine::Status s = engine::writeFileAtomically(file, text); !s) return s;
    if (chmod(file.c_str(), 0755) != 0)
        return engine::makeError("{}: cannot make it executable", file.string());
    return {};
}

// "0-3,7": the tasks as Slurm's --array list.
std::string arrayList(const std::vector<std::uint32_t>& tasks) {
    std::string out;
    for (std::size_t i = 0; i < tasks.size();) {
        std::size_t j = i;
        while (j + 1 < tasks.size() && tasks[j + 1] == tasks[j] + 1) ++j;
        out += fmt::format("{}{}", out.empty() ? "" : ",", tasks[i]);
        if (j > i) out += fmt::format("-{}", tasks[j]);
        i = j + 1;
    }
    return out;
}

// sbatch --parsable prints "ID" or "ID;CLUSTER".
engine::Result<std::string> submit(const std::vector<std::string>& args) {
    auto r = runProgram(args);
    if (!r) return r.error();
    if (!r->exit.ok())
        return engine::makeError("sbatch failed ({}); its message is above", describeExit(r->exit));
    std::string id = r->out.substr(0, r->out.find_first_of(";\n"));
    if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
        return engine::makeError("sbatch printed '{}', not a job id", r->out);
    return id;
}

bool isActive(const std::string& state) {
    static const std::set<std::string> active = {
        "PENDING",      "RUNNING",  "CONFIGURING", "COMPLETING", "REQUEUED",  "REQUEUE_FED",
        "REQUEUE_HOLD", "RESIZING", "SUSPENDED",   "SIGNALING",  "STAGE_OUT", "STOPPED"};
    return active.count(state) > 0;
}

class SlurmScheduler : public JobScheduler {
public:
    std::string name() const override { return "slurm"; }

    engine::Status run(const fs::path& dir, const std::vector<std::uint32_t>& tasks,
                       const JobOptions& o) override {
        if (!findOnPath("sbatch"))
            return engine::makeError(
                "--scheduler slurm: sbatch is not on PATH (no Slurm here; --scheduler parallel "
                "or local run the job without it)");
        auto m = readManifest(dir);
        if (!m) return m.error();
        const fs::path folder = fs::absolute(jobFolder(dir));
        const std::string kind = m->get("kind").string();
        std::vector<std::string> task = taskCommand(dir, "");
        task.pop_back();  // the index is Slurm's, read when the script runs
        if (engine::Status s = writeScript(
                folder / "task.sh",
                fmt::format("Written by vox: one task of the job in {}; Slurm gives its index.",
                            fs::absolute(dir).string()),
                task, "\"$SLURM_ARRAY_TASK_ID\"");
            !s)
            return s;
        if (engine::Status s = writeScript(folder / "join.sh",
                                           fmt::format("Written by vox: the join of the job in {}.",
                                                       fs::absolute(dir).string()),
                                           joinCommand(*m));
            !s)
            return s;
        std::vector<std::string> shared;
        if (!o.partition.empty()) shared.push_back("--partition=" + o.partition);
        for (const std::string& extra : o.sbatchOptions) shared.push_back(extra);

        engine::Json ids = engine::Json::object();
        std::string array;
        if (!tasks.empty()) {
            std::vector<std::string> args = {
                "sbatch",
                "--parsable",
                "--job-name=vox-" + kind,
                "--array=" + arrayList(tasks) + (o.throttle ? fmt::format("%{}", o.throttle) : ""),
                "--requeue",
                "--open-mode=append",
                "--output=" + (folder / "task_%a.log").string()};
            args.insert(args.end(), shared.begin(), shared.end());
            args.push_back((folder / "task.sh").string());
            auto id = submit(args);
            if (!id) return id.error();
            array = *id;
            ids["array"] = array;
        }
        std::vector<std::string> args = {"sbatch", "--parsable", "--job-name=vox-" + kind + "-join",
                                         "--open-mode=append",
                                         "--output=" + (folder / "join.log").string()};
        if (!array.empty())
            args.insert(args.end(), {"--dependency=afterok:" + array, "--kill-on-invalid-dep=yes"});
        args.insert(args.end(), shared.begin(), shared.end());
        args.push_back((folder / "join.sh").string());
        auto join = submit(args);
        if (!join) return join.error();  // the array runs; `vox job join DIR` joins by hand
        ids["join"] = *join;
        if (engine::Status s = recordSubmission(dir, "slurm", tasks, ids); !s) return s;
        if (!array.empty())
            std::printf("slurm    array job %s: tasks %s, logs %s/task_N.log\n", array.c_str(),
                        arrayList(tasks).c_str(), folder.string().c_str());
        std::printf("slurm    join job %s%s, log %s/join.log\n", join->c_str(),
                    array.empty()
                        ? ""
                        : fmt::format(" after every task succeeded (afterok:{})", array).c_str(),
                    folder.string().c_str());
        return {};
    }

    SchedulerView view(const engine::Json& manifest) const override {
        SchedulerView v;
        // Each task's latest submission names the array job it is in.
        std::map<std::string, std::uint32_t> arrayOf;  // "12_3" -> task 3
        std::string joinId;
        for (const engine::Json& s : manifest.get("submissions").items()) {
            if (s.get("scheduler").string() != "slurm") continue;
            for (const engine::Json& t : s.get("tasks").items()) {
                const std::uint32_t task = std::uint32_t(t.number());
                std::erase_if(arrayOf, [&](const auto& e) { return e.second == task; });
                arrayOf[fmt::format("{}_{}", s.get("array").string(), task)] = task;
            }
            joinId = s.get("join").string();
        }
        std::set<std::string> jobs;
        for (const auto& [id, task] : arrayOf) jobs.insert(id.substr(0, id.find('_')));
        if (!joinId.empty()) jobs.insert(joinId);
        if (jobs.empty()) return v;
        // One job at a time: squeue refuses the whole list when one id is no longer known.
        std::string out;
        for (const std::string& j : jobs) {
            auto r = runProgram({"squeue", "--noheader", "--array", "--states=all", "--jobs=" + j,
                                 "--format=%i|%T|%r|%N"},
                                false);
            if (!r) {
                v.error = r.error().message;
                return v;
            }
            if (r->exit.ok()) out += r->out;
        }
        std::stringstream lines(out);
        std::string line;
        while (std::getline(lines, line)) {
            std::vector<std::string> f;
            std::stringstream fields(line);
            std::string field;
            while (std::getline(fields, field, '|')) f.push_back(field);
            if (f.size() < 3) continue;
            f.resize(4);  // a pending job has no node: getline drops the empty last field
            std::string text = f[1];
            if (f[1] == "RUNNING" || f[1] == "COMPLETING")
                text += " on " + f[3];
            else if (f[2] != "None" && !f[2].empty())
                text += " (" + f[2] + ")";
            if (f[0] == joinId) {
                v.join = "slurm " + joinId + " " + text;
            } else if (auto it = arrayOf.find(f[0]); it != arrayOf.end()) {
                v.tasks[it->second] = "slurm " + f[0] + " " + text;
                if (isActive(f[1])) v.active.push_back(it->second);
                if (f[1] == "RUNNING") v.running.push_back(it->second);
            }
        }
        for (const auto& [id, task] : arrayOf)
            if (!v.tasks.count(task)) v.tasks[task] = "slurm " + id + " no longer in squeue";
        return v;
    }

    engine::Status retry(std::uint32_t task) const override {
        const char* job = std::getenv("SLURM_ARRAY_JOB_ID");
        const char* index = std::getenv("SLURM_ARRAY_TASK_ID");
        if (!job || !index)
            return engine::makeError(
                "task {}: not in a Slurm array task (no SLURM_ARRAY_JOB_ID): cannot requeue it; "
                "re-run the submitting command",
                task);
        auto r = runProgram({"scontrol", "requeue", fmt::format("{}_{}", job, index)});
        if (!r) return r.error();
        if (!r->exit.ok())
            return engine::makeError("scontrol requeue {}_{}: {}", job, index,
                                     describeExit(r->exit));
        return {};
    }
};

}  // namespace

std::unique_ptr<JobScheduler> makeSlurmScheduler() { return std::make_unique<SlurmScheduler>(); }

}  // namespace vox::job
