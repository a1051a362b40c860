// gpu::ComputePipeline reads each binding's descriptor type from the shader's SPIR-V: the world's
// cell and page-table reads are texel fetches (usamplerBuffer), so those bindings must be uniform
// texel buffers and every other binding stays a storage buffer.
#include <gtest/gtest.h>

#include "gpu/compute_pipeline.h"
#include "gpu/gpu_test_context.h"
#include "shared/bindings.h"
#include "shared/light_sampling.h"
#include "shared/trace_rays.h"

using namespace gpu_testing;

class ComputePipelineBindings : public GpuTest {};

TEST_F(ComputePipelineBindings, TypesFollowTheShaderDeclarations) {
    const std::uint32_t count = shared::TRACE_BINDING_HITS + 1u;
    engine::gpu::ComputePipeline trace(context(), "world/trace_rays_hierarchical", count);
    const std::vector<VkDescriptorType>& types = trace.bindingTypes();
    ASSERT_EQ(types.size(), count);
    for (std::uint32_t b = 0; b < count; ++b) {
        const bool texel = b == shared::WORLD_BINDING_CELLS || b == shared::WORLD_BINDING_PAGES;
        EXPECT_EQ(types[b], texel ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER)
            << "binding " << b;
    }
}

TEST_F(ComputePipelineBindings, LightPassesReadTheEmittersAndAliasTableAsTexels) {
    const std::uint32_t count = shared::LIGHT_SAMPLING_BINDING_RADIANCE + 1u;
    engine::gpu::ComputePipeline lit(context(), "baselines/light_sampling", count);
    const std::vector<VkDescriptorType>& types = lit.bindingTypes();
    EXPECT_EQ(types[shared::LIGHTS_BINDING_ALIAS], VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER);
    EXPECT_EQ(types[shared::LIGHTS_BINDING_EMITTERS], VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER);
    EXPECT_EQ(types[shared::LIGHTS_BINDING_ALIVE], VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    EXPECT_EQ(types[shared::WORLD_BINDING_INFO], VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
}

TEST_F(ComputePipelineBindings, ShadersWithoutTexelReadsKeepStorageBuffers) {
    engine::gpu::ComputePipeline tonemap(context(), "post/tonemap", shared::TONEMAP_BINDING_LDR + 1u);
    for (VkDescriptorType t : tonemap.bindingTypes()) EXPECT_EQ(t, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
}
