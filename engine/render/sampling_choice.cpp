#include "render/sampling_choice.h"

#include <cmath>
#include <vector>

#include "render/regir/regir_grid.h"

namespace engine::render {

SamplingFacts samplingFacts(const lighting::EmitterList& emitters, glm::ivec3 worldVoxels,
                            const shared::RegirKnobs& regir) {
    SamplingFacts f;
    f.emitters = emitters.aliveCount();
    const shared::RegirGridInfo grid = regirGridFor(worldVoxels, regir);
    f.regirCell = grid.origin.w;
    // Two passes in double: 10^6 lamps of equal power sum without losing the small terms.
    double power = 0.0;
    glm::dvec3 centroid(0.0);
    for (std::uint32_t slot : emitters.aliveSlots()) {
        const shared::GpuEmitter& e = emitters.slots()[slot];
        const double p = e.radiance.w;
        centroid += p * (glm::dvec3(e.minCorner) + 0.5 * double(e.minCorner.w));
        power += p;
    }
    if (!(power > 0.0)) return f;
    centroid /= power;
    double moment = 0.0;
    std::vector<bool> occupied(grid.dims.w, false);
    std::uint32_t occupiedCells = 0;
    for (std::uint32_t slot : emitters.aliveSlots()) {
        const shared::GpuEmitter& e = emitters.slots()[slot];
        const glm::dvec3 p = glm::dvec3(e.minCorner) + 0.5 * double(e.minCorner.w);
        const glm::dvec3 d = p - centroid;
        moment += e.radiance.w * glm::dot(d, d);
        const std::uint32_t cell = shared::regirCellOf(grid, glm::vec3(p));
        if (cell < grid.dims.w && !occupied[cell]) {
            occupied[cell] = true;
            ++occupiedCells;
        }
    }
    f.spread = std::sqrt(moment / power);
    f.perOccupiedCell = occupiedCells ? double(f.emitters) / occupiedCells : 0.0;
    return f;
}

bool autoChoosesRegir(const SamplingFacts& f) {
    return f.emitters >= kAutoRegirMinEmitters &&
           f.spread >= kAutoRegirMinSpreadCells * f.regirCell &&
           f.perOccupiedCell <= kAutoRegirMaxPerCell;
}

lighting::LightingSettings resolveSampling(lighting::LightingSettings s, bool regir) {
    if (!s.autoSampling) return s;
    s.autoSampling = false;
    if (s.byPower && regir) s.regir.enabled = 1u;
    return s;
}

}  // namespace engine::render
