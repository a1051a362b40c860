// Per-pass GPU timestamps: a query pool with a begin/end pair per named pass (each stamp written
// twice, see timestamp_timer.cpp for lavapipe), read back after the frame's submission completes.
#pragma once

#include <string>
#include <utility>
#include <vector>
#include <vulkan/vulkan.h>

namespace engine::gpu {

class Context;

class TimestampTimer {
public:
    TimestampTimer(Context& ctx, std::uint32_t maxPasses);
    ~TimestampTimer();
    TimestampTimer(const TimestampTimer&) = delete;
    TimestampTimer& operator=(const TimestampTimer&) = delete;

    void reset(VkCommandBuffer cmd);
    void begin(VkCommandBuffer cmd, const std::string& pass);
    void end(VkCommandBuffer cmd);
    // Milliseconds per pass, in recording order. Call after the submission has completed.
    std::vector<std::pair<std::string, double>> results() const;

private:
    void stamp(VkCommandBuffer cmd, std::uint32_t query);

    Context& mCtx;
    VkQueryPool mPool = VK_NULL_HANDLE;
    std::uint32_t mMaxPasses;
    std::vector<std::string> mNames;
};

}  // namespace engine::gpu
