// The GPU context of a vox command, made one way: the benches' without validation layers (they
// would distort the timings), the image commands' with them in a debug build (a Vulkan mistake
// then fails the run).
#pragma once

#include <memory>

#include "core/error.h"

namespace engine::gpu {
class Context;
}

namespace vox {

// A bench's GPU: the default device and options.
engine::Result<std::unique_ptr<engine::gpu::Context>> createBenchGpu();
// The GPU of `vox render` and `vox capture`: validation layers on in a debug build.
engine::Result<std::unique_ptr<engine::gpu::Context>> createValidatedGpu();

// "device   NAME (TYPE, DRIVER)" on stdout.
void printDevice(const engine::gpu::Context& gpu);

}  // namespace vox
