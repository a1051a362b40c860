// vox bench restir: ReSTIR's error at equal time against uniform light sampling and against RIS
// without reuse, per scene, over several seeds. One run's MSE is decided by a few outlier pixels,
// so every row is rendered with N seeds and reported as the median and spread (min–max; the JSON
// also has the quartiles) of its MSE, MAE, mean ratio and time, and compared with ReSTIR by the
// median of per-seed ratios. A run's time is, on a CPU device (lavapipe), the process's CPU time
// per frame, else its fastest frame's GPU time: on a shared machine, wall-clock and GPU
// timestamps also count the waits for a core. Equal time: the baselines (uniform: shadow rays;
// RIS: candidates) get as many as fit in ReSTIR's frame time, from a linear fit of their time as a
// ratio to ReSTIR's, measured in interleaved rounds (metrics/interleaved_rounds.h: a drifting
// machine slows both alike); then each seed renders every row back to back, the order reversed on
// every other seed. A comparison is MSE x time per seed (the work-normalised error, which an
// imperfect fit does not move), its median over seeds and the sign test's interval; a verdict
// ("> 1": the versus row wins) only when the interval excludes 1 (--confidence), else
// "unresolved". Rows are lighting knobs, so new modes are rows without code:
// --variant "NAME:--knob value ..." and --sampling LIST.
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "bench_setup.h"
#include "commands.h"
#include "gpu/context.h"
#include "number_options.h"
#include "restir_bench.h"
#include "restir_bench_report.h"

