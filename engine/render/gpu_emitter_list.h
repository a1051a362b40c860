// GpuEmitterList: the GPU copy of an EmitterList — slots (only changed ones are uploaded), the
// alive list and alias table (re-uploaded when the set of lights changed), and the list info.
#pragma once

#include "gpu/buffer.h"
#include "lighting/emitter_list.h"

namespace engine::gpu {
class Context;
class Uploader;
}  // namespace engine::gpu

namespace engine::render {

struct EmitterUploadStats {
    std::uint32_t slots = 0;
    bool aliveAndAlias = false;
};

class GpuEmitterList {
public:
    explicit GpuEmitterList(gpu::Context& ctx);

    // Queues the uploads and clears the list's change marks.
    EmitterUploadStats sync(lighting::EmitterList& list, gpu::Uploader& uploader);

    const gpu::Buffer& info() const { return mInfo; }
    const gpu::Buffer& emitters() const { return mEmitters; }
    const gpu::Buffer& alive() const { return mAlive; }
    const gpu::Buffer& alias() const { return mAlias; }

private:
    void ensure(gpu::Buffer& buffer, std::uint64_t bytes, const char* name, bool& grown);

    gpu::Context& mCtx;
    gpu::Buffer mInfo, mEmitters, mAlive, mAlias;
};

}  // namespace engine::render
