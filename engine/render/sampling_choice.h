// --sampling auto: power or ReGIR candidates, chosen per scene from what the emitter list says.
// ReGIR's cells keep the lights near them (shared/regir.h); that pays when the lights spread over
// many cells, so that most of the power a pixel's candidates are drawn from lies far from it and
// a power draw wastes its candidate (and its shadow ray) on a light that gives it nearly nothing.
// When the lights sit within a cell or two of each other, or are few, every cell would hold the
// same lights the alias table draws anyway; when each cell holds more lights than it has entries,
// its entries are a random few of them; either way the grid's build is pure cost. The evidence for
// the thresholds: `vox bench lights` and `vox bench restir --sampling power,regir`
// (docs/PERFORMANCE.md, "Light-count scaling").
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

#include "lighting/emitter_list.h"
#include "lighting/lighting_settings.h"
#include "shared/regir.h"

namespace engine::render {

struct SamplingFacts {
    std::uint32_t emitters = 0;
    // Power-weighted RMS distance of the emitters from their power-weighted centroid (voxels):
    // how far apart the light a scene holds lies, robust to a lone stray lamp.
    double spread = 0.0;
    double regirCell = 1.0;  // the edge of ReGIR's cell over this world (voxels)
    // Emitters per ReGIR cell that holds any (by their centres): how many lights a cell's
    // REGIR_CELL_ENTRIES entries would have to stand for.
    double perOccupiedCell = 0.0;
};

// Fewer emitters than this: a power draw of 32 candidates already sees most of them.
inline constexpr std::uint32_t kAutoRegirMinEmitters = 64;
// The lights' spread, in ReGIR cells, from which the grid's locality pays for its build.
inline constexpr double kAutoRegirMinSpreadCells = 2.0;
// More lights than a cell has entries (REGIR_CELL_ENTRIES) per occupied cell: the entries hold a
// random few of the many nearby lights, no better than a power draw, and the build is pure cost
// (`vox bench lights`: power wins or ties from ~33 lamps per cell up).
inline constexpr double kAutoRegirMaxPerCell = double(shared::REGIR_CELL_ENTRIES);

SamplingFacts samplingFacts(const lighting::EmitterList& emitters, glm::ivec3 worldVoxels,
                            const shared::RegirKnobs& regir);
bool autoChoosesRegir(const SamplingFacts& facts);
// `s` with --sampling auto replaced by its choice (power, or regir when `regir`); settings that
// name their sampling are returned as they are. Sampling stays uniform if `s` draws uniformly.
lighting::LightingSettings resolveSampling(lighting::LightingSettings s, bool regir);

}  // namespace engine::render
