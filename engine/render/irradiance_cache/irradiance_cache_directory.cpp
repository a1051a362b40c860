#include "render/irradiance_cache/irradiance_cache_directory.h"

#include <algorithm>
#include <bit>
#include <optional>

#include "core/hash.h"

namespace engine::render {

namespace {

glm::uvec2 keyWords(const CacheKey& key) {
    return {
        static_cast<std::uint32_t>(key.voxel.x) | (static_cast<std::uint32_t>(key.voxel.y) << 16),
        static_cast<std::uint32_t>(key.voxel.z) | (key.coarse << shared::CACHE_KEY_COARSE_SHIFT) |
            (key.set << 31)};
}

// The rays one update of `key` may trace: S per face traced (CacheWork). A coarse entry traces
// one face, a voxel's entry its open faces (at least one: a key comes from a visible face, or
// surrounds a moving object).
std::uint32_t updateCost(const CacheKey& key, const CacheWork& work) {
    const std::uint32_t perFace = work.raysPerUpdate / shared::CACHE_FACES;
    if (key.coarse != 0) return perFace;
    if (key.set != shared::CACHE_SET_STATIC || !work.openFaces) return work.raysPerUpdate;
    return perFace * std::clamp(work.openFaces(key.voxel), 1u, shared::CACHE_FACES);
}

// A candidate's place in the order: its class (CacheWork), then the frame of its last update.
std::uint64_t candidateOrder(std::uint64_t cls, std::uint64_t lastUpdateFrame) {
    return cls << 56 | (lastUpdateFrame & ((1ull << 56) - 1));
}

}  // namespace

std::uint64_t packCacheKey(const CacheKey& key) {
    glm::uvec2 w = keyWords(key);
    return static_cast<std::uint64_t>(w.x) | (static_cast<std::uint64_t>(w.y) << 32);
}

std::uint32_t cacheKeyHash(const CacheKey& key) {
    glm::uvec2 w = keyWords(key);
    return pcgHash(w.x ^ pcgHash(w.y));
}

IrradianceCacheDirectory::IrradianceCacheDirectory(std::uint32_t maxSlots)
    : mMaxSlots(std::max(maxSlots, 1u)) {}

void IrradianceCacheDirectory::clear() {
    mSlots.clear();
    mEntries.clear();
    mFree.clear();
    mIndex.clear();
}

std::uint32_t IrradianceCacheDirectory::slotOf(const CacheKey& key) const {
    auto it = mIndex.find(packCacheKey(key));
    return it == mIndex.end() ? ~0u : it->second;
}

void IrradianceCacheDirectory::release(std::uint32_t slot) {
    mIndex.erase(packCacheKey(mSlots[slot].key));
    mSlots[slot].live = false;
    mFree.push_back(slot);
}

std::uint32_t IrradianceCacheDirectory::allocate(const CacheKey& key, std::uint64_t frame,
                                                 double time, CacheFrameLists& lists) {
    std::uint32_t slot;
    if (!mFree.empty()) {
        slot = mFree.back();
        mFree.pop_back();
    } else {
        slot = static_cast<std::uint32_t>(mSlots.size());
        mSlots.emplace_back();
        mEntries.emplace_back();
    }
    Slot& s = mSlots[slot];
    s = Slot{};
    s.key = key;
    s.live = true;
    s.lastSeen = frame;
    s.lastUpdate = time;
    mEntries[slot] = shared::CacheEntry{glm::ivec4(key.voxel, static_cast<int>(key.set)),
                                        static_cast<float>(time), 0u, 0u, key.coarse};
    mIndex.emplace(packCacheKey(key), slot);
    lists.tableChanged = true;
    return slot;
}

// Evicts the least recently seen entries (never this frame's) so that `wanted` new keys fit, in
// one batch of at least an eighth of the slots so eviction does not run every frame. Returns the
// free slots available afterwards.
std::uint32_t IrradianceCacheDirectory::makeRoom(std::size_t wanted, std::uint64_t frame,
                                                 CacheFrameLists& lists) {
    std::size_t available = mFree.size() + (mMaxSlots - mSlots.size());
    if (wanted > available) {
        std::vector<std::uint32_t> candidates;
        for (std::uint32_t slot = 0; slot < mSlots.size(); ++slot) {
            if (mSlots[slot].live && mSlots[slot].lastSeen != frame) candidates.push_back(slot);
        }
        std::size_t want =
            std::min(candidates.size(), std::max(wanted - available, std::size_t(mMaxSlots / 8)));
        std::partial_sort(candidates.begin(),
                          candidates.begin() + static_cast<std::ptrdiff_t>(want), candidates.end(),
                          [&](std::uint32_t a, std::uint32_t b) {
                              return mSlots[a].lastSeen != mSlots[b].lastSeen
                                         ? mSlots[a].lastSeen < mSlots[b].lastSeen
                                         : a < b;
                          });
        for (std::size_t i = 0; i < want; ++i) release(candidates[i]);
        lists.evicted = static_cast<std::uint32_t>(want);
        lists.tableChanged = lists.tableChanged || want > 0;
        available += want;
    }
    return static_cast<std::uint32_t>(available);
}

// One visible entry or new key competing for this frame's rays.
struct IrradianceCacheDirectory::Candidate {
    std::uint64_t order;  // class << 56 | last update frame
    std::uint64_t key;
    std::uint32_t index;  // a slot, or firstFresh + i for fresh[i]
    std::uint32_t cost;
    std::uint32_t cls() const { return static_cast<std::uint32_t>(order >> 56); }
};

CacheFrameLists IrradianceCacheDirectory::beginFrame(std::span<const CacheKey> visible, double time,
                                                     float fadeSeconds, const CacheWork& work) {
    CacheFrameLists lists;
    const std::uint64_t frame = ++mFrame;
    fadeDynamicEntries(time, fadeSeconds, work.objectsMoved, lists);
    std::vector<CacheKey> fresh;
    const std::vector<std::uint32_t> seen = markSeen(visible, frame, fresh);
    // Fresh keys are numbered after the slots until they get one.
    const auto firstFresh = static_cast<std::uint32_t>(mSlots.size());
    const std::vector<Candidate> candidates = rankCandidates(seen, fresh, firstFresh, frame, work);
    const std::vector<bool> chosen = chooseWithinBudget(candidates, work.rayBudget, lists.rays);
    std::vector<std::uint32_t> selected =
        slotsForChosen(candidates, chosen, fresh, firstFresh, frame, time, lists);
    startUpdates(selected, frame, time, work, lists);
    return lists;
}

// Dynamic entries fade out after their last update; their slots come back. While no object
// moves, what a dynamic entry holds stays true: its fade clock waits.
void IrradianceCacheDirectory::fadeDynamicEntries(double time, float fadeSeconds, bool objectsMoved,
                                                  CacheFrameLists& lists) {
    for (std::uint32_t slot = 0; slot < mSlots.size(); ++slot) {
        Slot& s = mSlots[slot];
        if (!s.live || s.key.set != shared::CACHE_SET_DYNAMIC) continue;
        if (!objectsMoved) {
            s.lastUpdate = time;
            mEntries[slot].updatedAt = static_cast<float>(time);
        }
        if (time - s.lastUpdate > fadeSeconds) {
            release(slot);
            ++lists.faded;
            lists.tableChanged = true;
        }
    }
}

// Known keys are marked seen and their slots returned, each once; new ones, sorted and without
// repeats, go to `fresh`: candidates without a slot yet.
std::vector<std::uint32_t> IrradianceCacheDirectory::markSeen(std::span<const CacheKey> visible,
                                                              std::uint64_t frame,
                                                              std::vector<CacheKey>& fresh) {
    std::vector<std::uint32_t> seen;
    for (const CacheKey& key : visible) {
        auto it = mIndex.find(packCacheKey(key));
        if (it == mIndex.end()) {
            fresh.push_back(key);
            continue;
        }
        Slot& s = mSlots[it->second];
        if (s.lastSeen == frame) continue;  // a duplicate
        s.lastSeen = frame;
        seen.push_back(it->second);
    }
    std::sort(fresh.begin(), fresh.end(), [](const CacheKey& a, const CacheKey& b) {
        return packCacheKey(a) < packCacheKey(b);
    });
    fresh.erase(std::unique(fresh.begin(), fresh.end()), fresh.end());
    return seen;
}

// A known entry as a candidate: its class (CacheWork) and the rays its update costs. None when
// it is converged and fresh enough.
std::optional<IrradianceCacheDirectory::Candidate> IrradianceCacheDirectory::candidateFor(
    std::uint32_t slot, std::uint64_t frame, const CacheWork& work) const {
    const Slot& s = mSlots[slot];
    const std::uint32_t update = updateCost(s.key, work);
    std::uint32_t cost = update;
    // An entry whose surroundings did not change: still converging (3), due a refresh (4), or
    // converged and fresh enough (none).
    const auto settledClass = [&]() -> std::optional<std::uint64_t> {
        if (s.updates < work.convergedAfter) return 3;
        if (frame - s.lastUpdateFrame >= work.refreshFrames || work.rayBudget == 0) return 4;
        return std::nullopt;
    };
    const bool nearMovingObject = glm::all(glm::greaterThanEqual(s.key.voxel, work.nearMin)) &&
                                  glm::all(glm::lessThanEqual(s.key.voxel, work.nearMax));
    std::optional<std::uint64_t> cls;
    if (s.key.set == shared::CACHE_SET_DYNAMIC) {
        // Around a moving object, every frame; around objects at rest, like static entries.
        cls = work.objectsMoved ? 1 : s.reset ? 2 : settledClass();
    } else if (s.traced < work.phases) {
        // Invalidated by an edit and not updated since: as urgent as a new entry; its later
        // tracing updates converge like any other (they still trace, at twice the cost).
        cls = s.traced == 0 ? 0 : 3;
        cost = 2 * update;
    } else {
        cls = s.reset || nearMovingObject ? 2 : settledClass();
    }
    if (!cls) return std::nullopt;
    return Candidate{candidateOrder(*cls, s.lastUpdateFrame), packCacheKey(s.key), slot, cost};
}

// Every candidate in the order it is served: class (CacheWork), then the frame of its last
// update (most stale first), then the key.
std::vector<IrradianceCacheDirectory::Candidate> IrradianceCacheDirectory::rankCandidates(
    std::span<const std::uint32_t> seen, std::span<const CacheKey> fresh, std::uint32_t firstFresh,
    std::uint64_t frame, const CacheWork& work) const {
    std::vector<Candidate> candidates;
    candidates.reserve(seen.size() + fresh.size());
    for (std::uint32_t slot : seen) {
        if (std::optional<Candidate> c = candidateFor(slot, frame, work)) candidates.push_back(*c);
    }
    for (std::uint32_t i = 0; i < fresh.size(); ++i) {
        const bool dynamic = fresh[i].set == shared::CACHE_SET_DYNAMIC;
        const std::uint32_t update = updateCost(fresh[i], work);
        candidates.push_back({candidateOrder(dynamic ? 1 : 0, 0), packCacheKey(fresh[i]),
                              firstFresh + i, dynamic ? update : 2 * update});
    }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
        return a.order != b.order ? a.order < b.order : a.key < b.key;
    });
    return candidates;
}

