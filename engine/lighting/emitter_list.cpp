#include "lighting/emitter_list.h"

#include <algorithm>
#include <bit>
#include <functional>
#include <numbers>

#include "core/check.h"
#include "lighting/alias_table.h"
#include "world/solid_voxels.h"

namespace engine::lighting {

namespace {

using world::BrickGrid;
using world::kBrickDim;
using world::MaterialId;

constexpr glm::ivec3 kFaceNormals[6] = {{-1, 0, 0}, {1, 0, 0},  {0, -1, 0},
                                        {0, 1, 0},  {0, 0, -1}, {0, 0, 1}};

std::size_t paletteHash(const world::Palette& palette) {
    std::size_t h = palette.size();
    for (const world::Material& m : palette.materials()) {
        glm::vec3 e = m.emittedRadiance();
        for (float v : {e.x, e.y, e.z}) h = h * 1000003u ^ std::hash<float>{}(v);
    }
    return h;
}

// Exposure of voxel p: bit f set when the neighbour across face f is empty (or outside the world).
std::uint32_t voxelExposure(const BrickGrid& grid, glm::ivec3 p) {
    std::uint32_t mask = 0;
    for (std::uint32_t f = 0; f < 6; ++f) {
        if (grid.get(p + kFaceNormals[f]) == world::kEmpty) mask |= 1u << f;
    }
    return mask;
}

// Exposure of a whole cell's side: any empty voxel across that side counts.
std::uint32_t cellExposure(const BrickGrid& grid, glm::ivec3 cell) {
    std::uint32_t mask = 0;
    const glm::ivec3 lo = cell * kBrickDim;
    for (std::uint32_t f = 0; f < 6; ++f) {
        const int axis = int(f >> 1);
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        glm::ivec3 p = lo;
        p[axis] = (f & 1) ? lo[axis] + kBrickDim : lo[axis] - 1;
        bool exposed = false;
        for (int i = 0; i < kBrickDim && !exposed; ++i) {
            for (int j = 0; j < kBrickDim && !exposed; ++j) {
                glm::ivec3 q = p;
                q[u] += i;
                q[v] += j;
                exposed = grid.get(q) == world::kEmpty;
            }
        }
        if (exposed) mask |= 1u << f;
    }
    return mask;
}

}  // namespace

EmitterList::EmitterList(EmitterSettings settings) : mSettings(settings) {}

void EmitterList::scanCell(const world::Scene& scene, glm::ivec3 cell,
                           std::vector<Candidate>& out) const {
    const BrickGrid& grid = scene.grid;
    const std::uint32_t value = grid.cell(cell);
    if (value == shared::CELL_EMPTY) return;
    const glm::ivec3 lo = cell * kBrickDim;
    if (!BrickGrid::cellIsBrick(value)) {
        const MaterialId m = BrickGrid::cellMaterial(value);
        if (!scene.palette[m].emissive()) return;
        if (mSettings.brickLights) {
            std::uint32_t mask = cellExposure(grid, cell);
            if (mask) out.push_back({lo, kBrickDim, mask, m});
            return;
        }
        // Brick lights off: the cell's exposed surface voxels, one light each (interior voxels
        // of a uniform cell are enclosed).
        for (int z = 0; z < kBrickDim; ++z)
            for (int y = 0; y < kBrickDim; ++y)
                for (int x = 0; x < kBrickDim; ++x) {
                    bool boundary = x == 0 || y == 0 || z == 0 || x == 7 || y == 7 || z == 7;
                    if (!boundary) continue;
                    glm::ivec3 p = lo + glm::ivec3(x, y, z);
                    if (std::uint32_t mask = voxelExposure(grid, p)) out.push_back({p, 1, mask, m});
                }
        return;
    }
    const world::BrickVoxels& voxels = grid.brickVoxels(BrickGrid::cellBrick(value));
    for (int i = 0; i < world::kBrickVoxels; ++i) {
        const MaterialId m = voxels[i];
        if (m == world::kEmpty || !scene.palette[m].emissive()) continue;
        glm::ivec3 p = lo + world::brickVoxelPosition(i);
        if (std::uint32_t mask = voxelExposure(grid, p)) out.push_back({p, 1, mask, m});
    }
}

EmitterUpdateStats EmitterList::rebuild(const world::Scene& scene) {
    EmitterUpdateStats stats;
    stats.full = true;
    // Every old slot is freed (new generation), so no reservoir survives a full rebuild.
    for (std::uint32_t slot : std::vector<std::uint32_t>(mAlive)) freeSlot(slot);
    mCellSlots.clear();
    mTotalPower = 0.0;
    world::forEachOccupiedCell(
        scene.grid, [&](glm::ivec3 c) { rescanCell(scene, scene.grid.cellIndex(c), c, stats); });
    mBuiltSettings = mSettings;
    mBuiltSize = scene.grid.sizeInCells();
    mBuiltPaletteHash = paletteHash(scene.palette);
    mAliveChanged = true;
    mAliasStale = true;
    return stats;
}

EmitterUpdateStats EmitterList::update(const world::Scene& scene) {
    if (mBuiltSize != scene.grid.sizeInCells() || !(mBuiltSettings == mSettings) ||
        mBuiltPaletteHash != paletteHash(scene.palette)) {
        return rebuild(scene);
    }
    EmitterUpdateStats stats;
    const BrickGrid& grid = scene.grid;
    const glm::ivec3 size = grid.sizeInCells();
    // Touched cells and their face neighbours, each once.
    std::vector<std::uint32_t> todo;
    for (std::uint32_t index : grid.touchedCells()) {
        glm::ivec3 c(int(index % size.x), int((index / size.x) % size.y),
                     int(index / (std::size_t(size.x) * size.y)));
        todo.push_back(index);
        for (const glm::ivec3& n : kFaceNormals) {
            if (grid.containsCell(c + n))
                todo.push_back(static_cast<std::uint32_t>(grid.cellIndex(c + n)));
        }
    }
    std::sort(todo.begin(), todo.end());
    todo.erase(std::unique(todo.begin(), todo.end()), todo.end());
    for (std::uint32_t index : todo) {
        glm::ivec3 c(int(index % size.x), int((index / size.x) % size.y),
                     int(index / (std::size_t(size.x) * size.y)));
        rescanCell(scene, index, c, stats);
    }
    if (stats.added || stats.removed || stats.changed) mAliasStale = true;
    return stats;
}

void EmitterList::rescanCell(const world::Scene& scene, std::size_t cellIndex, glm::ivec3 cell,
                             EmitterUpdateStats& stats) {
    ++stats.cellsScanned;
    std::vector<Candidate> found;
    scanCell(scene, cell, found);
    auto it = mCellSlots.find(static_cast<std::uint32_t>(cellIndex));
    std::vector<std::uint32_t> old =
        it == mCellSlots.end() ? std::vector<std::uint32_t>{} : std::move(it->second);
    if (found.empty() && old.empty()) return;

    // Match by position and size so surviving emitters keep their slots.
    std::unordered_map<std::uint64_t, std::uint32_t> oldByKey;
    auto key = [](glm::ivec3 p, int size) {
        return (std::uint64_t(std::uint32_t(p.x)) << 44) ^
               (std::uint64_t(std::uint32_t(p.y)) << 24) ^
               (std::uint64_t(std::uint32_t(p.z)) << 4) ^ std::uint64_t(size == 1 ? 0 : 1);
    };
    for (std::uint32_t slot : old) {
        const shared::GpuEmitter& e = mSlots[slot];
        oldByKey[key(glm::ivec3(e.minCorner), e.minCorner.w)] = slot;
    }
    std::vector<std::uint32_t> now;
    now.reserve(found.size());
    for (const Candidate& c : found) {
        auto match = oldByKey.find(key(c.minCorner, c.size));
        std::uint32_t slot;
        if (match != oldByKey.end()) {
            slot = match->second;
            oldByKey.erase(match);
            const shared::GpuEmitter& e = mSlots[slot];
            if (e.info.x == c.faceMask && e.info.z == c.material) {
                now.push_back(slot);
                continue;
            }
            // Same place, different light: a new generation so old reservoirs are dropped.
            mTotalPower -= e.radiance.w;
            ++mSlots[slot].info.y;
            ++stats.changed;
        } else {
            slot = allocateSlot();
            ++stats.added;
        }
        writeSlot(slot, c, scene.palette);
        now.push_back(slot);
    }
    for (auto& [k, slot] : oldByKey) {
        freeSlot(slot);
        ++stats.removed;
    }
    if (now.empty()) {
        mCellSlots.erase(static_cast<std::uint32_t>(cellIndex));
    } else {
        mCellSlots[static_cast<std::uint32_t>(cellIndex)] = std::move(now);
    }
}

std::uint32_t EmitterList::allocateSlot() {
    std::uint32_t slot;
    if (!mFreeSlots.empty()) {
        slot = mFreeSlots.back();
        mFreeSlots.pop_back();
    } else {
        slot = static_cast<std::uint32_t>(mSlots.size());
        mSlots.push_back(shared::GpuEmitter{});
        mAlivePosition.push_back(0);
        mSlotChanged.push_back(0);
    }
    mAlivePosition[slot] = static_cast<std::uint32_t>(mAlive.size());
    mAlive.push_back(slot);
    mAliveChanged = true;
    return slot;
}

void EmitterList::freeSlot(std::uint32_t slot) {
    shared::GpuEmitter& e = mSlots[slot];
    mTotalPower -= e.radiance.w;
    e.info.w &= ~shared::EMITTER_FLAG_ALIVE;
    e.radiance.w = 0.0f;
    ++e.info.y;  // a reservoir holding the old generation is now stale
    std::uint32_t pos = mAlivePosition[slot];
    std::uint32_t last = mAlive.back();
    mAlive[pos] = last;
    mAlivePosition[last] = pos;
    mAlive.pop_back();
    mFreeSlots.push_back(slot);
    mAliveChanged = true;
    if (!mSlotChanged[slot]) {
        mSlotChanged[slot] = 1;
        mChangedSlots.push_back(slot);
    }
}

void EmitterList::writeSlot(std::uint32_t slot, const Candidate& c, const world::Palette& palette) {
    shared::GpuEmitter& e = mSlots[slot];
    const world::Material& m = palette[c.material];
    glm::vec3 radiance = m.emittedRadiance();
    int faces = std::popcount(c.faceMask);
    // Radiant flux of a Lambertian emitter: pi x radiance x exposed area.
    double power =
        double(luminance(radiance)) * double(faces) * double(c.size * c.size) * std::numbers::pi;
    e.minCorner = glm::ivec4(c.minCorner, c.size);
    e.radiance = glm::vec4(radiance, float(power));
    e.info.x = c.faceMask;
    e.info.z = c.material;
    e.info.w = shared::EMITTER_FLAG_ALIVE;
    mTotalPower += power;
    if (!mSlotChanged[slot]) {
        mSlotChanged[slot] = 1;
        mChangedSlots.push_back(slot);
    }
}

const std::vector<shared::AliasEntry>& EmitterList::aliasTable() {
    if (mAliasStale) {
        std::vector<double> weights;
        weights.reserve(mAlive.size());
        for (std::uint32_t slot : mAlive) weights.push_back(mSlots[slot].radiance.w);
        mAlias = buildAliasTable(mAlive, weights);
        // Re-add from scratch: the running total drifts with every incremental +/-, and the GPU
        // divides slot power by it to get the alias table's probabilities.
        mTotalPower = 0.0;
        for (double w : weights) mTotalPower += w;
        mAliasStale = false;
    }
    return mAlias;
}

shared::EmitterListInfo EmitterList::info() const {
    shared::EmitterListInfo info{};
    info.counts = glm::uvec4(aliveCount(), static_cast<std::uint32_t>(mSlots.size()),
                             static_cast<std::uint32_t>(mAlias.size()), 0u);
    info.power = glm::vec4(float(mTotalPower), 0.0f, 0.0f, 0.0f);
    return info;
}

void EmitterList::clearChanges() {
    for (std::uint32_t slot : mChangedSlots) mSlotChanged[slot] = 0;
    mChangedSlots.clear();
    mAliveChanged = false;
}

}  // namespace engine::lighting
