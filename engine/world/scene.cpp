#include "world/scene.h"

#include <fmt/format.h>

namespace engine::world {

Status checkCamera(const CameraPreset& c) {
    for (int i = 0; i < 3; ++i) {
        for (auto [what, v] :
             {std::pair{"position", c.position[i]}, std::pair{"target", c.target[i]}}) {
            if (Status ok = checkNumber(fmt::format("camera '{}' {} {}", c.name, what, "xyz"[i]), v,
                                        kCoordinateRange);
                !ok)
                return ok;
        }
    }
    if (Status ok = checkNumber(fmt::format("camera '{}' fov", c.name), c.fovYDegrees, kFovRange);
        !ok)
        return ok;
    if (glm::length(c.target - c.position) < 1e-4f)
        return makeError("camera '{}': target equals position", c.name);
    return {};
}

CameraPreset Scene::camera(std::string_view wanted) const {
    for (const CameraPreset& c : cameras) {
        if (wanted.empty() || c.name == wanted) return c;
    }
    glm::vec3 size(grid.sizeInVoxels());
    CameraPreset overview;
    overview.name = "overview";
    overview.target = size * 0.5f;
    overview.position = glm::vec3(size.x * 1.1f, size.y * 1.2f, size.z * 1.3f);
    return overview;
}

std::uint64_t Scene::emissiveVoxels() const {
    std::uint64_t count = 0;
    grid.topGrid().forEachLiveCell([&](std::uint32_t c) {
        if (c == shared::CELL_EMPTY) return;
        if (!BrickGrid::cellIsBrick(c)) {
            count += palette[BrickGrid::cellMaterial(c)].emissive() ? kBrickVoxels : 0;
            return;
        }
        for (MaterialId m : grid.brickVoxels(BrickGrid::cellBrick(c)))
            count += palette[m].emissive();
    });
    return count;
}

}  // namespace engine::world
