#include "restir_bench_report.h"

#include <cstdio>
#include <fmt/format.h>

#include "bench_setup.h"
#include "metrics/median_interval.h"
#include "metrics/seed_statistics.h"

namespace vox {

namespace {

using engine::lighting::LightingSettings;
using engine::metrics::SeedSummary;

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

// A row's MSE x cost over the versus row's: the work-normalised error ratio (inverse relative
// efficiency), which an imperfect equal-cost count barely moves (MSE ~ 1 / samples). The cost is
// the model's (counted work at calibrated per-kind costs), not a clock reading. The MSE ratio's
// interval over seeds (the renders are deterministic: seeds are the only randomness) times the
// cost ratio's over the calibration rounds; its coverage is the product of the two.
engine::metrics::MedianInterval workNormalisedRatio(const SceneResults& s, std::size_t i,
                                                    std::size_t v, double confidence) {
    using namespace engine::metrics;
    return productInterval(medianInterval(perSeedRatios(s.rows[i].mse, s.rows[v].mse), confidence),
                           costRatio(s, i, v));
}

std::string jsonInterval(const engine::metrics::MedianInterval& m, double confidence,
                         double noise = 0.0) {
    return fmt::format(
        "{{\"median\": {}, \"low\": {}, \"high\": {}, \"coverage\": {}, \"verdict\": \"{}\"}}",
        m.median, m.low, m.high, m.covered,
        engine::metrics::verdictName(engine::metrics::verdictOf(m, confidence, noise)));
}

// The calibration: per-kind costs (in the yardstick's frame time) with the rounds' intervals,
// and every point's counted work and times.
std::string jsonModel(const SceneResults& r) {
    std::string kinds;
    for (std::size_t k = 0; k < engine::render::kWorkKinds; ++k) {
        const engine::metrics::MedianInterval& m = r.model.perKindInterval[k];
        kinds += fmt::format(
            "{}{}: {{\"cost\": {}, \"low\": {}, \"high\": {}}}", k ? ", " : "",
            jsonString(std::string(engine::render::workKindName(engine::render::WorkKind(k)))),
            r.model.perKind[k], m.low, m.high);
    }
    std::string points;
    for (const CalibrationPoint& p : r.calibration) {
        points += fmt::format("{}{{\"label\": {}, \"work\": {}, \"round_ms\": {}}}",
                              points.empty() ? "" : ", ", jsonString(p.label),
                              jsonArray({p.work.count.begin(), p.work.count.end()}),
                              jsonArray(p.roundMs));
    }
    return fmt::format("{{\"kinds\": {{{}}}, \"worst_residual\": {}, \"points\": [{}]}}", kinds,
                       r.model.worstResidual, points);
}

// "M = 98.3 (64–128)": the equal-cost count and the rungs it is interpolated between.
std::string scaledText(const Row& row, const RowResult& r) {
    const std::string rungs =
        r.ladder.high > r.ladder.low ? fmt::format(" ({}–{})", r.ladder.low, r.ladder.high) : "";
    if (row.scale == EqualTime::ShadowRays)
        return fmt::format("{:.1f} rays{}", r.equalCount, rungs);
    if (row.scale == EqualTime::Candidates) return fmt::format("M = {:.1f}{}", r.equalCount, rungs);
    return "";
}

// The rungs' per-seed measurements, for a scaled row.
std::string jsonRungs(const RowResult& r) {
    std::string out;
    const std::uint32_t counts[2] = {r.ladder.low, r.ladder.high};
    for (int k = 0; k < (r.ladder.high > r.ladder.low ? 2 : 1); ++k) {
        const RungResult& g = r.rungs[k];
        out += fmt::format(
            "{}{{\"count\": {}, \"ms\": {}, \"mse\": {}, \"mae\": {}, \"mean_ratio\": {}}}",
            k ? ", " : "", counts[k], jsonArray(g.ms), jsonArray(g.mse), jsonArray(g.mae),
            jsonArray(g.meanRatio));
    }
    return "[" + out + "]";
}

// The scaled knob's name in the JSON, empty for an unscaled row.
std::string_view scaledKnob(const Row& row) {
    return row.scale == EqualTime::ShadowRays   ? "shadow_rays"
           : row.scale == EqualTime::Candidates ? "candidates"
                                                : "";
}

// The row's settings with the scaled knob at its fitted count.
LightingSettings shownSettings(const Row& row, const RowResult& r) {
    LightingSettings shown = row.lighting;
    if (row.scale == EqualTime::ShadowRays) shown.shadowRays = r.scaledTo;
    if (row.scale == EqualTime::Candidates) shown.restir.candidates = r.scaledTo;
    return shown;
}

}  // namespace

engine::Status RestirReport::open(const std::filesystem::path& out, const std::string& device) {
    const RestirBenchOptions& o = mSetup.options;
    if (engine::Status s = openOutputFile(mJson, out); !s) return s;
    mJson.stream() << fmt::format(
        "{{\"size\": [{}, {}], \"device\": {}, \"clock\": \"{}\", \"reference_spp\": {}, "
        "\"frames\": {}, \"seeds\": {}, \"noise\": {}, \"cost_drift\": {}, "
        "\"statistics\": \"median, quartiles (type 7) and min-max over seeds; ratios: per-seed "
        "ratio row / versus row, "
        "then their median and spread\", \"scenes\": [\n",
        mSetup.frame.width, mSetup.frame.height, jsonString(device),
        mSetup.cpuClock ? "cpu" : "gpu", o.referenceSpp, o.frames, o.seeds, o.noise, o.costDrift);

    mCsvPath = std::filesystem::path(out).replace_extension(".csv");
    if (engine::Status s = mCsv.open(mCsvPath); !s) return s;
    // One line per scene and row, medians over seeds: `vox bench recommend --sampling` reads it.
    // base = the row's settings without the sampling knob: rows that differ only by sampling share
    // it.
    mCsv.stream()
        << "scene,emitters,row,method,sampling,base,equal_time,ms,mse,mse_min,mse_max,mae,mae_min,"
           "mae_max,mean_ratio\n";

    mTable = fmt::format(
        "| scene | emitters | row | equal cost | cost ÷ {0} | ms (÷ {0}) | MSE | MAE | "
        "mean ratio |",
        mSetup.rows[mSetup.versus[0]].name);
    std::string rule = "| --- | ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: |";
    for (std::size_t v : mSetup.versus) {
        mTable += fmt::format(" MSE ÷ {0} | MAE ÷ {0} | MSE×cost ÷ {0} [{1:.0f} % interval] |",
                              mSetup.rows[v].name, 100.0 * o.confidence);
        rule += " ---: | ---: | ---: |";
    }
    mTable += "\n" + rule + "\n";
    return {};
}

void RestirReport::addScene(const std::string& scene, const SceneResults& results, bool last) {
    mJson.stream() << fmt::format(
        "  {{\"scene\": {}, \"emitters\": {}, \"yardstick_ms\": {}, \"cost_model\": {}, "
        "\"rows\": [\n",
        jsonString(scene), results.emitters, results.targetMs, jsonModel(results));
    std::printf("\n%s (%u emitters; median over %u seeds, min–max in brackets)\n", scene.c_str(),
                results.emitters, mSetup.options.seeds);
    for (std::size_t i = 0; i < mSetup.rows.size(); ++i) addRow(scene, results, i);
    mJson.stream() << "  ]}" << (last ? "" : ",") << "\n";
}

void RestirReport::addRow(const std::string& scene, const SceneResults& results, std::size_t i) {
    const Row& row = mSetup.rows[i];
    const RowResult& r = results.rows[i];
    const std::uint32_t emitters = results.emitters;
    SeedSummary ms = engine::metrics::summarize(r.ms), mse = engine::metrics::summarize(r.mse),
                mae = engine::metrics::summarize(r.mae),
                mean = engine::metrics::summarize(r.meanRatio);
    const LightingSettings shown = shownSettings(row, r);
    mJson.stream() << fmt::format(
        "    {{\"name\": {}, \"settings\": {}, \"sampling\": {}, \"equal_time\": {}, "
        "\"equal_count\": {}, \"fitted_count\": {}, \"ladder\": {}, \"ms\": {}, \"mse\": {}, "
        "\"mae\": {}, \"mean_ratio\": {}, \"per_seed\": {{\"ms\": {}, \"mse\": {}, "
        "\"mae\": {}, \"mean_ratio\": {}}}, "
        "\"versus\": {{",
        jsonString(row.name), jsonString(settingsText(shown, scaledKnob(row))),
        jsonString(row.sampling),
        row.scale == EqualTime::None ? "null"
                                     : fmt::format("{{\"{}\": {}}}", scaledKnob(row), r.scaledTo),
        row.scale == EqualTime::None ? "null" : fmt::format("{}", r.equalCount),
        row.scale == EqualTime::None ? "null" : fmt::format("{}", r.fittedCount),
        row.scale == EqualTime::None ? "null" : jsonRungs(r), jsonSummary(ms), jsonSummary(mse),
        jsonSummary(mae), jsonSummary(mean), jsonArray(r.ms), jsonArray(r.mse), jsonArray(r.mae),
        jsonArray(r.meanRatio));
    // The scaled knob is no part of what the row is.
    const std::string base =
        row.scale == EqualTime::None ? settingsText(withDefaultSampling(shown)) : "";
    mCsv.stream() << fmt::format("{},{},\"{}\",{},{},\"{}\",{},{},{},{},{},{},{},{},{}\n", scene,
                                 emitters, row.name, methodName(shown), row.sampling, base,
                                 r.scaledTo, ms.median, mse.median, mse.min, mse.max, mae.median,
                                 mae.min, mae.max, mean.median);
    std::printf("  %-28s %-20s %7.2f ms  MSE %s  MAE %s  mean %s", row.name.c_str(),
                scaledText(row, r).c_str(), ms.median, cell(mse, "{:.2e}").c_str(),
                cell(mae, "{:.2e}").c_str(), cell(mean, "{:.2f}").c_str());
    const double timeRatio =
        engine::metrics::summarize(
            engine::metrics::perSeedRatios(r.ms, results.rows[mSetup.versus[0]].ms))
            .median;
    const engine::metrics::MedianInterval cost = costRatio(results, i, mSetup.versus[0]);
    mTable += fmt::format(
        "| {} | {} | {} | {} | {:.2f} [{:.2f}–{:.2f}] | {:.2f} ({:.2f}×) | {} | "
        "{} | {} |",
        scene, emitters, row.name, scaledText(row, r), cost.median, cost.low, cost.high, ms.median,
        timeRatio, cell(mse, "{:.2e}"), cell(mae, "{:.2e}"), cell(mean, "{:.2f}"));
    addVersus(r, i, results);
    std::printf("\n");
    mTable += "\n";
    mJson.stream() << "}}" << (i + 1 < mSetup.rows.size() ? "," : "") << "\n";
}

// Row i against each versus row: error ratios per seed, the cost ratio under the model and the
// verdict of their product; the time ratio per seed beside them.
void RestirReport::addVersus(const RowResult& r, std::size_t i, const SceneResults& results) {
    const double confidence = mSetup.options.confidence;
    for (std::size_t k = 0; k < mSetup.versus.size(); ++k) {
        const std::size_t v = mSetup.versus[k];
        const RowResult& d = results.rows[v];
        SeedSummary mseRatio =
            engine::metrics::summarize(engine::metrics::perSeedRatios(r.mse, d.mse));
        SeedSummary maeRatio =
            engine::metrics::summarize(engine::metrics::perSeedRatios(r.mae, d.mae));
        SeedSummary msRatio =
            engine::metrics::summarize(engine::metrics::perSeedRatios(r.ms, d.ms));
        const engine::metrics::MedianInterval work = workNormalisedRatio(results, i, v, confidence);
        const std::string_view verdict = engine::metrics::verdictName(
            engine::metrics::verdictOf(work, confidence, mSetup.options.noise));
        // The clock's view beside the model's: time per seed (rows interleaved A B .., .. B A).
        const engine::metrics::MedianInterval time =
            engine::metrics::medianInterval(engine::metrics::perSeedRatios(r.ms, d.ms), confidence);
        const engine::metrics::MedianInterval cost = costRatio(results, i, v);
        mJson.stream() << fmt::format(
            "{}{}: {{\"mse_ratio\": {}, \"mae_ratio\": {}, \"ms_ratio\": {}, "
            "\"time_ratio\": {}, \"cost_ratio\": {}, "
            "\"mse_cost_ratio\": {}}}",
            k ? ", " : "", jsonString(mSetup.rows[v].name), jsonSummary(mseRatio),
            jsonSummary(maeRatio), jsonSummary(msRatio), jsonInterval(time, confidence),
            jsonInterval(cost, kCostRounds.confidence),
            jsonInterval(work, confidence, mSetup.options.noise));
        if (v == i) {
            mTable += " — | — | — |";
            continue;
        }
        mTable += fmt::format(
            " **{:.2f}×** ({:.2f}–{:.2f}) | {:.2f}× ({:.2f}–{:.2f}) | {:.2f}× "
            "[{:.2f}–{:.2f}] {} |",
            mseRatio.median, mseRatio.min, mseRatio.max, maeRatio.median, maeRatio.min,
            maeRatio.max, work.median, work.low, work.high, verdict);
        std::printf("  ÷%s MSE %.2fx MAE %.2fx MSE×cost %.2fx [%.2f–%.2f] %s",
                    mSetup.rows[v].name.c_str(), mseRatio.median, maeRatio.median, work.median,
                    work.low, work.high, std::string(verdict).c_str());
    }
}

engine::Status RestirReport::commit(double wallSeconds) {
    mJson.stream() << fmt::format("], \"wall_seconds\": {}}}\n", wallSeconds);
    if (engine::Status s = mJson.commit(); !s) return s;
    return mCsv.commit();
}

}  // namespace vox
