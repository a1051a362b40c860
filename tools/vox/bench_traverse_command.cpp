// vox bench traverse: rays per second and DDA steps per ray, in one run on one world and view,
// for the GPU traversal (lavapipe here) and the CPU reference on all cores, each in the
// hierarchical mode (empty-space skipping inside bricks) and the plain two-level mode.
// Same rays for every method: camera rays, then one shadow ray towards the sun per hit.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <thread>
#include <time.h>

#include "bench_median.h"
#include "bench_setup.h"
#include "classic_dda.h"
#include "commands.h"
#include "core/atomic_file.h"
#include "gpu/command_list.h"
#include "gpu/context.h"
#include "gpu/timestamp_timer.h"
#include "gpu/uploader.h"
#include "number_options.h"
#include "render/camera.h"
#include "render/passes/trace_rays_pass.h"
#include "shared/trace_rays.h"
#include "world/ray_traversal.h"

namespace vox {

namespace {

using engine::world::Ray;
using engine::world::RayHit;
using engine::world::TraversalMode;

struct BenchOptions {
    std::string world = "terrain_1024";
    std::string camera;
    std::string size = "640x360";
    int repeats = 5;
    std::string output = "out/bench_traverse.json";
};

struct MethodResult {
    std::string name;
    double ms = 0.0;  // median wall (CPU) or GPU timestamp time for all rays
    // Median CPU time of the whole process over the same runs (all threads, lavapipe's too):
    // unlike wall time it hardly moves when other processes load the machine.
    double cpuMs = 0.0;
    std::uint64_t rays = 0;
    std::uint64_t steps = 0;
    // GPU only: steps as the SIMD hardware pays for them. llvmpipe runs 8 lanes in lockstep, so a
    // batch of 8 consecutive rays costs 8 x its longest ray's steps.
    std::uint64_t laneSteps = 0;
    double raysPerSecond() const { return double(rays) / (ms * 1e-3); }
    double stepsPerRay() const { return double(steps) / double(std::max<std::uint64_t>(rays, 1)); }
};

constexpr std::size_t kSimdLanes = 8;  // llvmpipe with 256-bit vectors: 8 invocations per batch

// CPU time of the whole process, all threads, in milliseconds.
double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

std::vector<Ray> shadowRays(const std::vector<Ray>& primary, const std::vector<RayHit>& hits,
                            glm::vec3 toSun) {
    std::vector<Ray> out;
    for (std::size_t i = 0; i < primary.size(); ++i) {
        if (!hits[i].hit || hits[i].face >= 6) continue;
        glm::vec3 n(engine::world::faceNormal(hits[i].face));
        if (glm::dot(n, toSun) <= 0.0f) continue;
        Ray r;
        r.origin = primary[i].origin + primary[i].direction * hits[i].t + n * 1e-3f;
        r.direction = toSun;
        out.push_back(r);
    }
    return out;
}

template <typename Trace>
MethodResult benchCpu(const std::vector<Ray>& rays, Trace&& trace, int repeats, const char* name) {
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    MethodResult r;
    r.name = name;
    std::vector<double> times, cpuTimes;
    std::vector<std::uint64_t> steps(threads);
    for (int rep = 0; rep < repeats + 1; ++rep) {  // first run warms caches, not counted
        const double cpuStart = processCpuMs();
        auto start = std::chrono::steady_clock::now();
        std::vector<std::thread> pool;
        for (unsigned t = 0; t < threads; ++t) {
            pool.emplace_back([&, t] {
                std::uint64_t s = 0;
                // Interleaved rows of 64 rays keep both threads' work even.
                for (std::size_t base = t * 64; base < rays.size(); base += threads * 64) {
                    std::size_t end = std::min(rays.size(), base + 64);
                    for (std::size_t i = base; i < end; ++i) s += trace(rays[i]).steps;
                }
                steps[t] = s;
            });
        }
        for (auto& th : pool) th.join();
        double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        if (rep > 0) {
            times.push_back(ms);
            cpuTimes.push_back(processCpuMs() - cpuStart);
        }
    }
    r.ms = median(times);
    r.cpuMs = median(cpuTimes);
    r.rays = rays.size();
    for (auto s : steps) r.steps += s;
    return r;
}

// What an edit costs the skip distances rays cross open air with: a voxel set in the middle of
// the emptiest super cells (every super cell within 3 turns nearer), then cleared again (they are
// searched anew). Median microseconds per edit and the super cells each rewrote.
struct SkipEditCost {
    double occupyUs = 0.0, clearUs = 0.0;
    std::size_t occupyRewrites = 0, clearRewrites = 0;
    int edits = 0;
};

SkipEditCost measureSkipEditCost(engine::world::BrickGrid grid) {
    SkipEditCost cost;
    std::vector<glm::ivec3> places;
    const glm::ivec3 n = grid.sizeInSuperCells();
    for (int z = 0; z < n.z && places.size() < 200; ++z)
        for (int y = 0; y < n.y && places.size() < 200; ++y)
            for (int x = 0; x < n.x && places.size() < 200; ++x)
                if (grid.superCells()[grid.superCellIndex({x, y, z})] == shared::SUPER_SKIP_MAX)
                    places.push_back(glm::ivec3(x, y, z) * 32 + 16);
    std::vector<double> occupy, clear;
    grid.clearDirty();
    for (glm::ivec3 p : places) {
        auto start = std::chrono::steady_clock::now();
        grid.set(p, 1);
        occupy.push_back(
            std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
                .count());
        cost.occupyRewrites = std::max(cost.occupyRewrites, grid.dirtySuperCells().size());
        grid.clearDirty();
        start = std::chrono::steady_clock::now();
        grid.set(p, engine::world::kEmpty);
        clear.push_back(
            std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
                .count());
        cost.clearRewrites = std::max(cost.clearRewrites, grid.dirtySuperCells().size());
        grid.clearDirty();
    }
    cost.edits = int(places.size());
    if (!places.empty()) {
        cost.occupyUs = median(occupy);
        cost.clearUs = median(clear);
    }
    return cost;
}

// The same rays for every method: camera rays, then one shadow ray towards the sun per hit;
// `hits` are the CPU reference's for the camera rays.
struct BenchRays {
    std::vector<Ray> primary, shadows, all;
    std::vector<RayHit> hits;
};

BenchRays benchRays(const engine::world::Scene& scene, const engine::world::CameraPreset& camera,
                    const engine::render::FrameSettings& fs) {
    BenchRays b;
    shared::FrameParams params = engine::render::makeFrameParams(camera, scene.sky, fs);
    for (std::uint32_t y = 0; y < fs.height; ++y)
        for (std::uint32_t x = 0; x < fs.width; ++x)
            b.primary.push_back(
                Ray{camera.position, engine::render::cameraRayDirection(params, {x, y})});
    b.hits.resize(b.primary.size());
    for (std::size_t i = 0; i < b.primary.size(); ++i)
        b.hits[i] = engine::world::traceRay(scene.grid, b.primary[i]);
    b.all = b.primary;
    b.shadows = shadowRays(b.primary, b.hits, glm::normalize(scene.sky.sunDirection));
    b.all.insert(b.all.end(), b.shadows.begin(), b.shadows.end());
    return b;
}

// The GPU traversal: the world and the rays uploaded once, then the trace dispatch alone timed.
class GpuTraceBench {
public:
    GpuTraceBench(engine::gpu::Context& gpu, engine::world::Scene& scene, const BenchRays& rays)
        : mGpu(gpu), mRays(rays), mWorld(gpu), mUploader(gpu), mTimer(gpu, 4), mPass(gpu) {
        for (const Ray& r : rays.all)
            mInputs.push_back({glm::vec4(r.origin, 1e30f), glm::vec4(r.direction, 0.0f)});
        using engine::gpu::BufferKind;
        mParams.emplace(gpu, BufferKind::Storage, sizeof(shared::TraceRaysParams), "bench.params");
        mRaysBuf.emplace(gpu, BufferKind::Storage, mInputs.size() * sizeof(shared::TraceRayInput),
                         "bench.rays");
        mHits.emplace(gpu, BufferKind::Storage, mInputs.size() * sizeof(shared::TraceRayOutput),
                      "bench.hits");
        mReadback.emplace(gpu, BufferKind::Readback, mHits->size(), "bench.readback");
        engine::gpu::CommandList cmd(gpu);
        cmd.begin();
        mWorld.sync(scene, mUploader);
        mUploader.write(*mRaysBuf, 0, mInputs.data(), mRaysBuf->size());
        mUploader.record(cmd);
        cmd.submitAndWait();
    }

