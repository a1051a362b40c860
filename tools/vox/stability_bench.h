// vox bench stability's parts (bench_stability_command.cpp has the story): what its cases share
// (the GPU, the frame, the reference cache and the outputs), the measurements they are made of
// (stability_measures.cpp), and the cases themselves — ReSTIR and the irradiance cache's
// (stability_cases.cpp), voxel cone tracing's (stability_vct_cases.cpp) and the DVF sky light's
// (stability_sky_cases.cpp). Each case adds lines to the markdown table and the response curves.
#pragma once

#include <filesystem>
#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/error.h"
#include "lighting/lighting_settings.h"
#include "render/renderer.h"
#include "world/scene.h"

namespace engine::gpu {
class Context;
}

namespace vox {

// A dynamic object's run: the per-frame MAE over the whole image and over the pixels whose
// primary hit is on the object (ghosting shows there first).
struct MovingRun {
    std::vector<double> mae, maeObject;
};

struct StabilityContext {
    engine::gpu::Context& gpu;
    engine::render::FrameSettings frame;
    std::filesystem::path cache;
    std::ostream& curves;           // case,method,frame,mae
    std::vector<std::string> rows;  // markdown table rows
    std::string output;             // the output folder, as given
    // The cache's run on the fast crate, made for the response case and reused for ghosting.
    std::optional<MovingRun> fastCacheRun;
};

// The worlds whose still camera's flicker is measured.
inline const std::vector<std::string> kFlickerWorlds{"cornell", "mountain", "apartments"};

// --- measurements (stability_measures.cpp) ---

double maeOf(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b,
             const engine::render::FrameSettings& f);
double meanRadiance(const std::vector<glm::vec4>& img);
// Flicker: the mean |frame - previous frame| over the frames added, relative to their mean
// radiance (the first frame only starts the count).
class FlickerMeter {
public:
    explicit FlickerMeter(const engine::render::FrameSettings& frame) : mFrame(frame) {}
    void add(std::vector<glm::vec4> image);
    double value() const;

private:
    engine::render::FrameSettings mFrame;
    std::vector<glm::vec4> mPrevious;
    double mSum = 0.0, mMean = 0.0;
};

// Mean of v[from..].
double mean(const std::vector<double>& v, std::size_t from = 0);
// Frames until `errors` is within 10 % of its steady state (the median of the last 8), and that
// steady state.
std::pair<int, double> framesToSteady(const std::vector<double>& errors);
// A method of the flicker and response rows by name: restir, restir-unbiased, ris (no reuse)
// or uniform.
engine::lighting::LightingSettings methodSettings(const std::string& method);

// Mean |frame - previous frame| over `frames` frames after `warmup`, relative to the mean
// radiance.
double flicker(StabilityContext& c, engine::world::Scene& scene,
               engine::lighting::LightingSettings l, int warmup, int frames, bool reseed);

// Steady state on `scene`, then `edit` and count frames until the error against the edited
// scene's reference is back within 10 % of its new steady state; for ReSTIR biased and unbiased.
void response(StabilityContext& c, const std::string& name, engine::world::Scene scene,
              const std::function<void(engine::world::Scene&)>& edit);

// A dynamic object still for `still` frames, then moving along its path for `moving` frames at
// 30 fps; each moving frame's error against the converged reference of that frame's pose
// (cached on disk per time; one reference when the object never moves). `indirectOnly`
// compares the cache's indirect term with the path tracer's (one bounce minus direct light), so
// the direct light's noise does not hide it.
MovingRun movingRun(StabilityContext& c, const std::string& name, const engine::world::Scene& scene,
                    const engine::world::CameraPreset& camera,
                    const engine::lighting::LightingSettings& l, bool indirectOnly, int still,
                    int moving);

// How a response curve is named: in the CSV (its case and method), in the table and on stdout.
struct ResponseNames {
    const char* curveCase;
    const char* curveMethod;
    const char* rowCase;
    const char* rowMethod;
    const char* shortMethod;
};
// A response curve (one error per frame after the change) to the CSV, its frames to a steady
// error to the table (`more`: what else the row says, after the first frame's error) and stdout.
void addResponse(StabilityContext& c, const ResponseNames& names, const std::vector<double>& errors,
                 const std::string& more = "");

// The crate of worlds/thin_wall.toml made fast: it sweeps along the room's south wall, 56 voxels
// in 0.5 s (3.7 voxels a frame at 30 fps) and back, so the world voxels it covers are new almost
// every frame. `still`: parked at its start instead.
engine::world::Scene fastCrate(const engine::world::Scene& thinWall, bool still);
// worlds/thin_wall.toml, its edits made so far cleared.
engine::Result<engine::world::Scene> loadThinWall();
// The irradiance cache with an N^3 neighbourhood of dynamic voxels.
engine::lighting::LightingSettings cacheLighting(std::uint32_t neighbourhood);

// The cache's indirect term as an 8-bit image, `scale` mapping to white (linear, clamped).
std::vector<std::uint32_t> indirectImage(const std::vector<glm::vec4>& indirect, float scale);
// An empty world of `size` with a white material (1) and a lamp (2), no sun or sky.
engine::world::Scene simpleScene(glm::ivec3 size);

// --- the cases ---

// ReSTIR's and the cache's: flicker, response to edits and to a moving object, and the known
// failure cases (stability_cases.cpp).
engine::Status restirCases(StabilityContext& c);
// Voxel cone tracing's (stability_vct_cases.cpp).
engine::Status vctCases(StabilityContext& c);
// DVF sky light's (stability_sky_cases.cpp).
engine::Status skyCases(StabilityContext& c);

}  // namespace vox
