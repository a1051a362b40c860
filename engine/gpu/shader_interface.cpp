#include "gpu/shader_interface.h"

#include <algorithm>
#include <memory>
#include <spirv_cross_c.h>

#include "core/check.h"

namespace engine::gpu {

namespace {
using Context = std::unique_ptr<spvc_context_s, decltype(&spvc_context_destroy)>;

std::span<const spvc_reflected_resource> resourcesOf(spvc_resources resources,
                                                     spvc_resource_type type) {
    const spvc_reflected_resource* list = nullptr;
    size_t count = 0;
    spvc_resources_get_resource_list_for_type(resources, type, &list, &count);
    return {list, count};
}
}  // namespace

ShaderInterface reflectShaderInterface(std::span<const std::uint32_t> code,
                                       std::uint32_t bindingCount, const char* name) {
    spvc_context raw = nullptr;
    CHECK_MSG(spvc_context_create(&raw) == SPVC_SUCCESS, "SPIRV-Cross: no context");
    Context context(raw, spvc_context_destroy);
    spvc_parsed_ir ir = nullptr;
    spvc_compiler compiler = nullptr;
    spvc_resources resources = nullptr;
    const bool parsed =
        spvc_context_parse_spirv(raw, code.data(), code.size(), &ir) == SPVC_SUCCESS &&
        spvc_context_create_compiler(raw, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP,
                                     &compiler) == SPVC_SUCCESS &&
        spvc_compiler_create_shader_resources(compiler, &resources) == SPVC_SUCCESS;
    CHECK_MSG(parsed, "shader %s: %s", name, spvc_context_get_last_error_string(raw));

    ShaderInterface out;
    const spvc_specialization_constant* constants = nullptr;
    size_t constantCount = 0;
    spvc_compiler_get_specialization_constants(compiler, &constants, &constantCount);
    for (size_t i = 0; i < constantCount; ++i) out.specIds.push_back(constants[i].constant_id);
    std::sort(out.specIds.begin(), out.specIds.end());
    out.specIds.erase(std::unique(out.specIds.begin(), out.specIds.end()), out.specIds.end());

    out.bindingTypes.assign(bindingCount, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    out.writable.assign(bindingCount, false);
    // The binding of a resource in set 0 below bindingCount, or bindingCount for any other.
    auto bindingOf = [&](const spvc_reflected_resource& r) {
        if (spvc_compiler_get_decoration(compiler, r.id, SpvDecorationDescriptorSet) != 0)
            return bindingCount;
        return std::min(spvc_compiler_get_decoration(compiler, r.id, SpvDecorationBinding),
                        bindingCount);
    };
    for (const spvc_reflected_resource& r :
         resourcesOf(resources, SPVC_RESOURCE_TYPE_STORAGE_BUFFER)) {
        const std::uint32_t b = bindingOf(r);
        if (b == bindingCount) continue;
        const SpvDecoration* decorations = nullptr;
        size_t count = 0;
        spvc_compiler_get_buffer_block_decorations(compiler, r.id, &decorations, &count);
        out.writable[b] = std::find(decorations, decorations + count, SpvDecorationNonWritable) ==
                          decorations + count;
    }
    for (const spvc_reflected_resource& r :
         resourcesOf(resources, SPVC_RESOURCE_TYPE_SAMPLED_IMAGE)) {
        const std::uint32_t b = bindingOf(r);
        if (b == bindingCount) continue;
        spvc_type type = spvc_compiler_get_type_handle(compiler, r.type_id);
        CHECK_MSG(spvc_type_get_image_dimension(type) == SpvDimBuffer,
                  "shader %s, binding %u: only sampled buffer images", name, b);
        out.bindingTypes[b] = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    }
    for (spvc_resource_type type :
         {SPVC_RESOURCE_TYPE_STORAGE_IMAGE, SPVC_RESOURCE_TYPE_SEPARATE_IMAGE})
        for (const spvc_reflected_resource& r : resourcesOf(resources, type))
            CHECK_MSG(bindingOf(r) == bindingCount,
                      "shader %s, binding %u: only sampled buffer images", name, bindingOf(r));
    return out;
}

}  // namespace engine::gpu
