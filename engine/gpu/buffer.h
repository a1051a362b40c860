// gpu::Buffer: a VkBuffer with its own memory. Storage buffers are device-local and reachable by
// device address; staging and readback buffers are host-visible and stay mapped. A storage buffer
// can also be bound as a uniform texel buffer, through a view of the format its owner gives it
// (setTexelFormat), where a shader declares a usamplerBuffer (gpu::ComputePipeline).
#pragma once

#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vulkan/vulkan.h>

namespace engine::gpu {

class Context;

enum class BufferKind {
    Storage,   // device-local storage buffer, transfer source and destination, indirect dispatch
               // arguments
    Staging,   // host-visible, transfer source
    Readback,  // host-visible, transfer destination
};

class Buffer {
public:
    Buffer() = default;
    Buffer(Context& ctx, BufferKind kind, std::uint64_t bytes, const std::string& debugName);
    ~Buffer();
    Buffer(Buffer&& other) noexcept;
    Buffer& operator=(Buffer&& other) noexcept;
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    VkBuffer handle() const { return mBuffer; }
    std::uint64_t size() const { return mSize; }
    std::uint64_t deviceAddress() const { return mAddress; }
    bool valid() const { return mBuffer != VK_NULL_HANDLE; }
    const std::string& name() const { return mName; }

    // Host-visible buffers only.
    void* mapped() const { return mMapped; }
    template <typename T>
    std::span<const T> view() const {
        return {static_cast<const T*>(mMapped), static_cast<std::size_t>(mSize / sizeof(T))};
    }
    void write(const void* data, std::uint64_t bytes, std::uint64_t offset = 0);

    // Storage buffers only: a view of the whole buffer as texels of `format` (e.g.
    // VK_FORMAT_R32_UINT), for shaders that read it through a usamplerBuffer. Throws
    // TexelBufferTooLarge (gpu/texel_buffer_limit.h) past the device's maxTexelBufferElements.
    void setTexelFormat(VkFormat format);
    VkBufferView texelView() const { return mView; }

private:
    void release();

    Context* mCtx = nullptr;
    VkBuffer mBuffer = VK_NULL_HANDLE;
    VkDeviceMemory mMemory = VK_NULL_HANDLE;
    VkBufferView mView = VK_NULL_HANDLE;
    std::uint64_t mSize = 0;
    std::uint64_t mAddress = 0;
    void* mMapped = nullptr;
    std::string mName;
};

}  // namespace engine::gpu
