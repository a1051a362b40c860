#include "gpu/timestamp_timer.h"

#include "core/check.h"
#include "gpu/context.h"
#include "gpu/vk_check.h"

namespace engine::gpu {

TimestampTimer::TimestampTimer(Context& ctx, std::uint32_t maxPasses)
    : mCtx(ctx), mMaxPasses(maxPasses) {
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = 4 * maxPasses;
    VK_CHECK(vkCreateQueryPool(ctx.device(), &info, nullptr, &mPool));
    ctx.setObjectName(VK_OBJECT_TYPE_QUERY_POOL, reinterpret_cast<std::uint64_t>(mPool),
                      "timestamps");
}

TimestampTimer::~TimestampTimer() { vkDestroyQueryPool(mCtx.device(), mPool, nullptr); }

void TimestampTimer::reset(VkCommandBuffer cmd) {
    vkCmdResetQueryPool(cmd, mPool, 0, 4 * mMaxPasses);
    mNames.clear();
}

// Queries per pass: begin, its settle stamp, end, its settle stamp.
//
// Why two stamps, both at BOTTOM_OF_PIPE: once a device has drawn anything (the sandbox's HUD
// render pass), lavapipe's llvmpipe no longer stamps a timestamp when the command runs but when
// it next flushes its binned scene, so the begin and end of a compute pass can collapse onto one
// flush and the pass reads ~0 ms while the next one absorbs its time. A BOTTOM_OF_PIPE write
// flushes before it is queued, so a second write right after it resolves the first one where it
// stands. On a real GPU this measures each pass after the previous one finished (no overlap
// counted twice) and the settle stamps cost nothing measurable.
void TimestampTimer::stamp(VkCommandBuffer cmd, std::uint32_t query) {
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, mPool, query);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, mPool, query + 1);
}

void TimestampTimer::begin(VkCommandBuffer cmd, const std::string& pass) {
    CHECK_MSG(mNames.size() < mMaxPasses, "too many timed passes (max %u)", mMaxPasses);
    stamp(cmd, 4 * static_cast<std::uint32_t>(mNames.size()));
    mNames.push_back(pass);
}

void TimestampTimer::end(VkCommandBuffer cmd) {
    stamp(cmd, 4 * static_cast<std::uint32_t>(mNames.size()) - 2);
}

std::vector<std::pair<std::string, double>> TimestampTimer::results() const {
    std::vector<std::pair<std::string, double>> out;
    if (mNames.empty()) return out;
    std::vector<std::uint64_t> ticks(4 * mNames.size());
    VK_CHECK(vkGetQueryPoolResults(
        mCtx.device(), mPool, 0, static_cast<std::uint32_t>(ticks.size()),
        ticks.size() * sizeof(std::uint64_t), ticks.data(), sizeof(std::uint64_t),
        VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    for (std::size_t i = 0; i < mNames.size(); ++i) {
        double ns =
            static_cast<double>(ticks[4 * i + 2] - ticks[4 * i]) * mCtx.info().timestampPeriodNs;
        out.emplace_back(mNames[i], ns * 1e-6);
    }
    return out;
}

}  // namespace engine::gpu
