// vox bench display: what a player sees, against the converged image of the same frame
// (issue 37; docs/DISPLAY.md). Each world plays its flythrough (the scene's own [path] with its
// edits, lights and moving objects, else worlds/paths/<world>_flythrough.toml) once per row, the
// rows' frames interleaved so they share the machine's drift:
//   raw S        today's image: shaded at S x the display size, blown up by nearest neighbour,
//   upsampled S  jittered primary rays resolved over frames to the display size,
//   denoised S   the lighting denoised first, then that resolve,
//   raw 1        shaded at the display's own size.
// Per frame: wall milliseconds of the whole Renderer::render (host work, uploads, submission and
// wait); every K-th frame the shown image against the path tracer's box-filtered image of that
// frame at the display size (metrics/display_error.h: relative MAE and RMSE, SSIM, mean ratio).
// Then the stability cases on a world with a timeline (display_stability.cpp). Results: CSVs, a
// markdown table; tools/plot_display.py draws error against time.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <memory>
#include <optional>
#include <string>

#include "bench_median.h"
#include "bench_setup.h"
#include "commands.h"
#include "display_bench.h"
#include "gpu/context.h"
#include "lighting_options.h"
#include "metrics/display_error.h"
#include "number_options.h"
#include "progress_line.h"
#include "render/flythrough_player.h"
#include "scene/path_file.h"

namespace vox {

namespace {

namespace fs = std::filesystem;
using engine::lighting::LightingSettings;
using engine::render::FlythroughPlayer;
using engine::render::Renderer;
using engine::world::Flythrough;
using engine::world::Scene;
using Clock = std::chrono::steady_clock;

struct DisplayBenchOptions {
    std::vector<std::string> worlds{"sandbox", "cornell", "apartments"};
    std::string size = "640x360";
    std::vector<double> scales{0.25, 0.5};
    std::optional<std::uint32_t> frames;  // absent: the whole path
    std::uint32_t referenceEvery = 10;
    std::uint32_t referenceSpp = 128;
    std::string only;                        // "flythrough" or "stability": that part alone
    std::string stabilityWorld = "sandbox";  // "none": skip the stability cases
    std::string stabilitySize;               // default: --size
    std::uint32_t stabilitySpp = 64;
    StabilityOptions stability;  // its frame counts; display and spp from the options above
    bool images = false;  // PNGs of every reference frame: the reference and each row's image
    LightingOptions lighting;
    std::string output = "out/display";
};

// One row's run through a world: its own scene copy (the timeline edits it), renderer, player.
struct Run {
    DisplayRow row;
    Scene scene;
    Flythrough fly;
    std::unique_ptr<Renderer> renderer;
    std::unique_ptr<FlythroughPlayer> player;
    std::vector<double> wallMs;
    std::vector<engine::metrics::DisplayErrors> errors;
};

// The world's own [path], else worlds/paths/<world>_flythrough.toml.
engine::Result<Flythrough> flythroughOf(const Scene& scene, const std::string& world) {
    if (auto own = engine::scene::loadFlythroughFile(scene.sourcePath)) return own;
    const std::string file = fs::path(world).stem().string() + "_flythrough.toml";
    std::error_code ec;
    for (fs::path dir : {fs::path("worlds/paths"), fs::path(VOX_SOURCE_DIR) / "worlds/paths"})
        if (fs::is_regular_file(dir / file, ec))
            return engine::scene::loadFlythroughFile(dir / file);
    return engine::makeError("{}: no [path] in the scene and no worlds/paths/{}", world, file);
}

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(p * double(v.size() - 1) + 0.5))];
}

template <typename F>
double meanOf(const std::vector<engine::metrics::DisplayErrors>& v, F field) {
    double s = 0.0;
    for (const auto& e : v) s += field(e);
    return v.empty() ? 0.0 : s / double(v.size());
}

struct Outputs {
    std::ostream& frames;
    std::ostream& summary;
    std::string table;
};

