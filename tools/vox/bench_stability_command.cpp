// vox bench stability: how the lighting methods behave over time and where they are known to
// fail — flicker on a still camera, frames to recover after edits, and the failure cases of the
// thesis and the literature. Each case is a scene, a scenario and a metric; results go to a
// table (markdown), a CSV of per-frame errors and a chart (tools/plot_stability.py).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>

#include "bench_setup.h"
#include "commands.h"
#include "core/atomic_file.h"
#include "gpu/context.h"
#include "stability_bench.h"

namespace vox {

namespace {

struct StabilityOptions {
    std::string size = "96x64";
    std::string output = "out/stability";
    std::string cases =
        "all";  // all | vct | sky (only voxel cone tracing's or DVF sky light's rows)
};

// The cases of each --cases value, in the table's order.
using Cases = engine::Status (*)(StabilityContext&);
const std::vector<Cases>& casesOf(const std::string& name) {
    static const std::vector<Cases> all{restirCases, vctCases, skyCases}, vct{vctCases},
        sky{skyCases};
    return name == "vct" ? vct : name == "sky" ? sky : all;
}

// The table and the chart of the curves.
engine::Status writeTable(const StabilityContext& c, const std::filesystem::path& out) {
    engine::AtomicFile mdFile;
    if (engine::Status s = mdFile.open(out / "stability_table.md"); !s) return s;
    std::ostream& md = mdFile.stream();
    md << fmt::format(
        "Measured on {} at {}x{}.\n\n| case | method | result |\n| --- | --- | --- |\n",
        c.gpu.info().name, c.frame.width, c.frame.height);
    for (const std::string& row : c.rows) md << row << "\n";
    return mdFile.commit();
}

void drawChart(const std::filesystem::path& out) {
    std::string plot = fmt::format("/usr/bin/python3 {}/tools/plot_stability.py {} {}",
                                   VOX_SOURCE_DIR, (out / "response.csv").string(), out.string());
    if (std::system(plot.c_str()) != 0)
        std::fprintf(stderr, "note: chart not drawn (needs python3-matplotlib)\n");
}

int runStability(const StabilityOptions& o) {
    auto bench = openBench(o.size);
    if (!bench) return fail(bench.error());
    std::filesystem::path out(o.output);
    std::filesystem::create_directories(out);
    engine::AtomicFile curvesFile;
    if (engine::Status s = curvesFile.open(out / "response.csv"); !s) return fail(s.error());
    std::ostream& curves = curvesFile.stream();
    curves << "case,method,frame,mae\n";
    StabilityContext c{*bench->gpu, bench->frame, out / "cache", curves, {}, o.output, {}};
    for (Cases cases : casesOf(o.cases)) {
        if (engine::Status s = cases(c); !s) return fail(s.error());
    }
    if (engine::Status s = writeTable(c, out); !s) return fail(s.error());
    if (engine::Status s = curvesFile.commit(); !s) return fail(s.error());
    drawChart(out);
    std::printf("wrote    %s and response.csv\n", (out / "stability_table.md").string().c_str());
    return 0;
}

}  // namespace

void addBenchStabilityCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand("stability",
                                     "Flicker, response to edits, and the known failure cases");
    auto o = std::make_shared<StabilityOptions>();
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("-o,--output", o->output, "Output folder")->capture_default_str();
    cmd->add_option("--cases", o->cases,
                    "all | vct | sky (only voxel cone tracing's or DVF sky light's rows)")
        ->check(CLI::IsMember({"all", "vct", "sky"}))
        ->capture_default_str();
    cmd->callback([o, &exitCode] { exitCode = runStability(*o); });
}

}  // namespace vox
