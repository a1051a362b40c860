#include "render/passes/compute_pass.h"

#include <vector>

#include "core/check.h"
#include "gpu/command_list.h"

namespace engine::render {

ComputePass::ComputePass(gpu::Context& ctx, std::string name, const std::string& shader,
                         std::uint32_t bindingCount)
    : mName(std::move(name)), mBindingCount(bindingCount), mPipeline(ctx, shader, bindingCount) {}

ComputePass::Bound ComputePass::bound(std::span<const PassBinding> bindings) const {
    CHECK(bindings.size() == mBindingCount);
    Bound out{std::vector<const gpu::Buffer*>(mBindingCount, nullptr),
              std::vector<std::uint8_t>(mBindingCount, 0)};
    for (const PassBinding& b : bindings) {
        CHECK(b.binding < mBindingCount && out.buffers[b.binding] == nullptr &&
              b.buffer != nullptr);
        out.buffers[b.binding] = b.buffer;
        out.writes[b.binding] = b.writes ? 1 : 0;
    }
    return out;
}

void ComputePass::recordIndirect(gpu::CommandList& cmd, std::span<const PassBinding> bindings,
                                 const gpu::Buffer& args, std::uint64_t offset) {
    const Bound b = bound(bindings);
    cmd.beginPass(mName);
    mPipeline.dispatchIndirect(cmd, b.buffers, args, offset, b.writes);
    cmd.endPass();
}

void ComputePass::record(gpu::CommandList& cmd, std::span<const PassBinding> bindings,
                         glm::uvec2 groups) {
    const Bound b = bound(bindings);
    cmd.beginPass(mName);
    if (groups.x > 0 && groups.y > 0)
        mPipeline.dispatch(cmd, b.buffers, groups.x, groups.y, 1, b.writes);
    cmd.endPass();
}

void ComputePass::recordSeries(gpu::CommandList& cmd,
                               std::span<const std::vector<PassBinding>> series,
                               glm::uvec2 groups) {
    cmd.beginPass(mName);
    for (const std::vector<PassBinding>& bindings : series) {
        const Bound b = bound(bindings);
        if (groups.x > 0 && groups.y > 0)
            mPipeline.dispatch(cmd, b.buffers, groups.x, groups.y, 1, b.writes);
    }
    cmd.endPass();
}

}  // namespace engine::render
