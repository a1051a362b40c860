#include "gpu/presenter.h"

#include <algorithm>
#include <cstring>

#include "core/check.h"
#include "gpu/command_list.h"
#include "gpu/imgui_overlay.h"
#include "gpu/swapchain.h"
#include "gpu/vk_check.h"

namespace engine::gpu {

namespace {

bool isSrgb(VkFormat f) { return f == VK_FORMAT_B8G8R8A8_SRGB || f == VK_FORMAT_R8G8B8A8_SRGB; }
bool isBgra(VkFormat f) { return f == VK_FORMAT_B8G8R8A8_SRGB || f == VK_FORMAT_B8G8R8A8_UNORM; }

void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                  VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                  VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.oldLayout = from;
    b.newLayout = to;
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

}  // namespace

Presenter::Presenter(Context& ctx, glm::uvec2 framebufferSize, bool overlay) : mCtx(ctx) {
    mSwapchain = std::make_unique<Swapchain>(ctx, framebufferSize);
    mSwapchainGeneration = mSwapchain->generation();
    if (overlay) {
        // The render pass depends only on the format, which a rebuild keeps.
        VkFormat format = mSwapchain->format() != VK_FORMAT_UNDEFINED ? mSwapchain->format()
                                                                      : VK_FORMAT_B8G8R8A8_UNORM;
        mOverlay = std::make_unique<ImGuiOverlay>(
            ctx, format, mSwapchain->minImageCount(),
            std::max(mSwapchain->imageCount(), mSwapchain->minImageCount()));
    }
}

Presenter::~Presenter() {
    vkDeviceWaitIdle(mCtx.device());
    mOverlay.reset();
    releaseSourceImage();
    mSwapchain.reset();
}

void Presenter::releaseSourceImage() {
    if (mSource) vkDestroyImage(mCtx.device(), mSource, nullptr);
    if (mSourceMemory) vkFreeMemory(mCtx.device(), mSourceMemory, nullptr);
    mSource = VK_NULL_HANDLE;
    mSourceMemory = VK_NULL_HANDLE;
    mSourceSize = glm::uvec2(0);
}

void Presenter::ensureSourceImage(glm::uvec2 size) {
    if (mSource && mSourceSize == size) return;
    vkDeviceWaitIdle(mCtx.device());
    releaseSourceImage();
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    // Same encoding as the swapchain, so the blit does not re-encode the sRGB values.
    info.format = isSrgb(mSwapchain->format()) ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
    info.extent = {size.x, size.y, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VK_CHECK(vkCreateImage(mCtx.device(), &info, nullptr, &mSource));
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(mCtx.device(), mSource, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex =
        mCtx.findMemoryType(req.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    CHECK(alloc.memoryTypeIndex != UINT32_MAX);
    VK_CHECK(vkAllocateMemory(mCtx.device(), &alloc, nullptr, &mSourceMemory));
    VK_CHECK(vkBindImageMemory(mCtx.device(), mSource, mSourceMemory, 0));
    mCtx.setObjectName(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<std::uint64_t>(mSource),
                       "present.source");
    mSourceSize = size;
}

bool Presenter::beginFrame(glm::uvec2 framebufferSize) {
    CHECK(!mFrameOpen);
    if (!mSwapchain->acquire(framebufferSize)) return false;
    if (mSwapchain->generation() != mSwapchainGeneration) {
        mSwapchainGeneration = mSwapchain->generation();
        if (mOverlay) mOverlay->onSwapchainRebuilt(mSwapchain->minImageCount());
    }
    if (mOverlay) mOverlay->newFrame();
    mFrameOpen = true;
    return true;
}

void Presenter::record(CommandList& cmd, const Buffer& ldr, glm::uvec2 ldrSize) {
    CHECK_MSG(mFrameOpen, "Presenter::record without beginFrame");
    ensureSourceImage(ldrSize);
    VkCommandBuffer c = cmd.handle();
    VkImage target = mSwapchain->image();
    VkExtent2D extent = mSwapchain->extent();
    cmd.beginPass("present");

    // LDR buffer -> source image. The barrier that ends the frame's submission (CommandList) made
    // the buffer readable by transfers; the previous frame's blit read the image, hence the
    // transfer source stage.
    imageBarrier(c, mSource, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                 VK_ACCESS_TRANSFER_WRITE_BIT);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {ldrSize.x, ldrSize.y, 1};
    vkCmdCopyBufferToImage(c, ldr.handle(), mSource, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                           &copy);
    imageBarrier(c, mSource, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                 VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                 VK_ACCESS_TRANSFER_READ_BIT);

    // Source -> window image, scaled. The acquire semaphore is waited on at the transfer stage.
    imageBarrier(c, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                 VK_ACCESS_TRANSFER_WRITE_BIT);
    VkImageBlit blit{};
    blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.srcOffsets[1] = {static_cast<std::int32_t>(ldrSize.x),
                          static_cast<std::int32_t>(ldrSize.y), 1};
    blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.dstOffsets[1] = {static_cast<std::int32_t>(extent.width),
                          static_cast<std::int32_t>(extent.height), 1};
    vkCmdBlitImage(c, mSource, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_NEAREST);

    VkImageLayout layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    VkPipelineStageFlags stage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    VkAccessFlags access = VK_ACCESS_TRANSFER_WRITE_BIT;
    if (mOverlay) {
        imageBarrier(c, target, layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, stage, access,
                     VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
        mOverlay->record(c, mSwapchain->view(), extent, mOverlayData);
        layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        stage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
        access = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    }

    mCaptureRecorded = false;
    if (mCaptureRequested) {
        std::uint64_t bytes = std::uint64_t(extent.width) * extent.height * 4u;
        if (!mCaptureBuffer.valid() || mCaptureBuffer.size() < bytes)
            mCaptureBuffer = Buffer(mCtx, BufferKind::Readback, bytes, "present.capture");
        imageBarrier(c, target, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, stage, access,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
        VkBufferImageCopy back{};
        back.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        back.imageExtent = {extent.width, extent.height, 1};
        vkCmdCopyImageToBuffer(c, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               mCaptureBuffer.handle(), 1, &back);
        VkBufferMemoryBarrier host{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
        host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        host.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        host.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        host.buffer = mCaptureBuffer.handle();
        host.size = VK_WHOLE_SIZE;
        vkCmdPipelineBarrier(c, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0,
                             nullptr, 1, &host, 0, nullptr);
        layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        stage = VK_PIPELINE_STAGE_TRANSFER_BIT;
        access = 0;  // reads need no availability
        mCaptureRecorded = true;
        mCaptureRequested = false;
    }
    // Presentation needs no access mask: the present semaphore orders it after the submission.
    imageBarrier(c, target, layout, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, stage, access,
                 VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
    cmd.endPass();
}

SubmitSync Presenter::submitSync() const { return mSwapchain->submitSync(); }

void Presenter::endFrame() {
    CHECK(mFrameOpen);
    mFrameOpen = false;
    mSwapchain->present();
    mOverlayData = nullptr;
    if (mCaptureRecorded) {
        VkExtent2D extent = mSwapchain->extent();
        mCapture.width = extent.width;
        mCapture.height = extent.height;
        mCapture.rgba8.resize(std::size_t(extent.width) * extent.height);
        std::memcpy(mCapture.rgba8.data(), mCaptureBuffer.mapped(), mCapture.rgba8.size() * 4u);
        if (isBgra(mSwapchain->format())) {
            for (std::uint32_t& p : mCapture.rgba8)
                p = (p & 0xFF00FF00u) | ((p >> 16) & 0xFFu) | ((p & 0xFFu) << 16);
        }
        mCaptureRecorded = false;
    }
}

}  // namespace engine::gpu
