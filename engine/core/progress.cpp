#include "core/progress.h"

#include <atomic>

namespace engine {

namespace {
std::atomic<ProgressSink> gSink{nullptr};
}

void setProgressSink(ProgressSink sink) { gSink.store(sink, std::memory_order_relaxed); }

void reportProgress(std::string_view task, std::uint64_t done, std::uint64_t total) {
    if (ProgressSink sink = gSink.load(std::memory_order_relaxed)) sink(task, done, total);
}

}  // namespace engine
