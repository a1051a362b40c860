#include "gpu/window_surface.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "gpu/vk_check.h"

namespace engine::gpu {

std::vector<std::string> windowInstanceExtensions() {
    std::uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    std::vector<std::string> out;
    for (std::uint32_t i = 0; names && i < count; ++i) out.emplace_back(names[i]);
    return out;
}

Result<VkSurfaceKHR> createWindowSurface(VkInstance instance, GLFWwindow* window) {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    VkResult r = glfwCreateWindowSurface(instance, window, nullptr, &surface);
    if (r != VK_SUCCESS)
        return makeError("cannot create a Vulkan surface for the window ({})", resultName(r));
    return surface;
}

}  // namespace engine::gpu
