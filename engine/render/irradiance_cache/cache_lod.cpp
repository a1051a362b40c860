#include "render/irradiance_cache/cache_lod.h"

namespace engine::render {

glm::ivec3 coarsePatchBase(glm::ivec3 voxel, std::uint32_t face) {
    const std::uint32_t axis = face >> 1, ua = (axis + 1) % 3, va = (axis + 2) % 3;
    glm::ivec3 base = voxel;
    base[ua] &= ~1;
    base[va] &= ~1;
    return base;
}

std::optional<CacheKey> coarsePatchKey(const world::BrickGrid& grid, glm::ivec3 voxel,
                                       std::uint32_t face) {
    if (face >= shared::CACHE_FACES || glm::any(glm::lessThan(voxel, glm::ivec3(0))))
        return std::nullopt;
    const std::uint32_t axis = face >> 1, ua = (axis + 1) % 3, va = (axis + 2) % 3;
    const glm::ivec3 base = coarsePatchBase(voxel, face);
    glm::ivec3 normal(0);
    normal[axis] = (face & 1u) ? 1 : -1;
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            glm::ivec3 v = base;
            v[ua] += i;
            v[va] += j;
            if (grid.get(v) == world::kEmpty || grid.get(v + normal) != world::kEmpty)
                return std::nullopt;
        }
    }
    return CacheKey{base, shared::CACHE_SET_STATIC, 1u + face};
}

CacheKey staticKeyFor(const world::BrickGrid& grid, glm::ivec3 voxel, std::uint32_t face,
                      float viewDistance, float lodDistance) {
    return StaticKeys(grid, lodDistance).keyFor(voxel, face, viewDistance);
}

CacheKey StaticKeys::keyFor(glm::ivec3 voxel, std::uint32_t face, float viewDistance) {
    if (mLodDistance > 0.0f && viewDistance >= mLodDistance) {
        const glm::ivec4 patch(coarsePatchBase(voxel, face), static_cast<int>(face));
        if (patch != mPatch) {
            mPatch = patch;
            mPatchOpen = coarsePatchKey(mGrid, voxel, face).has_value();
        }
        if (mPatchOpen) return CacheKey{glm::ivec3(patch), shared::CACHE_SET_STATIC, 1u + face};
    }
    return CacheKey{voxel, shared::CACHE_SET_STATIC};
}

}  // namespace engine::render