// Spends the budget: dynamic entries up to half of it (so new keys cannot starve a moving
// object), new keys, then the rest in order. Adds the rays spent to `spent`.
std::vector<bool> IrradianceCacheDirectory::chooseWithinBudget(
    std::span<const Candidate> candidates, std::uint64_t rayBudget, std::uint64_t& spent) {
    const std::uint64_t budget = rayBudget == 0 ? ~0ull : rayBudget;
    std::vector<bool> chosen(candidates.size(), false);
    auto take = [&](std::size_t i, std::uint64_t limit) {
        if (chosen[i] || spent + candidates[i].cost > limit) return;
        chosen[i] = true;
        spent += candidates[i].cost;
    };
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        if (candidates[i].cls() == 1) take(i, budget / 2);
    }
    for (std::size_t i = 0; i < candidates.size(); ++i) take(i, budget);
    return chosen;
}

// The slots of the chosen candidates, in candidate order: a fresh key gets one, evicting if the
// memory budget is full, or is dropped (and its rays given back) when there is no room.
std::vector<std::uint32_t> IrradianceCacheDirectory::slotsForChosen(
    std::span<const Candidate> candidates, const std::vector<bool>& chosen,
    std::span<const CacheKey> fresh, std::uint32_t firstFresh, std::uint64_t frame, double time,
    CacheFrameLists& lists) {
    std::size_t wanted = 0;
    for (std::size_t i = 0; i < candidates.size(); ++i)
        wanted += chosen[i] && candidates[i].index >= firstFresh;
    std::uint32_t room = wanted ? makeRoom(wanted, frame, lists) : 0;
    std::vector<std::uint32_t> selected;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        if (!chosen[i]) {
            ++lists.waiting;
            continue;
        }
        std::uint32_t slot = candidates[i].index;
        if (slot >= firstFresh) {
            if (room == 0) {
                ++lists.dropped;
                lists.rays -= candidates[i].cost;
                continue;
            }
            --room;
            slot = allocate(fresh[slot - firstFresh], frame, time, lists);
        }
        selected.push_back(slot);
    }
    return selected;
}

