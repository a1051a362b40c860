// gpu::ImGuiOverlay: draws Dear ImGui's draw lists (the HUD, built by game/hud.h with ImGui's
// core API) over a swapchain image, through ImGui's own Vulkan backend. The game creates the
// ImGui context before this and destroys it after.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vulkan/vulkan.h>

struct ImDrawData;

namespace engine::gpu {

class Context;

class ImGuiOverlay {
public:
    ImGuiOverlay(Context& ctx, VkFormat colorFormat, std::uint32_t minImageCount,
                 std::uint32_t imageCount);
    ~ImGuiOverlay();
    ImGuiOverlay(const ImGuiOverlay&) = delete;
    ImGuiOverlay& operator=(const ImGuiOverlay&) = delete;

    void newFrame();
    // Draws `data` onto `view` (COLOR_ATTACHMENT_OPTIMAL before and after; contents kept).
    void record(VkCommandBuffer cmd, VkImageView view, VkExtent2D extent, ImDrawData* data);
    // The swapchain's views were recreated: drop framebuffers that point at the old ones.
    void onSwapchainRebuilt(std::uint32_t minImageCount);

private:
    VkFramebuffer framebuffer(VkImageView view, VkExtent2D extent);
    void releaseFramebuffers();

    Context& mCtx;
    VkRenderPass mRenderPass = VK_NULL_HANDLE;
    VkDescriptorPool mPool = VK_NULL_HANDLE;
    std::unordered_map<VkImageView, VkFramebuffer> mFramebuffers;
};

}  // namespace engine::gpu
