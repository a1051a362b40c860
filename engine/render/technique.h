// Technique: what the frame asks of every lighting technique — light tiles, ReGIR, the preview,
// ReSTIR (and RIS), the baselines, the reference, the sky term, the path-traced and cone-traced
// indirect terms, the irradiance cache. A technique owns its buffers and passes (kajiya's
// renderers, Falcor's RTXDI module). Renderer::render is a loop over the techniques the frame
// plan (frame_plan.h) says run: prepare each (host work and uploads, from what changed), record
// each (its passes, in registry order: technique_registry.cpp), collect each (its statistics,
// once the GPU is done).
//
// Besides the virtual functions, a technique class T has, for the registry (techniqueEntry<T>):
//   static TechniquePlan plan(const lighting::LightingSettings&, const SceneShape&, glm::uvec2);
//   static std::string describe(const lighting::LightingSettings&);  // for logs; "" for nothing
//   explicit T(gpu::Context&);
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <utility>
#include <vector>

#include "lighting/lighting_settings.h"
#include "render/camera.h"
#include "render/frame_changes.h"
#include "render/passes/scene_bindings.h"
#include "shared/frame_params.h"
#include "world/scene.h"

namespace engine::gpu {
class Buffer;
class Uploader;
}  // namespace engine::gpu

namespace engine::render {

struct FrameResult;
class FrameCommands;

// What the frame plan needs of the scene.
struct SceneShape {
    glm::ivec3 sizeInVoxels{0};
    bool dynamicGrid = false;  // the scene has objects this frame (world::DynamicGrid::present)
};
SceneShape sceneShape(const world::Scene& scene);

// What a technique asks of a frame that runs it: the one answer to "is it on?", its shader
// features and its memory.
struct TechniquePlan {
    bool runs = false;
    std::uint64_t deviceBytes = 0;  // device memory it holds at the frame's size when it runs
    bool addsIndirect = false;  // it writes the frame's indirect term (else the frame clears it)
    // It writes the display image (FrameBuffers::display) and that image tonemapped
    // (FrameBuffers::ldr), so the frame's tonemap pass does not run: a second pass over the
    // window's pixels cost about a third of the resolve's time on lavapipe.
    bool writesDisplay = false;
    // The shader features it decides (FEATURE_*, value); they are 0 in a frame that does not run
    // it.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> features;
};

// What every technique may read of the frame it prepares.
struct FrameInput {
    const world::Scene& scene;
    const world::CameraPreset& camera;
    const FrameSettings& settings;
    const lighting::LightingSettings& lighting;
    glm::uvec2 size;
    glm::uvec2 displaySize;  // the displayed image's (size, unless a technique writes the display)
    std::uint32_t frameIndex;
    std::uint32_t emitters;  // alive emitters this frame (the emitter list's, as uploaded)
};

// The frame's buffers that the passes of different techniques hand each other.
struct FrameBuffers {
    SceneBindings scene;                 // the world and the emitter list
    const gpu::Buffer& frameParams;      // FrameParams
    const gpu::Buffer& gbuffer;          // this frame's G-buffer (primary rays)
    const gpu::Buffer& prevGbuffer;      // last frame's
    const gpu::Buffer& surfaceKeys;      // this frame's surface key per pixel (primary rays)
    const gpu::Buffer& prevSurfaceKeys;  // last frame's
    gpu::Buffer& radiance;               // the direct light, then every term added to it
    gpu::Buffer& indirect;               // the indirect term alone
    gpu::Buffer& rayStats;               // preview: steps and rays per pixel
    gpu::Buffer& exposure;               // the display's ExposureState: auto exposure writes it
    gpu::Buffer& display;                // the display image at displaySize, when one is planned
    gpu::Buffer& ldr;                    // the shown image, tonemapped: RGBA8 at displaySize
    const gpu::Buffer& prevDisplay;      // last frame's
    glm::uvec2 size;
    glm::uvec2 displaySize;
    std::uint32_t parity;  // which of a ping-pong pair is this frame's (0 or 1)
};

class Technique {
public:
    virtual ~Technique() = default;
    // Host work before the frame's uploads are recorded: queue this frame's parameters into
    // `uploader`, and fill this technique's fields of the frame's parameters.
    virtual void prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                         shared::FrameParams& params) = 0;
    // Its passes, after those of the techniques before it in the registry.
    virtual void record(FrameCommands& commands, const FrameBuffers& frame) = 0;
    // Once the frame's submissions completed: its statistics.
    virtual void collect(FrameResult& result) { (void)result; }
    // A frame that does not run it: drop what such a frame would leave stale.
    virtual void skip() {}
};

}  // namespace engine::render