void summarise(const std::vector<Run>& runs, const std::string& world, glm::uvec2 display,
               Outputs& out) {
    auto rawAt = [&](double scale) -> const Run* {
        for (const Run& r : runs)
            if (r.row.mode == engine::lighting::Display::Raw && r.row.scale == scale) return &r;
        return nullptr;
    };
    for (const Run& r : runs) {
        const double mae = meanOf(r.errors, [](auto& e) { return e.relativeMae; });
        const double rmse = meanOf(r.errors, [](auto& e) { return e.relativeRmse; });
        const double ssim = meanOf(r.errors, [](auto& e) { return e.ssim; });
        const double ratio = meanOf(r.errors, [](auto& e) { return e.meanRatio; });
        const double wall = median(r.wallMs), p95 = percentile(r.wallMs, 0.95);
        const Run* raw = rawAt(r.row.scale);
        const double rawMae = raw ? meanOf(raw->errors, [](auto& e) { return e.relativeMae; }) : 0;
        const double rawWall = raw ? median(raw->wallMs) : 0.0;
        const auto f = rowFrame(r.row, display);
        out.summary << fmt::format(
            "{},{},{:g},{}x{},{}x{},{:.5f},{:.5f},{:.5f},{:.4f},{:.2f},{:.2f},"
            "{:.4f},{:.4f},{},{}\n",
            world, r.row.label(), r.row.scale, f.width, f.height, display.x, display.y, mae, rmse,
            ssim, ratio, wall, p95, mae / std::max(rawMae, 1e-12), wall / std::max(rawWall, 1e-12),
            r.wallMs.size(), r.errors.size());
        const std::string row = fmt::format(
            "| {} | {} | {}x{} | {:.4f} | {:.4f} | {:.3f} | {:.3f} | {:.1f} | {:.1f} | {:.2f} | "
            "{:.2f} |\n",
            world, r.row.label(), f.width, f.height, mae, rmse, ssim, ratio, wall, p95,
            mae / std::max(rawMae, 1e-12), wall / std::max(rawWall, 1e-12));
        out.table += row;
        std::printf("%s", row.c_str());
    }
    std::fflush(stdout);
}

engine::Status benchWorld(engine::gpu::Context& ctx, const std::string& world,
                          const DisplayBenchOptions& o, glm::uvec2 display, Outputs& out) {
    auto loaded = loadWorld(world);
    if (!loaded) return loaded.error();
    auto fly = flythroughOf(*loaded, world);
    if (!fly) return fly.error();
    const double fps = fly->fps;
    if (engine::Status s = fly->checkFrames(fps); !s) return s;
    const std::uint32_t count =
        o.frames ? std::min(*o.frames, fly->frameCount(fps)) : fly->frameCount(fps);
    auto lighting = lightingSettings(o.lighting, &*loaded);
    if (!lighting) return lighting.error();

    std::vector<Run> runs;
    for (const DisplayRow& row : displayRows(o.scales)) {
        Run r;
        r.row = row;
        r.scene = *loaded;
        r.fly = *fly;
        if (engine::Status s = r.fly.timeline.bind(r.scene); !s) return s;
        runs.push_back(std::move(r));
    }
    for (Run& r : runs) {  // after the vector stops moving: the players hold references
        r.renderer = std::make_unique<Renderer>(ctx);
        r.player = std::make_unique<FlythroughPlayer>(*r.renderer, r.scene, r.fly, fps);
    }
    Scene refScene = *loaded;
    Flythrough refFly = *fly;
    if (engine::Status s = refFly.timeline.bind(refScene); !s) return s;
    DisplayReference reference(ctx, *lighting, o.referenceSpp);

    ProgressLine progress(fmt::format("{} ({} frames x {} rows, {}x{})", loaded->name, count,
                                      runs.size(), display.x, display.y),
                          count);
    for (std::uint32_t i = 0; i < count; ++i) {
        const bool referenceFrame = i % o.referenceEvery == o.referenceEvery - 1;
        std::vector<glm::vec4> ref;
        if (referenceFrame) {
            refFly.timeline.applyThrough(i, fps, refScene);
            const double t = Flythrough::frameTime(i, fps);
            ref = reference.render(refScene, refFly.camera.at(t), display, t);
            if (o.images) {
                const auto file = fs::path(o.output) / "images" /
                                  fmt::format("{}_{:04}_reference.png", loaded->name, i);
                if (engine::Status s = writeViewPng(file, ref, display, viewExposure(ref)); !s)
                    return s;
            }
        }
        for (Run& r : runs) {
            auto frame = rowFrame(r.row, display);
            const auto start = Clock::now();
            r.player->render(i, frame, rowLighting(r.row, *lighting));
            const double ms =
                std::chrono::duration<double, std::milli>(Clock::now() - start).count();
            r.wallMs.push_back(ms);
            std::string errorText = ",,,";
            if (referenceFrame) {
                const auto shown = shownImage(*r.renderer, display);
                auto e = engine::metrics::compareDisplay({shown, display.x, display.y},
                                                         {ref, display.x, display.y});
                if (!e) return e.error();
                r.errors.push_back(*e);
                if (o.images) {
                    std::string row = r.row.label();
                    std::replace(row.begin(), row.end(), ' ', '_');
                    const auto file = fs::path(o.output) / "images" /
                                      fmt::format("{}_{:04}_{}.png", loaded->name, i, row);
                    if (engine::Status s = writeViewPng(file, shown, display, viewExposure(ref));
                        !s)
                        return s;
                }
                errorText = fmt::format("{:.6f},{:.6f},{:.5f},{:.5f}", e->relativeMae,
                                        e->relativeRmse, e->ssim, e->meanRatio);
            }
            out.frames << fmt::format("{},{},{},{:.3f},{}\n", loaded->name, r.row.label(), i, ms,
                                      errorText);
        }
        progress.update(i + 1, referenceFrame ? "reference frame" : "");
    }
    progress.finish();
    summarise(runs, loaded->name, display, out);
    return {};
}

