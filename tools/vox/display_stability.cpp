// vox bench display's stability cases (display_bench.h). Each group of the world's timeline
// events that share a frame is replayed on a still camera — the path's camera at that moment,
// scene time held there — so that what changes on screen is the event alone:
//   still: `stillFrames` frames converge; the last is compared with the converged reference
//          (relative MAE); 16 more give the flicker of the converged image: the mean
//          |frame - previous frame| of the clamped luminance over the reference's mean (the last
//          16 still frames give it while converging);
//   edit / light: the event, then `afterFrames` frames; its region (pixels whose reference
//          luminance changed by more than 10 %) is followed until its mean stays within 10 % of
//          the row's new steady value (the mean of the last 4 frames), which is also compared
//          with the reference's;
//   object: a dynamic object starts, seen from the path's camera moved towards it until it
//          spans a third of the view (objectCamera); each of `ghostFrames` frames is compared with
//          its own reference. A pixel the object left a frames ago is "age a"; the ghost trail is
//          the largest age whose relative error is above 1.5x that of the pixels the object never
//          covered (0: no ghost). Coverage comes from the native raw row's G-buffer, a pixel
//          counted as covered while the object touches its box (objectFootprint).
// Luminance is clamped at the reference's 98th percentile as in metrics/display_error.h.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <optional>
#include <ostream>

#include "display_bench.h"
#include "metrics/display_error.h"
#include "metrics/heat_map.h"
#include "progress_line.h"
#include "shared/gbuffer.h"

