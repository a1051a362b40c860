#include "world/mountain_generator.h"

#include <algorithm>
#include <cmath>

#include "world/value_noise.h"

namespace engine::world {

namespace {

// Ridged multifractal-style noise in [0, 1]: 1 - |2n - 1| turns valleys of value noise into
// sharp crests, squared so the crests are narrow.
float ridgedNoise(float x, float z, const MountainParams& p) {
    float sum = 0.0f, norm = 0.0f, amp = 1.0f, freq = 1.0f / std::max(p.wavelength, 1.0f);
    for (int o = 0; o < std::max(p.octaves, 1); ++o) {
        float r = 1.0f - std::abs(2.0f * valueNoise(x * freq, z * freq, p.seed + 1013u * o) - 1.0f);
        sum += amp * r * r;
        norm += amp;
        amp *= 0.5f;
        freq *= 2.0f;
    }
    return sum / norm;
}

}  // namespace

int mountainHeight(const MountainParams& p, int x, int z) {
    float fx = float(x), fz = float(z);
    float d = glm::length(glm::vec2(fx, fz) - p.peak) / std::max(p.radius, 1.0f);
    // Concave flanks: steep near the summit, flattening into the foothills.
    float massif = std::pow(std::max(0.0f, 1.0f - d), 1.6f);
    float ridge = ridgedNoise(fx, fz, p);
    float rise =
        (p.peakHeight - p.baseHeight) * massif * (1.0f - p.ridges + p.ridges * 2.0f * ridge);
    float hills = p.hills * (2.0f * valueNoise(fx / 57.0f, fz / 57.0f, p.seed ^ 0x51ed27u) - 1.0f);
    float h = p.baseHeight + hills + rise;
    if (p.terrace > 0) h = std::floor(h / float(p.terrace)) * float(p.terrace);
    return std::max(1, static_cast<int>(std::floor(h)));
}

void generateMountain(BrickGrid& grid, const MountainParams& p) {
    fillHeightField(
        grid, [&](int x, int z) { return mountainHeight(p, x, z); }, p.materials);
}

}  // namespace engine::world
