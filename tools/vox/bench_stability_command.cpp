// vox bench stability: how the lighting methods behave over time and where they are known to
// fail — flicker on a still camera, frames to recover after edits, and the failure cases of the
// thesis and the literature. Each case is a scene, a scenario and a metric; results go to a
// table (markdown), a CSV of per-frame errors and a chart (tools/plot_stability.py).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>

#include <fmt/format.h>

#include "core/atomic_file.h"
#include "commands.h"
#include "gpu/context.h"
#include "io/image_io.h"
#include "metrics/image_metrics.h"
#include "render/renderer.h"
#include "sweep_runner.h"
#include "world/world_edits.h"

namespace vox {

namespace {

using engine::lighting::LightingSettings;
using engine::lighting::Method;
using engine::render::FrameSettings;
using engine::render::Renderer;
using engine::world::Box;
using engine::world::Scene;

struct StabilityOptions {
    std::string size = "96x64";
    std::string output = "out/stability";
    std::string cases = "all";  // all | vct | sky (only voxel cone tracing's or DVF sky light's rows)
};

struct Context {
    engine::gpu::Context& gpu;
    FrameSettings frame;
    std::filesystem::path cache;
    std::ostream& curves;  // case,method,frame,mae
    std::vector<std::string> rows;  // markdown table rows
};

double maeOf(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b, const FrameSettings& f) {
    return engine::metrics::compareImages({a, f.width, f.height}, {b, f.width, f.height})->mae;
}

double meanRadiance(const std::vector<glm::vec4>& img) {
    double s = 0.0;
    for (const glm::vec4& p : img) s += (p.x + p.y + p.z) / 3.0;
    return s / double(img.size());
}

// Mean |frame - previous frame| over `frames` frames after `warmup`, relative to the mean radiance.
double flicker(Context& c, Scene& scene, LightingSettings l, int warmup, int frames, bool reseed) {
    Renderer r(c.gpu);
    std::vector<glm::vec4> prev;
    double sum = 0.0, mean = 0.0;
    for (int i = 0; i < warmup + frames; ++i) {
        if (reseed) {
            l.seed += 7919;
            r.resetHistory();
        }
        r.render(scene, scene.camera(), c.frame, l);
        if (i < warmup - 1) continue;
        std::vector<glm::vec4> img = r.readback().radiance;
        if (!prev.empty()) {
            sum += maeOf(img, prev, c.frame);
            mean += meanRadiance(img);
        }
        prev = std::move(img);
    }
    return sum / std::max(mean, 1e-12);
}

// Steady state on `scene`, then `edit` and count frames until the error against the edited
// scene's reference is back within 10 % of its new steady state.
void response(Context& c, const std::string& name, Scene scene, const std::function<void(Scene&)>& edit) {
    const int before = 16, after = 32;
    Scene edited = scene;
    edit(edited);
    edited.grid.clearDirty();
    auto ref = cachedReference(c.gpu, edited, edited.camera(), c.frame, 512, 0, c.cache, name);
    for (const char* method : {"restir", "restir-unbiased"}) {
        LightingSettings l;
        l.restir.unbiased = std::string(method) == "restir-unbiased";
        Renderer r(c.gpu);
        Scene live = scene;
        for (int i = 0; i < before; ++i) r.render(live, live.camera(), c.frame, l);
        edit(live);
        std::vector<double> errors;
        for (int i = 0; i < after; ++i) {
            r.render(live, live.camera(), c.frame, l);
            errors.push_back(maeOf(r.readback().radiance, *ref, c.frame));
            c.curves << fmt::format("{},{},{},{}\n", name, method, i + 1, errors.back());
        }
        std::vector<double> tail(errors.end() - 8, errors.end());
        std::sort(tail.begin(), tail.end());
        double steady = tail[tail.size() / 2];
        int frames = 0;
        while (frames < after && errors[std::size_t(frames)] > 1.1 * steady) ++frames;
        c.rows.push_back(fmt::format("| response: {} | {} | {} frame(s) to within 10 % of steady state (steady MAE {:.3e}, first frame {:.3e}) |",
                                     name, method, frames + 1, steady, errors.front()));
        std::printf("%-28s %-16s recovered after %d frame(s); steady MAE %.3e, first frame %.3e\n", name.c_str(), method,
                    frames + 1, steady, errors.front());
    }
}

// A dynamic object still for `still` frames, then moving along its path for `moving` frames at
// 30 fps; each moving frame's error against the converged reference of that frame's pose
// (cached on disk per time; one reference when the object never moves). `indirectOnly`
// compares the cache's indirect term with the path tracer's (one bounce minus direct light), so
// the direct light's noise does not hide it. Returns the per-frame MAE over the whole image and
// over the pixels whose primary hit is on the object (ghosting shows there first).
struct MovingRun {
    std::vector<double> mae, maeObject;
};
constexpr double kFps = 30.0;

MovingRun movingRun(Context& c, const std::string& name, const Scene& scene, const engine::world::CameraPreset& camera,
                    const LightingSettings& l, bool indirectOnly, int still, int moving) {
    bool moves = false;
    for (const auto& object : scene.objects) moves |= object.path.keys().size() > 1;
    std::vector<std::vector<glm::vec4>> refs;
    for (int i = 1; i <= moving; ++i) {
        if (!moves && !refs.empty()) {
            refs.push_back(refs.front());
            continue;
        }
        FrameSettings f = c.frame;
        f.timeSeconds = moves ? i / kFps : 0.0;
        const std::string variant = moves ? fmt::format("{}-t{}", name, i) : name;
        auto reference = [&](std::uint32_t bounces) {
            Scene copy = scene;
            auto ref = cachedReference(c.gpu, copy, camera, f, 256, bounces, c.cache, variant);
            return ref ? std::move(*ref) : std::vector<glm::vec4>(std::size_t(c.frame.width) * c.frame.height);
        };
        std::vector<glm::vec4> ref = reference(0);
        if (indirectOnly) {
            std::vector<glm::vec4> withBounce = reference(1);
            for (std::size_t p = 0; p < ref.size(); ++p) ref[p] = glm::max(withBounce[p] - ref[p], glm::vec4(0.0f));
        }
        refs.push_back(std::move(ref));
    }
    MovingRun run;
    Renderer r(c.gpu);
    Scene live = scene;
    FrameSettings f = c.frame;
    for (int i = -still + 1; i <= moving; ++i) {
        f.timeSeconds = moves ? std::max(i, 0) / kFps : 0.0;
        r.render(live, camera, f, l);
        if (i < 1) continue;
        auto img = r.readback();
        const auto& ref = refs[std::size_t(i - 1)];
        const auto& mine = indirectOnly ? img.indirect : img.radiance;
        run.mae.push_back(maeOf(mine, ref, c.frame));
        double sum = 0.0;
        std::size_t n = 0;
        for (std::size_t p = 0; p < img.gbuffer.size(); ++p) {
            if (!(img.gbuffer[p].data.w & shared::GBUFFER_FLAG_DYNAMIC)) continue;
            for (int k = 0; k < 3; ++k) sum += std::abs(mine[p][k] - ref[p][k]);
            n += 3;
        }
        run.maeObject.push_back(n ? sum / double(n) : 0.0);
    }
    return run;
}

// The crate of worlds/thin_wall.toml made fast: it sweeps along the room's south wall, 56 voxels
// in 0.5 s (3.7 voxels a frame at 30 fps) and back, so the world voxels it covers are new almost
// every frame. `still`: parked at its start instead.
Scene fastCrate(const Scene& thinWall, bool still) {
    using engine::world::ObjectKey;
    Scene s = thinWall;
    std::vector<ObjectKey> keys{ObjectKey{0.0, {4.0, 6.0, 4.0}}};
    if (!still) keys.insert(keys.end(), {ObjectKey{0.5, {60.0, 6.0, 4.0}}, ObjectKey{1.0, {4.0, 6.0, 4.0}}});
    s.objects[0].path = engine::world::ObjectPath(keys, !still);
    return s;
}

// Frames until `errors` is within 10 % of its steady state (the median of the last 8).
std::pair<int, double> framesToSteady(const std::vector<double>& errors) {
    std::vector<double> tail(errors.end() - std::min<std::ptrdiff_t>(8, std::ptrdiff_t(errors.size())), errors.end());
    std::sort(tail.begin(), tail.end());
    double steady = tail[tail.size() / 2];
    int frames = 0;
    while (frames < int(errors.size()) && errors[std::size_t(frames)] > 1.1 * steady) ++frames;
    return {frames + 1, steady};
}

double mean(const std::vector<double>& v, std::size_t from = 0) {
    double s = 0.0;
    for (std::size_t i = from; i < v.size(); ++i) s += v[i];
    return v.size() > from ? s / double(v.size() - from) : 0.0;
}

// The cache's indirect term as an 8-bit image, `scale` mapping to white (linear, clamped).
std::vector<std::uint32_t> indirectImage(const std::vector<glm::vec4>& indirect, float scale) {
    std::vector<std::uint32_t> out;
    for (const glm::vec4& p : indirect) {
        std::uint32_t rgba = 0xff000000u;
        for (int k = 0; k < 3; ++k) rgba |= std::uint32_t(std::clamp(p[k] / scale, 0.0f, 1.0f) * 255.0f + 0.5f) << (8 * k);
        out.push_back(rgba);
    }
    return out;
}

Scene simpleScene(glm::ivec3 size) {
    Scene s;
    s.name = "stability";
    s.grid = engine::world::BrickGrid(size);
    (void)s.palette.add(engine::world::Material{"white", glm::vec3(0.75f)});
    (void)s.palette.add(engine::world::Material{"lamp", glm::vec3(0.8f), glm::vec3(1.0f, 0.85f, 0.6f), 20.0f});
    s.sky.sunRadiance = glm::vec3(0.0f);
    s.sky.skyRadiance = glm::vec3(0.0f);
    return s;
}

// Voxel cone tracing (`--indirect vct`) under the same stresses as the cache: flicker of its
// indirect term on a still camera, frames to recover after an edit and when an object starts
// moving (its indirect term against the path tracer's one-bounce indirect light), and its leak
// through the one-voxel walls of worlds/thin_wall.toml, with the leak mitigation on and off.
engine::Status vctCases(Context& c) {
    using engine::lighting::Indirect;
    auto vct = [](bool mitigation) {
        LightingSettings l;
        l.indirect = Indirect::Vct;
        l.vct.leakMitigation = mitigation;
        return l;
    };
    for (const char* world : {"cornell", "mountain", "apartments"}) {
        auto scene = loadWorld(world);
        if (!scene) return scene.error();
        Renderer r(c.gpu);
        std::vector<glm::vec4> prev;
        double sum = 0.0, mean = 0.0;
        for (int i = 0; i < 6; ++i) {
            r.render(*scene, scene->camera(), c.frame, vct(true));
            std::vector<glm::vec4> img = r.readback().indirect;
            if (!prev.empty()) {
                sum += maeOf(img, prev, c.frame);
                mean += meanRadiance(img);
            }
            prev = std::move(img);
        }
        const double f = sum / std::max(mean, 1e-12);
        c.rows.push_back(fmt::format("| flicker: {} | restir + vct (indirect term) | {:.3f} |", world, f));
        std::printf("flicker %-12s vct indirect %.4f\n", world, f);
    }
    // The cones' indirect term against the path tracer's (one bounce minus direct light).
    auto indirectReference = [&](Scene scene, const engine::world::CameraPreset& camera, const FrameSettings& f,
                                 const std::string& name) -> engine::Result<std::vector<glm::vec4>> {
        auto direct = cachedReference(c.gpu, scene, camera, f, 256, 0, c.cache, name);
        if (!direct) return direct.error();
        auto bounce = cachedReference(c.gpu, scene, camera, f, 256, 1, c.cache, name);
        if (!bounce) return bounce.error();
        for (std::size_t p = 0; p < direct->size(); ++p) (*bounce)[p] = glm::max((*bounce)[p] - (*direct)[p], glm::vec4(0.0f));
        return bounce;
    };
    {   // Response to an edit: a wall of the Cornell box removed.
        auto cornell = loadWorld("cornell");
        if (!cornell) return cornell.error();
        cornell->grid.clearDirty();
        auto edit = [](Scene& s) { fillBox(s.grid, Box{{68, 8, 148}, {148, 168, 228}}, engine::world::kEmpty); };
        Scene edited = *cornell;
        edit(edited);
        edited.grid.clearDirty();
        auto ref = indirectReference(edited, edited.camera(), c.frame, "wall removed");
        if (!ref) return ref.error();
        Renderer r(c.gpu);
        Scene live = *cornell;
        for (int i = 0; i < 4; ++i) r.render(live, live.camera(), c.frame, vct(true));
        edit(live);
        std::vector<double> errors;
        for (int i = 0; i < 16; ++i) {
            r.render(live, live.camera(), c.frame, vct(true));
            errors.push_back(maeOf(r.readback().indirect, *ref, c.frame));
            c.curves << fmt::format("{},{},{},{}\n", "wall removed", "restir + vct (indirect term)", i + 1, errors.back());
        }
        auto [frames, steady] = framesToSteady(errors);
        c.rows.push_back(fmt::format("| response: wall removed | restir + vct (indirect term vs 1-bounce indirect) | {} frame(s) to within 10 % of steady state (steady MAE {:.3e}, first frame {:.3e}) |",
                                     frames, steady, errors.front()));
        std::printf("%-28s %-16s recovered after %d frame(s); steady MAE %.3e\n", "wall removed", "vct", frames, steady);
    }
    auto thinWall = loadWorld("thin_wall");
    if (!thinWall) return thinWall.error();
    thinWall->grid.clearDirty();
    {   // A dynamic object starts moving (the fast crate, as for the cache).
        const Scene fast = fastCrate(*thinWall, false);
        MovingRun run = movingRun(c, "fast object", fast, fast.camera("outside"), vct(true), true, 16, 32);
        for (std::size_t i = 0; i < run.mae.size(); ++i)
            c.curves << fmt::format("{},{},{},{}\n", "object starts moving", "restir + vct (indirect term)", i + 1, run.mae[i]);
        auto [frames, steady] = framesToSteady(run.mae);
        c.rows.push_back(fmt::format("| response: dynamic object starts moving (3.7 voxels/frame) | restir + vct (indirect term vs 1-bounce indirect) | {} frame(s) to within 10 % of steady state (steady MAE {:.3e}, first frame {:.3e}, largest {:.3e}) |",
                                     frames, steady, run.mae.front(), *std::max_element(run.mae.begin(), run.mae.end())));
        std::printf("%-28s %-16s recovered after %d frame(s); steady MAE %.3e\n", "object starts moving", "vct", frames, steady);
    }
    {   // The leak: the sealed room's inside (the path tracer and the cache see 0 there), against
        // the outside's mean, at t = 2.5 s as for the cache.
        FrameSettings f = c.frame;
        f.timeSeconds = 2.5;
        for (bool mitigation : {true, false}) {
            Renderer r(c.gpu);
            r.render(*thinWall, thinWall->camera("outside"), f, vct(mitigation));
            const std::vector<glm::vec4> outdoor = r.readback().indirect;
            r.render(*thinWall, thinWall->camera("inside"), f, vct(mitigation));
            const std::vector<glm::vec4> in = r.readback().indirect;
            float insideMax = 0.0f;
            for (const glm::vec4& p : in) insideMax = std::max({insideMax, p.x, p.y, p.z});
            const double inMean = meanRadiance(in), outMean = meanRadiance(outdoor);
            c.rows.push_back(fmt::format("| thin wall (1 voxel), indirect | restir + vct, leak mitigation {} | mean indirect inside the sealed room: {:.3g} = {:.1f} % of the outside's mean {:.3g} (largest inside {:.3g}) |",
                                         mitigation ? "on" : "off", inMean, 100.0 * inMean / outMean, outMean, insideMax));
            std::printf("thin wall vct (mitigation %s): inside mean %.3g (%.1f %% of outside %.3g), max %.3g\n",
                        mitigation ? "on" : "off", inMean, 100.0 * inMean / outMean, outMean, insideMax);
        }
    }
    return {};
}

// Sky light from discrete visibility fields (`--sky dvf`) under the same stresses: flicker of its
// sky term on a still camera, frames until an edit that opens a roof reaches a steady error
// against the brute-force sky term (`--sky reference`) of the opened room, and what the sealed,
// one-voxel-thin room of worlds/thin_wall.toml sees of the sky from inside (0 is right).
engine::Status skyCases(Context& c) {
    using engine::lighting::Sky;
    auto sky = [](Sky mode) {
        LightingSettings l;
        l.method = Method::Uniform;  // the sky term is read alone
        l.sky = mode;
        return l;
    };
    auto skyTerm = [&](Renderer& r, Scene& scene, const engine::world::CameraPreset& camera, Sky mode) {
        r.render(scene, camera, c.frame, sky(mode));
        return r.dvfSky().readSkyTerm();
    };
    for (const char* world : {"sandbox", "mountain"}) {
        auto scene = loadWorld(world);
        if (!scene) return scene.error();
        Renderer r(c.gpu);
        std::vector<glm::vec4> prev;
        double sum = 0.0, mean = 0.0;
        for (int i = 0; i < 8; ++i) {
            std::vector<glm::vec4> img = skyTerm(r, *scene, scene->camera(), Sky::Dvf);
            if (i < 4) continue;  // the masks' first build spreads over a few frames
            if (!prev.empty()) {
                sum += maeOf(img, prev, c.frame);
                mean += meanRadiance(img);
            }
            prev = std::move(img);
        }
        const double f = sum / std::max(mean, 1e-12);
        c.rows.push_back(fmt::format("| flicker: {} | restir + sky dvf (sky term) | {:.3f} |", world, f));
        std::printf("flicker %-12s dvf sky %.4f\n", world, f);
    }
    auto thinWall = loadWorld("thin_wall");
    if (!thinWall) return thinWall.error();
    thinWall->grid.clearDirty();
    thinWall->objects.clear();  // the room alone
    const engine::world::CameraPreset inside = thinWall->camera("inside");
    const Box roof{{33, 25, 9}, {55, 26, 55}};
    {   // The sealed room from inside: DVF and the brute-force rays both must see no sky.
        for (Sky mode : {Sky::Dvf, Sky::Reference}) {
            Renderer r(c.gpu);
            std::vector<glm::vec4> in;
            for (int i = 0; i < 4; ++i) in = skyTerm(r, *thinWall, inside, mode);
            float insideMax = 0.0f;
            for (const glm::vec4& p : in) insideMax = std::max({insideMax, p.x, p.y, p.z});
            const char* name = mode == Sky::Dvf ? "restir + sky dvf" : "restir + sky reference";
            c.rows.push_back(fmt::format("| thin wall (1 voxel), sky | {} | largest sky term inside the sealed room: {:.3g} |",
                                         name, insideMax));
            std::printf("thin wall %-24s largest sky term inside %.3g\n", name, insideMax);
        }
    }
    {   // Response to an edit: the room's roof removed.
        Scene opened = *thinWall;
        fillBox(opened.grid, roof, engine::world::kEmpty);
        opened.grid.clearDirty();
        std::vector<glm::vec4> ref;
        {
            Renderer r(c.gpu);
            for (int i = 0; i < 16; ++i) ref = skyTerm(r, opened, inside, Sky::Reference);
        }
        Renderer r(c.gpu);
        Scene live = *thinWall;
        for (int i = 0; i < 4; ++i) skyTerm(r, live, inside, Sky::Dvf);
        fillBox(live.grid, roof, engine::world::kEmpty);
        std::vector<double> errors;
        for (int i = 0; i < 12; ++i) {
            errors.push_back(maeOf(skyTerm(r, live, inside, Sky::Dvf), ref, c.frame));
            c.curves << fmt::format("{},{},{},{}\n", "roof removed", "restir + sky dvf (sky term)", i + 1, errors.back());
        }
        auto [frames, steady] = framesToSteady(errors);
        c.rows.push_back(fmt::format("| response: roof removed | restir + sky dvf (sky term vs brute-force sky rays) | {} frame(s) to within 10 % of steady state (steady MAE {:.3e}, first frame {:.3e}; reference mean {:.3e}) |",
                                     frames, steady, errors.front(), meanRadiance(ref)));
        std::printf("%-28s %-16s recovered after %d frame(s); steady MAE %.3e\n", "roof removed", "dvf sky", frames, steady);
    }
    return {};
}

int runStability(const StabilityOptions& o) {
    auto size = parseSize(o.size, "--size");
    if (!size) return fail(size.error());
    auto ctx = engine::gpu::Context::create({});
    if (!ctx) return fail(ctx.error());
    std::filesystem::path out(o.output);
    std::filesystem::create_directories(out);
    engine::AtomicFile curvesFile;
    if (engine::Status s = curvesFile.open(out / "response.csv"); !s) return fail(s.error());
    std::ostream& curves = curvesFile.stream();
    curves << "case,method,frame,mae\n";
    Context c{**ctx, {}, out / "cache", curves, {}};
    c.frame.width = (*size).x;
    c.frame.height = (*size).y;

    // The table, the curves and the chart (also after `--cases vct`).
    auto finish = [&]() -> int {
        engine::AtomicFile mdFile;
        if (engine::Status s = mdFile.open(out / "stability_table.md"); !s) return fail(s.error());
        std::ostream& md = mdFile.stream();
        md << fmt::format("Measured on {} at {}x{}.\n\n| case | method | result |\n| --- | --- | --- |\n", c.gpu.info().name,
                          c.frame.width, c.frame.height);
        for (const std::string& row : c.rows) md << row << "\n";
        if (engine::Status s = mdFile.commit(); !s) return fail(s.error());
        if (engine::Status s = curvesFile.commit(); !s) return fail(s.error());
        std::string plot = fmt::format("/usr/bin/python3 {}/tools/plot_stability.py {} {}", VOX_SOURCE_DIR,
                                       (out / "response.csv").string(), out.string());
        if (std::system(plot.c_str()) != 0) std::fprintf(stderr, "note: chart not drawn (needs python3-matplotlib)\n");
        std::printf("wrote    %s and response.csv\n", (out / "stability_table.md").string().c_str());
        return 0;
    };
    if (o.cases == "vct") {
        if (engine::Status s = vctCases(c); !s) return fail(s.error());
        return finish();
    }
    if (o.cases == "sky") {
        if (engine::Status s = skyCases(c); !s) return fail(s.error());
        return finish();
    }

    // 1. Flicker on a still camera, relative to an unbiased 16-sample estimate's own flicker.
    for (const char* world : {"cornell", "mountain", "apartments"}) {
        auto scene = loadWorld(world);
        if (!scene) return fail(scene.error());
        LightingSettings ref;
        ref.method = Method::Reference;
        ref.referenceFilter = engine::lighting::ReferenceFilter::PixelCentre;  // the pixel the other methods shade
        ref.samplesPerFrame = 16;
        double base = flicker(c, *scene, ref, 1, 6, true);
        std::string line = fmt::format("| flicker: {} | reference 16 spp | {:.3f} (the yardstick) |", world, base);
        c.rows.push_back(line);
        std::printf("flicker %-12s reference16 %.4f\n", world, base);
        for (const char* method : {"restir", "restir-unbiased", "ris", "uniform"}) {
            LightingSettings l;
            l.restir.unbiased = std::string(method) == "restir-unbiased";
            if (std::string(method) == "ris") {
                l.method = Method::Ris;
                l.restir.temporal = l.restir.spatial = l.restir.candidateVisibility = false;
            }
            if (std::string(method) == "uniform") l.method = Method::Uniform;
            double f = flicker(c, *scene, l, 12, 6, false);
            c.rows.push_back(fmt::format("| flicker: {} | {} | {:.3f} = {:.2f}x the reference's |", world, method, f, f / base));
            std::printf("flicker %-12s %-16s %.4f (%.2fx)\n", world, method, f, f / base);
        }
    }

    // 2. Response after edits in the Cornell box.
    auto cornell = loadWorld("cornell");
    if (!cornell) return fail(cornell.error());
    cornell->grid.clearDirty();
    auto white = *cornell->palette.find("white");
    auto lightMat = *cornell->palette.find("light");
    const Box halfLight{{72, 256, 72}, {136, 264, 200}};
    response(c, "emitter switched off", *cornell, [&](Scene& s) { fillBox(s.grid, halfLight, white); });
    Scene dimmed = *cornell;
    fillBox(dimmed.grid, halfLight, white);
    dimmed.grid.clearDirty();
    response(c, "emitter switched on", dimmed, [&](Scene& s) { fillBox(s.grid, halfLight, lightMat); });
    response(c, "wall removed", *cornell,
             [&](Scene& s) { fillBox(s.grid, Box{{68, 8, 148}, {148, 168, 228}}, engine::world::kEmpty); });

    // (d) A dynamic object starts moving: the fast crate of the thin-wall world, parked for 16
    // frames, then off along its path; against each frame's own reference. ReSTIR alone: the
    // image against the direct-light reference; with the cache: its indirect term against the
    // path tracer's one-bounce indirect light (both runs are reused for the ghosting case below).
    auto thinWall = loadWorld("thin_wall");
    if (!thinWall) return fail(thinWall.error());
    thinWall->grid.clearDirty();
    const Scene fast = fastCrate(*thinWall, false);
    const auto fastCamera = fast.camera("outside");
    const int moving = 32;
    auto cacheLighting = [](std::uint32_t neighbourhood) {
        LightingSettings l;
        l.indirect = engine::lighting::Indirect::Cache;
        l.cache.neighbourhood = neighbourhood;
        return l;
    };
    MovingRun cacheN5 = movingRun(c, "fast object", fast, fastCamera, cacheLighting(5), true, 16, moving);
    {
        MovingRun direct = movingRun(c, "fast object", fast, fastCamera, LightingSettings{}, false, 16, moving);
        for (const auto& [method, run] : {std::pair{"restir (image vs direct reference)", &direct},
                                          std::pair{"restir + cache (indirect term vs 1-bounce indirect)", &cacheN5}}) {
            for (std::size_t i = 0; i < run->mae.size(); ++i)
                c.curves << fmt::format("{},{},{},{}\n", "object starts moving", method, i + 1, run->mae[i]);
            auto [frames, steady] = framesToSteady(run->mae);
            c.rows.push_back(fmt::format("| response: dynamic object starts moving (3.7 voxels/frame) | {} | {} frame(s) to within 10 % of steady state (steady MAE {:.3e}, first frame {:.3e}, largest {:.3e}) |",
                                         method, frames, steady, run->mae.front(), *std::max_element(run->mae.begin(), run->mae.end())));
            std::printf("%-28s %-52s recovered after %d frame(s); steady MAE %.3e, first frame %.3e\n", "object starts moving",
                        method, frames, steady, run->mae.front());
        }
    }

    // 3. Known failure cases.
    {   // An emitter seen at a grazing angle: a lamp lying on a floor; area mode's face choice by
        // solid angle at the face centre is poor right next to it (fireflies).
        Scene s = simpleScene({64, 32, 64});
        fillBox(s.grid, Box{{0, 0, 0}, {64, 2, 64}}, 1);
        s.grid.set({32, 2, 32}, 2);
        s.cameras.push_back({"low", {32.0f, 14.0f, 6.0f}, {32.0f, 2.0f, 32.0f}, 60.0f});
        s.grid.clearDirty();
        auto ref = cachedReference(c.gpu, s, s.camera(), c.frame, 2048, 0, c.cache, "grazing");
        for (bool area : {true, false}) {
            LightingSettings l;
            l.area = area;
            Renderer r(c.gpu);
            for (int i = 0; i < 12; ++i) r.render(s, s.camera(), c.frame, l);
            std::vector<glm::vec4> img = r.readback().radiance;
            int fireflies = 0;
            for (std::size_t i = 0; i < img.size(); ++i) {
                float a = img[i].x + img[i].y + img[i].z, b = (*ref)[i].x + (*ref)[i].y + (*ref)[i].z;
                fireflies += a > 4.0f * b + 0.05f;
            }
            double err = maeOf(img, *ref, c.frame);
            c.rows.push_back(fmt::format("| grazing emitter | restir {} | MAE {:.3e}, {} firefly pixel(s) (> 4x reference) of {} |",
                                         area ? "area" : "point", err, fireflies, img.size()));
            std::printf("grazing emitter restir %-5s MAE %.3e fireflies %d\n", area ? "area" : "point", err, fireflies);
        }
    }
    {   // Thin walls: a one-voxel wall between a lit and a dark room must not leak direct light.
        Scene s = simpleScene({64, 32, 32});
        fillBox(s.grid, Box{{0, 0, 0}, {64, 2, 32}}, 1);
        fillBox(s.grid, Box{{32, 2, 0}, {33, 32, 32}}, 1);
        s.grid.set({12, 5, 16}, 2);
        s.cameras.push_back({"above", {32.0f, 70.0f, 16.0f}, {32.0f, 0.0f, 16.01f}, 50.0f});
        s.grid.clearDirty();
        for (const char* method : {"restir", "reference"}) {
            LightingSettings l;
            if (std::string(method) == "reference") l.method = Method::Reference;
            Renderer r(c.gpu);
            for (int i = 0; i < 8; ++i) r.render(s, s.camera(), c.frame, l);
            auto img = r.readback();
            float leak = 0.0f;
            for (std::size_t i = 0; i < img.gbuffer.size(); ++i) {
                if (img.gbuffer[i].voxel.w == int(shared::FACE_POS_Y) && img.gbuffer[i].voxel.x > 32)
                    leak = std::max(leak, img.radiance[i].x + img.radiance[i].y + img.radiance[i].z);
            }
            c.rows.push_back(fmt::format("| thin wall (1 voxel), direct light | {} | largest radiance behind the wall: {:.3g} |",
                                         method, leak));
            std::printf("thin wall %-10s leak %.3g\n", method, leak);
        }
    }
    {   // Thin walls with the irradiance cache: the sealed one-voxel room of worlds/thin_wall.toml
        // in bright sun beside a lamp, the crate pressed against its west wall (t = 2.5 s). Both
        // views every frame, so entries inside and outside the wall are live neighbours (the
        // filter and the interpolation are where a leak would come from). Inside, the path
        // tracer sees nothing at all.
        const auto inside = thinWall->camera("inside"), outside = thinWall->camera("outside");
        LightingSettings l;
        l.indirect = engine::lighting::Indirect::Cache;
        Renderer r(c.gpu);
        FrameSettings f = c.frame;
        f.timeSeconds = 2.5;
        Scene s = *thinWall;
        for (int i = 0; i < 32; ++i) {
            r.render(s, outside, f, l);
            r.render(s, inside, f, l);
        }
        std::vector<glm::vec4> in = r.readback().indirect;
        r.render(s, outside, f, l);
        std::vector<glm::vec4> outdoor = r.readback().indirect;
        float insideMax = 0.0f, outsideMax = 0.0f;
        double outsideMean = 0.0;
        for (const glm::vec4& p : in) insideMax = std::max({insideMax, p.x, p.y, p.z});
        for (const glm::vec4& p : outdoor) {
            outsideMax = std::max({outsideMax, p.x, p.y, p.z});
            outsideMean += (p.x + p.y + p.z) / 3.0;
        }
        outsideMean /= double(outdoor.size());
        LightingSettings ref;
        ref.method = Method::Reference;
        ref.bounces = 3;
        ref.samplesPerFrame = 16;
        Renderer rr(c.gpu);
        for (int i = 0; i < 16; ++i) rr.render(s, inside, f, ref);
        float refInside = 0.0f;
        for (const glm::vec4& p : rr.readback().radiance) refInside = std::max({refInside, p.x, p.y, p.z});
        c.rows.push_back(fmt::format("| thin wall (1 voxel), indirect | restir + cache | largest indirect inside the sealed room: {:.3g} (outside: mean {:.3g}, largest {:.3g}) |",
                                     insideMax, outsideMean, outsideMax));
        c.rows.push_back(fmt::format("| thin wall (1 voxel), indirect | reference, 3 bounces, 256 spp | largest radiance inside: {:.3g} |", refInside));
        std::printf("thin wall cache: inside max %.3g, outside mean %.3g max %.3g; reference inside max %.3g\n", insideMax,
                    outsideMean, outsideMax, refInside);
        // The figure: both views' indirect term at one scale (the outside's largest), and the
        // inside amplified 1000x.
        const float scale = std::max(outsideMax, 1e-6f);
        const auto [w, h] = std::pair{c.frame.width, c.frame.height};
        const engine::Status pictures[] = {
            engine::io::writePng(o.output + "/thin_wall_outside_indirect.png", w, h, indirectImage(outdoor, scale)),
            engine::io::writePng(o.output + "/thin_wall_inside_indirect.png", w, h, indirectImage(in, scale)),
            engine::io::writePng(o.output + "/thin_wall_inside_indirect_x1000.png", w, h, indirectImage(in, scale / 1000.0f))};
        for (const engine::Status& written : pictures)
            if (!written) return fail(written.error());
    }
    {   // Lights removed while reservoirs point at them.
        Scene s = simpleScene({64, 32, 32});
        fillBox(s.grid, Box{{0, 0, 0}, {64, 2, 32}}, 1);
        fillBox(s.grid, Box{{32, 2, 0}, {33, 32, 32}}, 1);
        s.grid.set({12, 5, 16}, 2);
        s.grid.set({50, 5, 16}, 2);
        s.cameras.push_back({"above", {32.0f, 70.0f, 16.0f}, {32.0f, 0.0f, 16.01f}, 50.0f});
        s.grid.clearDirty();
        Renderer r(c.gpu);
        LightingSettings l;
        for (int i = 0; i < 8; ++i) r.render(s, s.camera(), c.frame, l);
        s.grid.set({12, 5, 16}, engine::world::kEmpty);
        r.render(s, s.camera(), c.frame, l);
        auto img = r.readback();
        int lit = 0;
        for (std::size_t i = 0; i < img.gbuffer.size(); ++i) {
            if (img.gbuffer[i].voxel.w == int(shared::FACE_POS_Y) && img.gbuffer[i].voxel.x < 32)
                lit += img.radiance[i].x + img.radiance[i].y + img.radiance[i].z > 0.0f;
        }
        c.rows.push_back(fmt::format("| light removed under live reservoirs | restir | {} pixel(s) still lit by it in the next frame |", lit));
        std::printf("removed light: %d pixel(s) lit in the next frame\n", lit);
    }
    {   // Fast dynamic objects (ghosting): the cache's indirect term on the fast crate's frames
        // against the path tracer's, with the N^3 neighbourhood (5) and without (0) — it updates
        // the dynamic voxels around the visible ones, so entries the object moves into are warm —
        // and, for the error floor, the same crate parked.
        MovingRun cacheN0 = movingRun(c, "fast object", fast, fastCamera, cacheLighting(0), true, 16, moving);
        const Scene parked = fastCrate(*thinWall, true);
        MovingRun still = movingRun(c, "parked object", parked, fastCamera, cacheLighting(5), true, 16, moving);
        engine::AtomicFile ghostingFile;
        if (engine::Status s = ghostingFile.open(out / "ghosting.csv"); !s) return fail(s.error());
        std::ostream& ghosting = ghostingFile.stream();
        ghosting << "case,method,frame,mae,mae_object\n";
        const double floor = mean(still.mae, 5), floorObject = mean(still.maeObject, 5);
        for (const auto& [method, run] : {std::pair{"cache N=5 (5^3 neighbourhood)", &cacheN5},
                                          std::pair{"cache N=0 (no neighbourhood)", &cacheN0},
                                          std::pair{"cache N=5 object parked", &still}}) {
            for (std::size_t i = 0; i < run->mae.size(); ++i)
                ghosting << fmt::format("fast object,{},{},{},{}\n", method, i + 1, run->mae[i], run->maeObject[i]);
            const double m = mean(run->mae, 5), mo = mean(run->maeObject, 5);
            c.rows.push_back(fmt::format("| fast dynamic object (3.7 voxels/frame), indirect term | {} | MAE over frames 6–32 {:.3e} ({:.2f}x parked); on the object's pixels {:.3e} ({:.2f}x parked) |",
                                         method, m, m / floor, mo, mo / floorObject));
            std::printf("fast object %-32s MAE %.3e (%.2fx parked), on the object %.3e (%.2fx parked)\n", method, m, m / floor,
                        mo, mo / floorObject);
        }
        if (engine::Status s = ghostingFile.commit(); !s) return fail(s.error());
    }

    // 4. Voxel cone tracing's rows.
    if (engine::Status s = vctCases(c); !s) return fail(s.error());
    // 5. DVF sky light's rows.
    if (engine::Status s = skyCases(c); !s) return fail(s.error());
    return finish();
}

}  // namespace

void addBenchStabilityCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand("stability", "Flicker, response to edits, and the known failure cases");
    auto o = std::make_shared<StabilityOptions>();
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("-o,--output", o->output, "Output folder")->capture_default_str();
    cmd->add_option("--cases", o->cases, "all | vct | sky (only voxel cone tracing's or DVF sky light's rows)")
        ->check(CLI::IsMember({"all", "vct", "sky"}))
        ->capture_default_str();
    cmd->callback([o, &exitCode] { exitCode = runStability(*o); });
}

}  // namespace vox
