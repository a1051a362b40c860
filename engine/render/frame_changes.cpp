#include "render/frame_changes.h"

namespace engine::render {

namespace {

bool sameView(const world::CameraPreset& a, const world::CameraPreset& b) {
    return a.position == b.position && a.target == b.target && a.fovYDegrees == b.fovYDegrees;
}

bool sameSky(const world::SkyLight& a, const world::SkyLight& b) {
    return a.sunDirection == b.sunDirection && a.sunRadiance == b.sunRadiance &&
           a.skyRadiance == b.skyRadiance;
}

// The grid's touched cells (linear indices) as cell coordinates.
std::vector<glm::ivec3> touchedCells(const world::BrickGrid& grid) {
    const glm::ivec3 cells = grid.sizeInCells();
    std::vector<glm::ivec3> out;
    out.reserve(grid.touchedCells().size());
    for (std::uint32_t c : grid.touchedCells()) {
        out.emplace_back(c % cells.x, (c / cells.x) % cells.y, c / (cells.x * cells.y));
    }
    return out;
}

}  // namespace

FrameChanges FrameChangeTracker::observe(const FrameObservation& frame) {
    FrameChanges c;
    c.sizeChanged = frame.size != mSize;
    if (c.sizeChanged) forgetHistory();
    c.settingsChanged = mLighting && !(*mLighting == frame.lighting);
    c.newWorld = frame.upload.full;
    c.editedCells = touchedCells(frame.scene.grid);
    c.staticWorldChanged = frame.upload.bricks || frame.upload.cells;
    c.objectsMoved = frame.upload.dynamicBytes > 0;
    const lighting::EmitterUpdateStats& lights = frame.emitterUpdate;
    c.lightsEdited = !lights.full && (lights.added || lights.removed || lights.changed);
    c.lightsUploaded = frame.emitterUpload.slots || frame.emitterUpload.aliveAndAlias;
    c.skyChanged = mSky && !sameSky(*mSky, frame.scene.sky);
    c.cameraMoved = !mCamera || !sameView(*mCamera, frame.camera);
    c.historyLost = !mHistoryValid || c.settingsChanged || c.lightsEdited;
    c.previousCamera = mCamera.value_or(frame.camera);

    mSize = frame.size;
    mLighting = frame.lighting;
    mSky = frame.scene.sky;
    mCamera = frame.camera;
    mHistoryValid = true;
    return c;
}

void FrameChangeTracker::forgetHistory() {
    mHistoryValid = false;
    mCamera.reset();
}

}  // namespace engine::render
