// The median the benches report: the upper middle value for an even count (not the mean of the
// middle two, as metrics/seed_statistics.h's is), 0 for none.
#pragma once

#include <algorithm>
#include <vector>

namespace vox {

inline double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace vox
