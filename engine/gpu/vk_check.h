// VK_CHECK: Vulkan calls that must not fail name their result, file and line, then abort.
// Failures a user can cause (no device, out of memory at startup) are reported as engine::Error
// by the code that can explain them instead.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <vulkan/vulkan.h>

namespace engine::gpu {
const char* resultName(VkResult result);
}

#define VK_CHECK(call)                                                                \
    do {                                                                              \
        VkResult vkCheckResult_ = (call);                                             \
        if (vkCheckResult_ != VK_SUCCESS) {                                           \
            std::fprintf(stderr, "%s:%d: %s failed: %s\n", __FILE__, __LINE__, #call, \
                         ::engine::gpu::resultName(vkCheckResult_));                  \
            std::abort();                                                             \
        }                                                                             \
    } while (0)
