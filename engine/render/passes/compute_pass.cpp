#include "render/passes/compute_pass.h"

#include <vector>

#include "core/check.h"
#include "gpu/command_list.h"

namespace engine::render {

ComputePass::ComputePass(gpu::Context& ctx, std::string name, const std::string& shader, std::uint32_t bindingCount)
    : mName(std::move(name)), mBindingCount(bindingCount), mPipeline(ctx, shader, bindingCount) {}

std::vector<const gpu::Buffer*> ComputePass::bound(std::span<const PassBinding> bindings) const {
    CHECK(bindings.size() == mBindingCount);
    std::vector<const gpu::Buffer*> buffers(mBindingCount, nullptr);
    for (const PassBinding& b : bindings) {
        CHECK(b.binding < mBindingCount && buffers[b.binding] == nullptr && b.buffer != nullptr);
        buffers[b.binding] = b.buffer;
    }
    return buffers;
}

void ComputePass::recordIndirect(gpu::CommandList& cmd, std::span<const PassBinding> bindings, const gpu::Buffer& args,
                                 std::uint64_t offset) {
    const std::vector<const gpu::Buffer*> buffers = bound(bindings);
    cmd.beginPass(mName);
    mPipeline.dispatchIndirect(cmd, buffers, args, offset);
    cmd.endPass();
    cmd.barrier();
}

void ComputePass::record(gpu::CommandList& cmd, std::span<const PassBinding> bindings, glm::uvec2 groups) {
    const std::vector<const gpu::Buffer*> buffers = bound(bindings);
    cmd.beginPass(mName);
    if (groups.x > 0 && groups.y > 0) mPipeline.dispatch(cmd, buffers, groups.x, groups.y);
    cmd.endPass();
    cmd.barrier();
}

}  // namespace engine::render
