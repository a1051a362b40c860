// CPU reference ray traversal over a BrickGrid. Mirrors shaders/common/brick_traversal.glsl
// operation for operation (the build uses -ffp-contract=off and the shader `precise`), so GPU
// and CPU agree hit for hit except in grazing cases at cell boundaries.
//
// The walk restarts a DDA step from the ray origin at every cell: it looks up the coarsest
// level that is empty around the current voxel (32^3 super cell, 8^3 cell, 4^3 or 2^3 block,
// voxel) and jumps to where the ray leaves that block. Open air, empty cells and empty space
// inside bricks cost one step per block instead of one per voxel.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <limits>

#include "world/brick_grid.h"

namespace engine::world {

struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, 1.0f};
    float tMax = std::numeric_limits<float>::infinity();
};

struct RayHit {
    bool hit = false;
    glm::ivec3 voxel{0};
    std::uint32_t face = shared::FACE_NONE;  // face of `voxel` the ray entered through
    float t = 0.0f;                          // distance (in units of |direction|) to that face
    MaterialId material = kEmpty;
    std::uint32_t steps = 0;  // DDA iterations taken
};

enum class TraversalMode {
    Hierarchical,   // skips empty super cells, and empty 4^3 and 2^3 blocks inside bricks (default)
    PlainTwoLevel,  // cells, then every voxel of a non-empty brick: the classic baseline
};

RayHit traceRay(const BrickGrid& grid, const Ray& ray,
                TraversalMode mode = TraversalMode::Hierarchical);

// Face normals by face index (shared::FACE_*).
glm::ivec3 faceNormal(std::uint32_t face);

}  // namespace engine::world
