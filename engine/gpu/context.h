// gpu::Context: the Vulkan instance, the chosen physical device (a real GPU if there is one,
// else lavapipe), the logical device with one compute queue, and the count of validation
// errors tests assert on. Only engine/gpu/ includes vulkan.h; the rest of the engine holds
// gpu:: objects.
//
// Headless by default. Given a window (ContextOptions::window) the context also owns the
// window's surface: it enables the instance extensions the window system needs, and picks a
// device and one queue family that computes, draws (the HUD) and presents to that surface,
// with VK_KHR_swapchain enabled.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vulkan/vulkan.h>

#include "core/error.h"

struct GLFWwindow;

namespace engine::gpu {

struct ContextOptions {
    // Validation layers: on in debug builds and tests; VOX_VALIDATION=0/1 overrides.
    bool validation = false;
    // Fail if validation was asked for but the layer is missing (tests must not pass vacuously).
    bool requireValidation = false;
    std::string applicationName = "vox";
    // Present to this window (gpu/window_surface.h creates its surface); null for headless.
    GLFWwindow* window = nullptr;
};

// Semaphores a submission waits on and signals (a swapchain image's acquire and present).
struct SubmitSync {
    VkSemaphore wait = VK_NULL_HANDLE;
    VkPipelineStageFlags waitStage = 0;
    VkSemaphore signal = VK_NULL_HANDLE;
};

struct DeviceInfo {
    std::string name;
    std::string driver;
    std::string type;  // "discrete GPU", "integrated GPU", "CPU", ...
    double timestampPeriodNs = 1.0;
    std::uint64_t maxStorageBufferRange = 0;
    // Texels a texel view may hold (gpu/texel_buffer_limit.h checks it): the device's, or lower
    // where VOX_MAX_TEXELS or Context::limitTexelBuffers asks (tests of the refusal).
    std::uint64_t maxTexelBufferElements = 0;
};

class Context {
public:
    static Result<std::unique_ptr<Context>> create(const ContextOptions& options = {});
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkInstance instance() const { return mInstance; }
    VkDevice device() const { return mDevice; }
    VkPhysicalDevice physicalDevice() const { return mPhysicalDevice; }
    VkQueue queue() const { return mQueue; }
    std::uint32_t queueFamily() const { return mQueueFamily; }
    VkCommandPool commandPool() const { return mCommandPool; }
    const DeviceInfo& info() const { return mInfo; }
    bool validationEnabled() const { return mValidation; }
    bool debugUtils() const { return mDebugUtils; }
    // The window's surface; VK_NULL_HANDLE for a headless context.
    VkSurfaceKHR surface() const { return mSurface; }

    // Validation errors seen so far (every message, warning or error, is printed to stderr).
    std::uint32_t validationErrors() const { return mValidationErrors.load(); }

    // Checks of texel views use min(the device's limit, texels) from now on; 0 restores the
    // device's limit. For tests of what a world over the limit does.
    void limitTexelBuffers(std::uint64_t texels);

    std::uint32_t findMemoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required,
                                 VkMemoryPropertyFlags preferred) const;
    void setObjectName(VkObjectType type, std::uint64_t handle, const char* name) const;

    // Incremented after every completed submission; pipelines recycle descriptor sets with it.
    std::uint64_t completedSubmissions() const { return mCompletedSubmissions; }
    void submitAndWait(VkCommandBuffer commandBuffer, const SubmitSync& sync = {});
    // Submits without waiting; `fence` signals when the GPU is done. The caller waits for it and
    // then calls countCompleted(), so completedSubmissions() only counts finished work.
    void submit(VkCommandBuffer commandBuffer, VkFence fence, const SubmitSync& sync = {});
    void countCompleted() { ++mCompletedSubmissions; }

private:
    Context() = default;
    Status init(const ContextOptions& options);
    // init's steps, in order (the window's surface is made between the instance and the device).
    Status createInstance(const ContextOptions& options);
    VkDebugUtilsMessengerCreateInfoEXT messengerCreateInfo();
    Status pickPhysicalDevice();
    void readDeviceInfo();
    Status createDevice();
    static VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(
        VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
        const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);

    VkInstance mInstance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT mMessenger = VK_NULL_HANDLE;
    VkSurfaceKHR mSurface = VK_NULL_HANDLE;
    VkPhysicalDevice mPhysicalDevice = VK_NULL_HANDLE;
    VkDevice mDevice = VK_NULL_HANDLE;
    VkQueue mQueue = VK_NULL_HANDLE;
    std::uint32_t mQueueFamily = 0;
    VkCommandPool mCommandPool = VK_NULL_HANDLE;
    VkFence mFence = VK_NULL_HANDLE;
    VkPhysicalDeviceMemoryProperties mMemoryProperties{};
    DeviceInfo mInfo;
    std::uint64_t mDeviceMaxTexelBufferElements = 0;
    bool mValidation = false;
    bool mDebugUtils = false;
    std::uint64_t mCompletedSubmissions = 0;
    std::atomic<std::uint32_t> mValidationErrors{0};
};

}  // namespace engine::gpu
