#include "render/dvf_sky/dvf_directions.h"

#include <algorithm>
#include <cmath>

namespace engine::render {
namespace {

void faceFrame(std::uint32_t face, glm::vec3& n, glm::vec3& t, glm::vec3& b) {
    const std::uint32_t axis = face >> 1u;
    n = glm::vec3(0.0f);
    n[axis] = (face & 1u) ? 1.0f : -1.0f;
    t = glm::vec3(0.0f);
    b = glm::vec3(0.0f);
    t[(axis + 1) % 3] = 1.0f;
    b[(axis + 2) % 3] = 1.0f;
}

// The sky's brightness relative to skyRadiance in direction `d` (common/surface.glsl).
double skyGradient(glm::dvec3 d) {
    const double up = std::clamp(d.y * 0.5 + 0.5, 0.0, 1.0);
    return 0.6 + (1.4 - 0.6) * up;
}

}  // namespace

glm::vec3 dvfDirection(std::uint32_t face, glm::vec2 uv) {
    const glm::vec2 p = uv * 2.0f - 1.0f;
    const float x = (p.x + p.y) * 0.5f, y = (p.y - p.x) * 0.5f;
    const float z = 1.0f - std::abs(x) - std::abs(y);
    glm::vec3 n, t, b;
    faceFrame(face, n, t, b);
    return glm::normalize(x * t + y * b + z * n);
}

std::uint32_t dvfTexel(std::uint32_t face, glm::vec3 dir) {
    glm::vec3 n, t, b;
    faceFrame(face, n, t, b);
    glm::vec3 l(glm::dot(dir, t), glm::dot(dir, b), std::max(glm::dot(dir, n), 0.0f));
    l /= std::abs(l.x) + std::abs(l.y) + l.z;
    const glm::vec2 p(l.x - l.y, l.x + l.y);
    const float grid = static_cast<float>(shared::DVF_GRID);
    const glm::vec2 c =
        glm::clamp((p * 0.5f + 0.5f) * grid, glm::vec2(0.0f), glm::vec2(grid - 0.5f));
    return static_cast<std::uint32_t>(c.x) + static_cast<std::uint32_t>(c.y) * shared::DVF_GRID;
}

std::array<float, 6 * shared::DVF_DIRECTIONS> dvfSkyWeights() {
    // Midpoint rule over 32x32 sub-texels; the solid angle of each from the map's Jacobian,
    // |∂ω/∂u × ∂ω/∂v|, by central differences (the map is smooth inside a texel).
    constexpr int kSub = 32;
    const double grid = shared::DVF_GRID;
    const double du = 1.0 / (grid * kSub);
    auto dir = [](std::uint32_t face, double u, double v) {
        return glm::dvec3(
            dvfDirection(face, glm::vec2(static_cast<float>(u), static_cast<float>(v))));
    };
    std::array<float, 6 * shared::DVF_DIRECTIONS> weights{};
    for (std::uint32_t face = 0; face < 6; ++face) {
        glm::vec3 nf, t, b;
        faceFrame(face, nf, t, b);
        const glm::dvec3 n(nf);
        for (std::uint32_t d = 0; d < shared::DVF_DIRECTIONS; ++d) {
            double sum = 0.0;
            for (int j = 0; j < kSub; ++j) {
                for (int i = 0; i < kSub; ++i) {
                    const double u = ((d % shared::DVF_GRID) + (i + 0.5) / kSub) / grid;
                    const double v = ((d / shared::DVF_GRID) + (j + 0.5) / kSub) / grid;
                    const double h = du * 0.25;
                    const glm::dvec3 w = dir(face, u, v);
                    const glm::dvec3 dwdu = (dir(face, u + h, v) - dir(face, u - h, v)) / (2.0 * h);
                    const glm::dvec3 dwdv = (dir(face, u, v + h) - dir(face, u, v - h)) / (2.0 * h);
                    const double solidAngle = glm::length(glm::cross(dwdu, dwdv)) * du * du;
                    sum += skyGradient(w) * std::max(glm::dot(w, n), 0.0) * solidAngle;
                }
            }
            weights[face * shared::DVF_DIRECTIONS + d] =
                static_cast<float>(sum / 3.14159265358979323846);
        }
    }
    return weights;
}

}  // namespace engine::render
