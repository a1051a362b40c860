#include "sweep_runner.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "core/exclusive_file_lock.h"
#include "core/hash.h"
#include "io/image_io.h"
#include "metrics/image_metrics.h"
#include "render/renderer.h"

namespace vox {

using engine::lighting::LightingSettings;
using engine::lighting::Method;

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

// Mean luminance over the surface pixels that do not emit, image and reference alike: the light
// the methods are responsible for (emitters and sky are exact in every method and would hide it).
double nonEmitterMeanRatio(const engine::render::FrameImages& img,
                           const std::vector<glm::vec4>& reference,
                           const engine::world::Scene& scene) {
    auto luminance = [](const glm::vec4& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; };
    double a = 0.0, b = 0.0;
    for (std::size_t i = 0; i < img.gbuffer.size() && i < reference.size(); ++i) {
        const shared::GBufferTexel& g = img.gbuffer[i];
        if (std::uint32_t(g.voxel.w) >= 6 ||
            scene.palette[engine::world::MaterialId(g.data.x)].emissive())
            continue;
        a += luminance(img.radiance[i]);
        b += luminance(reference[i]);
    }
    return b > 0.0 ? a / b : 0.0;
}

// CPU time of the whole process, all threads (lavapipe's included), in milliseconds.
double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

std::uint32_t hashBytes(const std::string& s, std::uint32_t h) {
    for (unsigned char c : s) h = engine::hashCombine(h, c);
    return h;
}

}  // namespace

SweepPoint measureSetting(engine::gpu::Context& gpu, engine::world::Scene& scene,
                          const engine::world::CameraPreset& camera,
                          const engine::render::FrameSettings& frame, LightingSettings lighting,
                          std::uint32_t frames, const std::vector<glm::vec4>& reference,
                          std::string label) {
    engine::render::Renderer renderer(gpu);
    return measureSetting(renderer, scene, camera, frame, lighting, frames, reference,
                          std::move(label));
}

SweepPoint measureSetting(engine::render::Renderer& renderer, engine::world::Scene& scene,
                          const engine::world::CameraPreset& camera,
                          const engine::render::FrameSettings& frame, LightingSettings lighting,
                          std::uint32_t frames, const std::vector<glm::vec4>& reference,
                          std::string label) {
    renderer.resetHistory();
    std::map<std::string, std::vector<double>> times;
    std::vector<double> totals, cpuTimes, wallTimes;
    SweepPoint p;
    p.scene = scene.name;
    p.label = std::move(label);
    p.method = engine::lighting::methodName(lighting.method);
    if (lighting.method == Method::Restir && lighting.restir.unbiased) p.method = "restir-unbiased";
    int counted = 0;
    for (std::uint32_t i = 0; i < frames; ++i) {
        // The path tracer as a method: each frame is its own estimate (samplesPerFrame samples),
        // not the accumulation of all frames so far, so its time and error belong together.
        if (lighting.method == Method::Reference) renderer.resetHistory();
        const double cpuBefore = processCpuMs();
        const auto wallBefore = std::chrono::steady_clock::now();
        engine::render::FrameResult r = renderer.render(scene, camera, frame, lighting);
        const double cpu = processCpuMs() - cpuBefore;
        const double wall =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wallBefore)
                .count();
        p.emitters = r.emitters;
        if (i < frames / 2) continue;
        for (const auto& [name, ms] : r.passMs) times[name].push_back(ms);
        totals.push_back(r.totalMs() - r.passMsOf("upload"));
        cpuTimes.push_back(cpu);
        wallTimes.push_back(wall);
        engine::render::FrameImages img = renderer.readback();
        auto e = engine::metrics::compareImages({img.radiance, frame.width, frame.height},
                                                {reference, frame.width, frame.height});
        if (e.ok()) {
            p.mae += e->mae;
            p.mse += e->mse;
            p.rmae += e->rmae;
        }
        p.meanRatio += nonEmitterMeanRatio(img, reference, scene);
        ++counted;
        if (lighting.method != Method::Restir)
            lighting.seed += 7919;  // memoryless methods: independent frames
    }
    for (auto& [name, v] : times) p.passMs[name] = median(v);
    p.totalMs = median(totals);
    p.cpuMs = median(cpuTimes);
    p.wallMs = median(wallTimes);
    p.fastestMs = totals.empty() ? 0.0 : *std::min_element(totals.begin(), totals.end());
    p.mae /= std::max(counted, 1);
    p.mse /= std::max(counted, 1);
    p.rmae /= std::max(counted, 1);
    p.meanRatio /= std::max(counted, 1);
    return p;
}

engine::Result<std::vector<glm::vec4>> cachedReference(engine::gpu::Context& gpu,
                                                       engine::world::Scene& scene,
                                                       const engine::world::CameraPreset& camera,
                                                       const engine::render::FrameSettings& frame,
                                                       std::uint32_t spp, std::uint32_t bounces,
                                                       const std::filesystem::path& cacheDir,
                                                       const std::string& variant) {
    std::ostringstream key;
    std::ifstream source(scene.sourcePath, std::ios::binary);
    key << source.rdbuf();
    key << fmt::format("|{} {} {}|{} {} {}|{}|{}x{}|{}|{}", camera.position.x, camera.position.y,
                       camera.position.z, camera.target.x, camera.target.y, camera.target.z,
                       camera.fovYDegrees, frame.width, frame.height, spp, bounces) +
               "|" + variant;
    // The estimator's version: images cached by an older reference (no MIS) are not reused.
    key << "|reference 2: pixel centre, MIS";
    std::uint32_t h = hashBytes(key.str(), 0x5eed);
    std::filesystem::path file = cacheDir / fmt::format("reference-{}-{:08x}.exr", scene.name, h);
    std::error_code ec;
    // The tasks of a sweep job share the cache: the first to need a reference renders it while
    // the others wait, then read it (without the cache folder, each renders its own).
    std::filesystem::create_directories(cacheDir, ec);
    auto lock = engine::ExclusiveFileLock::acquire(file.string() + ".lock");
    if (std::filesystem::exists(file, ec)) {
        auto img = engine::io::readExr(file);
        if (img.ok() && img->width == frame.width && img->height == frame.height)
            return std::move(img->pixels);
    }
    std::fprintf(stderr, "%s: rendering the reference (%u spp, %u bounce(s)) ...\n",
                 scene.name.c_str(), spp, bounces);
    engine::render::Renderer renderer(gpu);
    LightingSettings ref;
    ref.method = Method::Reference;
    // The methods measured against it shade pixel centres: a box-filtered reference would count
    // its edge coverage as their error.
    ref.referenceFilter = engine::lighting::ReferenceFilter::PixelCentre;
    ref.samplesPerFrame = 16;
    ref.bounces = bounces;
    for (std::uint32_t s = 0; s < spp; s += ref.samplesPerFrame)
        renderer.render(scene, camera, frame, ref);
    std::vector<glm::vec4> pixels = renderer.readback().radiance;
    std::filesystem::create_directories(cacheDir, ec);
    engine::Status saved = engine::io::writeExr(file, frame.width, frame.height, pixels);
    if (!saved) std::fprintf(stderr, "warning: %s\n", saved.error().message.c_str());
    return pixels;
}

}  // namespace vox
