// Camera maths shared by the renderer and CPU-side code: FrameParams from a camera preset, and
// the per-pixel ray direction (mirrors shaders/common/camera.glsl).
#pragma once

#include <cstdint>

#include "shared/frame_params.h"
#include "world/scene.h"

namespace engine::render {

struct FrameSettings {
    std::uint32_t width = 320;
    std::uint32_t height = 180;
    float exposure = 1.0f;
    // Scene time in seconds: poses the dynamic objects (world/dynamic_grid.h) and times the
    // irradiance cache's fade. The renderer
    // remembers the last frame's time for their motion vectors.
    double timeSeconds = 0.0;
    // The displayed image's size when the lighting's reconstruction resolves to it
    // (lighting::reconstructs); 0: the render size.
    std::uint32_t displayWidth = 0;
    std::uint32_t displayHeight = 0;
};

shared::FrameParams makeFrameParams(const world::CameraPreset& camera, const world::SkyLight& sky,
                                    const FrameSettings& settings);

// Unit direction through `pixel`'s sample: its centre, moved by the frame's jitter (0 unless the
// image is reconstructed).
glm::vec3 cameraRayDirection(const shared::FrameParams& f, glm::uvec2 pixel);
// Unit direction through a point of the image in pixel units (pixel i spans [i, i + 1)).
glm::vec3 cameraRayDirectionAt(const shared::FrameParams& f, glm::vec2 imagePosition);

}  // namespace engine::render
