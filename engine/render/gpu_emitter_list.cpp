#include "render/gpu_emitter_list.h"

#include <algorithm>
#include <bit>

#include "gpu/uploader.h"

namespace engine::render {

GpuEmitterList::GpuEmitterList(gpu::Context& ctx) : mCtx(ctx) {
    mInfo =
        gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::EmitterListInfo), "lights.info");
}

void GpuEmitterList::ensure(gpu::Buffer& buffer, std::uint64_t bytes, const char* name,
                            bool& grown) {
    bytes = std::max<std::uint64_t>(bytes, 256);
    if (buffer.valid() && buffer.size() >= bytes) return;
    buffer = gpu::Buffer(mCtx, gpu::BufferKind::Storage, std::bit_ceil(bytes), name);
    grown = true;
}

EmitterUploadStats GpuEmitterList::sync(lighting::EmitterList& list, gpu::Uploader& uploader) {
    EmitterUploadStats stats;
    bool grown = false;
    std::span<const shared::GpuEmitter> slots = list.slots();
    ensure(mEmitters, slots.size_bytes(), "lights.emitters", grown);
    if (!mEmitters.texelView())
        mEmitters.setTexelFormat(VK_FORMAT_R32G32B32A32_UINT);  // GpuEmitter: 3 texels
    if (grown) {
        // A new buffer: every slot, once.
        uploader.write(mEmitters, 0, slots.data(), slots.size_bytes());
        stats.slots = static_cast<std::uint32_t>(slots.size());
    } else {
        std::vector<std::uint32_t> changed(list.changedSlots().begin(), list.changedSlots().end());
        std::sort(changed.begin(), changed.end());
        for (std::uint32_t slot : changed) {
            uploader.write(mEmitters, std::uint64_t(slot) * sizeof(shared::GpuEmitter),
                           &slots[slot], sizeof(shared::GpuEmitter));
        }
        stats.slots = static_cast<std::uint32_t>(changed.size());
    }
    bool aliveGrown = false;
    ensure(mAlive, list.aliveSlots().size_bytes(), "lights.alive", aliveGrown);
    const std::vector<shared::AliasEntry>& alias = list.aliasTable();
    ensure(mAlias, alias.size() * sizeof(shared::AliasEntry), "lights.alias", aliveGrown);
    if (!mAlias.texelView())
        mAlias.setTexelFormat(VK_FORMAT_R32G32B32A32_UINT);  // shaders fetch AliasEntry texels
    if (list.aliveChanged() || aliveGrown) {
        uploader.write(mAlive, 0, list.aliveSlots().data(), list.aliveSlots().size_bytes());
        uploader.write(mAlias, 0, alias.data(), alias.size() * sizeof(shared::AliasEntry));
        stats.aliveAndAlias = true;
    }
    shared::EmitterListInfo info = list.info();
    uploader.write(mInfo, 0, &info, sizeof(info));
    list.clearChanges();
    return stats;
}

}  // namespace engine::render
