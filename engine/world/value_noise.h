// Seeded 2D value noise for height fields: a hash of the lattice point, smoothly interpolated.
// Pure functions of (x, z, seed), so generated worlds repeat exactly.
#pragma once

#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>

#include "core/hash.h"

namespace engine::world {

inline float latticeValue(int x, int z, std::uint32_t seed) {
    std::uint32_t h = hashCombine(hashCombine(seed, static_cast<std::uint32_t>(x)),
                                  static_cast<std::uint32_t>(z));
    return static_cast<float>(h) * (1.0f / 4294967296.0f);
}

// Smoothly interpolated value noise in [0, 1).
inline float valueNoise(float x, float z, std::uint32_t seed) {
    float fx = std::floor(x), fz = std::floor(z);
    int ix = static_cast<int>(fx), iz = static_cast<int>(fz);
    float tx = x - fx, tz = z - fz;
    tx = tx * tx * (3.0f - 2.0f * tx);
    tz = tz * tz * (3.0f - 2.0f * tz);
    float a = latticeValue(ix, iz, seed), b = latticeValue(ix + 1, iz, seed);
    float c = latticeValue(ix, iz + 1, seed), d = latticeValue(ix + 1, iz + 1, seed);
    return glm::mix(glm::mix(a, b, tx), glm::mix(c, d, tx), tz);
}

}  // namespace engine::world
