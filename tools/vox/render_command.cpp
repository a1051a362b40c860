#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "command_files.h"
#include "commands.h"
#include "core/atomic_file.h"
#include "gpu/context.h"
#include "io/image_io.h"
#include "lighting_options.h"
#include "number_options.h"
#include "render/frame_plan.h"
#include "render/renderer.h"
#include "scene/scene_lighting.h"
#include "shared/vct.h"
#include "tool_gpu.h"

namespace vox {

namespace {

// --pos and --target: both or neither, each in the world's coordinate range, apart.
engine::Result<std::optional<std::pair<glm::vec3, glm::vec3>>> commandLineView(
    const RenderOptions& o) {
    if (o.pos.empty() != o.target.empty())
        return engine::makeError("--pos and --target go together");
    if (o.pos.empty()) return std::optional<std::pair<glm::vec3, glm::vec3>>{};
    auto p = parseVec3(o.pos, "--pos", engine::world::kCoordinateRange);
    if (!p) return p.error();
    auto t = parseVec3(o.target, "--target", engine::world::kCoordinateRange);
    if (!t) return t.error();
    if (glm::length(*t - *p) < 1e-4f) return engine::makeError("--target must differ from --pos");
    return std::optional{std::pair{*p, *t}};
}

// The camera: --pos/--target, else the named preset (which must exist), and --fov over either.
engine::Result<engine::world::CameraPreset> cameraOf(
    const RenderOptions& o, const engine::world::Scene& scene,
    const std::optional<std::pair<glm::vec3, glm::vec3>>& view) {
    engine::world::CameraPreset camera;
    if (view) {
        camera = scene.camera(o.camera);
        camera.name = "command line";
        camera.position = view->first;
        camera.target = view->second;
    } else {
        if (!o.camera.empty()) {
            bool found = false;
            for (const auto& c : scene.cameras) found |= c.name == o.camera;
            if (!found)
                return engine::makeError("{}: no camera named '{}'", scene.sourcePath, o.camera);
        }
        camera = scene.camera(o.camera);
    }
    if (o.fov) camera.fovYDegrees = *o.fov;
    return camera;
}

// The last frame's passes, emitters, and the cache's and the DVF sky's state.
void printFrame(const engine::render::FrameResult& frame, const engine::render::FrameResult& first,
                const engine::render::FrameSettings& settings,
                const engine::lighting::LightingSettings& l) {
    std::printf("frame    %ux%u, %.2f ms GPU (last frame):", settings.width, settings.height,
                frame.totalMs());
    for (const auto& [name, ms] : frame.passMs) std::printf(" %s %.2f", name.c_str(), ms);
    std::printf("\n");
    std::printf("emitters %u (list update %.3f ms CPU)\n", frame.emitters, first.emitterUpdateMs);
    if (frame.cacheUsed) {
        const auto& c = frame.cache;
        std::printf(
            "cache    %u visible static + %u dynamic voxels, %u entries updated (%u dynamic; %u "
            "waiting for the ray "
            "budget), %u live, %.2f MiB GPU, %llu rays traced, %.2f ms CPU\n",
            c.visibleStatic, c.visibleDynamic, c.updated, c.dynamicEntries, c.waiting, c.entries,
            double(c.bytes) / 1048576.0, static_cast<unsigned long long>(c.raysTraced),
            frame.cachePrepareMs);
        if (c.coarseEntries)
            std::printf(
                "cache    level of detail: %u of the visible static entries are coarse (2x2 "
                "patches)\n",
                c.coarseEntries);
    }
    if (frame.vctUsed)
        std::printf("vct      %u of %u blocks of 4^3 texels classified, %.3f ms CPU (last frame)\n",
                    frame.vctBlocks, l.vct.levels * shared::VCT_BLOCKS_PER_LEVEL,
                    frame.vctPrepareMs);
    if (frame.skyUsed && l.sky == engine::lighting::Sky::Dvf) {
        std::printf(
            "sky      %u DVF masks (%u waiting), %u traced with %u rays in the last frame, %.2f "
            "MiB GPU table\n",
            frame.sky.usedSlots, frame.sky.queued, frame.sky.tracedMasks, frame.sky.tracedRays,
            double(frame.sky.tableBytes) / 1048576.0);
    }
}

// --timings: every frame's per-pass GPU milliseconds (and VCT's host time and blocks).
engine::Status writeTimings(const std::string& file, const std::string& world,
                            const engine::lighting::LightingSettings& l,
                            const engine::render::FrameSettings& settings,
                            const std::vector<engine::render::FrameResult>& results) {
    engine::AtomicFile out;
    if (engine::Status s = out.open(file); !s) return s;
    std::ostream& json = out.stream();
    json << "{\"world\": \"" << world << "\", \"lighting\": \""
         << engine::render::describeLighting(l) << "\", \"size\": [" << settings.width << ", "
         << settings.height << "], \"emitters\": " << results.back().emitters
         << ", \"frames\": [\n";
    for (std::size_t i = 0; i < results.size(); ++i) {
        json << "  {";
        for (std::size_t p = 0; p < results[i].passMs.size(); ++p)
            json << (p ? ", " : "") << "\"" << results[i].passMs[p].first
                 << "\": " << results[i].passMs[p].second;
        // Not passes: VCT's host time and the blocks it classified.
        if (results[i].vctUsed)
            json << ", \"vct.blocks (count)\": " << results[i].vctBlocks
                 << ", \"vct.prepare (CPU ms)\": " << results[i].vctPrepareMs;
        json << "}" << (i + 1 < results.size() ? "," : "") << "\n";
    }
    json << "]}\n";
    if (engine::Status s = out.commit(); !s) return s;
    std::printf("wrote    %s\n", file.c_str());
    return {};
}

// The image (-o, tonemapped PNG or linear EXR) and --exr.
engine::Status writeImages(const RenderOptions& o, const engine::render::FrameImages& images) {
    std::filesystem::path out(o.output);
    std::error_code ec;
    if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path(), ec);
    engine::Status s =
        out.extension() == ".png"
            ? engine::io::writePng(out, images.displayWidth, images.displayHeight, images.rgba8)
            : engine::io::writeExr(out, images.displayWidth, images.displayHeight, images.display);
    if (!s) return s;
    std::printf("wrote    %s\n", out.string().c_str());
    if (!o.exr.empty()) {
        s = engine::io::writeExr(o.exr, images.displayWidth, images.displayHeight, images.display);
        if (!s) return s;
        std::printf("wrote    %s (linear)\n", o.exr.c_str());
    }
    return {};
}

}  // namespace

