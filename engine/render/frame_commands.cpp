#include "render/frame_commands.h"

#include "core/check.h"

namespace engine::render {

FrameCommands::FrameCommands(gpu::Context& ctx, gpu::TimestampTimer& firstTimer,
                             gpu::TimestampTimer& secondTimer,
                             std::span<const std::uint32_t> specialization)
    : mFirst(ctx, &firstTimer),
      mSecond(ctx, &secondTimer),
      mFirstTimer(firstTimer),
      mSecondTimer(secondTimer) {
    mFirst.setSpecialization(specialization);
    mSecond.setSpecialization(specialization);
    mFirst.begin();
}

gpu::CommandList& FrameCommands::submitAndContinue(bool wait) {
    CHECK(!mContinued);
    if (wait) {
        mFirst.submitAndWait();
    } else {
        mFirst.submit();
        mFirstPending = true;
    }
    mContinued = true;
    // The first submission ended with a barrier (gpu::CommandList), which orders its writes
    // before what the second reads of them.
    mSecond.begin();
    return mSecond;
}

void FrameCommands::finish() {
    current().submitAndWait();
    // Done already: the queue runs submissions in order.
    if (mFirstPending) mFirst.wait();
    mFirstPending = false;
}

std::vector<std::pair<std::string, double>> FrameCommands::passMs() const {
    std::vector<std::pair<std::string, double>> out = mFirstTimer.results();
    if (mContinued) {
        for (const auto& pass : mSecondTimer.results()) out.push_back(pass);
    }
    return out;
}

}  // namespace engine::render
