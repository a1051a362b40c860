#include "tool_gpu.h"

#include <cstdio>

#include "gpu/context.h"

namespace vox {

engine::Result<std::unique_ptr<engine::gpu::Context>> createBenchGpu() {
    return engine::gpu::Context::create({});
}

engine::Result<std::unique_ptr<engine::gpu::Context>> createValidatedGpu() {
    engine::gpu::ContextOptions options;
#ifndef NDEBUG
    options.validation = true;
#endif
    return engine::gpu::Context::create(options);
}

void printDevice(const engine::gpu::Context& gpu) {
    const auto& dev = gpu.info();
    std::printf("device   %s (%s, %s)\n", dev.name.c_str(), dev.type.c_str(), dev.driver.c_str());
}

}  // namespace vox
