// gpu::ComputePipeline reads each binding's descriptor type from the shader's SPIR-V: the world's
// cell, page-table and dynamic-grid reads are texel fetches (usamplerBuffer), so those bindings
// must be uniform texel buffers and every other binding stays a storage buffer. And an indirect
// dispatch runs the workgroups its arguments buffer names.
#include "gpu/compute_pipeline.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>
#include <utility>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/command_list.h"
#include "gpu/gpu_test_context.h"
#include "gpu/uploader.h"
#include "shared/bindings.h"
#include "shared/frame_params.h"
#include "shared/light_sampling.h"
#include "shared/restir.h"
#include "shared/trace_rays.h"

using namespace gpu_testing;

class ComputePipelineBindings : public GpuTest {};

TEST_F(ComputePipelineBindings, TypesFollowTheShaderDeclarations) {
    const std::uint32_t count = shared::TRACE_BINDING_HITS + 1u;
    engine::gpu::ComputePipeline trace(context(), "world/trace_rays_hierarchical", count);
    const std::vector<VkDescriptorType>& types = trace.bindingTypes();
    ASSERT_EQ(types.size(), count);
    for (std::uint32_t b = 0; b < count; ++b) {
        const bool texel = b == shared::WORLD_BINDING_CELLS || b == shared::WORLD_BINDING_PAGES ||
                           b == shared::WORLD_BINDING_PALETTE || b == shared::WORLD_BINDING_DYNAMIC;
        EXPECT_EQ(types[b], texel ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER
                                  : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER)
            << "binding " << b;
    }
}

