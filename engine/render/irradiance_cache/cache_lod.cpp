#include "render/irradiance_cache/cache_lod.h"

namespace engine::render {

std::optional<CacheKey> coarsePatchKey(const world::BrickGrid& grid, glm::ivec3 voxel, std::uint32_t face) {
    if (face >= shared::CACHE_FACES || glm::any(glm::lessThan(voxel, glm::ivec3(0)))) return std::nullopt;
    const std::uint32_t axis = face >> 1, ua = (axis + 1) % 3, va = (axis + 2) % 3;
    glm::ivec3 base = voxel;
    base[ua] &= ~1;
    base[va] &= ~1;
    glm::ivec3 normal(0);
    normal[axis] = (face & 1u) ? 1 : -1;
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            glm::ivec3 v = base;
            v[ua] += i;
            v[va] += j;
            if (grid.get(v) == world::kEmpty || grid.get(v + normal) != world::kEmpty) return std::nullopt;
        }
    }
    return CacheKey{base, shared::CACHE_SET_STATIC, 1u + face};
}

CacheKey staticKeyFor(const world::BrickGrid& grid, glm::ivec3 voxel, std::uint32_t face, float viewDistance,
                      float lodDistance) {
    if (lodDistance > 0.0f && viewDistance >= lodDistance) {
        if (std::optional<CacheKey> coarse = coarsePatchKey(grid, voxel, face)) return *coarse;
    }
    return CacheKey{voxel, shared::CACHE_SET_STATIC};
}

}  // namespace engine::render
