// vox bench restir --counts-from: the scaled rows' equal-cost counts of an earlier run, read from
// its JSON ("scenes"[].rows[].equal_time), so that repeated runs render the same settings and only
// the cost model (calibrated in each run) moves their MSE x cost ratios.
#include <fstream>
#include <sstream>

#include "core/json.h"
#include "restir_bench.h"

namespace vox {

engine::Result<PinnedCounts> readPinnedCounts(const std::string& path) {
    std::ifstream in(path);
    if (!in) return engine::makeError("--counts-from {}: cannot read it", path);
    std::stringstream text;
    text << in.rdbuf();
    auto json = engine::parseJson(text.str(), path);
    if (!json) return json.error();
    PinnedCounts out;
    for (const engine::Json& scene : json->get("scenes").items()) {
        for (const engine::Json& row : scene.get("rows").items()) {
            const std::pair key{scene.get("scene").string(), row.get("name").string()};
            for (const auto& [knob, count] : row.get("equal_time").members())
                out[key] = count.number();
            // Since the count ladder: the exact count, not its rounding.
            if (row.get("equal_count").isNumber()) out[key] = row.get("equal_count").number();
        }
    }
    if (out.empty())
        return engine::makeError(
            "--counts-from {}: no equal-cost counts (not a bench restir JSON?)", path);
    return out;
}

}  // namespace vox