    // One mode's median times and steps; the hierarchical mode's primary hits are checked
    // against the CPU reference's (`mismatches`).
    MethodResult run(std::uint32_t mode, int repeats, std::uint64_t& mismatches) {
        MethodResult r;
        r.name =
            mode == shared::TRACE_MODE_HIERARCHICAL ? "gpu hierarchical" : "gpu plain two-level";
        std::vector<double> times, cpuTimes;
        for (int rep = 0; rep < repeats + 2;
             ++rep) {  // two warm-up runs: the first compiles the shader
            const double cpuStart = processCpuMs();
            dispatch(mode);
            if (rep >= 2) {
                times.push_back(mTimer.results().at(0).second);
                cpuTimes.push_back(processCpuMs() - cpuStart);
            }
        }
        r.ms = median(times);
        r.cpuMs = median(cpuTimes);
        r.rays = mInputs.size();
        countSteps(r, mode, mismatches);
        return r;
    }

private:
    void dispatch(std::uint32_t mode) {
        engine::gpu::CommandList cmd(mGpu, &mTimer);
        cmd.begin();
        shared::TraceRaysParams p{glm::uvec4(std::uint32_t(mInputs.size()), mode, 0u, 0u)};
        mUploader.write(*mParams, 0, &p, sizeof(p));
        mUploader.record(cmd);
        mPass.record(cmd, {mWorld, *mParams, *mRaysBuf, *mHits}, std::uint32_t(mInputs.size()),
                     mode);
        cmd.copyBuffer(*mHits, *mReadback, {{0, 0, mHits->size()}});
        cmd.barrier();
        cmd.submitAndWait();
    }

