#include "render/upsampling/temporal_upsampling.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "gpu/uploader.h"
#include "render/frame_commands.h"

namespace engine::render {

namespace {

float radicalInverse(std::uint32_t index, std::uint32_t base) {
    float result = 0.0f, digit = 1.0f / float(base);
    for (; index > 0; index /= base, digit /= float(base)) result += float(index % base) * digit;
    return result;
}

// The voxels of the edited cells, as one box (empty when nothing was edited): where a surface
// may have kept its place but not its material or light (a lamp turned to stone, a light
// switched), so a history of it is of another surface.
world::Box editedVoxels(const FrameChanges& changes) {
    if (changes.editedCells.empty()) return {};
    glm::ivec3 lo = changes.editedCells.front(), hi = lo;
    for (const glm::ivec3& c : changes.editedCells) {
        lo = glm::min(lo, c);
        hi = glm::max(hi, c);
    }
    return {lo * world::kBrickDim, (hi + 1) * world::kBrickDim};
}

}  // namespace

std::uint32_t jitterPhases(glm::uvec2 render, glm::uvec2 display) {
    const double ratio = double(display.x) / double(std::max(render.x, 1u));
    return std::clamp(std::uint32_t(std::lround(8.0 * ratio * ratio)), 16u, 128u);
}

glm::vec2 jitterOffset(std::uint32_t index) {
    return glm::vec2(radicalInverse(index, 2), radicalInverse(index, 3)) - 0.5f;
}

TemporalUpsampling::TemporalUpsampling(gpu::Context& ctx)
    : mCtx(ctx), mNeighbourhoodPass(ctx), mPass(ctx) {
    mParams = gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::UpsamplingParams),
                          "resolve.params");
}

TechniquePlan TemporalUpsampling::plan(const lighting::LightingSettings& l, const SceneShape&,
                                       glm::uvec2 size) {
    TechniquePlan p;
    p.runs = lighting::reconstructs(l);
    p.writesDisplay = true;
    // Its keys are per display pixel: the renderer's memory plan counts them with the display
    // image (Renderer::displayBytesPerPixel); its pre-pass's summary is per render pixel.
    p.deviceBytes = sizeof(shared::UpsamplingParams) +
                    std::uint64_t(size.x) * size.y * kNeighbourhoodBytesPerPixel;
    return p;
}

std::string TemporalUpsampling::describe(const lighting::LightingSettings& l) {
    return fmt::format("resolved to the display over up to {} frames", l.display.resolveHistory);
}

void TemporalUpsampling::skip() {
    mRestart = true;
    mPrevJitter = glm::vec2(0.0f);
}

void TemporalUpsampling::prepare(const FrameChanges& changes, const FrameInput& in,
                                 gpu::Uploader& uploader, shared::FrameParams& params) {
    if (in.displaySize != mDisplaySize) {
        mDisplaySize = in.displaySize;
        const std::uint64_t pixels = std::uint64_t(mDisplaySize.x) * mDisplaySize.y;
        for (auto& keys : mKeys) {
            keys = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(std::uint32_t),
                               "resolve.keys");
            keys.setTexelFormat(VK_FORMAT_R32_UINT);  // the resolve reads last frame's as texels
        }
        mRestart = true;
    }
    if (in.size != mRenderSize) {
        mRenderSize = in.size;
        mNeighbourhood =
            gpu::Buffer(mCtx, gpu::BufferKind::Storage,
                        std::uint64_t(mRenderSize.x) * mRenderSize.y * kNeighbourhoodBytesPerPixel,
                        "resolve.neighbourhood");
        // The resolve reads it as texels: at the nearest sample of each display pixel.
        mNeighbourhood.setTexelFormat(VK_FORMAT_R32G32B32A32_UINT);
    }
    const glm::vec2 jitter =
        in.lighting.display.jitter
            ? jitterOffset(in.frameIndex % jitterPhases(in.size, in.displaySize) + 1)
            : glm::vec2(0.0f);
    params.jitter = glm::vec4(jitter, mPrevJitter);
    mPrevJitter = jitter;

    shared::UpsamplingParams p{};
    // A new world or new settings start over; a new render size does not (the display is kept).
    p.flags =
        mRestart || changes.newWorld || changes.settingsChanged ? shared::UPSAMPLING_RESTART : 0u;
    // Objects that move are caught by their surface keys; the rest of a change only by the clip,
    // which a bright sub-pixel light or a noisy neighbourhood can hide.
    if (changes.staticWorldChanged || changes.lightsUploaded || changes.skyChanged)
        p.flags |= shared::UPSAMPLING_LIGHTING_CHANGED;
    if (changes.objectsMoved) p.flags |= shared::UPSAMPLING_OBJECTS_MOVED;
    // A cell around the edited voxels: their light changes most nearby (the shadow of a new
    // block, a wall lit by a lamp turned off), where the clip alone follows it too slowly.
    if (const world::Box edited = editedVoxels(changes); !edited.empty()) {
        p.editedMin = glm::ivec4(edited.min - world::kBrickDim, 0);
        p.editedMax = glm::ivec4(edited.max + world::kBrickDim, 0);
    }
    p.maxHistory = float(std::max(in.lighting.display.resolveHistory, 1u));
    // A still view settles after a whole jitter cycle, or the history's length if shorter. A
    // pixel's history fills by the weight its samples brought, and where the cycle's offsets fell
    // farther from its centre it filled frames after the others and kept moving while they were
    // still (a converged view flickered at 0.2x raw ReSTIR's, which is frozen).
    const bool still = !(p.flags & shared::UPSAMPLING_RESTART) && !changes.cameraMoved &&
                       !changes.worldChanged() && !changes.skyChanged && !changes.sizeChanged;
    mStillFrames = still ? mStillFrames + 1 : 0;
    if (mStillFrames >= std::min(jitterPhases(in.size, in.displaySize),
                                 std::max(in.lighting.display.resolveHistory, 1u)))
        p.flags |= shared::UPSAMPLING_SETTLED;
    p.clipGamma = 1.25f;
    uploader.write(mParams, 0, &p, sizeof(p));
    mRestart = false;
}

void TemporalUpsampling::record(FrameCommands& commands, const FrameBuffers& frame) {
    const std::uint32_t now = frame.parity, then = now ^ 1u;
    mNeighbourhoodPass.record(commands.current(),
                              {frame.frameParams, mParams, frame.gbuffer, frame.radiance,
                               frame.surfaceKeys, mNeighbourhood},
                              frame.size);
    mPass.record(
        commands.current(),
        {frame.frameParams, mParams, mNeighbourhood, frame.surfaceKeys, frame.radiance,
         frame.prevDisplay, frame.display, mKeys[then], mKeys[now], frame.exposure, frame.ldr},
        frame.displaySize);
}

}  // namespace engine::render
