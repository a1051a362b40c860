// gpu::Presenter: puts a frame in a window. The renderer's LDR buffer (packed RGBA8, render
// resolution) is copied into an image and blitted, scaled with nearest filtering, onto the
// acquired swapchain image; the ImGui overlay is drawn on top; the image is presented. The
// render resolution is independent of the window's, so a slow device can render a fraction of
// the pixels and still fill the window.
//
// Per frame: beginFrame() acquires; Renderer::render(..., &presenter) records the present
// pass into the frame's command list, submits with submitSync() and calls endFrame().
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/context.h"

struct ImDrawData;

namespace engine::gpu {

class CommandList;
class ImGuiOverlay;
class Swapchain;

// A presented window image, RGBA8 with R in the low byte (as the renderer's LDR image).
struct WindowCapture {
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint32_t> rgba8;
};

class Presenter {
public:
    // With `overlay`, an ImGui context must exist already (see ImGuiOverlay).
    Presenter(Context& ctx, glm::uvec2 framebufferSize, bool overlay);
    ~Presenter();
    Presenter(const Presenter&) = delete;
    Presenter& operator=(const Presenter&) = delete;

    // Acquires a window image; false when nothing can be shown this frame (minimised window,
    // swapchain rebuilt): skip rendering it.
    bool beginFrame(glm::uvec2 framebufferSize);
    // ImGui's draw data for this frame (or null: no overlay).
    void setOverlay(ImDrawData* data) { mOverlayData = data; }
    // Copies the presented image (with the overlay) back after this frame.
    void captureThisFrame() { mCaptureRequested = true; }

    // Called by the renderer: records the "present" pass, which reads `ldr` (size `ldrSize`).
    void record(CommandList& cmd, const Buffer& ldr, glm::uvec2 ldrSize);
    SubmitSync submitSync() const;
    // Called by the renderer after the submission completed: presents, and finishes a capture.
    void endFrame();

    // The last capture (after the frame that asked for it); empty before that.
    const WindowCapture& capture() const { return mCapture; }

private:
    void ensureSourceImage(glm::uvec2 size);
    void releaseSourceImage();

    Context& mCtx;
    std::unique_ptr<Swapchain> mSwapchain;
    std::unique_ptr<ImGuiOverlay> mOverlay;
    std::uint64_t mSwapchainGeneration = 0;
    ImDrawData* mOverlayData = nullptr;
    bool mFrameOpen = false;

    // The LDR frame as an image: a blit source (buffers cannot be blitted).
    VkImage mSource = VK_NULL_HANDLE;
    VkDeviceMemory mSourceMemory = VK_NULL_HANDLE;
    glm::uvec2 mSourceSize{0};

    bool mCaptureRequested = false;
    bool mCaptureRecorded = false;
    Buffer mCaptureBuffer;
    WindowCapture mCapture;
};

}  // namespace engine::gpu
