// vox bench sweep: lighting methods x settings on each scene, each point's time and error from
// the same run, written as CSV/JSON and charted (error against milliseconds, Pareto front joined,
// tools/plot_sweep.py). vox bench recommend: the cheapest setting a sweep found that meets a
// target error on a scene — model no more than the scene needs; with --sampling, ReSTIR's
// candidate sampling per scene from `vox bench restir`'s seeds.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "core/atomic_file.h"
#include "commands.h"
#include "number_options.h"
#include "gpu/context.h"
#include "lighting/emitter_list.h"
#include "lighting_options.h"
#include "sweep_runner.h"

namespace vox {

namespace {

using engine::lighting::LightingSettings;
using engine::lighting::Method;

struct SweepOptions {
    std::vector<std::string> worlds{"cornell", "mountain", "letters", "apartments"};
    std::string methods = "restir,restir-unbiased,ris,uniform";
    std::string candidates = "1,8,32";
    std::string modes = "point,area";
    std::string brickLights = "on,off";
    std::string rays = "1,4,16";
    std::string size = "128x72";
    std::uint32_t frames = 12;
    std::uint32_t referenceSpp = 1024;
    // Indirect-light series (docs/ACCURACY.md): ReSTIR's defaults for the direct light plus
    // none | cache-K | reference, measured against a multi-bounce reference.
    std::string indirect = "none,cache-32,cache-128,reference,vct";
    std::uint32_t indirectBounces = 3;
    std::uint32_t indirectReferenceSpp = 512;
    std::string output = "out/sweep";
};

std::vector<std::string> splitList(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream in(s);
    std::string item;
    while (std::getline(in, item, ',')) {
        if (!item.empty()) out.push_back(item);
    }
    return out;
}

engine::Result<std::vector<std::uint32_t>> numbers(const std::string& s, const char* option) {
    std::vector<std::uint32_t> out;
    for (const std::string& item : splitList(s)) {
        char* end = nullptr;
        unsigned long v = std::strtoul(item.c_str(), &end, 10);
        if (!end || *end || v < 1 || v > 4096) return engine::makeError("{}: '{}' is not a number in 1..4096", option, item);
        out.push_back(std::uint32_t(v));
    }
    if (out.empty()) return engine::makeError("{}: empty list", option);
    return out;
}

// All settings of the sweep, labelled.
engine::Result<std::vector<std::pair<std::string, LightingSettings>>> settingsOf(const SweepOptions& o) {
    auto ms = numbers(o.candidates, "--candidates");
    if (!ms) return ms.error();
    auto rays = numbers(o.rays, "--rays");
    if (!rays) return rays.error();
    std::vector<std::pair<std::string, LightingSettings>> out;
    for (const std::string& method : splitList(o.methods)) {
        for (const std::string& mode : splitList(o.modes)) {
            if (mode != "point" && mode != "area") return engine::makeError("--modes: '{}' is not point or area", mode);
            for (const std::string& bricks : splitList(o.brickLights)) {
                if (bricks != "on" && bricks != "off") return engine::makeError("--brick-lights: '{}' is not on or off", bricks);
                const std::vector<engine::lighting::KnobValue> values{
                    {engine::lighting::knobForOption("method"), method, "--methods"},
                    {engine::lighting::knobForOption("mode"), mode, "--modes"},
                    {engine::lighting::knobForOption("brick-lights"), bricks, "--brick-lights"}};
                auto base = engine::lighting::mergeLighting(LightingSettings{}, values);
                if (!base) return base.error();
                std::string tag = fmt::format("{} {}{}", method, mode, bricks == "off" ? " voxels" : "");
                if (base->method == Method::Uniform) {
                    for (std::uint32_t n : *rays) {
                        LightingSettings l = *base;
                        l.shadowRays = n;
                        out.push_back({fmt::format("{} {} rays", tag, n), l});
                    }
                } else if (base->method == Method::Restir || base->method == Method::Ris) {
                    for (std::uint32_t m : *ms) {
                        LightingSettings l = *base;
                        l.restir.candidates = m;
                        out.push_back({fmt::format("{} M={}", tag, m), l});
                    }
                } else {
                    out.push_back({tag, *base});
                }
            }
        }
    }
    for (const auto& [tag, l] : out) {  // --candidates and --rays may leave the knobs' ranges
        if (engine::Status valid = engine::lighting::validate(l); !valid) return engine::makeError("{}: {}", tag, valid.error().message);
    }
    return out;
}

// The indirect-light series, labelled: ReSTIR (biased, area, M = 32: the defaults) for the
// direct light and, for the indirect light, nothing, the irradiance cache with K directions per
// face, or the path tracer with the same bounces as the reference it is measured against (one
// sample per pixel, restarted every frame). The cache reads its own irradiance at each ray's hit
// for the same number of bounces, so all three aim at the same converged image.
engine::Result<std::vector<std::pair<std::string, LightingSettings>>> indirectSettingsOf(const SweepOptions& o) {
    using engine::lighting::Indirect;
    std::vector<std::pair<std::string, LightingSettings>> out;
    for (const std::string& item : splitList(o.indirect)) {
        LightingSettings l;
        if (item == "none") {
            out.push_back({"indirect none (restir)", l});
        } else if (item == "reference") {
            l.method = Method::Reference;
            l.referenceFilter = engine::lighting::ReferenceFilter::PixelCentre;  // as the reference it is measured against
            l.indirect = Indirect::Reference;
            l.bounces = o.indirectBounces;
            l.samplesPerFrame = 1;
            out.push_back({fmt::format("indirect reference {} bounces 1 spp", o.indirectBounces), l});
        } else if (item.rfind("cache-", 0) == 0) {
            auto k = numbers(item.substr(6), "--indirect cache-K");
            if (!k) return k.error();
            l.indirect = Indirect::Cache;
            l.cache.directions = k->front();
            l.cache.raysPerUpdate = std::min(l.cache.raysPerUpdate, l.cache.directions);
            l.cache.bounces = o.indirectBounces;
            if (engine::Status valid = engine::lighting::validate(l); !valid)
                return engine::makeError("--indirect {}: {}", item, valid.error().message);
            out.push_back({fmt::format("indirect cache K={}", k->front()), l});
        } else if (item == "vct" || item == "vct-leaky") {
            // Voxel cone tracing (one bounce; the extra bounce with 2+ reference bounces), with its
            // leak mitigation on, or off (vct-leaky).
            l.indirect = Indirect::Vct;
            l.vct.leakMitigation = item == "vct";
            l.vct.extraBounce = o.indirectBounces > 1;
            out.push_back({item == "vct" ? "indirect vct" : "indirect vct no leak mitigation", l});
        } else {
            return engine::makeError("--indirect: '{}' is not none, cache-K, vct, vct-leaky or reference", item);
        }
    }
    return out;
}

const char* indirectColumn(const LightingSettings& l) {
    return engine::lighting::indirectName(l.method == Method::Reference ? engine::lighting::Indirect::Reference : l.indirect);
}

int runSweep(const SweepOptions& o) {
    auto size = parseSize(o.size, "--size");
    if (!size) return fail(size.error());
    auto settings = settingsOf(o);
    if (!settings) return fail(settings.error());
    auto indirect = indirectSettingsOf(o);
    if (!indirect) return fail(indirect.error());
    auto ctx = engine::gpu::Context::create({});
    if (!ctx) return fail(ctx.error());
    engine::render::FrameSettings fs;
    fs.width = (*size).x;
    fs.height = (*size).y;
    std::filesystem::path out(o.output);
    std::filesystem::create_directories(out);
    engine::AtomicFile csvFile;
    if (engine::Status s = csvFile.open(out / "sweep.csv"); !s) return fail(s.error());
    std::ostream& csv = csvFile.stream();
    // reference_bounces 0: the point's error is against the direct-light reference; more: against
    // the path tracer with that many bounces (the indirect series, charted apart).
    csv << "scene,method,setting,emitters,total_ms,primary_ms,lighting_ms,mae,mse,rmae,indirect,reference_bounces,mean_ratio\n";
    std::size_t total = o.worlds.size() * (settings->size() + indirect->size()), done = 0;
    auto write = [&](const SweepPoint& p, const LightingSettings& l, std::uint32_t referenceBounces) {
        double primary = p.passMs.count("primary_rays") ? p.passMs.at("primary_rays") : 0.0;
        double tonemap = p.passMs.count("tonemap") ? p.passMs.at("tonemap") : 0.0;
        csv << fmt::format("{},{},\"{}\",{},{},{},{},{},{},{},{},{},{}\n", p.scene, p.method, p.label, p.emitters,
                           p.totalMs, primary, p.totalMs - primary - tonemap, p.mae, p.mse, p.rmae, indirectColumn(l),
                           referenceBounces, p.meanRatio);
        csv.flush();
    };
    for (const std::string& name : o.worlds) {
        auto scene = loadWorld(name);
        if (!scene) return fail(scene.error());
        engine::world::CameraPreset camera = scene->camera();
        engine::Result<std::vector<glm::vec4>> reference = std::vector<glm::vec4>{};
        if (!settings->empty()) reference = cachedReference(**ctx, *scene, camera, fs, o.referenceSpp, 0, out / "cache");
        if (!reference) return fail(reference.error());
        // Brick lights on and off are the same lights in a scene without uniform emissive bricks.
        engine::lighting::EmitterList lights;
        lights.rebuild(*scene);
        bool hasBrickLights = false;
        for (const auto& e : lights.slots()) hasBrickLights |= e.minCorner.w == 8 && (e.info.w & 1u);
        for (const auto& [label, l] : *settings) {
            ++done;
            if (!l.brickLights && !hasBrickLights) continue;
            std::fprintf(stderr, "\r  [%zu/%zu] %s: %-40s", done, total, scene->name.c_str(), label.c_str());
            write(measureSetting(**ctx, *scene, camera, fs, l, o.frames, *reference, label), l, 0);
        }
        if (indirect->empty()) continue;
        auto withBounces = cachedReference(**ctx, *scene, camera, fs, o.indirectReferenceSpp, o.indirectBounces, out / "cache");
        if (!withBounces) return fail(withBounces.error());
        for (const auto& [label, l] : *indirect) {
            ++done;
            std::fprintf(stderr, "\r  [%zu/%zu] %s: %-40s", done, total, scene->name.c_str(), label.c_str());
            write(measureSetting(**ctx, *scene, camera, fs, l, o.frames, *withBounces, label), l, o.indirectBounces);
        }
    }
    std::fprintf(stderr, "\n");
    if (engine::Status s = csvFile.commit(); !s) return fail(s.error());
    std::printf("wrote    %s\n", (out / "sweep.csv").string().c_str());
    // The chart needs Debian's matplotlib; without it the CSV is still complete.
    std::string plot = fmt::format("/usr/bin/python3 {}/tools/plot_sweep.py {} {}", VOX_SOURCE_DIR,
                                   (out / "sweep.csv").string(), out.string());
    if (std::system(plot.c_str()) != 0) std::fprintf(stderr, "note: chart not drawn (needs python3-matplotlib)\n");
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
        if (c == '"') quoted = !quoted;
        else if (c == ',' && !quoted) out.emplace_back();
        else out.back() += c;
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
    if (!in) return fail(engine::makeError("{}: no results; run `vox bench restir --sampling uniform,power` first", o.restir));
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header = csvFields(line);
    auto column = [&](const char* name) { return std::size_t(std::find(header.begin(), header.end(), name) - header.begin()); };
    const std::size_t cScene = column("scene"), cEmitters = column("emitters"), cSampling = column("sampling"),
                      cBase = column("base"), cMs = column("ms"), cMse = column("mse"), cMin = column("mse_min"), cMax = column("mse_max"),
                      cMae = column("mae");
    if (cMae >= header.size()) return fail(engine::makeError("{}: not a `vox bench restir` table", o.restir));
    struct Choice {
        std::string sampling;
        double ms, mse, mseMin, mseMax, mae;
    };
    std::map<std::string, std::pair<std::uint32_t, std::vector<Choice>>> scenes;  // by name: emitters, choices
    while (std::getline(in, line)) {
        std::vector<std::string> f = csvFields(line);
        if (f.size() < header.size() || f[cBase] != "--method restir" || (!only.empty() && f[cScene] != only)) continue;
        auto& [emitters, choices] = scenes[f[cScene]];
        emitters = std::uint32_t(std::atol(f[cEmitters].c_str()));
        choices.push_back({f[cSampling], std::atof(f[cMs].c_str()), std::atof(f[cMse].c_str()), std::atof(f[cMin].c_str()), std::atof(f[cMax].c_str()),
                           std::atof(f[cMae].c_str())});
    }
    std::vector<std::pair<std::uint32_t, std::string>> order;
    for (const auto& [name, entry] : scenes) {
        if (entry.second.size() >= 2) order.push_back({entry.first, name});
    }
    if (order.empty())
        return fail(engine::makeError("{}: no scene{} with ReSTIR rows for two sampling values; run `vox bench restir{} "
                                      "--sampling uniform,power`",
                                      o.restir, only.empty() ? "" : " '" + only + "'", only.empty() ? "" : " " + o.world));
    std::sort(order.begin(), order.end());
    for (const auto& [emitters, name] : order) {
        std::vector<Choice> c = scenes[name].second;
        std::sort(c.begin(), c.end(), [](const Choice& a, const Choice& b) { return a.mse < b.mse; });
        const bool separated = c[0].mseMax < c[1].mseMin;
        // The rows are not scaled to equal time: the time ratio says what the lower error costs.
        std::printf("%s (%u emitters): --sampling %s (MSE %.3e, %.2fx lower than %s; MAE %.3e vs %.3e; %.2fx its time)%s\n",
                    name.c_str(), emitters, c[0].sampling.c_str(), c[0].mse, c[1].mse / std::max(c[0].mse, 1e-30),
                    c[1].sampling.c_str(), c[0].mae, c[1].mae, c[0].ms / std::max(c[1].ms, 1e-9),
                    separated ? "" : "; the seeds' spreads overlap");
    }
    return 0;
}

int runRecommend(const RecommendOptions& o) {
    if (o.sampling) return runRecommendSampling(o);
    if (o.world.empty()) return fail(engine::makeError("bench recommend: a WORLD is needed (or --sampling)"));
    if (o.targetMae <= 0.0) return fail(engine::makeError("bench recommend: --target-mae is needed (or --sampling)"));
    auto scene = loadWorld(o.world);
    if (!scene) return fail(scene.error());
    std::ifstream in(o.sweep);
    if (!in) return fail(engine::makeError("{}: no sweep results; run `vox bench sweep {}` first", o.sweep, o.world));
    std::string line;
    std::getline(in, line);  // header
    struct Candidate {
        std::string setting;
        double ms, mae;
    };
    std::vector<Candidate> rows;
    while (std::getline(in, line)) {
        // scene,method,"setting",emitters,total_ms,primary_ms,lighting_ms,mae,mse,rmae[,indirect,reference_bounces[,mean_ratio]]
        // (sweeps from before the indirect series have no last two columns: all direct)
        std::size_t q1 = line.find('"'), q2 = line.find('"', q1 + 1);
        if (q1 == std::string::npos || q2 == std::string::npos) continue;
        if (line.substr(0, line.find(',')) != scene->name) continue;
        std::vector<std::string> rest = splitList(line.substr(q2 + 2));
        if (rest.size() < 5) continue;
        const bool againstIndirect = rest.size() >= 9 && std::atoi(rest[8].c_str()) > 0;
        if (againstIndirect != o.indirect) continue;
        rows.push_back({line.substr(q1 + 1, q2 - q1 - 1), std::atof(rest[1].c_str()), std::atof(rest[4].c_str())});
    }
    if (rows.empty())
        return fail(engine::makeError("{}: no {}rows for scene '{}'; run `vox bench sweep {}`", o.sweep,
                                      o.indirect ? "indirect-light " : "", scene->name, o.world));
    const Candidate* best = nullptr;
    for (const Candidate& c : rows) {
        if (c.mae <= o.targetMae && (!best || c.ms < best->ms)) best = &c;
    }
    if (!best) {
        auto closest = std::min_element(rows.begin(), rows.end(), [](const Candidate& a, const Candidate& b) { return a.mae < b.mae; });
        std::printf("no swept setting reaches MAE %.3e on %s; the most accurate is '%s' (MAE %.3e, %.2f ms)\n", o.targetMae,
                    scene->name.c_str(), closest->setting.c_str(), closest->mae, closest->ms);
        return 1;
    }
    std::printf("%s: cheapest setting with MAE <= %.3e: '%s' (MAE %.3e, %.2f ms per frame; %zu settings swept)\n",
                scene->name.c_str(), o.targetMae, best->setting.c_str(), best->mae, best->ms, rows.size());
    return 0;
}

}  // namespace

void addBenchSweepCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand("sweep", "Methods x settings per scene: error against time, CSV and chart");
    auto o = std::make_shared<SweepOptions>();
    cmd->add_option("worlds", o->worlds, "Worlds (default: the four thesis scenes)");
    cmd->add_option("--methods", o->methods, "Comma-separated methods")->capture_default_str();
    cmd->add_option("--candidates", o->candidates, "Candidate counts M for restir/ris")->capture_default_str();
    cmd->add_option("--modes", o->modes, "point, area or both")->capture_default_str();
    cmd->add_option("--brick-lights", o->brickLights, "on, off or both")->capture_default_str();
    cmd->add_option("--rays", o->rays, "Shadow rays for uniform light sampling")->capture_default_str();
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("--frames", o->frames, "Frames per setting (the last half are measured)")->capture_default_str()
        ->check(numberIn(engine::wholeRange(2, 1000, "frames")));
    cmd->add_option("--ref-spp", o->referenceSpp, "Reference samples per pixel (cached on disk)")->capture_default_str()
        ->check(numberIn(kSamplesRange));
    cmd->add_option("--indirect", o->indirect,
                    "Indirect-light series: none, cache-K (K directions), vct, vct-leaky, reference; empty = no series")
        ->capture_default_str();
    cmd->add_option("--indirect-bounces", o->indirectBounces,
                    "Bounces of the indirect reference (and of the cache and path-tracer points)")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 16, "bounces")));
    cmd->add_option("--indirect-ref-spp", o->indirectReferenceSpp, "Samples per pixel of the indirect reference (cached)")
        ->capture_default_str()
        ->check(numberIn(kSamplesRange));
    cmd->add_option("-o,--output", o->output, "Output folder")->capture_default_str();
    cmd->callback([o, &exitCode] { exitCode = runSweep(*o); });

    auto* rec = bench.add_subcommand("recommend", "The cheapest swept setting that meets a target MAE on a scene");
    auto r = std::make_shared<RecommendOptions>();
    rec->add_option("world", r->world, "World name or scene file (with --sampling: all scenes when left out)");
    rec->add_option("--target-mae", r->targetMae, "Target MAE against the reference (needed without --sampling)")
        ->check(numberIn(engine::aboveRange(0.0, 1e6)));
    rec->add_option("--sweep", r->sweep, "Sweep results (CSV from vox bench sweep)")->capture_default_str();
    rec->add_flag("--indirect", r->indirect,
                  "Choose among the indirect-light series (error against the multi-bounce reference)");
    rec->add_flag("--sampling", r->sampling,
                  "Choose ReSTIR's candidate sampling per scene from `vox bench restir --sampling A,B` (lowest median MSE)");
    rec->add_option("--restir", r->restir, "vox bench restir's CSV (for --sampling)")->capture_default_str();
    rec->callback([r, &exitCode] { exitCode = runRecommend(*r); });
}

}  // namespace vox
