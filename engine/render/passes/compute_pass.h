// ComputePass: the one shape of every pass — a labelled, timed compute dispatch whose storage
// buffers are bound by number. A pass's Io struct lists its buffers with the binding numbers the
// shader side takes from shaders/shared/ (bindings()), so the count of bindings follows from the
// list and a buffer cannot land on another buffer's binding. ScreenPass runs one over the image;
// LitPass (lit_pass.h) adds the world and the emitter list in front. The technique passes
// (render/restir/, render/baselines/, render/reference/, render/irradiance_cache/) name their
// own buffers.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "gpu/compute_pipeline.h"

namespace engine::gpu {
class Buffer;
class CommandList;
class Context;
}  // namespace engine::gpu

namespace engine::render {

// One storage buffer at one binding number of set 0, and whether the pass writes it: an Io
// struct holds what a pass reads as `const gpu::Buffer&` and what it writes (or reads and
// writes) as `gpu::Buffer&`, and that constness is the declaration the barriers follow
// (gpu::CommandList::access).
struct PassBinding {
    constexpr PassBinding() = default;
    constexpr PassBinding(std::uint32_t b, const gpu::Buffer* read) : binding(b), buffer(read) {}
    constexpr PassBinding(std::uint32_t b, gpu::Buffer* written)
        : binding(b), buffer(written), writes(true) {}
    std::uint32_t binding = 0;
    const gpu::Buffer* buffer = nullptr;
    bool writes = false;
};

// The number of bindings an Io struct lists: the size of the array its bindings() returns.
template <class Io>
constexpr std::uint32_t bindingCount() {
    return static_cast<std::uint32_t>(
        std::tuple_size_v<decltype(std::declval<const Io&>().bindings())>);
}

// `a`'s bindings, then `b`'s.
template <std::size_t A, std::size_t B>
std::array<PassBinding, A + B> joinBindings(const std::array<PassBinding, A>& a,
                                            const std::array<PassBinding, B>& b) {
    std::array<PassBinding, A + B> out{};
    for (std::size_t i = 0; i < A; ++i) out[i] = a[i];
    for (std::size_t i = 0; i < B; ++i) out[A + i] = b[i];
    return out;
}

// Workgroups of 8x8 threads covering an image of `size` pixels.
inline glm::uvec2 screenGroups(glm::uvec2 size) { return (size + 7u) / 8u; }

class ComputePass {
public:
    // `shader` is the path under shaders/ without ".comp"; `name` labels and times the dispatch.
    ComputePass(gpu::Context& ctx, std::string name, const std::string& shader,
                std::uint32_t bindingCount);
    // Binds every buffer at its binding (each of 0..bindingCount-1 exactly once) and dispatches
    // `groups` workgroups; a zero count records only the label. The dispatch waits for the
    // earlier commands that wrote what it reads or touched what it writes (PassBinding::writes).
    void record(gpu::CommandList& cmd, std::span<const PassBinding> bindings, glm::uvec2 groups);
    // Several such dispatches, one after another (dispatch i binds series[i]), labelled and timed
    // as one pass: a frame's work split to fit lavapipe's loop budget (render/loop_budget.h).
    void recordSeries(gpu::CommandList& cmd, std::span<const std::vector<PassBinding>> series,
                      glm::uvec2 groups);
    // The same with the workgroup counts an earlier pass wrote into `args` at `offset` (three
    // uints): for work whose size only the GPU knows, such as the pixels a pass set aside.
    void recordIndirect(gpu::CommandList& cmd, std::span<const PassBinding> bindings,
                        const gpu::Buffer& args, std::uint64_t offset);

private:
    // The buffers by binding number, and which of them the pass writes.
    struct Bound {
        std::vector<const gpu::Buffer*> buffers;
        std::vector<std::uint8_t> writes;
    };
    Bound bound(std::span<const PassBinding> bindings) const;

    std::string mName;
    std::uint32_t mBindingCount;
    gpu::ComputePipeline mPipeline;
};

// A ComputePass over the image whose buffers are an Io struct's (see bindingCount): a pass that
// shades pixels derives from it and names only its label and shader.
template <class Io>
class ScreenPass {
public:
    ScreenPass(gpu::Context& ctx, std::string name, const std::string& shader)
        : mPass(ctx, std::move(name), shader, bindingCount<Io>()) {}
    void record(gpu::CommandList& cmd, const Io& io, glm::uvec2 size) {
        mPass.record(cmd, io.bindings(), screenGroups(size));
    }

private:
    ComputePass mPass;
};

}  // namespace engine::render