// This frame's flags and phases: zero except on the selected entries, which are listed in
// `lists.update`, static ones first, each part in slot order.
void IrradianceCacheDirectory::startUpdates(std::vector<std::uint32_t>& selected,
                                            std::uint64_t frame, double time, const CacheWork& work,
                                            CacheFrameLists& lists) {
    for (shared::CacheEntry& e : mEntries) e.flags = 0u;
    std::sort(selected.begin(), selected.end(), [&](std::uint32_t a, std::uint32_t b) {
        bool sa = mSlots[a].key.set == shared::CACHE_SET_STATIC,
             sb = mSlots[b].key.set == shared::CACHE_SET_STATIC;
        return sa != sb ? sa : a < b;
    });
    for (std::uint32_t slot : selected) {
        Slot& s = mSlots[slot];
        shared::CacheEntry& e = mEntries[slot];
        const bool isStatic = s.key.set == shared::CACHE_SET_STATIC;
        e.flags = s.reset ? shared::CACHE_ENTRY_RESET : 0u;
        e.phase = (isStatic ? s.traced : s.updates) % std::max(work.phases, 1u);
        if (isStatic && s.traced < work.phases) {
            e.flags |= shared::CACHE_ENTRY_TRACE;
            lists.trace.push_back(slot);
        }
        if (!isStatic) {
            // A dynamic entry's key is a world voxel, so its static hits stay valid while it lives
            // (until an edit nearby): the first update of each phase traces the static world and
            // keeps the hits, the later ones trace only the dynamic grid (visibility_dynamic.comp).
            // Beyond 64 phases the bit set has no room: every update traces.
            const std::uint64_t bit = e.phase < 64 ? 1ull << e.phase : 0ull;
            if ((s.tracedPhases & bit) == 0) e.flags |= shared::CACHE_ENTRY_TRACE;
            s.tracedPhases |= bit;
        }
        if (isStatic) {
            ++lists.staticUpdates;
            ++s.traced;
        }
        s.updates = s.reset ? 1 : s.updates + 1;
        s.reset = false;
        s.lastUpdate = time;
        s.lastUpdateFrame = frame;
        e.updatedAt = static_cast<float>(time);
        lists.update.push_back(slot);
    }
}

