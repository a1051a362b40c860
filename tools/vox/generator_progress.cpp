#include "generator_progress.h"

#include <chrono>
#include <memory>
#include <string>

#include "core/progress.h"
#include "progress_line.h"

namespace vox {

namespace {

struct Task {
    std::string name;
    std::chrono::steady_clock::time_point start;
    std::unique_ptr<ProgressLine> line;
};
Task gTask;

void onProgress(std::string_view task, std::uint64_t done, std::uint64_t total) {
    const auto now = std::chrono::steady_clock::now();
    if (gTask.name != task) {
        // The line starts with the task (for its rate and ETA) but prints only after a second.
        gTask = {std::string(task), now,
                 std::make_unique<ProgressLine>(std::string(task), total, "step")};
    }
    const bool shown = now - gTask.start > std::chrono::seconds(1);
    if (shown) gTask.line->update(done);
    if (done >= total) {
        if (shown) gTask.line->finish();
        gTask = {};
    }
}

}  // namespace

void showLongProgress() { engine::setProgressSink(onProgress); }

}  // namespace vox
