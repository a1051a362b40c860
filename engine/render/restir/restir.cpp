#include "render/restir/restir.h"

#include <fmt/format.h>

#include "gpu/command_list.h"
#include "gpu/uploader.h"
#include "render/frame_commands.h"
#include "render/restir/restir_params.h"
#include "shared/shader_features.h"

namespace engine::render {

namespace {
// Candidates, own, and the two final reservoirs per pixel.
constexpr std::uint64_t kReservoirsPerPixel = 4;
}  // namespace

Restir::Restir(gpu::Context& ctx)
    : mCtx(ctx), mInitial(ctx), mTemporal(ctx), mSpatial(ctx), mShade(ctx) {
    mParams =
        gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::RestirParams), "restir.params");
}

TechniquePlan Restir::plan(const lighting::LightingSettings& l, const SceneShape&,
                           glm::uvec2 size) {
    TechniquePlan p;
    p.runs = lighting::resamples(l);
    const shared::RestirParams restir = restirParams(l, 0);
    p.features = {{FEATURE_CANDIDATE_VISIBILITY, restir.knobs.candidateVisibility},
                  {FEATURE_UNBIASED, restir.knobs.unbiased}};
    p.deviceBytes = sizeof(shared::RestirParams) +
                    kReservoirsPerPixel * size.x * size.y * sizeof(shared::Reservoir);
    return p;
}

std::string Restir::describe(const lighting::LightingSettings& l) {
    const char* sampling = l.regir.enabled  ? "regir"
                           : !l.byPower     ? "uniform"
                           : l.autoSampling ? "auto"
                                            : "power";
    const char* lights = l.brickLights ? "bricks" : "voxels";
    const char* mode = l.area ? "area" : "point";
    if (l.method == lighting::Method::Ris) {
        return fmt::format("ris {} M={} {} {}", mode, l.restir.candidates, sampling, lights);
    }
    return fmt::format(
        "restir {} {} M={} {} {}{}{}", l.restir.unbiased ? "unbiased" : "biased", mode,
        l.restir.candidates, sampling, lights, l.restir.temporal ? " temporal" : "",
        l.restir.spatial
            ? fmt::format(" spatial {}x{:.0f}px", l.restir.spatialTaps, l.restir.spatialRadius)
            : "");
}

void Restir::prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                     shared::FrameParams&) {
    if (in.size != mSize) {
        mSize = in.size;
        const std::uint64_t bytes = std::uint64_t(mSize.x) * mSize.y * sizeof(shared::Reservoir);
        using gpu::BufferKind;
        mCandidates = gpu::Buffer(mCtx, BufferKind::Storage, bytes, "restir.candidates");
        mOwn = gpu::Buffer(mCtx, BufferKind::Storage, bytes, "restir.own");
        mFinal[0] = gpu::Buffer(mCtx, BufferKind::Storage, bytes, "restir.reservoirs0");
        mFinal[1] = gpu::Buffer(mCtx, BufferKind::Storage, bytes, "restir.reservoirs1");
        // Passes that only read these fetch them as uvec4 texels (loadReservoir): one gather per
        // 16 B on lavapipe, where a storage-buffer read at a lane-varying index loops over lanes.
        for (gpu::Buffer* b : {&mCandidates, &mOwn, &mFinal[0], &mFinal[1]}) {
            b->setTexelFormat(VK_FORMAT_R32G32B32A32_UINT);
        }
    }
    const bool restir = in.lighting.method == lighting::Method::Restir;
    mTemporalReuse = restir && in.lighting.restir.temporal && !changes.historyLost;
    mSpatialReuse = restir && in.lighting.restir.spatial;
    const shared::RestirParams p = restirParams(in.lighting, in.frameIndex);
    uploader.write(mParams, 0, &p, sizeof(p));
}

void Restir::record(FrameCommands& commands, const FrameBuffers& frame) {
    gpu::CommandList& cmd = commands.current();
    const SceneBindings& scene = frame.scene;
    gpu::Buffer& final = mFinal[frame.parity];
    mInitial.record(cmd, scene, {frame.frameParams, mParams, frame.gbuffer, mCandidates}, mSize);
    gpu::Buffer* own = &mCandidates;
    if (mTemporalReuse) {
        mTemporal.record(cmd, scene,
                         {frame.frameParams, mParams, frame.gbuffer, frame.prevGbuffer, mCandidates,
                          mFinal[frame.parity ^ 1u], mOwn},
                         mSize);
        own = &mOwn;
    }
    if (mSpatialReuse) {
        mSpatial.record(cmd, scene,
                        {frame.frameParams, mParams, frame.gbuffer, *own, mCandidates, final},
                        mSize);
    } else {
        cmd.copyBuffer(*own, final, {{0, 0, own->size()}});
    }
    mShade.record(cmd, scene, {frame.frameParams, mParams, frame.gbuffer, final, frame.radiance},
                  mSize);
}

}  // namespace engine::render
