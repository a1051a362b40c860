#include "world/material.h"

namespace engine::world {

Palette::Palette() {
    mMaterials.push_back(Material{"empty", glm::vec3(0.0f), glm::vec3(0.0f), 0.0f});
}

std::optional<MaterialId> Palette::add(Material material) {
    if (mMaterials.size() >= kMaxMaterials) return std::nullopt;
    mMaterials.push_back(std::move(material));
    return static_cast<MaterialId>(mMaterials.size() - 1);
}

std::optional<MaterialId> Palette::find(std::string_view name) const {
    for (std::size_t i = 1; i < mMaterials.size(); ++i) {
        if (mMaterials[i].name == name) return static_cast<MaterialId>(i);
    }
    return std::nullopt;
}

std::vector<shared::GpuMaterial> Palette::toGpu() const {
    std::vector<shared::GpuMaterial> out;
    out.reserve(mMaterials.size());
    for (const Material& m : mMaterials) {
        shared::GpuMaterial g{};
        g.albedo = glm::vec4(m.albedo, 0.0f);
        g.emission = glm::vec4(m.emittedRadiance(), m.emissionStrength);
        g.flags = glm::uvec4(m.emissive() ? shared::MATERIAL_FLAG_EMISSIVE : 0u, 0u, 0u, 0u);
        out.push_back(g);
    }
    return out;
}

}  // namespace engine::world
