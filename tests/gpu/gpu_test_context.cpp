// The GPU tests' one Vulkan context and their ray-tracing helper (gpu_test_context.h).
#include "gpu/gpu_test_context.h"

#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <memory>

#include "gpu/buffer.h"
#include "gpu/command_list.h"
#include "gpu/uploader.h"
#include "render/gpu_world.h"
#include "render/passes/trace_rays_pass.h"

namespace gpu_testing {

engine::gpu::Context& context() {
    static std::unique_ptr<engine::gpu::Context> ctx = [] {
        engine::gpu::ContextOptions options;
        options.validation = true;
        options.requireValidation = true;
        auto created = engine::gpu::Context::create(options);
        if (!created) {
            std::fprintf(stderr, "GPU tests need a Vulkan device with validation layers: %s\n",
                         created.error().message.c_str());
            std::abort();
        }
        std::printf("GPU tests on %s (%s), validation %s\n", (*created)->info().name.c_str(),
                    (*created)->info().driver.c_str(),
                    (*created)->validationEnabled() ? "on" : "off");
        return std::move(created).value();
    }();
    return *ctx;
}

engine::world::Scene sceneWith(engine::world::BrickGrid grid, int materials) {
    engine::world::Scene scene;
    scene.grid = std::move(grid);
    for (int i = 1; i <= materials; ++i) {
        engine::world::Material m;
        m.name = fmt::format("m{}", i);
        m.albedo = glm::vec3(0.1f * float(i % 9), 0.5f, 1.0f - 0.1f * float(i % 9));
        (void)scene.palette.add(m);
    }
    return scene;
}

namespace {

std::vector<shared::TraceRayOutput> traceThrough(engine::render::GpuWorld& world,
                                                 engine::world::Scene& scene,
                                                 const std::vector<engine::world::Ray>& rays,
                                                 std::uint32_t mode) {
    using namespace engine;
    gpu::Context& ctx = context();
    gpu::Uploader uploader(ctx);
    render::TraceRaysPass pass(ctx);
    std::vector<shared::TraceRayInput> inputs;
    for (const world::Ray& r : rays)
        inputs.push_back({glm::vec4(r.origin, r.tMax), glm::vec4(r.direction, 0.0f)});
    shared::TraceRaysParams params{glm::uvec4(std::uint32_t(rays.size()), mode, 0u, 0u)};
    gpu::Buffer paramsBuf(ctx, gpu::BufferKind::Storage, sizeof(params), "test.params");
    gpu::Buffer raysBuf(ctx, gpu::BufferKind::Storage, inputs.size() * sizeof(inputs[0]),
                        "test.rays");
    gpu::Buffer hitsBuf(ctx, gpu::BufferKind::Storage,
                        inputs.size() * sizeof(shared::TraceRayOutput), "test.hits");
    gpu::Buffer readback(ctx, gpu::BufferKind::Readback, hitsBuf.size(), "test.readback");
    gpu::CommandList cmd(ctx);
    cmd.begin();
    world.sync(scene, uploader);
    uploader.write(paramsBuf, 0, &params, sizeof(params));
    uploader.write(raysBuf, 0, inputs.data(), raysBuf.size());
    uploader.record(cmd);
    pass.record(cmd, {world, paramsBuf, raysBuf, hitsBuf}, std::uint32_t(inputs.size()), mode);
    cmd.copyBuffer(hitsBuf, readback, {{0, 0, hitsBuf.size()}});
    cmd.barrier();
    cmd.submitAndWait();
    auto view = readback.view<shared::TraceRayOutput>();
    return {view.begin(), view.end()};
}

}  // namespace

std::vector<shared::TraceRayOutput> traceOnGpu(engine::world::Scene& scene,
                                               const std::vector<engine::world::Ray>& rays,
                                               std::uint32_t mode) {
    engine::render::GpuWorld world(context());
    return traceThrough(world, scene, rays, mode);
}

std::vector<shared::TraceRayOutput> traceOnGpu(engine::render::GpuWorld& world,
                                               engine::world::Scene& scene,
                                               const std::vector<engine::world::Ray>& rays,
                                               std::uint32_t mode) {
    std::vector<shared::TraceRayOutput> out = traceThrough(world, scene, rays, mode);
    scene.grid.clearDirty();
    return out;
}

}  // namespace gpu_testing
