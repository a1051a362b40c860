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
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "commands.h"
#include "core/atomic_file.h"
#include "gpu/context.h"
#include "lighting/lighting_knobs.h"
#include "lighting_options.h"
#include "metrics/interleaved_rounds.h"
#include "metrics/median_interval.h"
#include "metrics/seed_statistics.h"
#include "number_options.h"
#include "render/renderer.h"
#include "sweep_runner.h"

namespace vox {

namespace {

using engine::lighting::KnobValue;
using engine::lighting::LightingSettings;
using engine::lighting::Method;
using engine::metrics::SeedSummary;

struct RestirBenchOptions {
    std::vector<std::string> worlds{"cornell", "mountain", "letters", "apartments"};
    std::string size = "96x64";
    std::uint32_t frames = 12;
    std::uint32_t referenceSpp = 512;
    std::uint32_t seeds = 5;
    std::string rows = "restir,restir-unbiased,ris,uniform";
    std::string sampling;  // empty: the sampling knob's default
    std::vector<std::string> variants;
    std::string versus;          // empty: every ReSTIR row at defaults (one per --sampling value)
    double confidence = 0.9;     // of the verdicts' intervals; 5 seeds' min-max covers 93.75 %
    std::string clock = "auto";  // gpu: fastest frame's GPU timestamps; cpu: the process's CPU
                                 // time; auto: cpu on a CPU device
    bool quick = false;
    std::string output =
        "out/bench_restir.json";  // and the summary CSV beside it (.csv), for vox bench recommend
    std::string markdown;
};

// Which knob a row scales to ReSTIR's frame time.
enum class EqualTime { None, ShadowRays, Candidates };

struct Row {
    std::string name;
    LightingSettings lighting;
    EqualTime scale = EqualTime::None;
    std::string sampling;  // the sampling knob's value, for the recommendation
};

struct RowResult {
    std::vector<double> ms, mse, mae, meanRatio;  // one per seed
    std::uint32_t scaledTo = 0;                   // shadow rays or candidates (scaled rows)
    std::vector<double> roundMs;  // the interleaved timing's rounds, at the fitted settings
};

// The interleaved timing of all rows at their fitted settings: enough rounds that a time ratio's
// interval covers 97 %, so that with 5 seeds' min-max of error ratios (93.75 %) the product still
// covers 90 %.
constexpr engine::metrics::RoundsPlan kCostRounds{1, 10, 16, 0.97, 0.03};

std::vector<std::string> splitOn(const std::string& s, char separator) {
    std::vector<std::string> out;
    std::stringstream in(s);
    std::string item;
    while (std::getline(in, item, separator)) {
        if (!item.empty()) out.push_back(item);
    }
    return out;
}

const engine::lighting::Knob& knob(std::string_view option) {
    return *engine::lighting::knobForOption(option);
}

// The scaled knob follows the method, unless the row fixes it itself.
EqualTime scaleOf(const LightingSettings& l, const std::vector<KnobValue>& given) {
    auto gives = [&](std::string_view option) {
        return std::any_of(given.begin(), given.end(),
                           [&](const KnobValue& v) { return v.knob == &knob(option); });
    };
    if (l.method == Method::Uniform && !gives("shadow-rays")) return EqualTime::ShadowRays;
    if (l.method == Method::Ris && !gives("candidates")) return EqualTime::Candidates;
    return EqualTime::None;
}

engine::Result<Row> makeRow(std::string name, const std::vector<KnobValue>& values) {
    auto l = engine::lighting::mergeLighting(LightingSettings{}, values);
    if (!l) return engine::makeError("{}: {}", name, l.error().message);
    return Row{std::move(name), *l, scaleOf(*l, values), knobText(knob("sampling"), *l)};
}

// The rows: the default rows (per --sampling value for those that resample), then the variants.
engine::Result<std::vector<Row>> rowsOf(const RestirBenchOptions& o) {
    std::vector<std::string> samplings = splitOn(o.sampling, ',');
    if (samplings.empty()) samplings.push_back("");
    std::vector<Row> rows;
    for (const std::string& name : splitOn(o.rows, ',')) {
        if (name == "uniform") {  // uniform light sampling: no candidates, lights drawn uniformly
            auto row = makeRow(name, {{&knob("method"), "uniform", "--rows"},
                                      {&knob("sampling"), "uniform", "--rows"}});
            if (!row) return row.error();
            rows.push_back(*row);
            continue;
        }
        if (name != "restir" && name != "restir-unbiased" && name != "ris")
            return engine::makeError("--rows: '{}' is not restir, restir-unbiased, ris or uniform",
                                     name);
        for (const std::string& sampling : samplings) {
            std::vector<KnobValue> values{{&knob("method"), name, "--rows"}};
            if (!sampling.empty()) values.push_back({&knob("sampling"), sampling, "--sampling"});
            auto row = makeRow(
                sampling.empty() ? name : fmt::format("{} sampling={}", name, sampling), values);
            if (!row) return row.error();
            rows.push_back(*row);
        }
    }
    for (const std::string& v : o.variants) {
        std::size_t colon = v.find(':');
        if (colon == std::string::npos || colon == 0)
            return engine::makeError("--variant '{}': expected NAME:--knob value ...", v);
        auto values =
            knobValuesOf(v.substr(colon + 1), fmt::format("--variant {}", v.substr(0, colon)));
        if (!values) return values.error();
        auto row = makeRow(v.substr(0, colon), *values);
        if (!row) return row.error();
        rows.push_back(*row);
    }
    if (rows.empty()) return engine::makeError("--rows: no rows to measure");
    for (std::size_t i = 0; i < rows.size(); ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            if (rows[i].name == rows[j].name)
                return engine::makeError("two rows named '{}'", rows[i].name);
        }
    }
    return rows;
}

// The rows the others are divided by: --versus, else the ReSTIR rows at defaults.
engine::Result<std::vector<std::size_t>> versusOf(const RestirBenchOptions& o,
                                                  const std::vector<Row>& rows) {
    std::vector<std::size_t> out;
    auto indexOf = [&](const std::string& name) {
        for (std::size_t i = 0; i < rows.size(); ++i) {
            if (rows[i].name == name) return i;
        }
        return rows.size();
    };
    for (const std::string& name : splitOn(o.versus, ',')) {
        std::size_t i = indexOf(name);
        if (i == rows.size()) return engine::makeError("--versus: no row named '{}'", name);
        out.push_back(i);
    }
    if (o.versus.empty()) {
        for (std::size_t i = 0; i < rows.size(); ++i) {
            if (rows[i].name == "restir" || rows[i].name.rfind("restir sampling=", 0) == 0)
                out.push_back(i);
        }
        if (out.empty()) out.push_back(0);
    }
    if (rows[out[0]].scale !=
        EqualTime::None)  // the yardstick of equal time cannot be scaled to itself
        return engine::makeError(
            "--versus: '{}' is scaled to equal time itself; put an unscaled row first",
            rows[out[0]].name);
    return out;
}

// The method, the knob scaled to equal time (`also`, may be empty) and the knobs that differ from
// the defaults, as options: what a row is, in the JSON and the CSV.
std::string settingsText(const LightingSettings& l, std::string_view also = {}) {
    const LightingSettings defaults;
    std::string out;
    for (const engine::lighting::KnobGroup& g : engine::lighting::knobGroups()) {
        for (const engine::lighting::Knob& k : g.knobs) {
            const bool always = k.name == "method" || k.name == also;
            if (!engine::lighting::knobRelevant(k, l) && !always) continue;
            std::string value = knobText(k, l);
            if (value == knobText(k, defaults) && !always) continue;
            out += fmt::format("{}{} {}", out.empty() ? "" : " ", knobOption(g, k), value);
        }
    }
    return out;
}

// The method as the --method knob names it (restir-unbiased apart).
std::string methodName(const LightingSettings& l) {
    return l.method == Method::Restir && l.restir.unbiased ? "restir-unbiased"
                                                           : engine::lighting::methodName(l.method);
}

std::string jsonSummary(const SeedSummary& s) {
    return fmt::format(
        "{{\"median\": {}, \"q1\": {}, \"q3\": {}, \"min\": {}, \"max\": {}, \"count\": {}}}",
        s.median, s.q1, s.q3, s.min, s.max, s.count);
}
std::string jsonArray(const std::vector<double>& v) {
    std::string out;
    for (double x : v) out += fmt::format("{}{}", out.empty() ? "" : ", ", x);
    return "[" + out + "]";
}
std::string jsonString(const std::string& s) {
    std::string out;
    for (char c : s) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
    return "\"" + out + "\"";
}

// "1.23e-03 (1.01e-03–2.50e-03)": median (min–max).
std::string cell(const SeedSummary& s, const char* format) {
    return fmt::format(fmt::runtime(std::string(format) + " ({}–{})"), s.median,
                       fmt::format(fmt::runtime(format), s.min),
                       fmt::format(fmt::runtime(format), s.max));
}

// A row's MSE x time over the versus row's: the work-normalised error ratio (inverse relative
// efficiency), which an imperfect equal-time fit barely moves (MSE ~ 1 / samples). The MSE ratio's
// interval over seeds (the renders are deterministic: seeds are the only randomness) times the
// time ratio's over the interleaved rounds; its coverage is the product of the two.
engine::metrics::MedianInterval workNormalisedRatio(const RowResult& r, const RowResult& versus,
                                                    double confidence) {
    using namespace engine::metrics;
    return productInterval(
        medianInterval(perSeedRatios(r.mse, versus.mse), confidence),
        medianInterval(perSeedRatios(r.roundMs, versus.roundMs), kCostRounds.confidence));
}

std::string jsonInterval(const engine::metrics::MedianInterval& m, double confidence) {
    return fmt::format(
        "{{\"median\": {}, \"low\": {}, \"high\": {}, \"coverage\": {}, \"verdict\": \"{}\"}}",
        m.median, m.low, m.high, m.covered,
        engine::metrics::verdictName(engine::metrics::verdictOf(m, confidence)));
}

std::string scaledText(const Row& row, const RowResult& r) {
    if (row.scale == EqualTime::ShadowRays) return fmt::format("{} rays", r.scaledTo);
    if (row.scale == EqualTime::Candidates) return fmt::format("M = {}", r.scaledTo);
    return "";
}

int runRestirBench(RestirBenchOptions o) {
    if (o.quick) {  // a look in about a minute: small images, short history, a light reference
        o.size = "64x40";
        o.frames = 8;
        o.referenceSpp = 256;
    }
    auto size = parseSize(o.size, "--size");
    if (!size) return fail(size.error());
    auto rows = rowsOf(o);
    if (!rows) return fail(rows.error());
    auto versus = versusOf(o, *rows);
    if (!versus) return fail(versus.error());
    std::vector<engine::world::Scene> scenes;
    for (const std::string& name :
         o.worlds) {  // every world read before the first frame: a typo costs nothing
        auto scene = loadWorld(name);
        if (!scene) return fail(scene.error());
        scenes.push_back(std::move(*scene));
    }
    auto ctx = engine::gpu::Context::create({});
    if (!ctx) return fail(ctx.error());
    engine::gpu::Context& gpu = **ctx;
    std::printf("device   %s (%s)\n", gpu.info().name.c_str(), gpu.info().driver.c_str());
    // A frame's time. On lavapipe the device is this process's threads on cores other sessions
    // share: its CPU time is the work done, where GPU timestamps also count the waits for a core.
    const bool cpuClock = o.clock == "cpu" || (o.clock == "auto" && gpu.info().type == "CPU");
    auto timeOfPoint = [cpuClock](const SweepPoint& p) { return cpuClock ? p.cpuMs : p.fastestMs; };
    std::printf(
        "time     %s\n",
        cpuClock
            ? "CPU time of the process per frame (median): the CPU device's work and the host's"
            : "GPU timestamps of the fastest measured frame");
    engine::render::FrameSettings fs;
    fs.width = (*size).x;
    fs.height = (*size).y;
    const auto started = std::chrono::steady_clock::now();

    std::filesystem::path out(o.output);
    std::error_code ec;
    if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path(), ec);
    engine::AtomicFile jsonFile;
    if (engine::Status s = jsonFile.open(out); !s) return fail(s.error());
    std::ostream& json = jsonFile.stream();
    json << fmt::format(
        "{{\"size\": [{}, {}], \"device\": {}, \"clock\": \"{}\", \"reference_spp\": {}, "
        "\"frames\": {}, \"seeds\": {}, "
        "\"statistics\": \"median, quartiles (type 7) and min-max over seeds; ratios: per-seed "
        "ratio row / versus row, "
        "then their median and spread\", \"scenes\": [\n",
        fs.width, fs.height, jsonString(gpu.info().name), cpuClock ? "cpu" : "gpu", o.referenceSpp,
        o.frames, o.seeds);

