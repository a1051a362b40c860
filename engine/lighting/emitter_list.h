// EmitterList: every emissive voxel with at least one exposed face, as a light with a stable
// slot; a cell that is all one emissive material becomes one 8^3 brick light instead of its
// surface voxels (when brick lights are on).
//
// Updates are incremental: update() rescans only the cells the grid reports as touched, plus
// their six neighbours (whose boundary voxels may have gained or lost exposure), so the cost
// follows the edit, not the world. An emitter that survives a rescan keeps its slot; a freed or
// reused slot gets a new generation. The alias table over emitter power is rebuilt lazily.
// engine/render/gpu_emitter_list.h uploads the slots that changed.
#pragma once

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "shared/emitters.h"
#include "world/scene.h"

namespace engine::lighting {

struct EmitterSettings {
    bool brickLights = true;
    bool operator==(const EmitterSettings&) const = default;
};

struct EmitterUpdateStats {
    bool full = false;
    std::uint32_t cellsScanned = 0;
    std::uint32_t added = 0, removed = 0, changed = 0;
};

class EmitterList {
public:
    explicit EmitterList(EmitterSettings settings = {});

    // Full scan of the scene.
    EmitterUpdateStats rebuild(const world::Scene& scene);
    // Brings the list up to date with the grid's touched cells (a full rebuild when the world's
    // size, the palette or the settings changed since the last call).
    EmitterUpdateStats update(const world::Scene& scene);
    void setSettings(EmitterSettings settings) { mSettings = settings; }
    const EmitterSettings& settings() const { return mSettings; }

    std::span<const shared::GpuEmitter> slots() const { return mSlots; }
    std::span<const std::uint32_t> aliveSlots() const { return mAlive; }
    std::uint32_t aliveCount() const { return static_cast<std::uint32_t>(mAlive.size()); }
    double totalPower() const { return mTotalPower; }
    // Power-proportional table over the alive slots (rebuilt here if the list changed).
    const std::vector<shared::AliasEntry>& aliasTable();
    shared::EmitterListInfo info() const;

    // For the GPU mirror: slots written since the last clearChanges(), and whether the alive
    // list (hence the alias table) changed.
    std::span<const std::uint32_t> changedSlots() const { return mChangedSlots; }
    bool aliveChanged() const { return mAliveChanged; }
    void clearChanges();

private:
    struct Candidate {
        glm::ivec3 minCorner;
        int size;
        std::uint32_t faceMask;
        world::MaterialId material;
    };
    void scanCell(const world::Scene& scene, glm::ivec3 cell, std::vector<Candidate>& out) const;
    void rescanCell(const world::Scene& scene, std::size_t cellIndex, glm::ivec3 cell,
                    EmitterUpdateStats& stats);
    std::uint32_t allocateSlot();
    void freeSlot(std::uint32_t slot);
    void writeSlot(std::uint32_t slot, const Candidate& c, const world::Palette& palette);

    EmitterSettings mSettings;
    EmitterSettings mBuiltSettings;
    glm::ivec3 mBuiltSize{0};
    std::size_t mBuiltPaletteHash = 0;

    std::vector<shared::GpuEmitter> mSlots;
    std::vector<std::uint32_t> mFreeSlots;
    std::vector<std::uint32_t> mAlive;          // alive slots, any order
    std::vector<std::uint32_t> mAlivePosition;  // slot -> index in mAlive
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>>
        mCellSlots;  // cell index -> slots
    double mTotalPower = 0.0;

    std::vector<shared::AliasEntry> mAlias;
    bool mAliasStale = true;
    std::vector<std::uint32_t> mChangedSlots;
    std::vector<std::uint8_t> mSlotChanged;
    bool mAliveChanged = true;
};

// Luminance of linear Rec.709 RGB.
inline float luminance(glm::vec3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

}  // namespace engine::lighting
