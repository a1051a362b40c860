// Material palette: index 0 is "empty"; every other index names a diffuse material with linear
// albedo and optional emission. The palette travels with the world (scene files, .vdb metadata)
// and is uploaded whole to the GPU as shared::GpuMaterial.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shared/material.h"

namespace engine::world {

using MaterialId = std::uint16_t;
inline constexpr MaterialId kEmpty = 0;
inline constexpr std::size_t kMaxMaterials = 0xFFFF;

struct Material {
    std::string name;
    glm::vec3 albedo{0.8f};
    glm::vec3 emissionColor{0.0f};
    float emissionStrength = 0.0f;

    glm::vec3 emittedRadiance() const { return emissionColor * emissionStrength; }
    bool emissive() const {
        return emissionStrength > 0.0f &&
               glm::any(glm::greaterThan(emissionColor, glm::vec3(0.0f)));
    }
    bool operator==(const Material&) const = default;
};

class Palette {
public:
    Palette();  // holds only the reserved "empty" entry

    // Adds a material and returns its id; std::nullopt when the palette is full.
    std::optional<MaterialId> add(Material material);
    std::optional<MaterialId> find(std::string_view name) const;
    const Material& operator[](MaterialId id) const { return mMaterials.at(id); }
    Material& operator[](MaterialId id) { return mMaterials.at(id); }
    std::size_t size() const { return mMaterials.size(); }
    const std::vector<Material>& materials() const { return mMaterials; }

    std::vector<shared::GpuMaterial> toGpu() const;
    std::size_t gpuBytes() const { return mMaterials.size() * sizeof(shared::GpuMaterial); }
    bool operator==(const Palette&) const = default;

private:
    std::vector<Material> mMaterials;
};

}  // namespace engine::world
