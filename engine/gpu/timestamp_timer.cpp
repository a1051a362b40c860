#include "gpu/timestamp_timer.h"

#include "core/check.h"
#include "gpu/context.h"
#include "gpu/vk_check.h"

namespace engine::gpu {

TimestampTimer::TimestampTimer(Context& ctx, std::uint32_t maxPasses) : mCtx(ctx), mMaxPasses(maxPasses) {
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = 2 * maxPasses;
    VK_CHECK(vkCreateQueryPool(ctx.device(), &info, nullptr, &mPool));
    ctx.setObjectName(VK_OBJECT_TYPE_QUERY_POOL, reinterpret_cast<std::uint64_t>(mPool), "timestamps");
}

TimestampTimer::~TimestampTimer() { vkDestroyQueryPool(mCtx.device(), mPool, nullptr); }

void TimestampTimer::reset(VkCommandBuffer cmd) {
    vkCmdResetQueryPool(cmd, mPool, 0, 2 * mMaxPasses);
    mNames.clear();
}

void TimestampTimer::begin(VkCommandBuffer cmd, const std::string& pass) {
    CHECK_MSG(mNames.size() < mMaxPasses, "too many timed passes (max %u)", mMaxPasses);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, mPool, 2 * static_cast<std::uint32_t>(mNames.size()));
    mNames.push_back(pass);
}

void TimestampTimer::end(VkCommandBuffer cmd) {
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, mPool,
                        2 * static_cast<std::uint32_t>(mNames.size()) - 1);
}

std::vector<std::pair<std::string, double>> TimestampTimer::results() const {
    std::vector<std::pair<std::string, double>> out;
    if (mNames.empty()) return out;
    std::vector<std::uint64_t> ticks(2 * mNames.size());
    VK_CHECK(vkGetQueryPoolResults(mCtx.device(), mPool, 0, static_cast<std::uint32_t>(ticks.size()),
                                   ticks.size() * sizeof(std::uint64_t), ticks.data(), sizeof(std::uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    for (std::size_t i = 0; i < mNames.size(); ++i) {
        double ns = static_cast<double>(ticks[2 * i + 1] - ticks[2 * i]) * mCtx.info().timestampPeriodNs;
        out.emplace_back(mNames[i], ns * 1e-6);
    }
    return out;
}

}  // namespace engine::gpu