int runRender(const RenderOptions& o) {
    auto size = parseSize(o.size, "--size");
    if (!size) return fail(size.error());
    std::string ext = std::filesystem::path(o.output).extension().string();
    if (ext != ".png" && ext != ".exr")
        return fail(engine::makeError("-o {}: the file must end in .png or .exr", o.output));
    if (engine::Status s =
            checkCommandFiles({{"the world", worldFileOf(o.world)}},
                              {{"-o", o.output}, {"--exr", o.exr}, {"--timings", o.timings}});
        !s)
        return fail(s.error());
    auto view = commandLineView(o);
    if (!view) return fail(view.error());

    if (o.lighting.showSettings) return showSettings(o.world, o.lighting);
    auto scene = loadWorld(o.world);
    if (!scene) return fail(scene.error());
    auto lighting = lightingSettings(o.lighting, &*scene);
    if (!lighting) return fail(lighting.error());
    auto cameraOrError = cameraOf(o, *scene, *view);
    if (!cameraOrError) return fail(cameraOrError.error());
    const engine::world::CameraPreset& camera = *cameraOrError;

    auto ctx = createValidatedGpu();
    if (!ctx) return fail(ctx.error());
    printDevice(**ctx);
    std::printf("world    %s: %d x %d x %d voxels, %u bricks\n", scene->name.c_str(),
                scene->grid.sizeInVoxels().x, scene->grid.sizeInVoxels().y,
                scene->grid.sizeInVoxels().z, scene->grid.liveBricks());
    std::printf("camera   %s at (%.1f, %.1f, %.1f), fov %.1f\n", camera.name.c_str(),
                camera.position.x, camera.position.y, camera.position.z, camera.fovYDegrees);

    engine::render::Renderer renderer(**ctx);
    engine::render::FrameSettings settings;
    const glm::uvec2 renderSize = renderSizeOf(*size, o.renderScale);
    settings.width = renderSize.x;
    settings.height = renderSize.y;
    settings.displayWidth = (*size).x;
    settings.displayHeight = (*size).y;
    settings.exposure = o.exposure;
    settings.timeSeconds = o.time;  // every frame at the same scene time: a still
    if (!scene->objects.empty())
        std::printf("objects  %zu dynamic, posed at t = %g s\n", scene->objects.size(), o.time);
    // The reference adds samples per frame until --spp; the other methods run --frames frames
    // of a still camera (temporal reuse builds up history over them).
    engine::lighting::LightingSettings l = *lighting;
    std::uint32_t frames = o.frames;
    if (l.method == engine::lighting::Method::Reference) {
        l.samplesPerFrame = std::min<std::uint32_t>(o.spp, 16);
        frames = (o.spp + l.samplesPerFrame - 1) / l.samplesPerFrame;
    }
    std::printf("lighting %s, %u frame(s)\n", engine::render::describeLighting(l).c_str(), frames);
    std::vector<engine::render::FrameResult> results;
    for (std::uint32_t i = 0; i < frames; ++i) {
        results.push_back(renderer.render(*scene, camera, settings, l));
        if (frames > 4 && (i + 1) % std::max<std::uint32_t>(1, frames / 10) == 0)
            std::fprintf(stderr, "\r  frame %u/%u", i + 1, frames);
    }
    if (frames > 4) std::fprintf(stderr, "\n");
    engine::render::FrameImages images = renderer.readback();

    printFrame(results.back(), results.front(), settings, l);
    if (const auto& facts = renderer.samplingFacts();
        facts && l.byPower && engine::lighting::resamples(l))
        std::printf(
            "sampling auto chose %s: %u emitters spread %.0f voxels, %.1f ReGIR cells of %.0f, "
            "%.1f per occupied cell\n",
            results.back().regirSampling ? "regir" : "power", facts->emitters, facts->spread,
            facts->spread / facts->regirCell, facts->regirCell, facts->perOccupiedCell);
    if (!o.timings.empty()) {
        if (engine::Status s = writeTimings(o.timings, scene->name, l, settings, results); !s)
            return fail(s.error());
    }
    if (engine::Status s = writeImages(o, images); !s) return fail(s.error());
    if ((*ctx)->validationErrors() > 0) {
        std::fprintf(stderr, "vox: %u Vulkan validation error(s)\n", (*ctx)->validationErrors());
        return 1;
    }
    return 0;
}

