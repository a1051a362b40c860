#include "gpu/context.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string_view>
#include <vector>

#include "core/log.h"
#include "gpu/vk_check.h"
#include "gpu/window_surface.h"

namespace engine::gpu {

const char* resultName(VkResult result) {
    switch (result) {
        case VK_SUCCESS:
            return "VK_SUCCESS";
        case VK_NOT_READY:
            return "VK_NOT_READY";
        case VK_TIMEOUT:
            return "VK_TIMEOUT";
        case VK_INCOMPLETE:
            return "VK_INCOMPLETE";
        case VK_ERROR_OUT_OF_HOST_MEMORY:
            return "VK_ERROR_OUT_OF_HOST_MEMORY";
        case VK_ERROR_OUT_OF_DEVICE_MEMORY:
            return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
        case VK_ERROR_INITIALIZATION_FAILED:
            return "VK_ERROR_INITIALIZATION_FAILED";
        case VK_ERROR_DEVICE_LOST:
            return "VK_ERROR_DEVICE_LOST";
        case VK_ERROR_MEMORY_MAP_FAILED:
            return "VK_ERROR_MEMORY_MAP_FAILED";
        case VK_ERROR_LAYER_NOT_PRESENT:
            return "VK_ERROR_LAYER_NOT_PRESENT";
        case VK_ERROR_EXTENSION_NOT_PRESENT:
            return "VK_ERROR_EXTENSION_NOT_PRESENT";
        case VK_ERROR_FEATURE_NOT_PRESENT:
            return "VK_ERROR_FEATURE_NOT_PRESENT";
        case VK_ERROR_INCOMPATIBLE_DRIVER:
            return "VK_ERROR_INCOMPATIBLE_DRIVER";
        case VK_ERROR_TOO_MANY_OBJECTS:
            return "VK_ERROR_TOO_MANY_OBJECTS";
        case VK_ERROR_FORMAT_NOT_SUPPORTED:
            return "VK_ERROR_FORMAT_NOT_SUPPORTED";
        case VK_ERROR_OUT_OF_POOL_MEMORY:
            return "VK_ERROR_OUT_OF_POOL_MEMORY";
        case VK_ERROR_SURFACE_LOST_KHR:
            return "VK_ERROR_SURFACE_LOST_KHR";
        case VK_ERROR_OUT_OF_DATE_KHR:
            return "VK_ERROR_OUT_OF_DATE_KHR";
        case VK_SUBOPTIMAL_KHR:
            return "VK_SUBOPTIMAL_KHR";
        default:
            return "VkResult (unnamed)";
    }
}

namespace {

bool envFlag(const char* name, bool fallback) {
    const char* v = std::getenv(name);
    if (!v || !*v) return fallback;
    return std::string_view(v) != "0";
}

bool hasLayer(const char* name) {
    std::uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) {
        return std::strcmp(l.layerName, name) == 0;
    });
}

bool hasInstanceExtension(const char* name) {
    std::uint32_t count = 0;
    vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> exts(count);
    vkEnumerateInstanceExtensionProperties(nullptr, &count, exts.data());
    return std::any_of(exts.begin(), exts.end(), [&](const VkExtensionProperties& e) {
        return std::strcmp(e.extensionName, name) == 0;
    });
}

const char* deviceTypeName(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            return "discrete GPU";
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            return "integrated GPU";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            return "virtual GPU";
        case VK_PHYSICAL_DEVICE_TYPE_CPU:
            return "CPU";
        default:
            return "other";
    }
}

bool hasDeviceExtension(VkPhysicalDevice device, const char* name) {
    std::uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> exts(count);
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, exts.data());
    return std::any_of(exts.begin(), exts.end(), [&](const VkExtensionProperties& e) {
        return std::strcmp(e.extensionName, name) == 0;
    });
}

// The queue family every submission goes to: compute with timestamps; when presenting, also
// graphics (the HUD is drawn with a render pass) and present support for the surface. One
// family for everything keeps ownership transfers out of the frame.
std::optional<std::uint32_t> pickQueueFamily(VkPhysicalDevice device, VkSurfaceKHR surface) {
    std::uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &familyCount, families.data());
    for (std::uint32_t i = 0; i < familyCount; ++i) {
        if (!(families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) || families[i].timestampValidBits == 0)
            continue;
        if (surface) {
            VkBool32 present = VK_FALSE;
            vkGetPhysicalDeviceSurfaceSupportKHR(device, i, surface, &present);
            if (!present || !(families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT)) continue;
        }
        return i;
    }
    return std::nullopt;
}

