// The measurements vox bench stability's cases are made of.
#include <algorithm>
#include <cstdio>
#include <fmt/format.h>

#include "commands.h"
#include "metrics/image_metrics.h"
#include "stability_bench.h"
#include "sweep_runner.h"

namespace vox {

using engine::lighting::LightingSettings;
using engine::lighting::Method;
using engine::render::FrameSettings;
using engine::render::Renderer;
using engine::world::Scene;

double maeOf(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b,
             const FrameSettings& f) {
    return engine::metrics::compareImages({a, f.width, f.height}, {b, f.width, f.height})->mae;
}

double meanRadiance(const std::vector<glm::vec4>& img) {
    double s = 0.0;
    for (const glm::vec4& p : img) s += (p.x + p.y + p.z) / 3.0;
    return s / double(img.size());
}

void FlickerMeter::add(std::vector<glm::vec4> image) {
    if (!mPrevious.empty()) {
        mSum += maeOf(image, mPrevious, mFrame);
        mMean += meanRadiance(image);
    }
    mPrevious = std::move(image);
}

double FlickerMeter::value() const { return mSum / std::max(mMean, 1e-12); }

double mean(const std::vector<double>& v, std::size_t from) {
    double s = 0.0;
    for (std::size_t i = from; i < v.size(); ++i) s += v[i];
    return v.size() > from ? s / double(v.size() - from) : 0.0;
}

std::pair<int, double> framesToSteady(const std::vector<double>& errors) {
    std::vector<double> tail(
        errors.end() - std::min<std::ptrdiff_t>(8, std::ptrdiff_t(errors.size())), errors.end());
    std::sort(tail.begin(), tail.end());
    double steady = tail[tail.size() / 2];
    int frames = 0;
    while (frames < int(errors.size()) && errors[std::size_t(frames)] > 1.1 * steady) ++frames;
    return {frames + 1, steady};
}

LightingSettings methodSettings(const std::string& method) {
    LightingSettings l;
    l.restir.unbiased = method == "restir-unbiased";
    if (method == "ris") {
        l.method = Method::Ris;
        l.restir.temporal = l.restir.spatial = l.restir.candidateVisibility = false;
    }
    if (method == "uniform") l.method = Method::Uniform;
    return l;
}

double flicker(StabilityContext& c, Scene& scene, LightingSettings l, int warmup, int frames,
               bool reseed) {
    Renderer r(c.gpu);
    FlickerMeter meter(c.frame);
    for (int i = 0; i < warmup + frames; ++i) {
        if (reseed) {
            l.seed += 7919;
            r.resetHistory();
        }
        r.render(scene, scene.camera(), c.frame, l);
        if (i < warmup - 1) continue;
        meter.add(r.readback().radiance);
    }
    return meter.value();
}

void response(StabilityContext& c, const std::string& name, Scene scene,
              const std::function<void(Scene&)>& edit) {
    const int before = 16, after = 32;
    Scene edited = scene;
    edit(edited);
    edited.grid.clearDirty();
    auto ref = cachedReference(c.gpu, edited, edited.camera(), c.frame, 512, 0, c.cache, name);
    for (const char* method : {"restir", "restir-unbiased"}) {
        const LightingSettings l = methodSettings(method);
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
        auto [frames, steady] = framesToSteady(errors);
        c.rows.push_back(fmt::format(
            "| response: {} | {} | {} frame(s) to within 10 % of steady state (steady MAE {:.3e}, "
            "first frame {:.3e}) |",
            name, method, frames, steady, errors.front()));
        std::printf("%-28s %-16s recovered after %d frame(s); steady MAE %.3e, first frame %.3e\n",
                    name.c_str(), method, frames, steady, errors.front());
    }
}

void addResponse(StabilityContext& c, const ResponseNames& names, const std::vector<double>& errors,
                 const std::string& more) {
    for (std::size_t i = 0; i < errors.size(); ++i)
        c.curves << fmt::format("{},{},{},{}\n", names.curveCase, names.curveMethod, i + 1,
                                errors[i]);
    auto [frames, steady] = framesToSteady(errors);
    c.rows.push_back(fmt::format(
        "| response: {} | {} | {} frame(s) to within 10 % of steady state (steady MAE {:.3e}, "
        "first frame {:.3e}{}) |",
        names.rowCase, names.rowMethod, frames, steady, errors.front(), more));
    std::printf("%-28s %-16s recovered after %d frame(s); steady MAE %.3e\n", names.curveCase,
                names.shortMethod, frames, steady);
}

namespace {

constexpr double kFps = 30.0;

// The converged reference of each moving frame's pose (one when nothing moves).
std::vector<std::vector<glm::vec4>> movingReferences(StabilityContext& c, const std::string& name,
                                                     const Scene& scene,
                                                     const engine::world::CameraPreset& camera,
                                                     bool moves, bool indirectOnly, int moving) {
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
            return ref ? std::move(*ref)
                       : std::vector<glm::vec4>(std::size_t(c.frame.width) * c.frame.height);
        };
        std::vector<glm::vec4> ref = reference(0);
        if (indirectOnly) {
            std::vector<glm::vec4> withBounce = reference(1);
            for (std::size_t p = 0; p < ref.size(); ++p)
                ref[p] = glm::max(withBounce[p] - ref[p], glm::vec4(0.0f));
        }
        refs.push_back(std::move(ref));
    }
    return refs;
}

}  // namespace

