// vox bench restir's rows: lighting knobs, so new modes are rows without code.
#include <algorithm>
#include <fmt/format.h>
#include <sstream>

#include "lighting/lighting_knobs.h"
#include "lighting_options.h"
#include "restir_bench.h"

namespace vox {

namespace {

using engine::lighting::KnobValue;
using engine::lighting::LightingSettings;
using engine::lighting::Method;

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
    return Row{std::move(name), *l, scaleOf(*l, values), samplingText(*l)};
}

// A default row: uniform light sampling, or a resampling method per --sampling value.
engine::Status addDefaultRows(std::vector<Row>& rows, const std::string& name,
                              const std::vector<std::string>& samplings) {
    if (name == "uniform") {  // uniform light sampling: no candidates, lights drawn uniformly
        auto row = makeRow(name, {{&knob("method"), "uniform", "--rows"},
                                  {&knob("sampling"), "uniform", "--rows"}});
        if (!row) return row.error();
        rows.push_back(*row);
        return {};
    }
    if (name != "restir" && name != "restir-unbiased" && name != "ris")
        return engine::makeError("--rows: '{}' is not restir, restir-unbiased, ris or uniform",
                                 name);
    for (const std::string& sampling : samplings) {
        std::vector<KnobValue> values{{&knob("method"), name, "--rows"}};
        if (!sampling.empty()) values.push_back({&knob("sampling"), sampling, "--sampling"});
        auto row = makeRow(sampling.empty() ? name : fmt::format("{} sampling={}", name, sampling),
                           values);
        if (!row) return row.error();
        rows.push_back(*row);
    }
    return {};
}

// A --variant "NAME:--knob value ..." row.
engine::Result<Row> variantRow(const std::string& v) {
    std::size_t colon = v.find(':');
    if (colon == std::string::npos || colon == 0)
        return engine::makeError("--variant '{}': expected NAME:--knob value ...", v);
    auto values =
        knobValuesOf(v.substr(colon + 1), fmt::format("--variant {}", v.substr(0, colon)));
    if (!values) return values.error();
    return makeRow(v.substr(0, colon), *values);
}

}  // namespace

engine::Result<std::vector<Row>> rowsOf(const RestirBenchOptions& o) {
    std::vector<std::string> samplings = splitOn(o.sampling, ',');
    if (samplings.empty()) samplings.push_back("");
    std::vector<Row> rows;
    for (const std::string& name : splitOn(o.rows, ',')) {
        if (engine::Status s = addDefaultRows(rows, name, samplings); !s) return s.error();
    }
    for (const std::string& v : o.variants) {
        auto row = variantRow(v);
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

std::string settingsText(const LightingSettings& l, std::string_view also) {
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

std::string methodName(const LightingSettings& l) {
    return l.method == Method::Restir && l.restir.unbiased ? "restir-unbiased"
                                                           : engine::lighting::methodName(l.method);
}

std::string samplingText(const LightingSettings& l) { return knobText(knob("sampling"), l); }

LightingSettings withDefaultSampling(LightingSettings l) {
    (void)setKnob(knob("sampling"), l,
                  knobText(knob("sampling"), LightingSettings{}));  // the default is valid
    return l;
}

}  // namespace vox
