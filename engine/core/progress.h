// Progress of long CPU work (world generators, store imports and exports) for whoever shows it:
// `vox` prints a progress line on stderr once a task has run for a second, so a generator of a
// million lamps is not a silent minute. Without a sink a report costs a load and a branch.
#pragma once

#include <cstdint>
#include <string_view>

namespace engine {

using ProgressSink = void (*)(std::string_view task, std::uint64_t done, std::uint64_t total);

void setProgressSink(ProgressSink sink);
// `done` of `total` units of `task` (a label that reads as a line: "generating lamps");
// report done == total at the end.
void reportProgress(std::string_view task, std::uint64_t done, std::uint64_t total);

}  // namespace engine
