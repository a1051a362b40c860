#include "lighting/alias_table.h"

#include <numeric>

#include "core/check.h"

namespace engine::lighting {

std::vector<shared::AliasEntry> buildAliasTable(std::span<const std::uint32_t> slots,
                                                std::span<const double> weights) {
    CHECK(slots.size() == weights.size());
    const std::size_t n = weights.size();
    const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
    std::vector<shared::AliasEntry> table(n);
    if (n == 0 || !(total > 0.0)) return {};
    std::vector<double> scaled(n);
    std::vector<std::uint32_t> small, large;
    for (std::size_t i = 0; i < n; ++i) {
        scaled[i] = weights[i] * double(n) / total;
        (scaled[i] < 1.0 ? small : large).push_back(static_cast<std::uint32_t>(i));
        table[i] = {1.0f, slots[i], slots[i], static_cast<float>(weights[i] / total)};
    }
    while (!small.empty() && !large.empty()) {
        std::uint32_t s = small.back(), l = large.back();
        small.pop_back();
        table[s].probability = static_cast<float>(scaled[s]);
        table[s].alias = slots[l];
        scaled[l] = (scaled[l] + scaled[s]) - 1.0;
        if (scaled[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // Leftovers are 1 up to rounding.
    for (std::uint32_t i : small) table[i].probability = 1.0f;
    for (std::uint32_t i : large) table[i].probability = 1.0f;
    return table;
}

}  // namespace engine::lighting
