// The DVF sky's direction map and weights on the host (render/dvf_sky/dvf_directions.h).
#include "render/dvf_sky/dvf_directions.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

using namespace engine::render;

// With a uniform sky the weights of a face add up to (1/pi) ∫ cos dω = 1 over the hemisphere;
// with the engine's gradient (0.6 at the horizon... 1.4 straight up), an upward face gets
// (1/pi) ∫ (1 + 0.4 cos) cos dω = 1 + 0.4 * 2/3, a downward one 1 - 0.4 * 2/3 and a side one 1.
TEST(DvfDirections, WeightsIntegrateTheSkyOverTheHemisphere) {
    const auto w = dvfSkyWeights();
    const double expected[6] = {1.0, 1.0, 1.0 - 0.8 / 3.0, 1.0 + 0.8 / 3.0, 1.0, 1.0};
    for (int face = 0; face < 6; ++face) {
        double sum = 0.0;
        for (int d = 0; d < 64; ++d) {
            EXPECT_GT(w[face * 64 + d], 0.0f) << "face " << face << " texel " << d;
            sum += w[face * 64 + d];
        }
        EXPECT_NEAR(sum, expected[face], 2e-3) << "face " << face;
    }
}

// Every texel's centre direction lies in the face's hemisphere and maps back to the texel.
TEST(DvfDirections, TexelOfDirectionInvertsTheMap) {
    for (std::uint32_t face = 0; face < 6; ++face) {
        glm::vec3 n(0.0f);
        n[face >> 1u] = (face & 1u) ? 1.0f : -1.0f;
        for (std::uint32_t d = 0; d < 64; ++d) {
            const glm::vec2 uv((float(d % 8u) + 0.5f) / 8.0f, (float(d / 8u) + 0.5f) / 8.0f);
            const glm::vec3 dir = dvfDirection(face, uv);
            EXPECT_NEAR(glm::length(dir), 1.0f, 1e-5f);
            EXPECT_GT(glm::dot(dir, n), 0.0f) << "face " << face << " texel " << d;
            EXPECT_EQ(dvfTexel(face, dir), d) << "face " << face;
        }
    }
}

// dvf.invalidate widens an edit's cone by 0.32 rad for the texel's extent: no direction of a
// texel is further than that from its centre (the largest is ~0.303, at the diamond's corners).
TEST(DvfDirections, TexelsSpanLessThanTheInvalidationMargin) {
    for (std::uint32_t face = 0; face < 6; ++face) {
        for (std::uint32_t d = 0; d < 64; ++d) {
            const glm::vec3 centre = dvfDirection(
                face, glm::vec2((float(d % 8u) + 0.5f) / 8.0f, (float(d / 8u) + 0.5f) / 8.0f));
            for (int j = 0; j <= 16; ++j) {
                for (int i = 0; i <= 16; ++i) {
                    const glm::vec3 p =
                        dvfDirection(face, glm::vec2((float(d % 8u) + i / 16.0f) / 8.0f,
                                                     (float(d / 8u) + j / 16.0f) / 8.0f));
                    EXPECT_LE(std::acos(std::clamp(glm::dot(p, centre), -1.0f, 1.0f)), 0.32f)
                        << "face " << face << " texel " << d;
                }
            }
        }
    }
}
