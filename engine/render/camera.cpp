#include "render/camera.h"

#include <cmath>

namespace engine::render {

shared::FrameParams makeFrameParams(const world::CameraPreset& camera, const world::SkyLight& sky,
                                    const FrameSettings& settings) {
    glm::vec3 forward = glm::normalize(camera.target - camera.position);
    glm::vec3 worldUp(0.0f, 1.0f, 0.0f);
    if (std::abs(glm::dot(forward, worldUp)) > 0.999f) worldUp = glm::vec3(0.0f, 0.0f, 1.0f);
    glm::vec3 right = glm::normalize(glm::cross(forward, worldUp));
    glm::vec3 up = glm::cross(right, forward);
    float tanHalf = std::tan(glm::radians(camera.fovYDegrees) * 0.5f);
    float aspect = float(settings.width) / float(settings.height);

    shared::FrameParams f{};
    f.cameraPosition = glm::vec4(camera.position, tanHalf);
    f.cameraForward = glm::vec4(forward, aspect);
    f.cameraRight = glm::vec4(right, 0.0f);
    f.cameraUp = glm::vec4(up, 0.0f);
    f.sunDirection = glm::vec4(glm::normalize(sky.sunDirection), 0.0f);
    f.sunRadiance = glm::vec4(sky.sunRadiance, 0.0f);
    f.skyRadiance = glm::vec4(sky.skyRadiance, 0.0f);
    f.imageSize = glm::uvec4(settings.width, settings.height, 0u, 0u);
    f.exposure = glm::vec4(settings.exposure, 0.0f, 0.0f, 0.0f);
    f.displaySize = glm::uvec4(settings.width, settings.height, 0u, 0u);
    return f;
}

glm::vec3 cameraRayDirection(const shared::FrameParams& f, glm::uvec2 pixel) {
    return cameraRayDirectionAt(f, glm::vec2(pixel) + 0.5f + glm::vec2(f.jitter));
}

glm::vec3 cameraRayDirectionAt(const shared::FrameParams& f, glm::vec2 imagePosition) {
    glm::vec2 ndc = imagePosition / glm::vec2(f.imageSize.x, f.imageSize.y) * 2.0f - 1.0f;
    float tanHalf = f.cameraPosition.w;
    glm::vec3 d = glm::vec3(f.cameraForward) +
                  glm::vec3(f.cameraRight) * (ndc.x * tanHalf * f.cameraForward.w) -
                  glm::vec3(f.cameraUp) * (ndc.y * tanHalf);
    return glm::normalize(d);
}

}  // namespace engine::render