// Real GPUs first; lavapipe (a CPU device) is the fallback.
int deviceScore(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            return 4;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            return 3;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU:
            return 1;
        default:
            return 0;
    }
}

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

// Why the engine cannot run on a device (what it lacks), or nothing when it can. With a window
// the device must also present to its surface.
std::optional<std::string> unusableBecause(VkPhysicalDevice d,
                                           const VkPhysicalDeviceProperties& props,
                                           VkSurfaceKHR surface) {
    VkPhysicalDeviceVulkan12Features f12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    f2.pNext = &f12;
    vkGetPhysicalDeviceFeatures2(d, &f2);
    // ReSTIR's candidates are shared across a subgroup by shuffles
    // (restir/initial_candidates.comp).
    VkPhysicalDeviceSubgroupProperties subgroup{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
    VkPhysicalDeviceProperties2 props2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props2.pNext = &subgroup;
    vkGetPhysicalDeviceProperties2(d, &props2);
    const bool shuffles = (subgroup.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT) != 0 &&
                          (subgroup.supportedOperations & VK_SUBGROUP_FEATURE_SHUFFLE_BIT) != 0;
    const bool usable = props.apiVersion >= VK_API_VERSION_1_2 && f12.bufferDeviceAddress &&
                        f2.features.shaderInt64 && shuffles;
    if (!usable)
        return "needs Vulkan 1.2, bufferDeviceAddress, shaderInt64, subgroup shuffles in compute";
    if (surface &&
        (!hasDeviceExtension(d, VK_KHR_SWAPCHAIN_EXTENSION_NAME) || !pickQueueFamily(d, surface)))
        return "cannot present to the window";
    return std::nullopt;
}

}  // namespace

Result<std::unique_ptr<Context>> Context::create(const ContextOptions& options) {
    std::unique_ptr<Context> ctx(new Context());
    Status status = ctx->init(options);
    if (!status) return status.error();
    return ctx;
}

Status Context::init(const ContextOptions& options) {
    if (Status s = createInstance(options); !s) return s;
    if (options.window) {
        auto surface = createWindowSurface(mInstance, options.window);
        if (!surface) return surface.error();
        mSurface = *surface;
    }
    if (Status s = pickPhysicalDevice(); !s) return s;
    readDeviceInfo();
    if (Status s = createDevice(); !s) return s;
    log::info("Vulkan device: {} ({}, {}){}", mInfo.name, mInfo.type, mInfo.driver,
              mSurface ? ", presenting to a window" : "");
    return {};
}

// The instance with what was asked for: validation (when the layer is there), debug utils
// (when the loader has them) and the window system's surface extensions.
Status Context::createInstance(const ContextOptions& options) {
    mValidation = envFlag("VOX_VALIDATION", options.validation);
    if (mValidation && !hasLayer(kValidationLayer)) {
        if (options.requireValidation)
            return makeError(
                "Vulkan validation layer {} is not installed (apt-get install "
                "vulkan-validationlayers)",
                kValidationLayer);
        log::warn("validation requested but {} is not installed; continuing without it",
                  kValidationLayer);
        mValidation = false;
    }
    mDebugUtils = hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = options.applicationName.c_str();
    app.pEngineName = "voxengine";
    app.apiVersion = VK_API_VERSION_1_2;

    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    if (mValidation) layers.push_back(kValidationLayer);
    if (mDebugUtils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    std::vector<std::string> windowExtensions;
    if (options.window) {
        windowExtensions = windowInstanceExtensions();
        if (windowExtensions.empty())
            return makeError(
                "the window system offers no Vulkan surface (GLFW: Vulkan not supported)");
        for (const std::string& e : windowExtensions) {
            if (!hasInstanceExtension(e.c_str()))
                return makeError(
                    "the Vulkan loader lacks the instance extension {} needed to present to a "
                    "window",
                    e);
            extensions.push_back(e.c_str());
        }
    }

    const VkDebugUtilsMessengerCreateInfoEXT messengerInfo = messengerCreateInfo();
    // Synchronization validation catches missing barriers between passes. VOX_SYNC_VALIDATION=0
    // leaves it out (the rest of the layer stays on): its access history grows over thousands of
    // frames, which a memory soak test must not count as the engine's.
    VkValidationFeatureEnableEXT enables[] = {
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = envFlag("VOX_SYNC_VALIDATION", true) ? 1 : 0;
    features.pEnabledValidationFeatures = enables;
    if (mDebugUtils) features.pNext = &messengerInfo;

    VkInstanceCreateInfo instanceInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    instanceInfo.pApplicationInfo = &app;
    instanceInfo.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
    instanceInfo.ppEnabledLayerNames = layers.data();
    instanceInfo.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    instanceInfo.ppEnabledExtensionNames = extensions.data();
    if (mValidation) instanceInfo.pNext = &features;
    VkResult r = vkCreateInstance(&instanceInfo, nullptr, &mInstance);
    if (r != VK_SUCCESS)
        return makeError(
            "cannot create a Vulkan 1.2 instance ({}); is a Vulkan driver installed "
            "(apt-get install mesa-vulkan-drivers)?",
            resultName(r));

    if (mValidation && mDebugUtils) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(mInstance, "vkCreateDebugUtilsMessengerEXT"));
        if (create) VK_CHECK(create(mInstance, &messengerInfo, nullptr, &mMessenger));
    }
    return {};
}