namespace vox {

namespace {

// The closing lines: how to read the ratios, the time taken, the files written.
void printFooter(const RestirBenchOptions& o, double seconds, const std::filesystem::path& json,
                 const std::filesystem::path& csv) {
    std::printf(
        "\nratio = row / versus row per seed, median (min–max): above 1 favours the versus row "
        "(ReSTIR)\n");
    std::printf(
        "MSE×cost: the work-normalised ratio, cost = counted work at per-kind costs calibrated "
        "in %u+ interleaved rounds; its interval: the sign test's over seeds (MSE) times over the "
        "rounds' fits, widened by each kind's cost drifting %.0f %% between runs (cost); \"> 1\" "
        "(the versus row wins) or \"< 1\" only when it excludes 1 (by %.0f %%) with %.0f %% "
        "coverage, else unresolved\n",
        kCostRounds.minRounds, 100.0 * o.costDrift, 100.0 * o.noise, 100.0 * o.confidence);
    std::printf(
        "equal cost: scaled rows rendered at the powers of two around their equal-cost count, "
        "errors interpolated in log-log, time linearly\n");
    std::printf("wall time %.0f s (references included; cached ones are read back)\n", seconds);
    std::printf("wrote    %s\nwrote    %s\n", json.string().c_str(), csv.string().c_str());
}

engine::Status writeMarkdown(const std::string& file, const std::string& table) {
    engine::AtomicFile md;
    if (engine::Status s = openOutputFile(md, file); !s) return s;
    md.stream() << table;
    if (engine::Status s = md.commit(); !s) return s;
    std::printf("wrote    %s\n", file.c_str());
    return {};
}

int runRestirBench(RestirBenchOptions o) {
    if (o.quick) {  // a look in about a minute: small images, short history, a light reference
        o.size = "64x40";
        o.frames = 8;
        o.referenceSpp = 256;
    }
    auto frame = frameOfSize(o.size);
    if (!frame) return fail(frame.error());
    auto rows = rowsOf(o);
    if (!rows) return fail(rows.error());
    auto versus = versusOf(o, *rows);
    if (!versus) return fail(versus.error());
    PinnedCounts pinned;
    if (!o.countsFrom.empty()) {
        auto read = readPinnedCounts(o.countsFrom);
        if (!read) return fail(read.error());
        pinned = std::move(*read);
    }
    auto scenes = loadWorlds(o.worlds);
    if (!scenes) return fail(scenes.error());
    auto ctx = createBenchGpu();
    if (!ctx) return fail(ctx.error());
    engine::gpu::Context& gpu = **ctx;
    std::printf("device   %s (%s)\n", gpu.info().name.c_str(), gpu.info().driver.c_str());
    // A frame's time. On lavapipe the device is this process's threads on cores other sessions
    // share: its CPU time is the work done, where GPU timestamps also count the waits for a core.
    const bool cpuClock = o.clock == "cpu" || (o.clock == "auto" && gpu.info().type == "CPU");
    std::printf(
        "time     %s\n",
        cpuClock
            ? "CPU time of the process per frame (median): the CPU device's work and the host's"
            : "GPU timestamps of the fastest measured frame");
    const auto started = std::chrono::steady_clock::now();

    const std::filesystem::path out(o.output);
    const RestirSetup setup{o,
                            *rows,
                            *versus,
                            gpu,
                            *frame,
                            cpuClock,
                            out.parent_path() / "cache",
                            o.countsFrom.empty() ? nullptr : &pinned};
    RestirReport report(setup);
    if (engine::Status s = report.open(out, gpu.info().name); !s) return fail(s.error());
    // A scaled row renders at two rungs of its count ladder (at most).
    std::size_t renders = 0;
    for (const Row& row : *rows) renders += row.scale == EqualTime::None ? 1 : 2;
    RestirProgress progress{0, scenes->size() * renders * o.seeds};
    for (std::size_t w = 0; w < scenes->size(); ++w) {
        auto results = measureScene(setup, (*scenes)[w], progress);
        if (!results) return fail(results.error());
        report.addScene((*scenes)[w].name, *results, w + 1 == scenes->size());
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (engine::Status s = report.commit(seconds); !s) return fail(s.error());
    printFooter(o, seconds, out, report.csvPath());
    if (!o.markdown.empty()) {
        if (engine::Status s = writeMarkdown(o.markdown, report.table()); !s)
            return fail(s.error());
    }
    return 0;
}

}  // namespace

void addBenchRestirCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand(
        "restir",
        "ReSTIR's MSE and MAE at equal time vs uniform light sampling and RIS, over seeds");
    auto o = std::make_shared<RestirBenchOptions>();
    cmd->add_option("worlds", o->worlds, "Worlds (default: the four thesis scenes)");
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("--frames", o->frames, "Frames of ReSTIR history (the last half are measured)")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(4, 1000, "frames")));
    cmd->add_option("--ref-spp", o->referenceSpp,
                    "Reference samples per pixel (cached on disk beside the JSON)")
        ->capture_default_str()
        ->check(numberIn(kSamplesRange));
    cmd->add_option("--seeds", o->seeds, "Seeds per row: medians and spreads are over these")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 1000, "seeds")));
    cmd->add_option("--rows", o->rows,
                    "Default rows: restir, restir-unbiased, ris (equal time), uniform (equal time)")
        ->capture_default_str();
    cmd->add_option("--sampling", o->sampling,
                    "Values of the sampling knob (comma-separated): one restir, restir-unbiased "
                    "and ris row each")
        ->capture_default_str();
    cmd->add_option("--variant", o->variants,
                    "Another row: \"NAME:--knob value ...\" (any lighting option); a ris or "
                    "uniform row that does not "
                    "fix --candidates / --shadow-rays gets ReSTIR's time");
    cmd->add_option("--versus", o->versus,
                    "Rows the others are divided by, comma-separated (default: the restir rows); "
                    "the first one's time "
                    "is the equal time");
    cmd->add_option("--clock", o->clock,
                    "Time of a frame for equal time: gpu (fastest frame's timestamps), cpu (the "
                    "process's CPU time), "
                    "auto (cpu on a CPU device such as lavapipe)")
        ->capture_default_str()
        ->check(CLI::IsMember({"auto", "gpu", "cpu"}));
    cmd->add_option("--confidence", o->confidence,
                    "Confidence of the intervals behind a verdict (5 seeds' min-max covers 93.75 "
                    "%: 0.95 needs 6)")
        ->capture_default_str()
        ->check(numberIn(engine::closedRange(0.5, 0.999)));
    cmd->add_option("--noise", o->noise,
                    "A verdict needs its interval to exclude 1 by this fraction (a smaller "
                    "difference is within the cost model's own error)")
        ->capture_default_str()
        ->check(numberIn(engine::closedRange(0.0, 1.0)));
    cmd->add_option("--cost-drift", o->costDrift,
                    "How far each kind's relative cost may differ between runs (a factor 1 + "
                    "this either way): cost ratios' intervals, and so the verdicts, include it")
        ->capture_default_str()
        ->check(numberIn(engine::closedRange(0.0, 1.0)));
    cmd->add_option("--counts-from", o->countsFrom,
                    "Render the scaled rows at an earlier run's equal-cost counts (its JSON): "
                    "repeated runs then compare the same settings, and only this run's cost "
                    "model moves MSE×cost")
        ->check(CLI::ExistingFile);
    cmd->add_flag(
        "--quick", o->quick,
        "A first look: 64x40, 8 frames, 256 spp reference (over --size, --frames, --ref-spp)");
    cmd->add_option("-o,--output", o->output, "JSON results file")->capture_default_str();
    cmd->add_option("--markdown", o->markdown, "Also write the table as markdown here");
    cmd->callback([o, &exitCode] { exitCode = runRestirBench(*o); });
}

}  // namespace vox
