// Walker's alias method (Vose's O(n) construction): draws index i with probability
// weight[i] / sum in O(1). Used for power-proportional emitter candidates.
#pragma once

#include <span>
#include <vector>

#include "shared/emitters.h"

namespace engine::lighting {

// entries[i] describes slot slots[i]; weights must be >= 0 with a positive sum (else empty).
std::vector<shared::AliasEntry> buildAliasTable(std::span<const std::uint32_t> slots,
                                                std::span<const double> weights);

}  // namespace engine::lighting
