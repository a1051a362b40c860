#include "sweep_points.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <sstream>

#include "commands.h"
#include "lighting/emitter_list.h"
#include "lighting/lighting_knobs.h"
#include "sweep_runner.h"

namespace vox {

using engine::lighting::LightingSettings;
using engine::lighting::Method;

std::vector<std::string> splitList(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream in(s);
    std::string item;
    while (std::getline(in, item, ',')) {
        if (!item.empty()) out.push_back(item);
    }
    return out;
}

namespace {

engine::Result<std::vector<std::uint32_t>> numbers(const std::string& s, const char* option) {
    std::vector<std::uint32_t> out;
    for (const std::string& item : splitList(s)) {
        char* end = nullptr;
        unsigned long v = std::strtoul(item.c_str(), &end, 10);
        if (!end || *end || v < 1 || v > 4096)
            return engine::makeError("{}: '{}' is not a number in 1..4096", option, item);
        out.push_back(std::uint32_t(v));
    }
    if (out.empty()) return engine::makeError("{}: empty list", option);
    return out;
}

// All settings of the sweep, labelled.
engine::Result<std::vector<std::pair<std::string, LightingSettings>>> settingsOf(
    const SweepOptions& o) {
    auto ms = numbers(o.candidates, "--candidates");
    if (!ms) return ms.error();
    auto rays = numbers(o.rays, "--rays");
    if (!rays) return rays.error();
    std::vector<std::pair<std::string, LightingSettings>> out;
    for (const std::string& method : splitList(o.methods)) {
        for (const std::string& mode : splitList(o.modes)) {
            if (mode != "point" && mode != "area")
                return engine::makeError("--modes: '{}' is not point or area", mode);
            for (const std::string& bricks : splitList(o.brickLights)) {
                if (bricks != "on" && bricks != "off")
                    return engine::makeError("--brick-lights: '{}' is not on or off", bricks);
                const std::vector<engine::lighting::KnobValue> values{
                    {engine::lighting::knobForOption("method"), method, "--methods"},
                    {engine::lighting::knobForOption("mode"), mode, "--modes"},
                    {engine::lighting::knobForOption("brick-lights"), bricks, "--brick-lights"}};
                auto base = engine::lighting::mergeLighting(LightingSettings{}, values);
                if (!base) return base.error();
                std::string tag =
                    fmt::format("{} {}{}", method, mode, bricks == "off" ? " voxels" : "");
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
        if (engine::Status valid = engine::lighting::validate(l); !valid)
            return engine::makeError("{}: {}", tag, valid.error().message);
    }
    return out;
}

// The indirect-light series, labelled: ReSTIR (biased, area, M = 32: the defaults) for the
// direct light and, for the indirect light, nothing, the irradiance cache with K directions per
// face, or the path tracer with the same bounces as the reference it is measured against (one
// sample per pixel, restarted every frame). The cache reads its own irradiance at each ray's hit
// for the same number of bounces, so all three aim at the same converged image.
engine::Result<std::vector<std::pair<std::string, LightingSettings>>> indirectSettingsOf(
    const SweepOptions& o) {
    using engine::lighting::Indirect;
    std::vector<std::pair<std::string, LightingSettings>> out;
    for (const std::string& item : splitList(o.indirect)) {
        LightingSettings l;
        if (item == "none") {
            out.push_back({"indirect none (restir)", l});
        } else if (item == "reference") {
            l.method = Method::Reference;
            l.referenceFilter =
                engine::lighting::ReferenceFilter::PixelCentre;  // as the reference it is measured
                                                                 // against
            l.indirect = Indirect::Reference;
            l.bounces = o.indirectBounces;
            l.samplesPerFrame = 1;
            out.push_back(
                {fmt::format("indirect reference {} bounces 1 spp", o.indirectBounces), l});
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
            return engine::makeError(
                "--indirect: '{}' is not none, cache-K, vct, vct-leaky or reference", item);
        }
    }
    return out;
}

const char* indirectColumn(const LightingSettings& l) {
    return engine::lighting::indirectName(
        l.method == Method::Reference ? engine::lighting::Indirect::Reference : l.indirect);
}

// A point's line, as the sweep has always written it.
std::string pointLine(const SweepPoint& p, const LightingSettings& l,
                      std::uint32_t referenceBounces) {
    double primary = p.passMs.count("primary_rays") ? p.passMs.at("primary_rays") : 0.0;
    double tonemap = p.passMs.count("tonemap") ? p.passMs.at("tonemap") : 0.0;
    return fmt::format("{},{},\"{}\",{},{},{},{},{},{},{},{},{},{}\n", p.scene, p.method, p.label,
                       p.emitters, p.totalMs, primary, p.totalMs - primary - tonemap, p.mae, p.mse,
                       p.rmae, indirectColumn(l), referenceBounces, p.meanRatio);
}

}  // namespace

engine::Result<SweepPlan> planSweep(const SweepOptions& o) {
    SweepPlan plan;
    auto size = parseSize(o.size, "--size");
    if (!size) return size.error();
    plan.size = *size;
    auto direct = settingsOf(o);
    if (!direct) return direct.error();
    plan.direct = std::move(*direct);
    auto indirect = indirectSettingsOf(o);
    if (!indirect) return indirect.error();
    plan.indirect = std::move(*indirect);
    return plan;
}

engine::Status measureSweepPoints(
    engine::gpu::Context& gpu, const SweepOptions& o, const SweepPlan& plan, std::uint32_t first,
    std::uint32_t last, const std::function<bool(std::uint32_t)>& wanted,
    const std::function<engine::Status(std::uint32_t, const std::string&)>& onPoint) {
    engine::render::FrameSettings fs;
    fs.width = plan.size.x;
    fs.height = plan.size.y;
    const std::filesystem::path cache = std::filesystem::path(o.output) / "cache";
    const std::uint32_t perWorld = plan.pointsPerWorld();
    const std::size_t total = std::size_t(perWorld) * o.worlds.size();
    for (std::uint32_t w = 0; w < o.worlds.size() && perWorld > 0; ++w) {
        const std::uint32_t worldFirst = w * perWorld, worldLast = worldFirst + perWorld - 1;
        bool any = false;
        for (std::uint32_t k = std::max(first, worldFirst); k <= std::min(last, worldLast) && !any;
             ++k)
            any = !wanted || wanted(k);
        if (!any) continue;
        auto scene = loadWorld(o.worlds[w]);
        if (!scene) return scene.error();
        engine::world::CameraPreset camera = scene->camera();
        // Brick lights on and off are the same lights in a scene without uniform emissive bricks.
        engine::lighting::EmitterList lights;
        lights.rebuild(*scene);
        bool hasBrickLights = false;
        for (const auto& e : lights.slots())
            hasBrickLights |= e.minCorner.w == 8 && (e.info.w & 1u);
        std::optional<std::vector<glm::vec4>> reference,
            withBounces;  // rendered or read when needed
        for (std::uint32_t k = std::max(first, worldFirst); k <= std::min(last, worldLast); ++k) {
            if (wanted && !wanted(k)) continue;
            const std::uint32_t j = k - worldFirst;
            const bool direct = j < plan.direct.size();
            const auto& [label, l] =
                direct ? plan.direct[j] : plan.indirect[j - plan.direct.size()];
            if (direct && !l.brickLights && !hasBrickLights) {
                if (engine::Status s = onPoint(k, ""); !s) return s;
                continue;
            }
            std::optional<std::vector<glm::vec4>>& ref = direct ? reference : withBounces;
            if (!ref) {
                auto r = direct ? cachedReference(gpu, *scene, camera, fs, o.referenceSpp, 0, cache)
                                : cachedReference(gpu, *scene, camera, fs, o.indirectReferenceSpp,
                                                  o.indirectBounces, cache);
                if (!r) return r.error();
                ref = std::move(*r);
            }
            std::fprintf(stderr, "\r  [%u/%zu] %s: %-40s", k + 1, total, scene->name.c_str(),
                         label.c_str());
            const SweepPoint p = measureSetting(gpu, *scene, camera, fs, l, o.frames, *ref, label);
            if (engine::Status s = onPoint(k, pointLine(p, l, direct ? 0 : o.indirectBounces)); !s)
                return s;
        }
    }
    std::fprintf(stderr, "\n");
    return {};
}

void drawSweepCharts(const std::string& output) {
    const std::filesystem::path out(output);
    // The chart needs Debian's matplotlib; without it the CSV is still complete.
    std::string plot = fmt::format("/usr/bin/python3 {}/tools/plot_sweep.py {} {}", VOX_SOURCE_DIR,
                                   (out / "sweep.csv").string(), out.string());
    if (std::system(plot.c_str()) != 0)
        std::fprintf(stderr, "note: chart not drawn (needs python3-matplotlib)\n");
}

}  // namespace vox