void IrradianceCacheDirectory::relightAll() {
    for (Slot& s : mSlots) s.reset = s.reset || s.live;
}

std::uint32_t IrradianceCacheDirectory::invalidateStatic(std::span<const glm::ivec3> editedCellMins,
                                                         float radius) {
    if (editedCellMins.empty()) return 0;
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::ivec3& c : editedCellMins) {
        lo = glm::min(lo, glm::vec3(c));
        hi = glm::max(hi, glm::vec3(c + 8));
    }
    std::uint32_t marked = 0;
    for (Slot& s : mSlots) {
        const bool isStatic = s.key.set == shared::CACHE_SET_STATIC;
        if (!s.live || (isStatic ? s.traced == 0 : s.tracedPhases == 0)) continue;
        glm::vec3 p = glm::vec3(s.key.voxel) + 0.5f;
        // Quick reject against the edits' bounds, then the distance to each edited cell.
        glm::vec3 gap = glm::max(glm::max(lo - p, p - hi), glm::vec3(0.0f));
        if (glm::dot(gap, gap) > radius * radius) continue;
        for (const glm::ivec3& c : editedCellMins) {
            glm::vec3 g =
                glm::max(glm::max(glm::vec3(c) - p, p - glm::vec3(c + 8)), glm::vec3(0.0f));
            if (glm::dot(g, g) <= radius * radius) {
                if (isStatic) {
                    s.traced = 0;
                    s.reset = true;
                    ++marked;
                } else {
                    s.tracedPhases = 0;  // re-traced as its phases come round; its value blends on
                }
                break;
            }
        }
    }
    return marked;
}

std::vector<shared::CacheBucket> IrradianceCacheDirectory::buildTable() const {
    const std::uint32_t buckets = std::bit_ceil(std::max<std::uint32_t>(2u * usedSlots(), 64u));
    std::vector<shared::CacheBucket> table(
        buckets, shared::CacheBucket{glm::uvec4(shared::CACHE_TABLE_EMPTY)});
    for (std::uint32_t slot = 0; slot < mSlots.size(); ++slot) {
        const Slot& s = mSlots[slot];
        if (!s.live) continue;
        glm::uvec2 w = keyWords(s.key);
        std::uint32_t b = cacheKeyHash(s.key) & (buckets - 1);
        while (table[b].keySlot.x != shared::CACHE_TABLE_EMPTY) b = (b + 1) & (buckets - 1);
        table[b].keySlot = glm::uvec4(w.x, w.y, slot, 0);
    }
    return table;
}

}  // namespace engine::render