TEST_F(ComputePipelineBindings, LightPassesReadTheEmittersAndAliasTableAsTexels) {
    const std::uint32_t count = shared::LIGHT_SAMPLING_BINDING_PARTIAL + 1u;
    engine::gpu::ComputePipeline lit(context(), "baselines/light_sampling", count);
    const std::vector<VkDescriptorType>& types = lit.bindingTypes();
    EXPECT_EQ(types[shared::LIGHTS_BINDING_ALIAS], VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER);
    EXPECT_EQ(types[shared::LIGHTS_BINDING_EMITTERS], VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER);
    EXPECT_EQ(types[shared::LIGHTS_BINDING_ALIVE], VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    EXPECT_EQ(types[shared::WORLD_BINDING_INFO], VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
}

// The ReSTIR passes fetch the G-buffer and the reservoirs they only read as texels; a buffer a pass
// writes (its output, shade's final reservoirs) stays a storage buffer.
TEST_F(ComputePipelineBindings, RestirPassesReadWhatTheyOnlyReadAsTexels) {
    const VkDescriptorType texel = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER,
                           storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    struct Expected {
        const char* shader;
        std::vector<std::pair<std::uint32_t, VkDescriptorType>>
            own;  // the pass's own bindings, in order
    };
    const Expected passes[] = {
        {"restir/initial_candidates",
         {{shared::RESTIR_BINDING_FRAME, storage},
          {shared::RESTIR_BINDING_PARAMS, storage},
          {shared::RESTIR_BINDING_GBUFFER, texel},
          {shared::RESTIR_INITIAL_BINDING_OUT, storage}}},
        {"restir/temporal_reuse",
         {{shared::RESTIR_BINDING_FRAME, storage},
          {shared::RESTIR_BINDING_PARAMS, storage},
          {shared::RESTIR_BINDING_GBUFFER, texel},
          {shared::RESTIR_TEMPORAL_BINDING_PREV_GBUFFER, texel},
          {shared::RESTIR_TEMPORAL_BINDING_CANDIDATES, texel},
          {shared::RESTIR_TEMPORAL_BINDING_PREVIOUS, texel},
          {shared::RESTIR_TEMPORAL_BINDING_OWN, storage}}},
        {"restir/spatial_reuse",
         {{shared::RESTIR_BINDING_FRAME, storage},
          {shared::RESTIR_BINDING_PARAMS, storage},
          {shared::RESTIR_BINDING_GBUFFER, texel},
          {shared::RESTIR_SPATIAL_BINDING_OWN, texel},
          {shared::RESTIR_SPATIAL_BINDING_CANDIDATES, texel},
          {shared::RESTIR_SPATIAL_BINDING_OUT, storage}}},
        {"restir/shade",
         {{shared::RESTIR_BINDING_FRAME, storage},
          {shared::RESTIR_BINDING_PARAMS, storage},
          {shared::RESTIR_BINDING_GBUFFER, texel},
          {shared::RESTIR_SHADE_BINDING_FINAL, storage},
          {shared::RESTIR_SHADE_BINDING_RADIANCE, storage}}},
    };
    for (const Expected& pass : passes) {
        const std::uint32_t count = pass.own.back().first + 1u;
        engine::gpu::ComputePipeline pipeline(context(), pass.shader, count);
        const std::vector<VkDescriptorType>& types = pipeline.bindingTypes();
        ASSERT_EQ(types.size(), count) << pass.shader;
        EXPECT_EQ(types[shared::LIGHTS_BINDING_EMITTERS], texel) << pass.shader;
        for (auto [binding, type] : pass.own)
            EXPECT_EQ(types[binding], type) << pass.shader << " binding " << binding;
    }
}

TEST_F(ComputePipelineBindings, ShadersWithoutTexelReadsKeepStorageBuffers) {
    engine::gpu::ComputePipeline tonemap(context(), "post/tonemap",
                                         shared::TONEMAP_BINDING_EXPOSURE + 1u);
    for (VkDescriptorType t : tonemap.bindingTypes())
        EXPECT_EQ(t, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
}

// dispatchIndirect runs the workgroups an earlier command wrote into its arguments: none for
// (0, 0, 0), the first two 8x8 tiles of the image for (2, 1, 1) — the tonemap, which writes
// each pixel of its workgroups, shows which ran.
TEST_F(ComputePipelineBindings, IndirectDispatchRunsTheWorkgroupsItsArgumentsName) {
    using engine::gpu::Buffer;
    using engine::gpu::BufferKind;
    engine::gpu::Context& ctx = context();
    const glm::uvec2 size(32, 16);  // 4 x 2 workgroups
    const std::uint32_t pixels = size.x * size.y;
    shared::FrameParams frame{};
    frame.imageSize = glm::uvec4(size, 0u, 0u);
    frame.displaySize = frame.imageSize;  // the tonemap covers the displayed image
    frame.exposure = glm::vec4(1.0f);
    const std::vector<glm::vec4> radiance(pixels, glm::vec4(1.0f));
    Buffer params(ctx, BufferKind::Storage, sizeof(frame), "test.frame");
    Buffer light(ctx, BufferKind::Storage, pixels * sizeof(glm::vec4), "test.radiance");
    Buffer ldr(ctx, BufferKind::Storage, pixels * 4, "test.ldr");
    Buffer exposure(ctx, BufferKind::Storage, 16, "test.exposure");
    Buffer args(ctx, BufferKind::Storage, 16, "test.args");
    Buffer host(ctx, BufferKind::Readback, pixels * 4, "test.readback");
    engine::gpu::ComputePipeline tonemap(context(), "post/tonemap",
                                         shared::TONEMAP_BINDING_EXPOSURE + 1u);
    const std::vector<const Buffer*> buffers{&params, &light, &ldr, &exposure};
    engine::gpu::Uploader uploader(ctx);
    for (glm::uvec3 groups : {glm::uvec3(0u), glm::uvec3(2u, 1u, 1u)}) {
        uploader.write(params, 0, &frame, sizeof(frame));
        uploader.write(light, 0, radiance.data(), pixels * sizeof(glm::vec4));
        uploader.write(args, 0, &groups, sizeof(groups));
        engine::gpu::CommandList cmd(ctx);
        cmd.begin();
        cmd.fillBuffer(ldr, 0);
        cmd.barrier();
        uploader.record(cmd);
        cmd.barrier();
        tonemap.dispatchIndirect(cmd, buffers, args, 0);
        cmd.barrier();
        cmd.copyBuffer(ldr, host, {{0, 0, pixels * 4ull}});
        cmd.barrier();
        cmd.submitAndWait();
        auto out = host.view<std::uint32_t>();
        std::uint32_t written = 0, outside = 0;
        for (std::uint32_t i = 0; i < pixels; ++i) {
            const bool inTiles = i % size.x < 8u * groups.x && i / size.x < 8u * groups.y;
            written += out[i] != 0u;
            outside += out[i] != 0u && !inTiles;
        }
        EXPECT_EQ(written, 64u * groups.x * groups.y)
            << "groups " << groups.x << "," << groups.y << "," << groups.z;
        EXPECT_EQ(outside, 0u);
    }
}

// What a shader may write is read from its SPIR-V (a storage buffer not declared `readonly`): the
// check behind every pass's declared writes (ComputePipeline::dispatch).
TEST_F(ComputePipelineBindings, WritableBindingsFollowTheShaderDeclarations) {
    engine::gpu::ComputePipeline tonemap(context(), "post/tonemap",
                                         shared::TONEMAP_BINDING_EXPOSURE + 1u);
    const std::vector<bool>& writable = tonemap.writableBindings();
    EXPECT_FALSE(writable[shared::TONEMAP_BINDING_FRAME]);
    EXPECT_FALSE(writable[shared::TONEMAP_BINDING_RADIANCE]);
    EXPECT_TRUE(writable[shared::TONEMAP_BINDING_LDR]);  // writeonly is still a write
    const std::uint32_t count = shared::TRACE_BINDING_HITS + 1u;
    engine::gpu::ComputePipeline trace(context(), "world/trace_rays_hierarchical", count);
    for (std::uint32_t b = 0; b < count; ++b) {
        // The world's texel buffers and its readonly blocks are read; the hits written.
        EXPECT_EQ(trace.writableBindings()[b], b == shared::TRACE_BINDING_HITS) << "binding " << b;
    }
}

// Barriers follow from what commands read and write: commands that share no buffer run without
// one between them, a read of what an earlier command wrote (or a write of what it read or
// wrote) waits behind exactly one.
TEST_F(ComputePipelineBindings, BarriersOnlyBetweenDependentCommands) {
    using engine::gpu::Buffer;
    using engine::gpu::BufferKind;
    engine::gpu::Context& ctx = context();
    const glm::uvec2 size(16, 8);
    const std::uint32_t pixels = size.x * size.y;
    Buffer params(ctx, BufferKind::Storage, sizeof(shared::FrameParams), "test.frame");
    Buffer lightA(ctx, BufferKind::Storage, pixels * sizeof(glm::vec4), "test.radianceA");
    Buffer lightB(ctx, BufferKind::Storage, pixels * sizeof(glm::vec4), "test.radianceB");
    Buffer ldrA(ctx, BufferKind::Storage, pixels * 4, "test.ldrA");
    Buffer ldrB(ctx, BufferKind::Storage, pixels * 4, "test.ldrB");
    Buffer exposure(ctx, BufferKind::Storage, 16, "test.exposure");
    engine::gpu::ComputePipeline tonemap(ctx, "post/tonemap",
                                         shared::TONEMAP_BINDING_EXPOSURE + 1u);
    engine::gpu::CommandList cmd(ctx);
    cmd.begin();
    cmd.fillBuffer(params, 0);
    cmd.fillBuffer(lightA, 0);
    cmd.fillBuffer(lightB, 0);  // three fills of three buffers: no barrier between them
    EXPECT_EQ(cmd.barrierCount(), 0u);
    tonemap.dispatch(cmd, {&params, &lightA, &ldrA, &exposure}, 2,
                     1);  // reads what the fills wrote
    EXPECT_EQ(cmd.barrierCount(), 1u);
    tonemap.dispatch(cmd, {&params, &lightB, &ldrB, &exposure}, 2,
                     1);  // shares only reads with the first
    EXPECT_EQ(cmd.barrierCount(), 1u);
    cmd.fillBuffer(lightA, 0);  // writes what the first dispatch read
    EXPECT_EQ(cmd.barrierCount(), 2u);
    tonemap.dispatch(cmd, {&params, &lightB, &ldrB, &exposure}, 2,
                     1);  // its writes are behind barrier 2
    EXPECT_EQ(cmd.barrierCount(), 2u);
    tonemap.dispatch(cmd, {&params, &lightA, &ldrA, &exposure}, 2, 1);  // reads what the fill wrote
    EXPECT_EQ(cmd.barrierCount(), 3u);
    cmd.submitAndWait();
    EXPECT_EQ(cmd.barrierCount(), 4u);  // the one that ends a submission: the host and later lists
}
