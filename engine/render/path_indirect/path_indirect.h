// PathIndirect: the real-time path-traced indirect term (`--indirect path`), the baseline the
// irradiance cache is measured against at equal time (vox bench flythrough, docs/ACCURACY.md).
// Per pixel and frame, `samples` bounce paths from the G-buffer's surface (the reference path
// tracer's walk from the first bounce on), averaged over frames while camera and world stay still
// and restarted when either changes — on a flythrough every frame starts afresh.
// Owns the running sum and the parameters; the renderer passes the frame's buffers.
// Each frame: prepare() (before the frame's uploads are recorded), then record() after the
// direct lighting.
#pragma once

#include <cstdint>

#include "gpu/buffer.h"
#include "gpu/uploader.h"
#include "lighting/lighting_settings.h"
#include "render/path_indirect/path_indirect_pass.h"

namespace engine::render {

class PathIndirect {
public:
    explicit PathIndirect(gpu::Context& ctx);

    // `restart`: the camera moved, the world changed or the history is otherwise gone.
    void prepare(const lighting::LightingSettings& lighting, glm::uvec2 size, std::uint32_t frameIndex, bool restart,
                 gpu::Uploader& uploader);
    struct Io {
        const gpu::Buffer& frameParams;  // read
        const gpu::Buffer& gbuffer;      // read
        gpu::Buffer& radiance;           // the term is added
        gpu::Buffer& indirect;           // write: the term alone
    };
    void record(gpu::CommandList& cmd, const SceneBindings& scene, const Io& io);

    // Paths per pixel in the running sum after the last prepared frame.
    std::uint32_t accumulatedPaths() const { return mPaths; }

private:
    gpu::Context& mCtx;
    PathIndirectPass mPass;
    gpu::Buffer mParams, mAccumulation;
    glm::uvec2 mSize{0};
    std::uint32_t mPaths = 0;
};

}  // namespace engine::render