namespace vox {

namespace {

using engine::lighting::Display;
using engine::lighting::LightingSettings;
using engine::render::Renderer;
using engine::world::Flythrough;
using engine::world::Scene;
using engine::world::TimelineEvent;

double luminance(glm::vec4 p) { return 0.2126 * p.x + 0.7152 * p.y + 0.0722 * p.z; }

double clampLimit(const std::vector<glm::vec4>& reference) {
    std::vector<double> l(reference.size());
    for (std::size_t i = 0; i < l.size(); ++i) l[i] = luminance(reference[i]);
    const std::size_t k =
        std::min(l.size() - 1, std::size_t(engine::metrics::kDisplayClampPercentile * l.size()));
    std::nth_element(l.begin(), l.begin() + std::ptrdiff_t(k), l.end());
    return std::max(l[k], 1e-12);
}

std::vector<double> clampedLuminance(const std::vector<glm::vec4>& img, double limit) {
    std::vector<double> out(img.size());
    for (std::size_t i = 0; i < img.size(); ++i) out[i] = std::min(luminance(img[i]), limit);
    return out;
}

double meanOver(const std::vector<double>& v, const std::vector<std::uint8_t>& mask) {
    double s = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (mask[i]) s += v[i], ++n;
    return n ? s / double(n) : 0.0;
}

// Where a still image's error against the reference is, on clamped luminance, as shares of the
// relative MAE: pixels at an edge of the reference (its 3x3 neighbourhood spans more than half
// its mean: aliasing, resolution), and the error left after both images are averaged over 8x8
// blocks (bias: a tone or energy difference, not noise or edges).
struct ErrorSplit {
    double mae = 0.0, edgeShare = 0.0, blockMae = 0.0;
};

ErrorSplit splitError(const std::vector<double>& shown, const std::vector<double>& ref,
                      glm::uvec2 size) {
    ErrorSplit e;
    double sum = 0.0, refSum = 0.0, edge = 0.0;
    for (std::uint32_t y = 0; y < size.y; ++y) {
        for (std::uint32_t x = 0; x < size.x; ++x) {
            const std::size_t i = std::size_t(y) * size.x + x;
            double lo = ref[i], hi = ref[i], mean = 0.0;
            int n = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int qx = int(x) + dx, qy = int(y) + dy;
                    if (qx < 0 || qy < 0 || qx >= int(size.x) || qy >= int(size.y)) continue;
                    const double v = ref[std::size_t(qy) * size.x + std::size_t(qx)];
                    lo = std::min(lo, v), hi = std::max(hi, v), mean += v, ++n;
                }
            const double d = std::abs(shown[i] - ref[i]);
            sum += d;
            refSum += ref[i];
            if (hi - lo > 0.5 * mean / n) edge += d;
        }
    }
    double block = 0.0;
    for (std::uint32_t by = 0; by + 8 <= size.y; by += 8)
        for (std::uint32_t bx = 0; bx + 8 <= size.x; bx += 8) {
            double a = 0.0, b = 0.0;
            for (std::uint32_t y = by; y < by + 8; ++y)
                for (std::uint32_t x = bx; x < bx + 8; ++x)
                    a += shown[std::size_t(y) * size.x + x], b += ref[std::size_t(y) * size.x + x];
            block += std::abs(a - b);
        }
    e.mae = sum / std::max(refSum, 1e-12);
    e.edgeShare = edge / std::max(sum, 1e-12);
    e.blockMae = block / std::max(refSum, 1e-12);
    return e;
}

// Where a converged still image still moves (--images): a heat map of each pixel's mean |change|
// a frame over the reference's mean (red: a twentieth of it), and in the CSV the shares of the
// flicker at the reference's edges (as splitError's), in pixels that moved on every frame, and
// in the brightest 2 % of the reference (emitters, lit windows).
engine::Status writeFlicker(const std::filesystem::path& path, const std::vector<double>& sum,
                            const std::vector<std::uint32_t>& moves, int frames,
                            const std::vector<double>& ref, double refMean, glm::uvec2 size,
                            const std::string& label, std::ostream& csv) {
    std::vector<float> heat(sum.size());
    double total = 0.0, edge = 0.0, everyFrame = 0.0, bright = 0.0;
    std::size_t moved = 0, movedEveryFrame = 0;
    std::vector<double> sorted = ref;
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() * 49 / 50),
                     sorted.end());
    const double brightLimit = sorted[sorted.size() * 49 / 50];
    for (std::uint32_t y = 0; y < size.y; ++y) {
        for (std::uint32_t x = 0; x < size.x; ++x) {
            const std::size_t i = std::size_t(y) * size.x + x;
            heat[i] = float(sum[i] / std::max(frames, 1) / std::max(refMean, 1e-12));
            total += sum[i];
            moved += moves[i] > 0;
            if (moves[i] == std::uint32_t(frames)) everyFrame += sum[i], ++movedEveryFrame;
            if (ref[i] >= brightLimit) bright += sum[i];
            double lo = ref[i], hi = ref[i], mean = 0.0;
            int n = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int qx = int(x) + dx, qy = int(y) + dy;
                    if (qx < 0 || qy < 0 || qx >= int(size.x) || qy >= int(size.y)) continue;
                    const double v = ref[std::size_t(qy) * size.x + std::size_t(qx)];
                    lo = std::min(lo, v), hi = std::max(hi, v), mean += v, ++n;
                }
            if (hi - lo > 0.5 * mean / n) edge += sum[i];
        }
    }
    const double t = std::max(total, 1e-30);
    csv << fmt::format(
        "{},still_flicker_split,{:.6f},pixels that moved {} ({} on every frame: {:.2f} of "
        "it); at edges {:.2f}; brightest 2 % {:.2f}\n",
        label, total / std::max(frames, 1) / double(sum.size()) / std::max(refMean, 1e-12), moved,
        movedEveryFrame, everyFrame / t, edge / t, bright / t);
    engine::metrics::HeatMapOptions options;
    options.maxValue = 0.05f;
    auto written = engine::metrics::writeHeatMap(path, heat, size.x, size.y, options);
    if (!written) return written.error();
    return {};
}

std::string fileLabel(std::string s) {
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return s;
}

// The flicker of a still image is measured over this many frames after the still frames: a
// converged image's, as raw ReSTIR's (frozen on a still view) is. The last 16 of the still frames
// give the flicker while converging, a running mean's approach to it.
constexpr std::uint32_t kConvergedFlickerFrames = 16;

// A row replaying one case: its own scene and timeline (events before the case applied).
struct RowRun {
    DisplayRow row;
    Scene scene;
    engine::world::Timeline timeline;
    std::unique_ptr<Renderer> renderer;
    std::vector<double> regionMeans;  // edit / light: per frame after the event
    std::vector<std::uint8_t> objectMask;
};

const char* kindName(TimelineEvent::Kind k) {
    switch (k) {
        case TimelineEvent::Kind::Light:
            return "light";
        case TimelineEvent::Kind::DynamicStart:
            return "object";
        default:
            return "edit";
    }
}

