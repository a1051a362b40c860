// The bridge between a GLFW window (owned by game/window.h) and Vulkan: which instance
// extensions presenting needs, and the window's VkSurfaceKHR. Kept here so that only
// engine/gpu/ sees Vulkan types; the game hands over an opaque GLFWwindow*.
#pragma once

#include <string>
#include <vector>
#include <vulkan/vulkan.h>

#include "core/error.h"

struct GLFWwindow;

namespace engine::gpu {

// Instance extensions GLFW needs for surfaces on this system; empty when it cannot present.
std::vector<std::string> windowInstanceExtensions();
Result<VkSurfaceKHR> createWindowSurface(VkInstance instance, GLFWwindow* window);

}  // namespace engine::gpu
