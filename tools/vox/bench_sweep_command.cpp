// vox bench sweep: lighting methods x settings on each scene, each point's time and error from
// the same run, written as CSV/JSON and charted (error against milliseconds, Pareto front joined,
// tools/plot_sweep.py); with --scheduler its points become the tasks of a job (sweep_job.h).
// vox bench recommend: the cheapest setting a sweep found that meets a target error on a scene —
// model no more than the scene needs; with --sampling, ReSTIR's candidate sampling per scene from
// `vox bench restir`'s seeds.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "commands.h"
#include "core/atomic_file.h"
#include "gpu/context.h"
#include "job_status.h"
#include "lighting_options.h"
#include "number_options.h"
#include "sweep_job.h"
#include "sweep_points.h"
#include "sweep_runner.h"
#include "tool_gpu.h"

namespace vox {

namespace {

using engine::lighting::LightingSettings;
using engine::lighting::Method;

int runSweep(const SweepOptions& o) {
    if (!o.status.empty()) return job::printJobStatus(o.status);
    if (!o.join.empty()) return joinSweep(o.join);
    if (o.jobTask) return runSweepTask(o);
    if (!o.job.scheduler.empty()) return submitSweepJob(o);
    auto plan = planSweep(o);
    if (!plan) return fail(plan.error());
    auto ctx = createBenchGpu();
    if (!ctx) return fail(ctx.error());
    std::filesystem::path out(o.output);
    std::filesystem::create_directories(out);
    engine::AtomicFile csvFile;
    if (engine::Status s = csvFile.open(out / "sweep.csv"); !s) return fail(s.error());
    std::ostream& csv = csvFile.stream();
    // reference_bounces 0: the point's error is against the direct-light reference; more: against
    // the path tracer with that many bounces (the indirect series, charted apart).
    csv << kSweepCsvHeader;
    const std::uint32_t total = plan->pointsPerWorld() * std::uint32_t(o.worlds.size());
    if (total > 0) {
        engine::Status measured =
            measureSweepPoints(**ctx, o, *plan, 0, total - 1, {},
                               [&](std::uint32_t, const std::string& line) -> engine::Status {
                                   csv << line;
                                   csv.flush();
                                   return {};
                               });
        if (!measured) return fail(measured.error());
    }
    if (engine::Status s = csvFile.commit(); !s) return fail(s.error());
    std::printf("wrote    %s\n", (out / "sweep.csv").string().c_str());
    drawSweepCharts(o.output);
    return 0;
}

struct RecommendOptions {
    std::string world;
    double targetMae = 0.0;
    std::string sweep = "out/sweep/sweep.csv";
    bool indirect = false;  // choose among the indirect-light series (else the direct-light points)
    bool sampling = false;  // choose ReSTIR's candidate sampling from `vox bench restir`'s table
    std::string restir = "out/bench_restir.csv";
};

// One CSV line into fields; a quoted field may hold commas ("--spatial 5,30").
std::vector<std::string> csvFields(const std::string& line) {
    std::vector<std::string> out(1);
    bool quoted = false;
    for (char c : line) {
        if (c == '"')
            quoted = !quoted;
        else if (c == ',' && !quoted)
            out.emplace_back();
        else
            out.back() += c;
    }
    return out;
}

// ReSTIR's candidate sampling per scene, from measurement: among the ReSTIR rows of
// `vox bench restir --sampling A,B,...` that differ only by the sampling knob (at its other
// defaults), the one with the lowest median MSE over the seeds. When that row's worst seed is not
// better than the runner-up's best one the spreads overlap, and it says so: the seeds do not
// separate them. Scenes are listed by emitter count, the quantity that decides it.
int runRecommendSampling(const RecommendOptions& o) {
    std::string only;
    if (!o.world.empty()) {
        auto scene = loadWorld(o.world);
        if (!scene) return fail(scene.error());
        only = scene->name;
    }
    std::ifstream in(o.restir);
    if (!in)
        return fail(engine::makeError(
            "{}: no results; run `vox bench restir --sampling uniform,power` first", o.restir));
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header = csvFields(line);
    auto column = [&](const char* name) {
        return std::size_t(std::find(header.begin(), header.end(), name) - header.begin());
    };
    const std::size_t cScene = column("scene"), cEmitters = column("emitters"),
                      cSampling = column("sampling"), cBase = column("base"), cMs = column("ms"),
                      cMse = column("mse"), cMin = column("mse_min"), cMax = column("mse_max"),
                      cMae = column("mae");
    if (cMae >= header.size())
        return fail(engine::makeError("{}: not a `vox bench restir` table", o.restir));
    struct Choice {
        std::string sampling;
        double ms, mse, mseMin, mseMax, mae;
    };
    std::map<std::string, std::pair<std::uint32_t, std::vector<Choice>>>
        scenes;  // by name: emitters, choices
    while (std::getline(in, line)) {
        std::vector<std::string> f = csvFields(line);
        if (f.size() < header.size() || f[cBase] != "--method restir" ||
            (!only.empty() && f[cScene] != only))
            continue;
        auto& [emitters, choices] = scenes[f[cScene]];
        emitters = std::uint32_t(std::atol(f[cEmitters].c_str()));
        choices.push_back({f[cSampling], std::atof(f[cMs].c_str()), std::atof(f[cMse].c_str()),
                           std::atof(f[cMin].c_str()), std::atof(f[cMax].c_str()),
                           std::atof(f[cMae].c_str())});
    }
    std::vector<std::pair<std::uint32_t, std::string>> order;
    for (const auto& [name, entry] : scenes) {
        if (entry.second.size() >= 2) order.push_back({entry.first, name});
    }
    if (order.empty())
        return fail(engine::makeError(
            "{}: no scene{} with ReSTIR rows for two sampling values; run `vox bench restir{} "
            "--sampling uniform,power`",
            o.restir, only.empty() ? "" : " '" + only + "'", only.empty() ? "" : " " + o.world));
    std::sort(order.begin(), order.end());
    for (const auto& [emitters, name] : order) {
        std::vector<Choice> c = scenes[name].second;
        std::sort(c.begin(), c.end(),
                  [](const Choice& a, const Choice& b) { return a.mse < b.mse; });
        const bool separated = c[0].mseMax < c[1].mseMin;
        // The rows are not scaled to equal time: the time ratio says what the lower error costs.
        std::printf(
            "%s (%u emitters): --sampling %s (MSE %.3e, %.2fx lower than %s; MAE %.3e vs %.3e; "
            "%.2fx its time)%s\n",
            name.c_str(), emitters, c[0].sampling.c_str(), c[0].mse,
            c[1].mse / std::max(c[0].mse, 1e-30), c[1].sampling.c_str(), c[0].mae, c[1].mae,
            c[0].ms / std::max(c[1].ms, 1e-9), separated ? "" : "; the seeds' spreads overlap");
    }
    return 0;
}

int runRecommend(const RecommendOptions& o) {
    if (o.sampling) return runRecommendSampling(o);
    if (o.world.empty())
        return fail(engine::makeError("bench recommend: a WORLD is needed (or --sampling)"));
    if (o.targetMae <= 0.0)
        return fail(engine::makeError("bench recommend: --target-mae is needed (or --sampling)"));
    auto scene = loadWorld(o.world);
    if (!scene) return fail(scene.error());
    std::ifstream in(o.sweep);
    if (!in)
        return fail(engine::makeError("{}: no sweep results; run `vox bench sweep {}` first",
                                      o.sweep, o.world));
    std::string line;
    std::getline(in, line);  // header
    // A setting's cost and MAE with their spreads; sweeps before the cost model have only the
    // time and one MAE (no spread: nothing is resolved).
    struct Candidate {
        std::string setting;
        double ms, mae, costLow, costHigh, maeHigh;
        bool spread;  // seeds and intervals measured
    };
    std::vector<Candidate> rows;
    while (std::getline(in, line)) {
        // scene,method,"setting",emitters,total_ms,primary_ms,lighting_ms,mae,mse,rmae[,indirect,
        // reference_bounces[,mean_ratio[,seeds,cost_ms,cost_low,cost_high,mae_low,mae_high,...]]]
        // (sweeps from before the indirect series have no indirect columns: all direct)
        std::size_t q1 = line.find('"'), q2 = line.find('"', q1 + 1);
        if (q1 == std::string::npos || q2 == std::string::npos) continue;
        if (line.substr(0, line.find(',')) != scene->name) continue;
        std::vector<std::string> rest = splitList(line.substr(q2 + 2));
        if (rest.size() < 5) continue;
        const bool againstIndirect = rest.size() >= 9 && std::atoi(rest[8].c_str()) > 0;
        if (againstIndirect != o.indirect) continue;
        Candidate c{line.substr(q1 + 1, q2 - q1 - 1),
                    std::atof(rest[1].c_str()),
                    std::atof(rest[4].c_str()),
                    0.0,
                    0.0,
                    0.0,
                    rest.size() >= 16};
        c.costLow = c.costHigh = c.ms;
        c.maeHigh = c.mae;
        if (rest.size() >= 16) {
            c.ms = std::atof(rest[11].c_str());
            c.costLow = std::atof(rest[12].c_str());
            c.costHigh = std::atof(rest[13].c_str());
            c.maeHigh = std::atof(rest[15].c_str());
        }
        rows.push_back(c);
    }
    if (rows.empty())
        return fail(engine::makeError("{}: no {}rows for scene '{}'; run `vox bench sweep {}`",
                                      o.sweep, o.indirect ? "indirect-light " : "", scene->name,
                                      o.world));
    // The cheapest by median cost among those whose median MAE meets the target.
    const Candidate *best = nullptr, *next = nullptr;
    for (const Candidate& c : rows) {
        if (c.mae > o.targetMae) continue;
        if (!best || c.ms < best->ms) {
            next = best;
            best = &c;
        } else if (!next || c.ms < next->ms) {
            next = &c;
        }
    }
    if (!best) {
        auto closest =
            std::min_element(rows.begin(), rows.end(),
                             [](const Candidate& a, const Candidate& b) { return a.mae < b.mae; });
        std::printf(
            "no swept setting reaches MAE %.3e on %s; the most accurate is '%s' (MAE %.3e, %.2f "
            "ms)\n",
            o.targetMae, scene->name.c_str(), closest->setting.c_str(), closest->mae, closest->ms);
        return 1;
    }
    std::printf(
        "%s: cheapest setting with MAE <= %.3e: '%s' (MAE %.3e, %.2f ms per frame [%.2f–%.2f]; "
        "%zu settings swept)\n",
        scene->name.c_str(), o.targetMae, best->setting.c_str(), best->mae, best->ms, best->costLow,
        best->costHigh, rows.size());
    // Verdicts: the target met by every seed, and cheaper than the runner-up beyond the cost
    // intervals; else not resolved at the sweep's budget (more --seeds).
    if (!best->spread) {  // one measurement: nothing to resolve with
        std::printf(
            "  meets the target: not resolved at this budget (one measurement per "
            "setting)\n");
        return 0;
    }
    std::printf("  meets the target: %s\n",
                best->maeHigh <= o.targetMae
                    ? "yes, every seed"
                    : fmt::format("not resolved at this budget (the seeds' worst MAE {:.3e})",
                                  best->maeHigh)
                          .c_str());
    if (next) {
        std::printf("  cheaper than '%s' (%.2f ms [%.2f–%.2f]): %s\n", next->setting.c_str(),
                    next->ms, next->costLow, next->costHigh,
                    best->costHigh < next->costLow ? "yes, the intervals do not overlap"
                                                   : "not resolved at this budget");
    }
    return 0;
}

}  // namespace

void addBenchSweepCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand(
        "sweep", "Methods x settings per scene: error against time, CSV and chart");
    auto o = std::make_shared<SweepOptions>();
    cmd->add_option("worlds", o->worlds, "Worlds (default: the four thesis scenes)");
    cmd->add_option("--methods", o->methods, "Comma-separated methods")->capture_default_str();
    cmd->add_option("--candidates", o->candidates, "Candidate counts M for restir/ris")
        ->capture_default_str();
    cmd->add_option("--modes", o->modes, "point, area or both")->capture_default_str();
    cmd->add_option("--brick-lights", o->brickLights, "on, off or both")->capture_default_str();
    cmd->add_option("--rays", o->rays, "Shadow rays for uniform light sampling")
        ->capture_default_str();
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("--frames", o->frames, "Frames per setting (the last half are measured)")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(2, 1000, "frames")));
    cmd->add_option("--seeds", o->seeds,
                    "Interleaved rounds per world, one seed each: the errors' spread (the cost "
                    "model is calibrated in rounds of its own after them)")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 1000, "seeds")));
    cmd->add_option("--cost-drift", o->costDrift,
                    "How far each kind's relative cost may differ between runs (a factor 1 + "
                    "this either way); the cost intervals and the front's verdicts include it")
        ->capture_default_str()
        ->check(numberIn(engine::closedRange(0.0, 1.0)));
    cmd->add_option("--ref-spp", o->referenceSpp, "Reference samples per pixel (cached on disk)")
        ->capture_default_str()
        ->check(numberIn(kSamplesRange));
    cmd->add_option("--indirect", o->indirect,
                    "Indirect-light series: none, cache-K (K directions), vct, vct-leaky, "
                    "reference; empty = no series")
        ->capture_default_str();
    cmd->add_option("--indirect-bounces", o->indirectBounces,
                    "Bounces of the indirect reference (and of the cache and path-tracer points)")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 16, "bounces")));
    cmd->add_option("--indirect-ref-spp", o->indirectReferenceSpp,
                    "Samples per pixel of the indirect reference (cached)")
        ->capture_default_str()
        ->check(numberIn(kSamplesRange));
    cmd->add_option("-o,--output", o->output, "Output folder")->capture_default_str();
    job::addJobOptions(*cmd, o->job);
    cmd->add_option("--join", o->join, "Join the sweep job in DIR: the CSV and charts of one run")
        ->type_name("DIR");
    cmd->add_option("--status", o->status, "Where the sweep job in DIR stands")->type_name("DIR");
    cmd->add_option("--job-task", o->jobTask, "Measure task I's points of the job in --output")
        ->group("");
    cmd->callback([o, &exitCode] { exitCode = runSweep(*o); });

    auto* rec = bench.add_subcommand(
        "recommend", "The cheapest swept setting that meets a target MAE on a scene");
    auto r = std::make_shared<RecommendOptions>();
    rec->add_option("world", r->world,
                    "World name or scene file (with --sampling: all scenes when left out)");
    rec->add_option("--target-mae", r->targetMae,
                    "Target MAE against the reference (needed without --sampling)")
        ->check(numberIn(engine::aboveRange(0.0, 1e6)));
    rec->add_option("--sweep", r->sweep, "Sweep results (CSV from vox bench sweep)")
        ->capture_default_str();
    rec->add_flag(
        "--indirect", r->indirect,
        "Choose among the indirect-light series (error against the multi-bounce reference)");
    rec->add_flag("--sampling", r->sampling,
                  "Choose ReSTIR's candidate sampling per scene from `vox bench restir --sampling "
                  "A,B` (lowest median MSE)");
    rec->add_option("--restir", r->restir, "vox bench restir's CSV (for --sampling)")
        ->capture_default_str();
    rec->callback([r, &exitCode] { exitCode = runRecommend(*r); });
}

}  // namespace vox