// The display pixels a dynamic object touches, from the native raw row's G-buffer (one sample at
// each pixel's centre): those whose own centre or a neighbour's (3x3) sees it. The reference
// averages each pixel's whole box, so a pixel whose centre the object just left is still partly
// covered by it there — the object's own antialiased edge, not a ghost. Counted by centres alone,
// an object moving under a pixel a frame left "ghosts" of 3-4 frames in the raw rows too, which
// have no history.
std::vector<std::uint8_t> objectFootprint(const engine::render::FrameImages& images,
                                          glm::uvec2 size) {
    std::vector<std::uint8_t> centre(images.gbuffer.size()), out(images.gbuffer.size());
    for (std::size_t p = 0; p < centre.size(); ++p)
        centre[p] = (images.gbuffer[p].data.w & shared::GBUFFER_FLAG_DYNAMIC) != 0;
    for (std::uint32_t y = 0; y < size.y; ++y)
        for (std::uint32_t x = 0; x < size.x; ++x)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int qx = int(x) + dx, qy = int(y) + dy;
                    if (qx < 0 || qy < 0 || qx >= int(size.x) || qy >= int(size.y)) continue;
                    if (centre[std::size_t(qy) * size.x + std::size_t(qx)])
                        out[std::size_t(y) * size.x + x] = 1;
                }
    return out;
}

// The share of the view's height an object's box spans in its case.
constexpr float kObjectViewShare = 1.0f / 3.0f;

// An object case's camera: the path's camera moved along its line to the object (the line it
// sees the object along) until the object's box spans kObjectViewShare of the view's height,
// looking at it. From the path's cameras a small object leaves too few display pixels a frame to
// measure a ghost by (fewer than 16 per age at 320x180).
engine::world::CameraPreset objectCamera(engine::world::CameraPreset camera, const Scene& scene,
                                         const std::string& object, double t) {
    for (const engine::world::DynamicObject& o : scene.objects) {
        if (o.name != object) continue;
        const engine::world::Box box = o.worldBounds(o.poseAt(t));
        const glm::vec3 centre = glm::vec3(box.min + box.max) * 0.5f;
        const glm::ivec3 size = box.size();
        const float extent = float(std::max({size.x, size.y, size.z}));
        const float distance =
            extent / (kObjectViewShare * 2.0f * std::tan(glm::radians(camera.fovYDegrees) * 0.5f));
        const glm::vec3 away = camera.position - centre;
        if (glm::length(away) > distance)
            camera.position = centre + glm::normalize(away) * distance;
        camera.target = centre;
        break;
    }
    return camera;
}

// Per row, what the stability table says of it over all cases.
struct RowSummary {
    std::vector<double> stillMae, flicker, convergingFlicker, framesToSteady, steadyRatio;
    std::optional<int> ghostTrail;
    std::string ghostDetail;
};

}  // namespace

