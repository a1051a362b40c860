#include "gpu/buffer.h"

#include <utility>

#include "core/check.h"
#include "gpu/context.h"
#include "gpu/texel_buffer_limit.h"
#include "gpu/vk_check.h"

namespace engine::gpu {

Buffer::Buffer(Context& ctx, BufferKind kind, std::uint64_t bytes, const std::string& debugName)
    : mCtx(&ctx), mSize(bytes), mName(debugName) {
    CHECK(bytes > 0);
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = bytes;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkMemoryPropertyFlags required = 0, preferred = 0;
    switch (kind) {
        case BufferKind::Storage:
            info.usage =
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT |
                VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
            preferred = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
            break;
        case BufferKind::Staging:
            info.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
            required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
            break;
        case BufferKind::Readback:
            info.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
            required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
            preferred = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
            break;
    }
    VkDevice device = ctx.device();
    VK_CHECK(vkCreateBuffer(device, &info, nullptr, &mBuffer));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device, mBuffer, &req);
    VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
    flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = ctx.findMemoryType(req.memoryTypeBits, required, preferred);
    CHECK_MSG(alloc.memoryTypeIndex != UINT32_MAX, "no memory type for buffer %s",
              debugName.c_str());
    if (kind == BufferKind::Storage) alloc.pNext = &flags;
    VK_CHECK(vkAllocateMemory(device, &alloc, nullptr, &mMemory));
    VK_CHECK(vkBindBufferMemory(device, mBuffer, mMemory, 0));
    if (kind != BufferKind::Storage)
        VK_CHECK(vkMapMemory(device, mMemory, 0, VK_WHOLE_SIZE, 0, &mMapped));
    if (kind == BufferKind::Storage) {
        VkBufferDeviceAddressInfo addr{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
        addr.buffer = mBuffer;
        mAddress = vkGetBufferDeviceAddress(device, &addr);
    }
    ctx.setObjectName(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<std::uint64_t>(mBuffer),
                      debugName.c_str());
}

Buffer::~Buffer() { release(); }

Buffer::Buffer(Buffer&& other) noexcept { *this = std::move(other); }

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    if (this == &other) return *this;
    release();
    mCtx = std::exchange(other.mCtx, nullptr);
    mBuffer = std::exchange(other.mBuffer, VK_NULL_HANDLE);
    mMemory = std::exchange(other.mMemory, VK_NULL_HANDLE);
    mView = std::exchange(other.mView, VK_NULL_HANDLE);
    mSize = std::exchange(other.mSize, 0);
    mAddress = std::exchange(other.mAddress, 0);
    mMapped = std::exchange(other.mMapped, nullptr);
    mName = std::move(other.mName);
    return *this;
}

void Buffer::write(const void* data, std::uint64_t bytes, std::uint64_t offset) {
    CHECK_MSG(mMapped, "buffer %s is not host-visible", mName.c_str());
    CHECK(offset + bytes <= mSize);
    std::memcpy(static_cast<char*>(mMapped) + offset, data, bytes);
}

namespace {
std::uint64_t texelBytes(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R32_UINT:
        case VK_FORMAT_R32_SFLOAT:
            return 4;
        case VK_FORMAT_R32G32_UINT:
        case VK_FORMAT_R32G32_SFLOAT:
            return 8;
        case VK_FORMAT_R32G32B32A32_UINT:
        case VK_FORMAT_R32G32B32A32_SFLOAT:
            return 16;
        default:
            CHECK_MSG(false, "texel format %d: size unknown", int(format));
            return 0;
    }
}
}  // namespace

void Buffer::setTexelFormat(VkFormat format) {
    CHECK_MSG(mBuffer && !mMapped, "buffer %s: texel views are for storage buffers", mName.c_str());
    checkTexelCount(*mCtx, mSize / texelBytes(format), "buffer " + mName);
    VkDevice device = mCtx->device();
    if (mView) vkDestroyBufferView(device, mView, nullptr);
    VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
    info.buffer = mBuffer;
    info.format = format;
    info.offset = 0;
    info.range = VK_WHOLE_SIZE;
    VK_CHECK(vkCreateBufferView(device, &info, nullptr, &mView));
}

void Buffer::release() {
    if (!mCtx) return;
    VkDevice device = mCtx->device();
    if (mMapped) vkUnmapMemory(device, mMemory);
    if (mView) vkDestroyBufferView(device, mView, nullptr);
    if (mBuffer) vkDestroyBuffer(device, mBuffer, nullptr);
    if (mMemory) vkFreeMemory(device, mMemory, nullptr);
    mBuffer = VK_NULL_HANDLE;
    mMemory = VK_NULL_HANDLE;
    mView = VK_NULL_HANDLE;
    mMapped = nullptr;
    mCtx = nullptr;
}

}  // namespace engine::gpu
