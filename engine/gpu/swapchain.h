// gpu::Swapchain: the window's presentable images (VK_KHR_swapchain on Context::surface()).
//
// One frame in flight: a frame's submission waits on the acquire semaphore and signals the
// image's present semaphore, and the CPU waits for the submission (Context::submitAndWait)
// before the next acquire, so one acquire semaphore suffices. Present semaphores are per image:
// the presentation engine may still hold the previous image's. The chain is rebuilt when the
// window's size changes or the surface reports it out of date.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>
#include <vulkan/vulkan.h>

#include "gpu/context.h"

namespace engine::gpu {

class Swapchain {
public:
    Swapchain(Context& ctx, glm::uvec2 framebufferSize);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // Acquires the next image, rebuilding the chain first if the window was resized. False when
    // no image can be drawn this frame (a minimised window, or a rebuild): skip the frame.
    bool acquire(glm::uvec2 framebufferSize);
    // Queues the acquired image for display once the frame's submission has signalled.
    void present();

    VkImage image() const { return mImages[mImageIndex]; }
    VkImageView view() const { return mViews[mImageIndex]; }
    VkFormat format() const { return mFormat; }
    VkExtent2D extent() const { return mExtent; }
    std::uint32_t imageCount() const { return static_cast<std::uint32_t>(mImages.size()); }
    std::uint32_t minImageCount() const { return mMinImageCount; }
    // Changes whenever the images (and views) were recreated.
    std::uint64_t generation() const { return mGeneration; }
    // The wait/signal pair for the submission that draws into the acquired image.
    SubmitSync submitSync() const;

private:
    void build(glm::uvec2 framebufferSize);
    void releaseImages();

    Context& mCtx;
    VkSwapchainKHR mSwapchain = VK_NULL_HANDLE;
    VkFormat mFormat = VK_FORMAT_UNDEFINED;
    VkColorSpaceKHR mColorSpace = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    VkExtent2D mExtent{0, 0};
    std::uint32_t mMinImageCount = 2;
    std::vector<VkImage> mImages;
    std::vector<VkImageView> mViews;
    std::vector<VkSemaphore> mPresentReady;
    VkSemaphore mAcquired = VK_NULL_HANDLE;
    std::uint32_t mImageIndex = 0;
    std::uint64_t mGeneration = 0;
    bool mOutOfDate = false;
};

}  // namespace engine::gpu