void addRenderCommand(CLI::App& app, int& exitCode) {
    auto* cmd =
        app.add_subcommand("render", "Render a world headless to PNG (tonemapped) or EXR (linear)");
    auto o = std::make_shared<RenderOptions>();
    cmd->add_option("world", o->world,
                    "World name (worlds/NAME.toml) or scene file; default: sandbox");
    cmd->add_option("--camera", o->camera,
                    "Camera preset from the scene file (default: its first)");
    cmd->add_option("--pos", o->pos, "Camera position x,y,z (with --target)");
    cmd->add_option("--target", o->target, "Point the camera looks at x,y,z (with --pos)");
    cmd->add_option("--fov", o->fov, "Vertical field of view in degrees (default: the camera's)")
        ->check(numberIn(engine::world::kFovRange));
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("-o,--output", o->output, "Output image (.png or .exr)")->capture_default_str();
    cmd->add_option("--exr", o->exr,
                    "Also write the shown image, linear (before exposure and tonemapping), to this "
                    "EXR file: with --display upsampled or denoised the reconstruction's output, "
                    "with --display raw the lit image");
    cmd->add_option("--exposure", o->exposure, "Exposure multiplier before tonemapping")
        ->capture_default_str()
        ->check(numberIn(kExposureRange));
    cmd->add_option("--frames", o->frames, "Frames of a still camera (temporal reuse accumulates)")
        ->capture_default_str()
        ->check(numberIn(kFrameCountRange));
    cmd->add_option("--time", o->time, "Scene time in seconds (poses dynamic objects)")
        ->capture_default_str()
        ->check(numberIn(engine::closedRange(-1e7, 1e7, "s")));
    cmd->add_option("--spp", o->spp, "reference: samples per pixel")
        ->capture_default_str()
        ->check(numberIn(kSamplesRange));
    cmd->add_option("--timings", o->timings,
                    "Write per-frame, per-pass GPU milliseconds to this JSON file");
    addRenderScaleOption(*cmd, o->renderScale);
    addLightingOptions(*cmd, o->lighting);
    cmd->callback([o, cmd, &exitCode] {
        // A fixed --exposure is the exposure: not metered.
        o->lighting.commandDefaults = engine::scene::playerDefaults(cmd->count("--exposure") == 0);
        exitCode = runRender(*o);
    });
}

}  // namespace vox
