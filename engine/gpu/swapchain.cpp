#include "gpu/swapchain.h"

#include <algorithm>

#include "core/check.h"
#include "core/log.h"
#include "gpu/vk_check.h"

namespace engine::gpu {

namespace {

// The renderer's LDR image is already sRGB-encoded and ImGui's colours are sRGB values, so a
// UNORM target shows both unchanged; an sRGB-only surface still works (the presenter then
// uploads into an sRGB image and the blit's decode/encode cancels out).
VkSurfaceFormatKHR chooseFormat(const std::vector<VkSurfaceFormatKHR>& formats) {
    for (VkFormat want : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM,
                          VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB}) {
        for (const VkSurfaceFormatKHR& f : formats) {
            if (f.format == want && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
        }
    }
    return formats.front();
}

// Mailbox keeps input latency low without tearing; FIFO is the one mode every driver has.
VkPresentModeKHR choosePresentMode(const std::vector<VkPresentModeKHR>& modes) {
    if (std::find(modes.begin(), modes.end(), VK_PRESENT_MODE_MAILBOX_KHR) != modes.end())
        return VK_PRESENT_MODE_MAILBOX_KHR;
    return VK_PRESENT_MODE_FIFO_KHR;
}

}  // namespace

Swapchain::Swapchain(Context& ctx, glm::uvec2 framebufferSize) : mCtx(ctx) {
    CHECK_MSG(ctx.surface() != VK_NULL_HANDLE, "Swapchain needs a windowed Context");
    VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VK_CHECK(vkCreateSemaphore(ctx.device(), &info, nullptr, &mAcquired));
    ctx.setObjectName(VK_OBJECT_TYPE_SEMAPHORE, reinterpret_cast<std::uint64_t>(mAcquired),
                      "swapchain.acquired");
    build(framebufferSize);
}

Swapchain::~Swapchain() {
    vkDeviceWaitIdle(mCtx.device());
    releaseImages();
    if (mSwapchain) vkDestroySwapchainKHR(mCtx.device(), mSwapchain, nullptr);
    vkDestroySemaphore(mCtx.device(), mAcquired, nullptr);
}

void Swapchain::releaseImages() {
    for (VkImageView v : mViews) vkDestroyImageView(mCtx.device(), v, nullptr);
    for (VkSemaphore s : mPresentReady) vkDestroySemaphore(mCtx.device(), s, nullptr);
    mViews.clear();
    mPresentReady.clear();
    mImages.clear();
}

void Swapchain::build(glm::uvec2 framebufferSize) {
    VkPhysicalDevice gpu = mCtx.physicalDevice();
    VkSurfaceKHR surface = mCtx.surface();
    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(gpu, surface, &caps));
    std::uint32_t count = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, surface, &count, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(count);
    vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, surface, &count, formats.data());
    CHECK_MSG(!formats.empty(), "the surface offers no formats");
    vkGetPhysicalDeviceSurfacePresentModesKHR(gpu, surface, &count, nullptr);
    std::vector<VkPresentModeKHR> modes(count);
    vkGetPhysicalDeviceSurfacePresentModesKHR(gpu, surface, &count, modes.data());

    VkExtent2D extent = caps.currentExtent;
    if (extent.width == UINT32_MAX) {  // the surface takes its size from the swapchain
        extent.width =
            std::clamp(framebufferSize.x, caps.minImageExtent.width, caps.maxImageExtent.width);
        extent.height =
            std::clamp(framebufferSize.y, caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    vkDeviceWaitIdle(mCtx.device());
    releaseImages();
    mExtent = extent;
    mOutOfDate = false;
    if (extent.width == 0 || extent.height == 0)
        return;  // minimised: build when it has an area again

    VkSurfaceFormatKHR format = chooseFormat(formats);
    mFormat = format.format;
    mColorSpace = format.colorSpace;
    mMinImageCount = std::max(2u, caps.minImageCount);
    std::uint32_t wanted = caps.minImageCount + 1;
    if (caps.maxImageCount > 0) wanted = std::min(wanted, caps.maxImageCount);

    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface;
    info.minImageCount = wanted;
    info.imageFormat = format.format;
    info.imageColorSpace = format.colorSpace;
    info.imageExtent = extent;
    info.imageArrayLayers = 1;
    // Transfer dst: the renderer's image is blitted in; colour attachment: the HUD; transfer
    // src: window screenshots.
    info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                      (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    info.presentMode = choosePresentMode(modes);
    info.clipped = VK_TRUE;
    info.oldSwapchain = mSwapchain;
    VkSwapchainKHR created;
    VK_CHECK(vkCreateSwapchainKHR(mCtx.device(), &info, nullptr, &created));
    if (mSwapchain) vkDestroySwapchainKHR(mCtx.device(), mSwapchain, nullptr);
    mSwapchain = created;

    vkGetSwapchainImagesKHR(mCtx.device(), mSwapchain, &count, nullptr);
    mImages.resize(count);
    vkGetSwapchainImagesKHR(mCtx.device(), mSwapchain, &count, mImages.data());
    for (std::uint32_t i = 0; i < count; ++i) {
        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = mImages[i];
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = mFormat;
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView v;
        VK_CHECK(vkCreateImageView(mCtx.device(), &view, nullptr, &v));
        mViews.push_back(v);
        VkSemaphoreCreateInfo semInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        VkSemaphore s;
        VK_CHECK(vkCreateSemaphore(mCtx.device(), &semInfo, nullptr, &s));
        mPresentReady.push_back(s);
        mCtx.setObjectName(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<std::uint64_t>(mImages[i]),
                           "swapchain.image");
    }
    ++mGeneration;
    log::info("swapchain {}x{}, {} images, format {}", extent.width, extent.height, count,
              static_cast<int>(mFormat));
}

bool Swapchain::acquire(glm::uvec2 framebufferSize) {
    if (framebufferSize.x == 0 || framebufferSize.y == 0) return false;
    if (mOutOfDate || mImages.empty() ||
        framebufferSize != glm::uvec2(mExtent.width, mExtent.height)) {
        build(framebufferSize);
        if (mImages.empty()) return false;
    }
    VkResult r = vkAcquireNextImageKHR(mCtx.device(), mSwapchain, UINT64_MAX, mAcquired,
                                       VK_NULL_HANDLE, &mImageIndex);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {
        mOutOfDate = true;
        return false;
    }
    if (r == VK_SUBOPTIMAL_KHR) {
        mOutOfDate = true;  // the semaphore is signalled: draw this frame, rebuild for the next
        return true;
    }
    VK_CHECK(r);
    return true;
}

void Swapchain::present() {
    VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    info.waitSemaphoreCount = 1;
    info.pWaitSemaphores = &mPresentReady[mImageIndex];
    info.swapchainCount = 1;
    info.pSwapchains = &mSwapchain;
    info.pImageIndices = &mImageIndex;
    VkResult r = vkQueuePresentKHR(mCtx.queue(), &info);
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) {
        mOutOfDate = true;
        return;
    }
    VK_CHECK(r);
}

SubmitSync Swapchain::submitSync() const {
    return {mAcquired, VK_PIPELINE_STAGE_TRANSFER_BIT, mPresentReady[mImageIndex]};
}

}  // namespace engine::gpu
