#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "gpu/context.h"
#include "io/image_io.h"
#include "render/renderer.h"

namespace vox {

namespace {

struct RenderOptions {
    std::string world;
    std::string camera;
    std::string pos, target;
    float fov = 0.0f;
    std::string size = "640x360";
    std::string output = "out/render.png";
    std::string exr;
    float exposure = 1.0f;
};

int runRender(const RenderOptions& o) {
    auto size = parseSize(o.size, "--size");
    if (!size) return fail(size.error());
    std::filesystem::path out(o.output);
    std::string ext = out.extension().string();
    if (ext != ".png" && ext != ".exr") return fail(engine::makeError("-o {}: the file must end in .png or .exr", o.output));
    if (o.pos.empty() != o.target.empty()) return fail(engine::makeError("--pos and --target go together"));

    auto scene = loadWorld(o.world);
    if (!scene) return fail(scene.error());
    engine::world::CameraPreset camera;
    if (!o.pos.empty()) {
        auto pos = parseVec3(o.pos, "--pos");
        if (!pos) return fail(pos.error());
        auto target = parseVec3(o.target, "--target");
        if (!target) return fail(target.error());
        if (glm::length(*target - *pos) < 1e-4f) return fail(engine::makeError("--target must differ from --pos"));
        camera = scene->camera(o.camera);
        camera.name = "command line";
        camera.position = *pos;
        camera.target = *target;
    } else {
        if (!o.camera.empty()) {
            bool found = false;
            for (const auto& c : scene->cameras) found |= c.name == o.camera;
            if (!found) return fail(engine::makeError("{}: no camera named '{}'", scene->sourcePath, o.camera));
        }
        camera = scene->camera(o.camera);
    }
    if (o.fov != 0.0f) {
        if (o.fov <= 1.0f || o.fov >= 179.0f) return fail(engine::makeError("--fov must be in (1, 179) degrees"));
        camera.fovYDegrees = o.fov;
    }

    engine::gpu::ContextOptions ctxOptions;
#ifndef NDEBUG
    ctxOptions.validation = true;
#endif
    auto ctx = engine::gpu::Context::create(ctxOptions);
    if (!ctx) return fail(ctx.error());
    const auto& dev = (*ctx)->info();
    std::printf("device   %s (%s, %s)\n", dev.name.c_str(), dev.type.c_str(), dev.driver.c_str());
    std::printf("world    %s: %d x %d x %d voxels, %u bricks\n", scene->name.c_str(), scene->grid.sizeInVoxels().x,
                scene->grid.sizeInVoxels().y, scene->grid.sizeInVoxels().z, scene->grid.liveBricks());
    std::printf("camera   %s at (%.1f, %.1f, %.1f), fov %.1f\n", camera.name.c_str(), camera.position.x,
                camera.position.y, camera.position.z, camera.fovYDegrees);

    engine::render::Renderer renderer(**ctx);
    engine::render::FrameSettings settings;
    settings.width = (*size).x;
    settings.height = (*size).y;
    settings.exposure = o.exposure;
    engine::render::FrameResult frame = renderer.render(*scene, camera, settings);
    engine::render::FrameImages images = renderer.readback();

    std::printf("frame    %ux%u, %.2f ms GPU:", settings.width, settings.height, frame.totalMs());
    for (const auto& [name, ms] : frame.passMs) std::printf(" %s %.2f", name.c_str(), ms);
    std::printf("\n");

    std::error_code ec;
    if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path(), ec);
    engine::Status s = ext == ".png" ? engine::io::writePng(out, images.width, images.height, images.rgba8)
                                     : engine::io::writeExr(out, images.width, images.height, images.radiance);
    if (!s) return fail(s.error());
    std::printf("wrote    %s\n", out.string().c_str());
    if (!o.exr.empty()) {
        s = engine::io::writeExr(o.exr, images.width, images.height, images.radiance);
        if (!s) return fail(s.error());
        std::printf("wrote    %s (linear)\n", o.exr.c_str());
    }
    if ((*ctx)->validationErrors() > 0) {
        std::fprintf(stderr, "vox: %u Vulkan validation error(s)\n", (*ctx)->validationErrors());
        return 1;
    }
    return 0;
}

}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand("render", "Render a world headless to PNG (tonemapped) or EXR (linear)");
    auto o = std::make_shared<RenderOptions>();
    cmd->add_option("world", o->world, "World name (worlds/NAME.toml) or scene file; default: sandbox");
    cmd->add_option("--camera", o->camera, "Camera preset from the scene file (default: its first)");
    cmd->add_option("--pos", o->pos, "Camera position x,y,z (with --target)");
    cmd->add_option("--target", o->target, "Point the camera looks at x,y,z (with --pos)");
    cmd->add_option("--fov", o->fov, "Vertical field of view in degrees");
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("-o,--output", o->output, "Output image (.png or .exr)")->capture_default_str();
    cmd->add_option("--exr", o->exr, "Also write the linear radiance to this EXR file");
    cmd->add_option("--exposure", o->exposure, "Exposure multiplier before tonemapping")->capture_default_str();
    cmd->callback([o, &exitCode] { exitCode = runRender(*o); });
}

}  // namespace vox