// Validation warnings and errors of every type reach onValidationMessage, both while the
// instance is created (chained to its create info) and after (the messenger).
VkDebugUtilsMessengerCreateInfoEXT Context::messengerCreateInfo() {
    VkDebugUtilsMessengerCreateInfoEXT info{
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = &Context::onValidationMessage;
    info.pUserData = this;
    return info;
}

// The best-scoring usable device (VOX_DEVICE: a substring its name must contain); the error
// names every device turned down and why.
Status Context::pickPhysicalDevice() {
    std::uint32_t count = 0;
    vkEnumeratePhysicalDevices(mInstance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(mInstance, &count, devices.data());
    const char* wanted = std::getenv("VOX_DEVICE");
    int bestScore = -1;
    std::string rejected;
    for (VkPhysicalDevice d : devices) {
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(d, &props);
        if (std::optional<std::string> why = unusableBecause(d, props, mSurface)) {
            rejected += std::string(" ") + props.deviceName + " (" + *why + ");";
            continue;
        }
        if (wanted && !std::strstr(props.deviceName, wanted)) continue;
        int score = deviceScore(props.deviceType);
        if (score > bestScore) {
            bestScore = score;
            mPhysicalDevice = d;
        }
    }
    if (!mPhysicalDevice) {
        return makeError(
            "no usable Vulkan device{}{}{}", wanted ? " matching VOX_DEVICE=" : "",
            wanted ? wanted : "",
            rejected.empty() ? " (install mesa-vulkan-drivers for lavapipe)" : ":" + rejected);
    }
    return {};
}

// The chosen device's name, driver and limits (VOX_MAX_TEXELS lowers the texel limit) and its
// memory types.
void Context::readDeviceInfo() {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(mPhysicalDevice, &props);
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 props2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props2.pNext = &driver;
    vkGetPhysicalDeviceProperties2(mPhysicalDevice, &props2);
    mInfo.name = props.deviceName;
    mInfo.driver = driver.driverInfo;
    mInfo.type = deviceTypeName(props.deviceType);
    mInfo.timestampPeriodNs = props.limits.timestampPeriod;
    mInfo.maxStorageBufferRange = props.limits.maxStorageBufferRange;
    mDeviceMaxTexelBufferElements = props.limits.maxTexelBufferElements;
    mInfo.maxTexelBufferElements = mDeviceMaxTexelBufferElements;
    if (const char* v = std::getenv("VOX_MAX_TEXELS"); v && *v)
        limitTexelBuffers(std::strtoull(v, nullptr, 10));
    vkGetPhysicalDeviceMemoryProperties(mPhysicalDevice, &mMemoryProperties);
}

// The logical device with one queue (compute, timestamps, and presenting when there is a
// window), the features the engine uses, a command pool and a fence.
Status Context::createDevice() {
    std::optional<std::uint32_t> family = pickQueueFamily(mPhysicalDevice, mSurface);
    if (!family) return makeError("{}: no compute queue with timestamps", mInfo.name);
    mQueueFamily = *family;

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = mQueueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;

    VkPhysicalDeviceVulkan12Features enable12{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    enable12.bufferDeviceAddress = VK_TRUE;
    enable12.hostQueryReset = VK_TRUE;
    VkPhysicalDeviceFeatures2 enable{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    enable.pNext = &enable12;
    enable.features.shaderInt64 = VK_TRUE;

    VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    deviceInfo.pNext = &enable;
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    const char* swapchainExtension = VK_KHR_SWAPCHAIN_EXTENSION_NAME;
    if (mSurface) {
        deviceInfo.enabledExtensionCount = 1;
        deviceInfo.ppEnabledExtensionNames = &swapchainExtension;
    }
    VkResult r = vkCreateDevice(mPhysicalDevice, &deviceInfo, nullptr, &mDevice);
    if (r != VK_SUCCESS)
        return makeError("{}: cannot create the Vulkan device ({})", mInfo.name, resultName(r));
    vkGetDeviceQueue(mDevice, mQueueFamily, 0, &mQueue);

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = mQueueFamily;
    VK_CHECK(vkCreateCommandPool(mDevice, &poolInfo, nullptr, &mCommandPool));
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(mDevice, &fenceInfo, nullptr, &mFence));
    return {};
}

Context::~Context() {
    if (mDevice) {
        vkDeviceWaitIdle(mDevice);
        vkDestroyFence(mDevice, mFence, nullptr);
        vkDestroyCommandPool(mDevice, mCommandPool, nullptr);
        vkDestroyDevice(mDevice, nullptr);
    }
    if (mSurface) vkDestroySurfaceKHR(mInstance, mSurface, nullptr);
    if (mMessenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(mInstance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(mInstance, mMessenger, nullptr);
    }
    if (mInstance) vkDestroyInstance(mInstance, nullptr);
}

std::uint32_t Context::findMemoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required,
                                      VkMemoryPropertyFlags preferred) const {
    for (VkMemoryPropertyFlags want : {required | preferred, required}) {
        for (std::uint32_t i = 0; i < mMemoryProperties.memoryTypeCount; ++i) {
            if ((typeBits & (1u << i)) &&
                (mMemoryProperties.memoryTypes[i].propertyFlags & want) == want)
                return i;
        }
    }
    return UINT32_MAX;
}

void Context::setObjectName(VkObjectType type, std::uint64_t handle, const char* name) const {
    if (!mDebugUtils || !name) return;
    static auto setName = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(mInstance, "vkSetDebugUtilsObjectNameEXT"));
    if (!setName) return;
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = name;
    setName(mDevice, &info);
}

void Context::submitAndWait(VkCommandBuffer commandBuffer, const SubmitSync& sync) {
    submit(commandBuffer, mFence, sync);
    VK_CHECK(vkWaitForFences(mDevice, 1, &mFence, VK_TRUE, UINT64_MAX));
    VK_CHECK(vkResetFences(mDevice, 1, &mFence));
    countCompleted();
}

void Context::submit(VkCommandBuffer commandBuffer, VkFence fence, const SubmitSync& sync) {
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commandBuffer;
    if (sync.wait) {
        submit.waitSemaphoreCount = 1;
        submit.pWaitSemaphores = &sync.wait;
        submit.pWaitDstStageMask = &sync.waitStage;
    }
    if (sync.signal) {
        submit.signalSemaphoreCount = 1;
        submit.pSignalSemaphores = &sync.signal;
    }
    VK_CHECK(vkQueueSubmit(mQueue, 1, &submit, fence));
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::onValidationMessage(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* self = static_cast<Context*>(user);
    if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
        ++self->mValidationErrors;
        std::fprintf(stderr, "[vulkan validation error] %s\n", data->pMessage);
    } else {
        std::fprintf(stderr, "[vulkan validation warning] %s\n", data->pMessage);
    }
    return VK_FALSE;
}

void Context::limitTexelBuffers(std::uint64_t texels) {
    mInfo.maxTexelBufferElements = texels == 0 ? mDeviceMaxTexelBufferElements
                                               : std::min(texels, mDeviceMaxTexelBufferElements);
}

}  // namespace engine::gpu
