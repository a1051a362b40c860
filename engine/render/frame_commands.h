// FrameCommands: the command lists of one frame. Techniques record into current(); a technique
// whose host work can overlap the GPU (the irradiance cache picks its updates on the host) ends
// the first submission with submitAndContinue() and records the rest of the frame into a second
// list, so the host works while the GPU runs what was submitted. Each list has its own timer;
// passMs() joins their timings in submission order.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "gpu/command_list.h"
#include "gpu/timestamp_timer.h"

namespace engine::render {

class FrameCommands {
public:
    // Begins the first list. Every list dispatches with `specialization` (shader_features.h).
    FrameCommands(gpu::Context& ctx, gpu::TimestampTimer& firstTimer,
                  gpu::TimestampTimer& secondTimer, std::span<const std::uint32_t> specialization);

    gpu::CommandList& current() { return mContinued ? mSecond : mFirst; }
    // Submits what was recorded and begins the second list. `wait`: block until the first
    // submission completes, so the host can read what it wrote. Once per frame.
    gpu::CommandList& submitAndContinue(bool wait);
    // Submits the rest and waits for all of it.
    void finish();
    // GPU milliseconds per pass, both submissions, in order. After finish().
    std::vector<std::pair<std::string, double>> passMs() const;

private:
    gpu::CommandList mFirst, mSecond;
    gpu::TimestampTimer& mFirstTimer;
    gpu::TimestampTimer& mSecondTimer;
    bool mContinued = false;
    bool mFirstPending = false;  // submitted without waiting
};

}  // namespace engine::render
