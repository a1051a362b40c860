#include "render/passes/compute_pass.h"

#include <vector>

#include "core/check.h"
#include "gpu/command_list.h"

namespace engine::render {

ComputePass::ComputePass(gpu::Context& ctx, std::string name, const std::string& shader, std::uint32_t bindingCount)
    : mName(std::move(name)), mBindingCount(bindingCount), mPipeline(ctx, shader, bindingCount) {}

void ComputePass::record(gpu::CommandList& cmd, std::span<const PassBinding> bindings, glm::uvec2 groups) {
    CHECK(bindings.size() == mBindingCount);
    std::vector<const gpu::Buffer*> buffers(mBindingCount, nullptr);
    for (const PassBinding& b : bindings) {
        CHECK(b.binding < mBindingCount && buffers[b.binding] == nullptr && b.buffer != nullptr);
        buffers[b.binding] = b.buffer;
    }
    cmd.beginPass(mName);
    if (groups.x > 0 && groups.y > 0) mPipeline.dispatch(cmd, buffers, groups.x, groups.y);
    cmd.endPass();
    cmd.barrier();
}

}  // namespace engine::render