int runDisplayBench(const DisplayBenchOptions& o) {
    auto setup = openBench(o.size);
    if (!setup) return fail(setup.error());
    const glm::uvec2 display(setup->frame.width, setup->frame.height);
    glm::uvec2 stabilityDisplay = display;
    if (!o.stabilitySize.empty()) {
        auto s = frameOfSize(o.stabilitySize, "--stability-size");
        if (!s) return fail(s.error());
        stabilityDisplay = {s->width, s->height};
    }
    for (double s : o.scales)
        if (!(s >= 0.0625 && s <= 1.0))
            return fail(engine::makeError("--scales: {} is not in [0.0625, 1]", s));
    const fs::path out(o.output);
    if (o.images) {
        std::error_code ec;
        fs::create_directories(out / "images", ec);
        if (ec)
            return fail(
                engine::makeError("-o {}: cannot create images/: {}", o.output, ec.message()));
    }
    engine::AtomicFile framesFile, summaryFile, stabilityFile;
    if (engine::Status s = openOutputFile(framesFile, out / "frames.csv"); !s)
        return fail(s.error());
    if (engine::Status s = openOutputFile(summaryFile, out / "summary.csv"); !s)
        return fail(s.error());
    if (engine::Status s = openOutputFile(stabilityFile, out / "stability.csv"); !s)
        return fail(s.error());
    framesFile.stream() << "world,row,frame,wall_ms,relative_mae,relative_rmse,ssim,mean_ratio\n";
    summaryFile.stream() << "world,row,scale,render_size,display_size,relative_mae,relative_rmse,"
                            "ssim,mean_ratio,wall_ms_median,wall_ms_p95,mae_vs_raw_same_scale,"
                            "wall_vs_raw_same_scale,frames,reference_frames\n";
    stabilityFile.stream() << "case,row,value,detail\n";
    std::printf("display %ux%u; reference %u spp (box filter) every %u frames; rows interleaved\n",
                display.x, display.y, o.referenceSpp, o.referenceEvery);
    std::fflush(stdout);
    Outputs outputs{framesFile.stream(), summaryFile.stream(),
                    "| world | row | render size | rel. MAE | rel. RMSE | SSIM | mean ratio | wall "
                    "ms median | p95 | MAE / raw same scale | wall / raw same scale |\n"
                    "|---|---|---|---|---|---|---|---|---|---|---|\n"};
    for (const std::string& world : o.worlds) {
        if (o.only == "stability") break;
        if (engine::Status s = benchWorld(*setup->gpu, world, o, display, outputs); !s)
            return fail(s.error());
    }
    std::string stabilityTable;
    if (o.stabilityWorld != "none" && o.only != "flythrough") {
        auto scene = loadWorld(o.stabilityWorld);
        if (!scene) return fail(scene.error());
        auto fly = flythroughOf(*scene, o.stabilityWorld);
        if (!fly) return fail(fly.error());
        auto lighting = lightingSettings(o.lighting, &*scene);
        if (!lighting) return fail(lighting.error());
        StabilityOptions so = o.stability;
        so.display = stabilityDisplay;
        so.referenceSpp = o.stabilitySpp;
        if (o.images) so.images = out / "images";
        if (engine::Status s =
                displayStability(*setup->gpu, *scene, *fly, displayRows(o.scales), *lighting, so,
                                 stabilityTable, stabilityFile.stream());
            !s)
            return fail(s.error());
    }
    for (engine::AtomicFile* f : {&framesFile, &summaryFile, &stabilityFile})
        if (engine::Status s = f->commit(); !s) return fail(s.error());
    if (engine::Status s =
            engine::writeFileAtomically(out / "table.md", outputs.table + "\n" + stabilityTable);
        !s)
        return fail(s.error());
    std::printf(
        "\nwrote %s (summary.csv, frames.csv, stability.csv, table.md); chart: python3 "
        "tools/plot_display.py %s\n",
        out.c_str(), out.c_str());
    return 0;
}

}  // namespace

void addBenchDisplayCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand(
        "display",
        "What the player sees: raw, upsampled and denoised images against the "
        "converged frame, per render scale; stability after edits, lights, objects");
    auto o = std::make_shared<DisplayBenchOptions>();
    cmd->add_option("worlds", o->worlds,
                    "Worlds, each with a [path] or worlds/paths/<world>_flythrough.toml")
        ->capture_default_str();
    cmd->add_option("--size", o->size, "Display size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("--scales", o->scales, "Render scales of the raw/upsampled/denoised rows")
        ->delimiter(',')
        ->capture_default_str();
    cmd->add_option("--frames", o->frames, "Frames of each path to play (default: all)")
        ->check(numberIn(kFrameCountRange));
    cmd->add_option("--reference-every", o->referenceEvery,
                    "Compare with the reference every K-th frame")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 100000, "frames")));
    cmd->add_option("--reference-spp", o->referenceSpp, "Reference samples per pixel")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 65536, "samples per pixel")));
    cmd->add_option("--only", o->only,
                    "Run one part: flythrough (the worlds' paths) or stability (the still cases)")
        ->check(CLI::IsMember({"flythrough", "stability"}));
    cmd->add_option("--stability-world", o->stabilityWorld,
                    "World whose timeline events the stability cases replay on a still camera "
                    "(none: skip them)")
        ->capture_default_str();
    cmd->add_option("--stability-size", o->stabilitySize,
                    "Display size of the stability cases (default: --size)");
    cmd->add_option("--stability-spp", o->stabilitySpp,
                    "Reference samples per pixel of the stability cases")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 65536, "samples per pixel")));
    cmd->add_option("--still-frames", o->stability.stillFrames,
                    "Stability: still frames before each event (16 more give the flicker)")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(2, 100000, "frames")));
    cmd->add_option("--after-frames", o->stability.afterFrames,
                    "Stability: frames after an edit or light (the last 4 are its steady value)")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(4, 100000, "frames")));
    cmd->add_option("--ghost-frames", o->stability.ghostFrames,
                    "Stability: frames of a moving object, each against its own reference")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 100000, "frames")));
    cmd->add_option("--stability-cases", o->stability.cases,
                    "Stability: only the first N cases (0: all)")
        ->capture_default_str();
    cmd->add_flag("--images", o->images,
                  "Write every reference frame and each row's image of it as PNGs (images/); "
                  "the stability cases: each still camera's last frame, its reference and a "
                  "heat map of their difference");
    addLightingOptions(*cmd, o->lighting);
    cmd->add_option("-o,--output", o->output, "Output folder")->capture_default_str();
    cmd->callback([o, &exitCode] { exitCode = runDisplayBench(*o); });
}

}  // namespace vox