engine::Status displayStability(engine::gpu::Context& ctx, const Scene& scene,
                                const Flythrough& fly, const std::vector<DisplayRow>& rows,
                                const LightingSettings& base, const StabilityOptions& o,
                                std::string& table, std::ostream& csv) {
    Scene bound = scene;
    Flythrough f = fly;
    if (engine::Status s = f.timeline.bind(bound); !s) return s;
    // The events' frames, each once: a case replays everything its frame applies.
    std::vector<std::uint32_t> caseFrames;
    std::map<std::uint32_t, std::string> caseNames, caseObjects;
    for (const TimelineEvent& e : f.timeline.events()) {
        const std::uint32_t frame = engine::world::Timeline::firstFrame(e.time, f.fps);
        if (caseFrames.empty() || caseFrames.back() != frame) caseFrames.push_back(frame);
        if (e.kind == TimelineEvent::Kind::DynamicStart && !caseObjects.contains(frame))
            caseObjects[frame] = e.object;
        std::string& name = caseNames[frame];
        name += fmt::format("{}{} {}", name.empty() ? "" : " + ", kindName(e.kind),
                            e.kind == TimelineEvent::Kind::Light
                                ? fmt::format("{} {}", e.material, e.on ? "on" : "off")
                            : e.kind == TimelineEvent::Kind::DynamicStart ? e.object
                                                                          : e.material);
    }
    if (o.cases > 0 && caseFrames.size() > o.cases) {
        caseFrames.resize(o.cases);
        std::erase_if(caseNames, [&](const auto& c) { return c.first > caseFrames.back(); });
    }
    if (caseFrames.empty())
        return engine::makeError("{}: no timeline events for the stability cases", fly.source);
    std::ptrdiff_t nativeRow = -1;
    for (std::size_t i = 0; i < rows.size(); ++i)
        if (rows[i].mode == Display::Raw && rows[i].scale == 1.0) nativeRow = std::ptrdiff_t(i);

    std::vector<RowSummary> summary(rows.size());
    DisplayReference reference(ctx, base, o.referenceSpp);
    ProgressLine progress(fmt::format("stability ({} cases x {} rows, {}x{})", caseFrames.size(),
                                      rows.size(), o.display.x, o.display.y),
                          std::uint32_t(caseFrames.size()));
    std::uint32_t done = 0;
    for (std::uint32_t frame : caseFrames) {
        const std::string& name = caseNames[frame];
        const bool object = caseObjects.contains(frame);
        const double t0 = Flythrough::frameTime(frame, f.fps);
        const engine::world::CameraPreset camera =
            object ? objectCamera(f.camera.at(t0, "still"), bound, caseObjects[frame], t0)
                   : f.camera.at(t0, "still");
        // Everything before the case's frame, in the rows' and the reference's scenes.
        Scene before = bound;
        engine::world::Timeline timeline = f.timeline;
        if (frame > 0) timeline.applyThrough(frame - 1, f.fps, before);
        std::vector<RowRun> runs(rows.size());
        for (std::size_t i = 0; i < rows.size(); ++i) {
            runs[i].row = rows[i];
            runs[i].scene = before;
            runs[i].timeline = timeline;
            runs[i].renderer = std::make_unique<Renderer>(ctx);
        }
        Scene refScene = before;
        engine::world::Timeline refTimeline = timeline;
        const auto refBefore = reference.render(refScene, camera, o.display, t0);
        const double limitBefore = clampLimit(refBefore);
        const auto lumRefBefore = clampedLuminance(refBefore, limitBefore);
        if (!o.images.empty()) {
            // The reference's own noise: against one of 4x its samples.
            DisplayReference finer(ctx, base, o.referenceSpp * 4);
            const auto fine = finer.render(refScene, camera, o.display, t0);
            const ErrorSplit n =
                splitError(lumRefBefore, clampedLuminance(fine, limitBefore), o.display);
            csv << fmt::format(
                "\"{}\",reference,still_error_split,{:.5f},against {} spp: edge share {:.2f}; "
                "8x8 block MAE {:.5f}\n",
                name, n.mae, o.referenceSpp * 4, n.edgeShare, n.blockMae);
            const auto stem = o.images / fmt::format("still_{:04}", frame);
            if (engine::Status s = writeViewPng(stem.string() + "_reference.png", refBefore,
                                                o.display, viewExposure(refBefore));
                !s)
                return s;
        }
        double refMeanBefore = 0.0;
        for (double v : lumRefBefore) refMeanBefore += v;
        refMeanBefore /= double(lumRefBefore.size());

        auto render = [&](RowRun& r, double t) {
            auto frameSettings = rowFrame(r.row, o.display);
            frameSettings.timeSeconds = t;
            r.renderer->render(r.scene, camera, frameSettings, rowLighting(r.row, base));
        };
        // Still frames: converge (the error of the last, the flicker of the last 16 while
        // converging), then 16 more for the flicker of the converged image.
        for (RowRun& r : runs) {
            std::vector<double> previous;
            double flicker = 0.0, converging = 0.0;
            int pairs = 0, convergingPairs = 0;
            std::vector<glm::vec4> shown;
            // Per pixel over the converged frames: the summed |change| and the frames it moved.
            std::vector<double> pixelFlicker;
            std::vector<std::uint32_t> pixelMoves;
            for (std::uint32_t i = 0; i < o.stillFrames + kConvergedFlickerFrames; ++i) {
                render(r, t0);
                if (i + 16 < o.stillFrames) continue;
                auto image = shownImage(*r.renderer, o.display);
                const auto lum = clampedLuminance(image, limitBefore);
                if (!previous.empty()) {
                    double d = 0.0;
                    for (std::size_t p = 0; p < lum.size(); ++p)
                        d += std::abs(lum[p] - previous[p]);
                    d /= double(lum.size()) * std::max(refMeanBefore, 1e-12);
                    if (i < o.stillFrames) {
                        converging += d, ++convergingPairs;
                    } else {
                        flicker += d, ++pairs;
                        pixelFlicker.resize(lum.size());
                        pixelMoves.resize(lum.size());
                        for (std::size_t p = 0; p < lum.size(); ++p) {
                            const double c = std::abs(lum[p] - previous[p]);
                            pixelFlicker[p] += c;
                            pixelMoves[p] += c > 0.0;
                        }
                    }
                }
                previous = lum;
                if (i + 1 == o.stillFrames) shown = std::move(image);
            }
            auto e = engine::metrics::compareDisplay({shown, o.display.x, o.display.y},
                                                     {refBefore, o.display.x, o.display.y});
            if (!e) return e.error();
            RowSummary& s = summary[std::size_t(&r - runs.data())];
            if (!o.images.empty()) {
                const auto lum = clampedLuminance(shown, limitBefore);
                const ErrorSplit split = splitError(lum, lumRefBefore, o.display);
                csv << fmt::format(
                    "\"{}\",{},still_error_split,{:.5f},edge share {:.2f}; 8x8 block MAE "
                    "{:.5f}; mean ratio {:.4f}\n",
                    name, r.row.label(), split.mae, split.edgeShare, split.blockMae, e->meanRatio);
                std::vector<float> diff(lum.size());
                for (std::size_t p = 0; p < lum.size(); ++p)
                    diff[p] =
                        float(std::abs(lum[p] - lumRefBefore[p]) / std::max(refMeanBefore, 1e-12));
                const auto stem =
                    o.images / fmt::format("still_{:04}_{}", frame, fileLabel(r.row.label()));
                if (engine::Status st = writeViewPng(stem.string() + ".png", shown, o.display,
                                                     viewExposure(refBefore));
                    !st)
                    return st;
                engine::metrics::HeatMapOptions heat;
                heat.maxValue = 0.5f;  // |difference| of half the image's mean luminance: red
                auto written = engine::metrics::writeHeatMap(stem.string() + "_error.png", diff,
                                                             o.display.x, o.display.y, heat);
                if (!written) return written.error();
            }
            if (!o.images.empty() && !pixelFlicker.empty()) {
                if (engine::Status st =
                        writeFlicker(o.images / fmt::format("still_{:04}_{}_flicker.png", frame,
                                                            fileLabel(r.row.label())),
                                     pixelFlicker, pixelMoves, pairs, lumRefBefore, refMeanBefore,
                                     o.display, fmt::format("\"{}\",{}", name, r.row.label()), csv);
                    !st)
                    return st;
            }
            s.stillMae.push_back(e->relativeMae);
            s.flicker.push_back(pairs ? flicker / pairs : 0.0);
            s.convergingFlicker.push_back(convergingPairs ? converging / convergingPairs : 0.0);
            csv << fmt::format("\"{}\",{},still_relative_mae,{:.5f}\n", name, r.row.label(),
                               e->relativeMae);
            csv << fmt::format("\"{}\",{},still_flicker,{:.5f}\n", name, r.row.label(),
                               s.flicker.back());
            csv << fmt::format("\"{}\",{},still_flicker_converging,{:.5f}\n", name, r.row.label(),
                               s.convergingFlicker.back());
            if (object && std::ptrdiff_t(&r - runs.data()) == nativeRow)
                r.objectMask = objectFootprint(r.renderer->readback(), o.display);
        }
        // The event.
        refTimeline.applyThrough(frame, f.fps, refScene);
        for (RowRun& r : runs) r.timeline.applyThrough(frame, f.fps, r.scene);

        if (!object) {
            const auto refAfter = reference.render(refScene, camera, o.display, t0);
            const double limit = clampLimit(refAfter);
            const auto la = clampedLuminance(refAfter, limit);
            const auto lb = clampedLuminance(refBefore, limit);
            std::vector<std::uint8_t> region(la.size());
            std::size_t regionPixels = 0;
            for (std::size_t p = 0; p < la.size(); ++p) {
                region[p] = std::abs(la[p] - lb[p]) > 0.1 * std::max(la[p], lb[p]) &&
                            std::abs(la[p] - lb[p]) > 0.01 * limit;
                regionPixels += region[p];
            }
            const double refRegion = meanOver(la, region);
            for (std::size_t i = 0; i < runs.size(); ++i) {
                RowRun& r = runs[i];
                for (std::uint32_t j = 0; j < o.afterFrames; ++j) {
                    render(r, t0);
                    r.regionMeans.push_back(meanOver(
                        clampedLuminance(shownImage(*r.renderer, o.display), limit), region));
                }
                if (regionPixels < 16) {
                    csv << fmt::format(
                        "\"{}\",{},frames_to_10pct,,region of {} pixels: not in view\n", name,
                        r.row.label(), regionPixels);
                    continue;
                }
                const auto& m = r.regionMeans;
                const double steady =
                    (m[m.size() - 1] + m[m.size() - 2] + m[m.size() - 3] + m[m.size() - 4]) / 4.0;
                int frames = 1;
                for (std::size_t j = 0; j < m.size(); ++j)
                    if (std::abs(m[j] - steady) > 0.1 * steady) frames = int(j) + 2;
                summary[i].framesToSteady.push_back(frames);
                summary[i].steadyRatio.push_back(steady / std::max(refRegion, 1e-12));
                std::string curve;
                for (double v : m) curve += fmt::format(" {:.3f}", v / std::max(refRegion, 1e-12));
                csv << fmt::format(
                    "\"{}\",{},frames_to_10pct,{},region {} px; region mean / "
                    "reference per frame:{}\n",
                    name, r.row.label(), frames, regionPixels, curve);
            }
        } else if (nativeRow >= 0) {
            // Ghosts: each frame against its own reference, pixels binned by the frames since the
            // object left them.
            const std::size_t n = std::size_t(o.display.x) * o.display.y;
            std::vector<int> lastCovered(n, -1);
            const auto& mask0 = runs[std::size_t(nativeRow)].objectMask;
            for (std::size_t p = 0; p < n && p < mask0.size(); ++p)
                if (mask0[p]) lastCovered[p] = 0;
            constexpr int kAges = 8;
            std::vector<std::array<double, kAges + 1>> err(runs.size()), ref(runs.size());
            std::vector<double> bgErr(runs.size()), bgRef(runs.size());
            std::vector<std::array<std::size_t, kAges + 1>> counts(runs.size());
            std::vector<std::uint8_t> everCovered(n);
            for (std::size_t p = 0; p < n; ++p) everCovered[p] = lastCovered[p] >= 0;
            std::vector<std::vector<std::vector<double>>> shownLum(runs.size());
            std::vector<std::vector<double>> refLum;
            std::vector<std::vector<std::uint8_t>> masks;
            for (std::uint32_t j = 1; j <= o.ghostFrames; ++j) {
                const double t = t0 + double(j) / f.fps;
                const auto refJ = reference.render(refScene, camera, o.display, t);
                const double limit = clampLimit(refJ);
                refLum.push_back(clampedLuminance(refJ, limit));
                // --images: a few of the frames, each row's image and its |error| heat map.
                const bool write = !o.images.empty() && (j == 2 || j % 4 == 0);
                const auto stem = o.images / fmt::format("ghost_{:04}_{:02}", frame, j);
                if (write)
                    if (engine::Status st = writeViewPng(stem.string() + "_reference.png", refJ,
                                                         o.display, viewExposure(refJ));
                        !st)
                        return st;
                for (std::size_t i = 0; i < runs.size(); ++i) {
                    render(runs[i], t);
                    const auto shownJ = shownImage(*runs[i].renderer, o.display);
                    shownLum[i].push_back(clampedLuminance(shownJ, limit));
                    if (write) {
                        const std::string rowStem =
                            stem.string() + "_" + fileLabel(runs[i].row.label());
                        if (engine::Status st = writeViewPng(rowStem + ".png", shownJ, o.display,
                                                             viewExposure(refJ));
                            !st)
                            return st;
                        std::vector<float> diff(shownJ.size());
                        double mean = 0.0;
                        for (double v : refLum.back()) mean += v;
                        mean = std::max(mean / double(diff.size()), 1e-12);
                        for (std::size_t p = 0; p < diff.size(); ++p)
                            diff[p] =
                                float(std::abs(shownLum[i].back()[p] - refLum.back()[p]) / mean);
                        engine::metrics::HeatMapOptions heat;
                        heat.maxValue = 0.5f;
                        auto written = engine::metrics::writeHeatMap(
                            rowStem + "_error.png", diff, o.display.x, o.display.y, heat);
                        if (!written) return written.error();
                    }
                    if (std::ptrdiff_t(i) == nativeRow) {
                        masks.push_back(objectFootprint(runs[i].renderer->readback(), o.display));
                    }
                }
            }
            for (const auto& m : masks)
                for (std::size_t p = 0; p < n; ++p) everCovered[p] |= m[p];
            for (std::uint32_t j = 1; j <= o.ghostFrames; ++j) {
                const auto& m = masks[j - 1];
                for (std::size_t p = 0; p < n; ++p) {
                    if (m[p]) {
                        lastCovered[p] = int(j);
                        continue;
                    }
                    const int age = lastCovered[p] < 0 ? -1 : int(j) - lastCovered[p];
                    for (std::size_t i = 0; i < runs.size(); ++i) {
                        const double e = std::abs(shownLum[i][j - 1][p] - refLum[j - 1][p]);
                        if (!everCovered[p]) {
                            bgErr[i] += e;
                            bgRef[i] += refLum[j - 1][p];
                        } else if (age >= 1 && age <= kAges) {
                            err[i][std::size_t(age)] += e;
                            ref[i][std::size_t(age)] += refLum[j - 1][p];
                            ++counts[i][std::size_t(age)];
                        }
                    }
                }
            }
            for (std::size_t i = 0; i < runs.size(); ++i) {
                const double bg = bgErr[i] / std::max(bgRef[i], 1e-12);
                int trail = 0;
                std::string curve;
                for (int a = 1; a <= kAges; ++a) {
                    if (counts[i][std::size_t(a)] < 16) continue;
                    const double e =
                        err[i][std::size_t(a)] / std::max(ref[i][std::size_t(a)], 1e-12);
                    curve += fmt::format(" {}:{:.3f}", a, e);
                    if (e > 1.5 * bg) trail = a;
                }
                summary[i].ghostTrail = trail;
                summary[i].ghostDetail = fmt::format("background {:.3f}; by age{}", bg, curve);
                csv << fmt::format("\"{}\",{},ghost_trail_frames,{},\"{}\"\n", name,
                                   rows[i].label(), trail, summary[i].ghostDetail);
            }
        }
        progress.update(++done, name);
    }
    progress.finish();

    // The table: one line per row over all cases, the flicker relative to raw at the same scale.
    auto avg = [](const std::vector<double>& v) {
        double s = 0.0;
        for (double x : v) s += x;
        return v.empty() ? 0.0 : s / double(v.size());
    };
    auto worst = [](const std::vector<double>& v) {
        return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
    };
    table += fmt::format(
        "\nStability on {} ({} cases: {}; {}x{}, reference {} spp):\n\n| row | still rel. MAE "
        "after {} frames | flicker | flicker / raw same scale | flicker / raw while converging | "
        "frames to 10 % (worst) | steady / reference (range) | ghost trail (frames) "
        "|\n|---|---|---|---|---|---|---|---|\n",
        scene.name, caseFrames.size(),
        [&] {
            std::string s;
            for (auto& [fr, n] : caseNames)
                s += fmt::format("{}{} at frame {}", s.empty() ? "" : "; ", n, fr);
            return s;
        }(),
        o.display.x, o.display.y, o.referenceSpp, o.stillFrames);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        double rawFlicker = 0.0, rawConverging = 0.0;
        for (std::size_t k = 0; k < rows.size(); ++k)
            if (rows[k].mode == Display::Raw && rows[k].scale == rows[i].scale) {
                rawFlicker = avg(summary[k].flicker);
                rawConverging = avg(summary[k].convergingFlicker);
            }
        const auto& s = summary[i];
        const auto [lo, hi] =
            s.steadyRatio.empty()
                ? std::pair<double, double>{0.0, 0.0}
                : std::pair<double, double>{
                      *std::min_element(s.steadyRatio.begin(), s.steadyRatio.end()),
                      *std::max_element(s.steadyRatio.begin(), s.steadyRatio.end())};
        const std::string line = fmt::format(
            "| {} | {:.4f} | {:.4f} | {:.2f} | {:.2f} | {:.0f} | {:.2f}–{:.2f} | {} |\n",
            rows[i].label(), avg(s.stillMae), avg(s.flicker),
            avg(s.flicker) / std::max(rawFlicker, 1e-12),
            avg(s.convergingFlicker) / std::max(rawConverging, 1e-12), worst(s.framesToSteady), lo,
            hi, s.ghostTrail ? fmt::format("{} ({})", *s.ghostTrail, s.ghostDetail) : "—");
        table += line;
        std::printf("%s", line.c_str());
    }
    std::fflush(stdout);
    return {};
}

}  // namespace vox