MovingRun movingRun(StabilityContext& c, const std::string& name, const Scene& scene,
                    const engine::world::CameraPreset& camera, const LightingSettings& l,
                    bool indirectOnly, int still, int moving) {
    bool moves = false;
    for (const auto& object : scene.objects) moves |= object.path.keys().size() > 1;
    const std::vector<std::vector<glm::vec4>> refs =
        movingReferences(c, name, scene, camera, moves, indirectOnly, moving);
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

Scene fastCrate(const Scene& thinWall, bool still) {
    using engine::world::ObjectKey;
    Scene s = thinWall;
    std::vector<ObjectKey> keys{ObjectKey{0.0, {4.0, 6.0, 4.0}}};
    if (!still)
        keys.insert(keys.end(),
                    {ObjectKey{0.5, {60.0, 6.0, 4.0}}, ObjectKey{1.0, {4.0, 6.0, 4.0}}});
    s.objects[0].path = engine::world::ObjectPath(keys, !still);
    return s;
}

engine::Result<Scene> loadThinWall() {
    auto thinWall = loadWorld("thin_wall");
    if (!thinWall) return thinWall.error();
    thinWall->grid.clearDirty();
    return std::move(*thinWall);
}

LightingSettings cacheLighting(std::uint32_t neighbourhood) {
    LightingSettings l;
    l.indirect = engine::lighting::Indirect::Cache;
    l.cache.neighbourhood = neighbourhood;
    return l;
}

std::vector<std::uint32_t> indirectImage(const std::vector<glm::vec4>& indirect, float scale) {
    std::vector<std::uint32_t> out;
    for (const glm::vec4& p : indirect) {
        std::uint32_t rgba = 0xff000000u;
        for (int k = 0; k < 3; ++k)
            rgba |= std::uint32_t(std::clamp(p[k] / scale, 0.0f, 1.0f) * 255.0f + 0.5f) << (8 * k);
        out.push_back(rgba);
    }
    return out;
}

Scene simpleScene(glm::ivec3 size) {
    Scene s;
    s.name = "stability";
    s.grid = engine::world::BrickGrid(size);
    (void)s.palette.add(engine::world::Material{"white", glm::vec3(0.75f)});
    (void)s.palette.add(
        engine::world::Material{"lamp", glm::vec3(0.8f), glm::vec3(1.0f, 0.85f, 0.6f), 20.0f});
    s.sky.sunRadiance = glm::vec3(0.0f);
    s.sky.skyRadiance = glm::vec3(0.0f);
    return s;
}

}  // namespace vox
