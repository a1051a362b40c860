#include "gpu/imgui_overlay.h"

#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include "core/check.h"
#include "gpu/command_list.h"
#include "gpu/context.h"
#include "gpu/vk_check.h"

namespace engine::gpu {

namespace {
void checkImGuiResult(VkResult r) { VK_CHECK(r); }
}  // namespace

ImGuiOverlay::ImGuiOverlay(Context& ctx, VkFormat colorFormat, std::uint32_t minImageCount,
                           std::uint32_t imageCount)
    : mCtx(ctx) {
    CHECK_MSG(ImGui::GetCurrentContext() != nullptr, "create the ImGui context before the overlay");
    // Load the image the blit wrote; layouts stay COLOR_ATTACHMENT_OPTIMAL, the presenter's
    // barriers handle the transitions around the pass.
    VkAttachmentDescription color{};
    color.format = colorFormat;
    color.samples = VK_SAMPLE_COUNT_1_BIT;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &ref;
    VkRenderPassCreateInfo rp{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    rp.attachmentCount = 1;
    rp.pAttachments = &color;
    rp.subpassCount = 1;
    rp.pSubpasses = &subpass;
    VK_CHECK(vkCreateRenderPass(ctx.device(), &rp, nullptr, &mRenderPass));
    ctx.setObjectName(VK_OBJECT_TYPE_RENDER_PASS, reinterpret_cast<std::uint64_t>(mRenderPass),
                      "hud.renderPass");

    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 8};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    poolInfo.maxSets = 8;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &size;
    VK_CHECK(vkCreateDescriptorPool(ctx.device(), &poolInfo, nullptr, &mPool));

    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = ctx.instance();
    info.PhysicalDevice = ctx.physicalDevice();
    info.Device = ctx.device();
    info.QueueFamily = ctx.queueFamily();
    info.Queue = ctx.queue();
    info.DescriptorPool = mPool;
    info.MinImageCount = minImageCount;
    info.ImageCount = imageCount;
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = &checkImGuiResult;
    CHECK(ImGui_ImplVulkan_Init(&info, mRenderPass));

    CommandList cmd(ctx);
    cmd.begin();
    ImGui_ImplVulkan_CreateFontsTexture(cmd.handle());
    cmd.submitAndWait();
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

ImGuiOverlay::~ImGuiOverlay() {
    vkDeviceWaitIdle(mCtx.device());
    ImGui_ImplVulkan_Shutdown();
    releaseFramebuffers();
    vkDestroyDescriptorPool(mCtx.device(), mPool, nullptr);
    vkDestroyRenderPass(mCtx.device(), mRenderPass, nullptr);
}

void ImGuiOverlay::newFrame() { ImGui_ImplVulkan_NewFrame(); }

void ImGuiOverlay::releaseFramebuffers() {
    for (auto& [view, fb] : mFramebuffers) vkDestroyFramebuffer(mCtx.device(), fb, nullptr);
    mFramebuffers.clear();
}

void ImGuiOverlay::onSwapchainRebuilt(std::uint32_t minImageCount) {
    releaseFramebuffers();
    ImGui_ImplVulkan_SetMinImageCount(minImageCount);
}

VkFramebuffer ImGuiOverlay::framebuffer(VkImageView view, VkExtent2D extent) {
    auto it = mFramebuffers.find(view);
    if (it != mFramebuffers.end()) return it->second;
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = mRenderPass;
    info.attachmentCount = 1;
    info.pAttachments = &view;
    info.width = extent.width;
    info.height = extent.height;
    info.layers = 1;
    VkFramebuffer fb;
    VK_CHECK(vkCreateFramebuffer(mCtx.device(), &info, nullptr, &fb));
    mFramebuffers.emplace(view, fb);
    return fb;
}

void ImGuiOverlay::record(VkCommandBuffer cmd, VkImageView view, VkExtent2D extent,
                          ImDrawData* data) {
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = mRenderPass;
    begin.framebuffer = framebuffer(view, extent);
    begin.renderArea = {{0, 0}, extent};
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    if (data) ImGui_ImplVulkan_RenderDrawData(data, cmd);
    vkCmdEndRenderPass(cmd);
}

}  // namespace engine::gpu