    void countSteps(MethodResult& r, std::uint32_t mode, std::uint64_t& mismatches) {
        auto out = mReadback->view<shared::TraceRayOutput>();
        for (std::size_t batch = 0; batch < mInputs.size(); batch += kSimdLanes) {
            std::uint32_t longest = 0;
            for (std::size_t i = batch; i < std::min(mInputs.size(), batch + kSimdLanes); ++i)
                longest = std::max(longest, out[i].data.w);
            r.laneSteps += std::uint64_t(longest) * kSimdLanes;
        }
        for (std::size_t i = 0; i < mInputs.size(); ++i) {
            r.steps += out[i].data.w;
            if (mode == shared::TRACE_MODE_HIERARCHICAL && i < mRays.primary.size()) {
                const RayHit& hit = mRays.hits[i];
                mismatches += (out[i].data.x != 0) != hit.hit ||
                              (hit.hit && glm::ivec3(out[i].voxel) != hit.voxel);
            }
        }
    }

    engine::gpu::Context& mGpu;
    const BenchRays& mRays;
    engine::render::GpuWorld mWorld;
    engine::gpu::Uploader mUploader;
    engine::gpu::TimestampTimer mTimer;
    engine::render::TraceRaysPass mPass;
    std::vector<shared::TraceRayInput> mInputs;
    std::optional<engine::gpu::Buffer> mParams, mRaysBuf, mHits, mReadback;
};

// The CPU methods, each on all cores.
struct CpuMethod {
    const char* name;
    RayHit (*trace)(const engine::world::BrickGrid& grid, const Ray& ray);
};
const CpuMethod kCpuMethods[] = {
    {"cpu reference hierarchical",
     [](const engine::world::BrickGrid& g, const Ray& r) {
         return engine::world::traceRay(g, r, TraversalMode::Hierarchical);
     }},
    {"cpu reference plain",
     [](const engine::world::BrickGrid& g, const Ray& r) {
         return engine::world::traceRay(g, r, TraversalMode::PlainTwoLevel);
     }},
    {"cpu classic two-level DDA",
     [](const engine::world::BrickGrid& g, const Ray& r) { return traceClassicTwoLevel(g, r); }},
};

// What a run found besides the methods' speeds.
struct TraverseFindings {
    std::uint64_t gpuCpuMismatches = 0, classicMismatches = 0;
    SkipEditCost edit;
};

void printResults(const std::vector<MethodResult>& results, const BenchRays& rays,
                  const TraverseFindings& found) {
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::printf("\n%-28s %10s %12s %12s %12s %10s\n", "method", "ms", "Mrays/s", "steps/ray",
                "ns/step", "cpu ms");
    for (const MethodResult& r : results) {
        std::printf("%-28s %10.2f %12.3f %12.2f %12.3f %10.2f\n", r.name.c_str(), r.ms,
                    r.raysPerSecond() * 1e-6, r.stepsPerRay(),
                    r.ms * 1e6 / double(std::max<std::uint64_t>(r.steps, 1)), r.cpuMs);
    }
    for (const MethodResult& r : results) {
        if (r.laneSteps == 0) continue;
        std::printf("%-28s SIMD-%zu lanes busy %.0f%% of the steps they pay for\n", r.name.c_str(),
                    kSimdLanes, 100.0 * double(r.steps) / double(r.laneSteps));
    }
    const MethodResult& gpuH = results[0];
    const MethodResult& classic = results[4];
    std::printf(
        "\ngpu hierarchical vs cpu classic two-level DDA: %.2fx rays/s, %.2fx fewer steps per "
        "ray\n",
        gpuH.raysPerSecond() / classic.raysPerSecond(), classic.stepsPerRay() / gpuH.stepsPerRay());
    std::printf(
        "gpu hierarchical vs cpu classic two-level DDA in CPU time (all threads; steadier under "
        "load): %.2fx\n",
        classic.cpuMs / gpuH.cpuMs);
    std::printf(
        "primary-hit mismatches against the CPU reference: gpu %llu, classic DDA %llu, of %zu (CPU "
        "threads: %u)\n",
        static_cast<unsigned long long>(found.gpuCpuMismatches),
        static_cast<unsigned long long>(found.classicMismatches), rays.primary.size(), threads);
    const SkipEditCost& edit = found.edit;
    std::printf(
        "skip distances on an edit in open air (median of %d, whole voxel set() included): occupy "
        "%.1f us "
        "(%zu super cells rewritten at most), clear %.1f us (%zu)\n",
        edit.edits, edit.occupyUs, edit.occupyRewrites, edit.clearUs, edit.clearRewrites);
}

engine::Status writeJson(const std::filesystem::path& out, const std::string& world,
                         const engine::render::FrameSettings& fs,
                         const engine::gpu::DeviceInfo& dev,
                         const std::vector<MethodResult>& results, const BenchRays& rays,
                         const TraverseFindings& found) {
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    const SkipEditCost& edit = found.edit;
    engine::AtomicFile jsonFile;
    if (engine::Status s = openOutputFile(jsonFile, out); !s) return s;
    std::ostream& json = jsonFile.stream();
    json << "{\n  \"world\": \"" << world << "\", \"size\": [" << fs.width << ", " << fs.height
         << "], \"device\": \"" << dev.name << "\", \"driver\": \"" << dev.driver
         << "\", \"cpu_threads\": " << threads << ",\n  \"primary_rays\": " << rays.primary.size()
         << ", \"shadow_rays\": " << rays.shadows.size()
         << ", \"gpu_cpu_mismatches\": " << found.gpuCpuMismatches
         << ", \"classic_mismatches\": " << found.classicMismatches
         << ",\n  \"skip_edit\": {\"edits\": " << edit.edits << ", \"occupy_us\": " << edit.occupyUs
         << ", \"clear_us\": " << edit.clearUs << ", \"occupy_rewrites\": " << edit.occupyRewrites
         << ", \"clear_rewrites\": " << edit.clearRewrites << "},\n  \"methods\": [\n";
    for (std::size_t i = 0; i < results.size(); ++i) {
        const MethodResult& r = results[i];
        json << "    {\"name\": \"" << r.name << "\", \"ms\": " << r.ms << ", \"rays\": " << r.rays
             << ", \"cpu_ms\": " << r.cpuMs << ", \"steps\": " << r.steps
             << ", \"rays_per_second\": " << r.raysPerSecond()
             << ", \"steps_per_ray\": " << r.stepsPerRay() << ", \"lane_steps\": " << r.laneSteps
             << "}" << (i + 1 < results.size() ? "," : "") << "\n";
    }
    json << "  ]\n}\n";
    return jsonFile.commit();
}

int runBench(const BenchOptions& o) {
    auto frame = frameOfSize(o.size);
    if (!frame) return fail(frame.error());
    const engine::render::FrameSettings& fs = *frame;
    std::printf("loading world %s ...\n", o.world.c_str());
    auto scene = loadWorld(o.world);
    if (!scene) return fail(scene.error());
    auto ctx = createBenchGpu();
    if (!ctx) return fail(ctx.error());
    engine::gpu::Context& gpu = **ctx;
    printDevice(gpu);

    engine::world::CameraPreset camera = scene->camera(o.camera);
    const BenchRays rays = benchRays(*scene, camera, fs);
    std::printf("rays     %zu primary + %zu shadow at %ux%u, camera '%s'\n", rays.primary.size(),
                rays.shadows.size(), fs.width, fs.height, camera.name.c_str());

    std::vector<MethodResult> results;
    TraverseFindings found;
    {
        GpuTraceBench gpuBench(gpu, *scene, rays);
        for (std::uint32_t mode : {shared::TRACE_MODE_HIERARCHICAL, shared::TRACE_MODE_PLAIN}) {
            results.push_back(gpuBench.run(mode, o.repeats, found.gpuCpuMismatches));
            std::printf("  %-28s done\n", results.back().name.c_str());
        }
    }
    const engine::world::BrickGrid& grid = scene->grid;
    for (const CpuMethod& m : kCpuMethods) {
        results.push_back(benchCpu(
            rays.all, [&](const Ray& r) { return m.trace(grid, r); }, o.repeats, m.name));
        std::printf("  %-28s done\n", results.back().name.c_str());
    }
    // The classic DDA must find the same surfaces, or its speed means nothing.
    for (std::size_t i = 0; i < rays.primary.size(); ++i) {
        RayHit c = traceClassicTwoLevel(grid, rays.primary[i]);
        found.classicMismatches +=
            c.hit != rays.hits[i].hit || (c.hit && c.voxel != rays.hits[i].voxel);
    }
    found.edit = measureSkipEditCost(grid);

    printResults(results, rays, found);
    if (engine::Status s = writeJson(o.output, scene->name, fs, gpu.info(), results, rays, found);
        !s)
        return fail(s.error());
    std::printf("wrote    %s\n", std::filesystem::path(o.output).string().c_str());
    return 0;
}

}  // namespace

void addBenchTraverseCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand(
        "traverse", "Ray traversal speed: GPU vs CPU reference, hierarchical vs plain DDA");
    auto o = std::make_shared<BenchOptions>();
    cmd->add_option("world", o->world, "World name or scene file")->capture_default_str();
    cmd->add_option("--camera", o->camera, "Camera preset");
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("--repeats", o->repeats, "Timed repetitions per method (median reported)")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 1000, "repetitions")));
    cmd->add_option("-o,--output", o->output, "JSON results file")->capture_default_str();
    cmd->callback([o, &exitCode] { exitCode = runBench(*o); });
}

}  // namespace vox