    std::filesystem::path csvPath = std::filesystem::path(out).replace_extension(".csv");
    engine::AtomicFile csvFile;
    if (engine::Status s = csvFile.open(csvPath); !s) return fail(s.error());
    std::ostream& csv = csvFile.stream();
    // One line per scene and row, medians over seeds: `vox bench recommend --sampling` reads it.
    // base = the row's settings without the sampling knob: rows that differ only by sampling share
    // it.
    csv << "scene,emitters,row,method,sampling,base,equal_time,ms,mse,mse_min,mse_max,mae,mae_min,"
           "mae_max,mean_ratio\n";

    std::string table =
        fmt::format("| scene | emitters | row | equal time | ms (÷ {}) | MSE | MAE | mean ratio |",
                    (*rows)[(*versus)[0]].name);
    std::string rule = "| --- | ---: | --- | ---: | ---: | ---: | ---: | ---: |";
    for (std::size_t v : *versus) {
        table += fmt::format(" MSE ÷ {0} | MAE ÷ {0} | MSE×time ÷ {0} [{1:.0f} % interval] |",
                             (*rows)[v].name, 100.0 * o.confidence);
        rule += " ---: | ---: | ---: |";
    }
    table += "\n" + rule + "\n";

    const std::size_t total = scenes.size() * rows->size() * o.seeds;
    std::size_t done = 0;
    for (std::size_t w = 0; w < scenes.size(); ++w) {
        engine::world::Scene& scene = scenes[w];
        engine::world::CameraPreset camera = scene.camera();
        auto cached =
            cachedReference(gpu, scene, camera, fs, o.referenceSpp, 0, out.parent_path() / "cache");
        if (!cached) return fail(cached.error());
        const std::vector<glm::vec4>& reference = *cached;
        std::vector<RowResult> results(rows->size());
        engine::render::Renderer renderer(gpu);  // one per scene: pipelines built once
        std::uint32_t emitters = 0;
        // Equal time first: each scaled row's count is fitted to the yardstick's time (the first
        // versus row), the two measured back to back so that other work on the machine slows both.
        const std::size_t timed = (*versus)[0];
        std::vector<LightingSettings> settings;
        for (const Row& row : *rows) settings.push_back(row.lighting);
        // A setting's time as a ratio to the yardstick's: the median of per-round ratios over
        // interleaved rounds, so a machine that slows down during the fit slows both.
        const engine::metrics::RoundsPlan fitRounds{1, 6, 10, 0.95, 0.05};
        auto ratioToYardstick = [&](const LightingSettings& l) {
            const LightingSettings* pair[2] = {&settings[timed], &l};
            auto t = engine::metrics::measureInterleaved(
                2,
                [&](std::size_t k) {
                    return timeOfPoint(measureSetting(renderer, scene, camera, fs, *pair[k],
                                                      o.frames, reference, ""));
                },
                fitRounds);
            return t.ratioToFirst[1];
        };
        for (std::size_t i = 0; i < rows->size(); ++i) {
            const Row& row = (*rows)[i];
            if (row.scale == EqualTime::None) continue;
            LightingSettings& l = settings[i];
            std::uint32_t& n =
                row.scale == EqualTime::ShadowRays ? l.shadowRays : l.restir.candidates;
            const std::uint32_t maxN =
                row.scale == EqualTime::ShadowRays ? 4096u : 1024u;  // the knobs' ranges
            std::fprintf(stderr, "  %s: %s: fitting its time to %s's\n", scene.name.c_str(),
                         row.name.c_str(), (*rows)[timed].name.c_str());
            // Fit ratio = base + slope x n from n = 1 and 16 (in units of the yardstick's time),
            // pick n for a ratio of 1, then up to three correction steps until within 10 %
            // (timings are not quite linear).
            n = 1;
            const double r1 = ratioToYardstick(l).median;
            n = 16;
            const double r16 = ratioToYardstick(l).median;
            const double slope = std::max((r16 - r1) / 15.0, 1e-3 * std::max(r1, 1e-3));
            const double base = r1 - slope;
            auto countFor =
                [&](double perUnit) {  // at least 1: the yardstick may be below the fitted base
                    return std::uint32_t(
                        std::clamp(std::round((1.0 - base) / perUnit), 1.0, double(maxN)));
                };
            std::fprintf(stderr, "    %s: time / %s's: %.3f at 1, %.3f at 16\n", row.name.c_str(),
                         (*rows)[timed].name.c_str(), r1, r16);
            n = countFor(slope);
            for (int step = 0; step < 3; ++step) {
                const engine::metrics::MedianInterval rn = ratioToYardstick(l);
                std::fprintf(stderr, "    %s: %u: %.3f (%.3f–%.3f) of %s's time\n",
                             row.name.c_str(), n, rn.median, rn.low, rn.high,
                             (*rows)[timed].name.c_str());
                if (std::abs(rn.median - 1.0) < 0.1) break;
                std::uint32_t next = countFor(std::max((rn.median - base) / double(n), 1e-6));
                if (next == n) break;
                n = next;
            }
            results[i].scaledTo = n;
        }
        // The time ratios the verdicts use: all rows at their fitted settings, interleaved.
        std::fprintf(stderr, "  %s: timing every row in interleaved rounds\n", scene.name.c_str());
        const engine::metrics::InterleavedTimes rounds = engine::metrics::measureInterleaved(
            rows->size(),
            [&](std::size_t i) {
                return timeOfPoint(measureSetting(renderer, scene, camera, fs, settings[i],
                                                  o.frames, reference, ""));
            },
            kCostRounds);
        for (std::size_t i = 0; i < rows->size(); ++i) results[i].roundMs = rounds.times[i];
        // Then the seeds, every row of a seed back to back: the per-seed time ratios compare
        // measurements close in time.
        for (std::uint32_t seed = 0; seed < o.seeds; ++seed) {
            for (std::size_t k = 0; k < rows->size(); ++k) {
                const std::size_t i =
                    seed % 2 == 0 ? k : rows->size() - 1 - k;  // A B .., .. B A: drift cancels
                LightingSettings l = settings[i];
                l.seed += seed * 104729u;  // far apart: memoryless rows step the seed per frame
                std::fprintf(stderr, "  [%zu/%zu] %s: %s, seed %u/%u\n", ++done, total,
                             scene.name.c_str(), (*rows)[i].name.c_str(), seed + 1, o.seeds);
                renderer.setFrameIndex(
                    0);  // a point depends on its settings and seed alone, not on what ran before
                SweepPoint p = measureSetting(renderer, scene, camera, fs, l, o.frames, reference,
                                              (*rows)[i].name);
                emitters = p.emitters;
                results[i].ms.push_back(timeOfPoint(p));
                results[i].mse.push_back(p.mse);
                results[i].mae.push_back(p.mae);
                results[i].meanRatio.push_back(p.meanRatio);
            }
        }
        const double targetMs = engine::metrics::summarize(results[timed].ms).median;

        // Per scene: JSON and table rows.
        json << fmt::format(
            "  {{\"scene\": {}, \"emitters\": {}, \"equal_time_ms\": {}, \"rows\": [\n",
            jsonString(scene.name), emitters, targetMs);
        std::printf("\n%s (%u emitters; median over %u seeds, min–max in brackets)\n",
                    scene.name.c_str(), emitters, o.seeds);
        for (std::size_t i = 0; i < rows->size(); ++i) {
            const Row& row = (*rows)[i];
            const RowResult& r = results[i];
            SeedSummary ms = engine::metrics::summarize(r.ms),
                        mse = engine::metrics::summarize(r.mse),
                        mae = engine::metrics::summarize(r.mae),
                        mean = engine::metrics::summarize(r.meanRatio);
            LightingSettings shown = row.lighting;
            if (row.scale == EqualTime::ShadowRays) shown.shadowRays = r.scaledTo;
            if (row.scale == EqualTime::Candidates) shown.restir.candidates = r.scaledTo;
            json << fmt::format(
                "    {{\"name\": {}, \"settings\": {}, \"sampling\": {}, \"equal_time\": {}, "
                "\"ms\": {}, \"mse\": {}, "
                "\"mae\": {}, \"mean_ratio\": {}, \"per_seed\": {{\"ms\": {}, \"mse\": {}, "
                "\"mae\": {}, \"mean_ratio\": {}}}, "
                "\"versus\": {{",
                jsonString(row.name),
                jsonString(settingsText(shown, row.scale == EqualTime::ShadowRays   ? "shadow_rays"
                                               : row.scale == EqualTime::Candidates ? "candidates"
                                                                                    : "")),
                jsonString(row.sampling),
                row.scale == EqualTime::None
                    ? "null"
                    : fmt::format("{{\"{}\": {}}}",
                                  row.scale == EqualTime::ShadowRays ? "shadow_rays" : "candidates",
                                  r.scaledTo),
                jsonSummary(ms), jsonSummary(mse), jsonSummary(mae), jsonSummary(mean),
                jsonArray(r.ms), jsonArray(r.mse), jsonArray(r.mae), jsonArray(r.meanRatio));
            LightingSettings base = shown;
            (void)setKnob(knob("sampling"), base,
                          knobText(knob("sampling"), LightingSettings{}));  // the default is valid
            if (row.scale == EqualTime::None) {  // the scaled knob is no part of what the row is
                csv << fmt::format("{},{},\"{}\",{},{},\"{}\",{},{},{},{},{},{},{},{},{}\n",
                                   scene.name, emitters, row.name, methodName(shown), row.sampling,
                                   settingsText(base), r.scaledTo, ms.median, mse.median, mse.min,
                                   mse.max, mae.median, mae.min, mae.max, mean.median);
            } else {
                csv << fmt::format("{},{},\"{}\",{},{},\"\",{},{},{},{},{},{},{},{},{}\n",
                                   scene.name, emitters, row.name, methodName(shown), row.sampling,
                                   r.scaledTo, ms.median, mse.median, mse.min, mse.max, mae.median,
                                   mae.min, mae.max, mean.median);
            }
            std::printf("  %-28s %-9s %7.2f ms  MSE %s  MAE %s  mean %s", row.name.c_str(),
                        scaledText(row, r).c_str(), ms.median, cell(mse, "{:.2e}").c_str(),
                        cell(mae, "{:.2e}").c_str(), cell(mean, "{:.2f}").c_str());
            const double timeRatio =
                engine::metrics::summarize(engine::metrics::perSeedRatios(r.ms, results[timed].ms))
                    .median;
            table +=
                fmt::format("| {} | {} | {} | {} | {:.2f} ({:.2f}×) | {} | {} | {} |", scene.name,
                            emitters, row.name, scaledText(row, r), ms.median, timeRatio,
                            cell(mse, "{:.2e}"), cell(mae, "{:.2e}"), cell(mean, "{:.2f}"));
            for (std::size_t k = 0; k < versus->size(); ++k) {
                const RowResult& d = results[(*versus)[k]];
                SeedSummary mseRatio =
                    engine::metrics::summarize(engine::metrics::perSeedRatios(r.mse, d.mse));
                SeedSummary maeRatio =
                    engine::metrics::summarize(engine::metrics::perSeedRatios(r.mae, d.mae));
                SeedSummary msRatio =
                    engine::metrics::summarize(engine::metrics::perSeedRatios(r.ms, d.ms));
                const engine::metrics::MedianInterval work =
                    workNormalisedRatio(r, d, o.confidence);
                const std::string_view verdict =
                    engine::metrics::verdictName(engine::metrics::verdictOf(work, o.confidence));
                const engine::metrics::MedianInterval time = engine::metrics::medianInterval(
                    engine::metrics::perSeedRatios(r.roundMs, d.roundMs), kCostRounds.confidence);
                json << fmt::format(
                    "{}{}: {{\"mse_ratio\": {}, \"mae_ratio\": {}, \"ms_ratio\": {}, "
                    "\"time_ratio\": {}, "
                    "\"mse_time_ratio\": {}}}",
                    k ? ", " : "", jsonString((*rows)[(*versus)[k]].name), jsonSummary(mseRatio),
                    jsonSummary(maeRatio), jsonSummary(msRatio),
                    jsonInterval(time, kCostRounds.confidence), jsonInterval(work, o.confidence));
                if ((*versus)[k] == i) {
                    table += " — | — | — |";
                    continue;
                }
                table += fmt::format(
                    " **{:.2f}×** ({:.2f}–{:.2f}) | {:.2f}× ({:.2f}–{:.2f}) | {:.2f}× "
                    "[{:.2f}–{:.2f}] {} |",
                    mseRatio.median, mseRatio.min, mseRatio.max, maeRatio.median, maeRatio.min,
                    maeRatio.max, work.median, work.low, work.high, verdict);
                std::printf("  ÷%s MSE %.2fx MAE %.2fx MSE×time %.2fx [%.2f–%.2f] %s",
                            (*rows)[(*versus)[k]].name.c_str(), mseRatio.median, maeRatio.median,
                            work.median, work.low, work.high, std::string(verdict).c_str());
            }
            std::printf("\n");
            table += "\n";
            json << "}}" << (i + 1 < rows->size() ? "," : "") << "\n";
        }
        json << "  ]}" << (w + 1 < scenes.size() ? "," : "") << "\n";
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    json << fmt::format("], \"wall_seconds\": {}}}\n", seconds);
    if (engine::Status s = jsonFile.commit(); !s) return fail(s.error());
    if (engine::Status s = csvFile.commit(); !s) return fail(s.error());
    std::printf(
        "\nratio = row / versus row per seed, median (min–max): above 1 favours the versus row "
        "(ReSTIR)\n");
    std::printf(
        "MSE×time: the work-normalised ratio; its interval: the sign test's over seeds (MSE) times "
        "over %u+ "
        "interleaved rounds (time); \"> 1\" (the versus row wins) or \"< 1\" only when it excludes "
        "1 with %.0f %% "
        "coverage, else unresolved\n",
        kCostRounds.minRounds, 100.0 * o.confidence);
    std::printf("wall time %.0f s (references included; cached ones are read back)\n", seconds);
    std::printf("wrote    %s\nwrote    %s\n", out.string().c_str(), csvPath.string().c_str());
    if (!o.markdown.empty()) {
        std::filesystem::path md(o.markdown);
        if (md.has_parent_path()) std::filesystem::create_directories(md.parent_path(), ec);
        engine::AtomicFile mdFile;
        if (engine::Status s = mdFile.open(md); !s) return fail(s.error());
        mdFile.stream() << table;
        if (engine::Status s = mdFile.commit(); !s) return fail(s.error());
        std::printf("wrote    %s\n", md.string().c_str());
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
    cmd->add_flag(
        "--quick", o->quick,
        "A first look: 64x40, 8 frames, 256 spp reference (over --size, --frames, --ref-spp)");
    cmd->add_option("-o,--output", o->output, "JSON results file")->capture_default_str();
    cmd->add_option("--markdown", o->markdown, "Also write the table as markdown here");
    cmd->callback([o, &exitCode] { exitCode = runRestirBench(*o); });
}

}  // namespace vox
