#include "capture_csv.h"

#include <algorithm>
#include <fmt/format.h>

namespace vox {

std::string captureCsvText(const std::vector<CaptureCsvRow>& rows) {
    std::vector<std::string> passes;
    for (const CaptureCsvRow& r : rows)
        for (const auto& [name, ms] : r.passMs)
            if (std::find(passes.begin(), passes.end(), name) == passes.end())
                passes.push_back(name);
    std::string csv;
    if (!rows.empty()) {
        for (const auto& [name, value] : rows.front().fields)
            csv += (csv.empty() ? "" : ",") + name;
    }
    for (const std::string& p : passes) csv += ",gpu_" + p + "_ms";
    csv += ",gpu_total_ms,cpu_emitter_update_ms,wall_ms\n";
    for (const CaptureCsvRow& r : rows) {
        std::string line;
        for (const auto& [name, value] : r.fields) line += (line.empty() ? "" : ",") + value;
        for (const std::string& p : passes) {
            line += ",";
            for (const auto& [name, ms] : r.passMs) {
                if (name != p) continue;
                line += fmt::format("{:.4f}", ms);
                break;
            }
        }
        line +=
            fmt::format(",{:.4f},{:.4f},{:.2f}\n", r.gpuTotalMs, r.cpuEmitterUpdateMs, r.wallMs);
        csv += line;
    }
    return csv;
}

engine::Json captureCsvRowJson(const CaptureCsvRow& row) {
    engine::Json j;
    engine::Json& fields = j["fields"];
    fields = engine::Json::object();
    for (const auto& [name, value] : row.fields) fields[name] = value;
    engine::Json& passes = j["pass_ms"];
    passes = engine::Json::object();
    for (const auto& [name, ms] : row.passMs) passes[name] = ms;
    j["gpu_total_ms"] = row.gpuTotalMs;
    j["cpu_emitter_update_ms"] = row.cpuEmitterUpdateMs;
    j["wall_ms"] = row.wallMs;
    return j;
}

engine::Result<CaptureCsvRow> captureCsvRowFrom(const engine::Json& json) {
    if (!json.get("fields").isObject() || !json.get("pass_ms").isObject())
        return engine::makeError("a frame record without its CSV row");
    CaptureCsvRow row;
    for (const auto& [name, value] : json.get("fields").members())
        row.fields.emplace_back(name, value.string());
    for (const auto& [name, ms] : json.get("pass_ms").members())
        row.passMs.emplace_back(name, ms.number());
    row.gpuTotalMs = json.get("gpu_total_ms").number();
    row.cpuEmitterUpdateMs = json.get("cpu_emitter_update_ms").number();
    row.wallMs = json.get("wall_ms").number();
    return row;
}

}  // namespace vox
