#include "render/irradiance_cache/irradiance_cache.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numeric>
#include <optional>
#include <utility>

#include "core/check.h"
#include "core/hash.h"
#include "gpu/command_list.h"
#include "gpu/uploader.h"
#include "render/frame_commands.h"
#include "render/frame_result.h"
#include "render/irradiance_cache/cache_lod.h"
#include "render/irradiance_cache/cache_params.h"
#include "shared/irradiance_cache.h"
#include "shared/shader_features.h"

namespace engine::render {

namespace {

// The buffers every cache pass binds (shaders/irradiance_cache/irradiance_cache.glsl).
// One declaration for all the passes: a buffer any of them writes is written.
struct CachePassIo {
    const gpu::Buffer& params;       // read
    const gpu::Buffer& frameParams;  // read
    const gpu::Buffer& directions;   // read
    const gpu::Buffer& entries;      // read
    const gpu::Buffer& table;        // read
    gpu::Buffer& lists;          // the update and trace lists read; the face lists (faces) written
    gpu::Buffer& staticHits;     // read and written
    gpu::Buffer& selectedHits;   // read and written
    gpu::Buffer& irradiance;     // read and written
    gpu::Buffer& filtered;       // read and written
    const gpu::Buffer& gbuffer;  // read
    gpu::Buffer& radiance;       // read and written: the indirect term is added
    gpu::Buffer& indirect;       // written: the indirect term alone
    gpu::Buffer& counters;       // read and written; also the indirect dispatches' arguments
    gpu::Buffer& latePixels;     // written by the gather, read by the late gather
    auto bindings() const {
        return std::to_array<PassBinding>({{shared::CACHE_BINDING_PARAMS, &params},
                                           {shared::CACHE_BINDING_FRAME, &frameParams},
                                           {shared::CACHE_BINDING_DIRECTIONS, &directions},
                                           {shared::CACHE_BINDING_ENTRIES, &entries},
                                           {shared::CACHE_BINDING_TABLE, &table},
                                           {shared::CACHE_BINDING_LISTS, &lists},
                                           {shared::CACHE_BINDING_STATIC_HITS, &staticHits},
                                           {shared::CACHE_BINDING_SELECTED_HITS, &selectedHits},
                                           {shared::CACHE_BINDING_IRRADIANCE, &irradiance},
                                           {shared::CACHE_BINDING_FILTERED, &filtered},
                                           {shared::CACHE_BINDING_GBUFFER, &gbuffer},
                                           {shared::CACHE_BINDING_RADIANCE, &radiance},
                                           {shared::CACHE_BINDING_INDIRECT, &indirect},
                                           {shared::CACHE_BINDING_COUNTERS, &counters},
                                           {shared::CACHE_BINDING_LATE_PIXELS, &latePixels}});
    }
};
constexpr std::uint32_t kOwnBindings = bindingCount<CachePassIo>();

// Words of the lists buffer per slot: the update and trace lists (one each), then the face lists
// faces.comp builds (six per slot for the updates' faces, six for the trace list's; see
// cacheListedFace in shaders/irradiance_cache/irradiance_cache.glsl).
constexpr std::uint64_t kListWordsPerSlot = 2 + 2 * shared::CACHE_FACES;

// CACHE_DIRECTION_SETS sets of K cosine-distributed directions in a face's frame (z along the
// normal). The base set is a jittered Fibonacci lattice in (u1, u2) = (r^2, phi / 2pi); set r is
// the base shifted by its own uniform (a, b) modulo 1 (a Cranley-Patterson rotation), which keeps
// the lattice's stratification and makes every direction of the set cosine-distributed on its
// own: E = pi * mean(L) stays unbiased per entry over rotations. Shifting u2 turns the set about
// the normal, shifting u1 moves it across the strata of cos(theta).
std::vector<glm::vec4> makeDirections(std::uint32_t count) {
    std::vector<glm::vec2> base(count);
    Rng rng(0x1C0FFEEu + count);
    const float golden = 0.6180339887f;
    for (std::uint32_t k = 0; k < count; ++k) {
        float u1 = (static_cast<float>(k) + rng.nextFloat()) / static_cast<float>(count);
        float u2 = std::fmod(static_cast<float>(k) * golden + rng.nextFloat() * 0.25f, 1.0f);
        base[k] = {u1, u2};
    }
    // Interleave so the S rays of one update spread over the hemisphere (index j * K/S + r).
    std::uint32_t step = 7;
    while (std::gcd(step, count) != 1) step += 2;
    auto wrap = [](float u) { return u >= 1.0f ? u - 1.0f : u; };
    std::vector<glm::vec4> out(std::size_t(count) * shared::CACHE_DIRECTION_SETS);
    for (std::uint32_t set = 0; set < shared::CACHE_DIRECTION_SETS; ++set) {
        const float a = rng.nextFloat(), b = rng.nextFloat();
        for (std::uint32_t k = 0; k < count; ++k) {
            glm::vec2 u = base[(k * step) % count];
            float u1 = wrap(u.x + a), u2 = wrap(u.y + b);
            float r = std::sqrt(u1), phi = 2.0f * 3.14159265f * u2;
            out[std::size_t(set) * count + k] = glm::vec4(
                r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u1)), 0.0f);
        }
    }
    return out;
}

// The distinct keys of one frame's scan (packCacheKey values): open addressing in one array sized
// for the most keys the scan can produce, so a key costs a probe, not an allocation (an
// unordered_set's node per key was most of the scan's time). ~0 is never a key: a voxel's
// coordinates stay below 0xFFFF.
class KeySet {
public:
    explicit KeySet(std::size_t maxKeys)
        : mBuckets(std::bit_ceil(std::max<std::size_t>(2 * maxKeys, 64)), kEmpty) {}
    // True when the key was not in the set yet.
    bool insert(std::uint64_t key) {
        const std::size_t mask = mBuckets.size() - 1;
        for (std::size_t b = mix(key) & mask;; b = (b + 1) & mask) {
            if (mBuckets[b] == key) return false;
            if (mBuckets[b] == kEmpty) {
                mBuckets[b] = key;
                ++mSize;
                return true;
            }
        }
    }
    std::size_t size() const { return mSize; }

private:
    static constexpr std::uint64_t kEmpty = ~0ull;
    static std::uint64_t mix(std::uint64_t x) {  // splitmix64's finaliser
        x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
        x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
        return x ^ (x >> 31);
    }
    std::vector<std::uint64_t> mBuckets;
    std::size_t mSize = 0;
};

// The keys a frame's pixels see, from a G-buffer: the static ones (voxel faces, or coarse 2x2
// patches far away), then an N^3 neighbourhood around each visible dynamic voxel, so the values
// a moving object interpolates are ready before it gets there (§4.4).
struct VisibleKeys {
    std::vector<CacheKey> keys;
    std::uint32_t staticKeys = 0;           // distinct static keys seen
    std::vector<glm::ivec3> dynamicVoxels;  // distinct dynamic voxels seen
};

VisibleKeys visibleKeys(const lighting::IrradianceCacheSettings& settings,
                        const CacheFrameInput& frameIn) {
    VisibleKeys out;
    // Neighbouring pixels mostly see the same voxel: a key equal to the previous pixel's of its set
    // skips the set's probe.
    KeySet seenStatic(frameIn.gbuffer.size()), seenDynamic(frameIn.gbuffer.size());
    std::uint64_t lastStatic = ~0ull, lastDynamic = ~0ull;
    // A static pixel whose voxel, face and level are the previous pixel's has its key already.
    glm::ivec4 lastVoxelFace(-1);
    bool lastFar = false;
    std::optional<StaticKeys> staticKeys;
    // A static pixel far enough away reads a coarse entry where its face's 2x2 patch is open.
    const bool lod = settings.lodDistance > 0.0f && frameIn.grid != nullptr;
    if (lod) staticKeys.emplace(*frameIn.grid, settings.lodDistance);
    for (const shared::GBufferTexel& g : frameIn.gbuffer) {
        const auto face = static_cast<std::uint32_t>(g.voxel.w);
        if (face >= 6u) continue;
        glm::ivec3 v(g.voxel);
        if ((g.data.w & shared::GBUFFER_FLAG_DYNAMIC) != 0u) {
            const std::uint64_t packed = packCacheKey({v, shared::CACHE_SET_DYNAMIC});
            if (packed != lastDynamic && seenDynamic.insert(packed)) out.dynamicVoxels.push_back(v);
            lastDynamic = packed;
            continue;
        }
        const float distance = std::bit_cast<float>(g.data.y);
        const bool far = lod && distance >= settings.lodDistance;
        if (g.voxel == lastVoxelFace && far == lastFar) continue;
        lastVoxelFace = g.voxel;
        lastFar = far;
        const CacheKey key =
            lod ? staticKeys->keyFor(v, face, distance) : CacheKey{v, shared::CACHE_SET_STATIC};
        const std::uint64_t packed = packCacheKey(key);
        if (packed != lastStatic && seenStatic.insert(packed)) out.keys.push_back(key);
        lastStatic = packed;
    }
    out.staticKeys = static_cast<std::uint32_t>(seenStatic.size());
    const int half = static_cast<int>(settings.neighbourhood / 2);
    const std::size_t side = 2 * std::size_t(half) + 1;
    KeySet added(out.dynamicVoxels.size() * side * side * side);
    for (const glm::ivec3& v : out.dynamicVoxels) {
        for (int z = -half; z <= half; ++z) {
            for (int y = -half; y <= half; ++y) {
                for (int x = -half; x <= half; ++x) {
                    glm::ivec3 n = v + glm::ivec3(x, y, z);
                    if (glm::any(glm::lessThan(n, glm::ivec3(0))) ||
                        glm::any(glm::greaterThan(n, glm::ivec3(0xFFFE))))
                        continue;
                    CacheKey key{n, shared::CACHE_SET_DYNAMIC};
                    if (added.insert(packCacheKey(key))) out.keys.push_back(key);
                }
            }
        }
    }
    return out;
}

// Workgroups of CACHE_GROUP_SIZE threads for a 1-D grid of `threads`, in rows of 65535 groups
// (the shaders' cacheThread() undoes it).
glm::uvec2 threadGroups(std::uint64_t threads) {
    std::uint64_t groups = (threads + shared::CACHE_GROUP_SIZE - 1) / shared::CACHE_GROUP_SIZE;
    return {static_cast<std::uint32_t>(std::min<std::uint64_t>(groups, 65535)),
            static_cast<std::uint32_t>((groups + 65534) / 65535)};
}

}  // namespace

IrradianceCache::IrradianceCache(gpu::Context& ctx)
    : mCtx(ctx),
      mFaces(ctx, "cache.faces", "irradiance_cache/faces", kOwnBindings),
      mListDispatch(ctx, "cache.list_dispatch", "irradiance_cache/list_dispatch", kOwnBindings),
      mTraceStatic(ctx, "cache.trace_static", "irradiance_cache/trace_static", kOwnBindings),
      mVisibilityStatic(ctx, "cache.visibility_static", "irradiance_cache/visibility_static",
                        kOwnBindings),
      mVisibilityStaticFull(ctx, "cache.visibility_static",
                            "irradiance_cache/visibility_static_full", kOwnBindings),
      mVisibilityDynamic(ctx, "cache.visibility_dynamic", "irradiance_cache/visibility_dynamic",
                         kOwnBindings),
      mVisibilityDynamicFull(ctx, "cache.visibility_dynamic",
                             "irradiance_cache/visibility_dynamic_full", kOwnBindings),
      mBounce(ctx, "cache.bounce", "irradiance_cache/light_bounce", kOwnBindings),
      mFilter(ctx, "cache.filter", "irradiance_cache/filter", kOwnBindings),
      mGather(ctx, "cache.gather", "irradiance_cache/gather", kOwnBindings),
      mGatherLate(ctx, "cache.gather_late", "irradiance_cache/gather_late", kOwnBindings),
      mUploader(ctx) {
    mParams =
        gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::CacheParams), "cache.params");
    mCounters = gpu::Buffer(ctx, gpu::BufferKind::Storage, shared::CACHE_COUNTER_COUNT * 4,
                            "cache.counters");
    mCountersHost = gpu::Buffer(ctx, gpu::BufferKind::Readback, shared::CACHE_COUNTER_COUNT * 4,
                                "cache.countersHost");
}

std::uint64_t IrradianceCache::bytesPerSlot(const lighting::IrradianceCacheSettings& s) {
    return sizeof(shared::CacheEntry) +
           shared::CACHE_FACES * s.directions * 4ull                     // entry, static hits
           + 2ull * shared::CACHE_FACES * sizeof(glm::vec4)              // irradiance, filtered
           + 2ull * sizeof(shared::CacheBucket) + kListWordsPerSlot * 4  // table, lists
           + shared::CACHE_FACES * s.raysPerUpdate * 4ull;               // selected hits
}

std::uint32_t IrradianceCache::directionRotation(glm::ivec3 voxel, std::uint32_t set,
                                                 std::uint32_t seed, std::uint32_t coarse) {
    const std::uint32_t x =
        static_cast<std::uint32_t>(voxel.x) | (static_cast<std::uint32_t>(voxel.y) << 16);
    const std::uint32_t y = static_cast<std::uint32_t>(voxel.z) |
                            (coarse << shared::CACHE_KEY_COARSE_SHIFT) | (set << 31);
    return pcgHash(x ^ pcgHash(y ^ pcgHash(seed ^ 0x9E3779B9u)));
}

glm::vec3 IrradianceCache::rayDirection(glm::ivec3 voxel, std::uint32_t set, std::uint32_t face,
                                        std::uint32_t k, std::uint32_t coarse) const {
    const std::uint32_t rotation = directionRotation(voxel, set, mSeed, coarse);
    glm::vec3 local(
        mDirections[std::size_t(rotation % shared::CACHE_DIRECTION_SETS) * mSettings.directions +
                    k]);
    const std::uint32_t mirror = rotation >> 29;
    if (mirror & 1u) std::swap(local.x, local.y);
    if (mirror & 2u) local.x = -local.x;
    if (mirror & 4u) local.y = -local.y;
    const std::uint32_t axis = face >> 1;
    glm::vec3 d;
    d[(axis + 1) % 3] = local.x;
    d[(axis + 2) % 3] = local.y;
    d[axis] = (face & 1u) ? local.z : -local.z;
    return d;
}

std::uint32_t IrradianceCache::directionIndex(std::uint32_t slot, std::uint32_t j) const {
    return j * (mSettings.directions / mSettings.raysPerUpdate) + mDirectory.entry(slot).phase;
}

void IrradianceCache::clear() { mConfigured = false; }

void IrradianceCache::reset(const lighting::IrradianceCacheSettings& settings, std::uint32_t seed) {
    mSettings = settings;
    mSeed = seed;
    mConfigured = true;
    mDirectionsUploaded = false;
    auto slots = static_cast<std::uint32_t>(
        std::clamp<std::uint64_t>(settings.budgetBytes / bytesPerSlot(settings), 1, 1u << 24));
    mDirectory = IrradianceCacheDirectory(slots);
    mDirections = makeDirections(settings.directions);
    mDirectionBuffer = gpu::Buffer(mCtx, gpu::BufferKind::Storage,
                                   mDirections.size() * sizeof(glm::vec4), "cache.directions");
    mCapacity = 0;
    mStaticHits = {};
    mIrradiance = {};
    mFiltered = {};
    mEntries = {};
    mLists = {};
    mTable = {};
    mSelectedHits = {};
}

void IrradianceCache::ensureCapacity(std::uint32_t slots, gpu::CommandList& cmd) {
    if (slots <= mCapacity) return;
    std::uint32_t capacity =
        std::min(std::max(std::bit_ceil(slots), 1024u), std::max(mDirectory.maxSlots(), slots));
    // Every new buffer is cleared once, when made: lavapipe's device memory is host memory whose
    // pages are mapped at their first write, and a pass that first writes them pays for the page
    // faults (on a moving camera the slots' static hits came to trace_static unwritten, and the
    // faults doubled its time).
    auto make = [&](gpu::Buffer& buffer, std::uint64_t bytes, const char* name) {
        buffer = gpu::Buffer(mCtx, gpu::BufferKind::Storage, bytes, name);
        cmd.fillBuffer(buffer, 0);
    };
    std::vector<std::pair<gpu::Buffer*, gpu::Buffer>> grown;  // (buffer, its old contents)
    auto grow = [&](gpu::Buffer& buffer, std::uint64_t bytesPerSlot, const char* name) {
        if (buffer.valid()) grown.emplace_back(&buffer, std::move(buffer));
        make(buffer, capacity * bytesPerSlot, name);
    };
    grow(mStaticHits, shared::CACHE_FACES * mSettings.directions * 4ull, "cache.staticHits");
    grow(mIrradiance, shared::CACHE_FACES * sizeof(glm::vec4), "cache.irradiance");
    grow(mFiltered, shared::CACHE_FACES * sizeof(glm::vec4), "cache.filtered");
    make(mEntries, capacity * sizeof(shared::CacheEntry), "cache.entries");
    make(mLists, kListWordsPerSlot * capacity * 4, "cache.lists");
    make(mSelectedHits, std::uint64_t(capacity) * shared::CACHE_FACES * mSettings.raysPerUpdate * 4,
         "cache.selectedHits");
    for (auto& [buffer, old] : grown) {
        cmd.copyBuffer(old, *buffer, {{0, 0, old.size()}});
        mRetired.push_back(std::move(old));
    }
    mCapacity = capacity;
}

void IrradianceCache::pickUpdates(const lighting::IrradianceCacheSettings& settings,
                                  const CacheFrameInput& frameIn, gpu::Uploader& uploader,
                                  gpu::CommandList& cmd) {
    mRetired.clear();  // the previous frame has completed
    // The seed picks every entry's directions: a new seed invalidates every cached hit.
    if (!mConfigured || !(settings == mSettings) || frameIn.seed != mSeed)
        reset(settings, frameIn.seed);
    mStats = {};
    const VisibleKeys seen = visibleKeys(settings, frameIn);
    const std::vector<CacheKey>& visible = seen.keys;
    const std::vector<glm::ivec3>& dynamicVoxels = seen.dynamicVoxels;
    mStats.visibleStatic = seen.staticKeys;
    mStats.visibleDynamic = static_cast<std::uint32_t>(dynamicVoxels.size());

    // The budget's terms. Static entries within a few voxels of a visible moving object see its
    // shadow and bounce change every frame: they come before the merely stale ones.
    CacheWork work;
    work.rayBudget = settings.rayBudget;
    work.raysPerUpdate = settings.raysPerUpdate * shared::CACHE_FACES;
    work.phases = settings.directions / settings.raysPerUpdate;
    work.convergedAfter = static_cast<std::uint32_t>(std::ceil(1.0f / settings.alpha));
    if (frameIn.grid != nullptr) {
        // The shaders' rule for a static entry's face (cacheFaceExposed): its neighbour is not
        // static solid.
        work.openFaces = [grid = frameIn.grid](glm::ivec3 v) {
            std::uint32_t open = 0;
            for (int axis = 0; axis < 3; ++axis) {
                glm::ivec3 step(0);
                step[axis] = 1;
                open +=
                    (grid->get(v - step) == world::kEmpty) + (grid->get(v + step) == world::kEmpty);
            }
            return open;
        };
    }
    work.objectsMoved = frameIn.objectsMoved;
    if (!dynamicVoxels.empty() && frameIn.objectsMoved) {
        constexpr int kNearMovingObject = 8;  // voxels
        work.nearMin = glm::ivec3(std::numeric_limits<int>::max());
        work.nearMax = glm::ivec3(std::numeric_limits<int>::min());
        for (const glm::ivec3& v : dynamicVoxels) {
            work.nearMin = glm::min(work.nearMin, v - kNearMovingObject);
            work.nearMax = glm::max(work.nearMax, v + kNearMovingObject);
        }
    }
    if (frameIn.lightsChanged) mDirectory.relightAll();
    mStats.invalidated = mDirectory.invalidateStatic(frameIn.editedCellMins, settings.maxRayLength);
    CacheFrameLists lists =
        mDirectory.beginFrame(visible, frameIn.timeSeconds, settings.fadeSeconds, work);
    mUpdate = std::move(lists.update);
    mStaticUpdates = lists.staticUpdates;
    mTrace = std::move(lists.trace);
    mStats.updated = static_cast<std::uint32_t>(mUpdate.size());
    mStats.dynamicEntries = static_cast<std::uint32_t>(mUpdate.size()) - mStaticUpdates;
    mStats.traced = static_cast<std::uint32_t>(mTrace.size());
    mStats.waiting = lists.waiting;
    mStats.entries = mDirectory.liveEntries();
    for (const CacheKey& key : visible)
        mStats.coarseEntries += key.coarse != 0 && mDirectory.slotOf(key) != ~0u;
    mStats.dropped = lists.dropped;
    mStats.evicted = lists.evicted;
    mStats.rays = lists.rays;
    mFrameIndex = frameIn.frameIndex;
    mImage = frameIn.size;
    const std::uint64_t latePixelBytes =
        std::max<std::uint64_t>(std::uint64_t(mImage.x) * mImage.y, 1) * 4;
    if (!mLatePixels.valid() || mLatePixels.size() != latePixelBytes) {
        if (mLatePixels.valid()) mRetired.push_back(std::move(mLatePixels));
        mLatePixels =
            gpu::Buffer(mCtx, gpu::BufferKind::Storage, latePixelBytes, "cache.latePixels");
    }

    ensureCapacity(std::max(mDirectory.usedSlots(), 1u), cmd);
    if (lists.tableChanged || !mTable.valid()) {
        std::vector<shared::CacheBucket> table = mDirectory.buildTable();
        if (!mTable.valid() || mTable.size() != table.size() * sizeof(shared::CacheBucket)) {
            mTable = gpu::Buffer(mCtx, gpu::BufferKind::Storage,
                                 table.size() * sizeof(shared::CacheBucket), "cache.table");
        }
        uploader.write(mTable, 0, table.data(), table.size() * sizeof(shared::CacheBucket));
    }
    auto entries = mDirectory.entries();
    uploader.write(mEntries, 0, entries.data(), entries.size_bytes());
    uploader.write(mLists, 0, mUpdate.data(), mUpdate.size() * 4);
    uploader.write(mLists, std::uint64_t(mCapacity) * 4, mTrace.data(), mTrace.size() * 4);
    if (!mDirectionsUploaded) {  // fixed until the next reset
        uploader.write(mDirectionBuffer, 0, mDirections.data(),
                       mDirections.size() * sizeof(glm::vec4));
        mDirectionsUploaded = true;
    }

    CacheFrame frame;
    frame.updates = static_cast<std::uint32_t>(mUpdate.size());
    frame.staticUpdates = mStaticUpdates;
    frame.traces = static_cast<std::uint32_t>(mTrace.size());
    frame.buckets = static_cast<std::uint32_t>(mTable.size() / sizeof(shared::CacheBucket));
    frame.capacity = mCapacity;
    frame.frameIndex = frameIn.frameIndex;
    frame.seed = frameIn.seed;
    frame.image = frameIn.size;
    frame.timeSeconds = frameIn.timeSeconds;
    const shared::CacheParams params = cacheParams(settings, frame);
    uploader.write(mParams, 0, &params, sizeof(params));

    mStats.bytes = mParams.size() + mDirectionBuffer.size() + mEntries.size() + mTable.size() +
                   mLists.size() + mStaticHits.size() + mSelectedHits.size() + mIrradiance.size() +
                   mFiltered.size() + mLatePixels.size();
}

TechniquePlan IrradianceCache::plan(const lighting::LightingSettings& l, const SceneShape&,
                                    glm::uvec2 size) {
    TechniquePlan p;
    p.runs = lighting::usesCache(l);
    p.addsIndirect = true;
    // Its budget, and the G-buffer it reads back for the next frame's pick.
    p.deviceBytes =
        l.cache.budgetBytes + std::uint64_t(size.x) * size.y * sizeof(shared::GBufferTexel);
    p.features = {{FEATURE_CACHE_MULTI_BOUNCE, l.cache.bounces > 1u ? 1u : 0u},
                  {FEATURE_CACHE_FALLBACK, l.cache.fallbackRadius > 0u ? 1u : 0u}};
    return p;
}

std::string IrradianceCache::describe(const lighting::LightingSettings& l) {
    const lighting::IrradianceCacheSettings& c = l.cache;
    return fmt::format("cache K={} S={} bounces={} alpha={:g} N={} {} budget={}", c.directions,
                       c.raysPerUpdate, c.bounces, c.alpha, c.neighbourhood,
                       c.filter ? "filtered" : "unfiltered",
                       c.rayBudget ? fmt::format("{} rays", c.rayBudget) : std::string("none")) +
           (c.lodDistance > 0.0f ? fmt::format(" lod={:g}", c.lodDistance) : std::string());
}

void IrradianceCache::prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader&,
                              shared::FrameParams&) {
    if (changes.newWorld) clear();
    if (!mGBufferHost.valid() || in.size != mFrameInput.size) {
        mGBufferHost =
            gpu::Buffer(mCtx, gpu::BufferKind::Readback,
                        std::uint64_t(in.size.x) * in.size.y * sizeof(shared::GBufferTexel),
                        "cache.gbufferHost");
        mGBufferHostValid = false;
    }
    mFrameSettings = in.lighting.cache;
    CacheFrameInput& f = mFrameInput;
    f.size = in.size;
    f.timeSeconds = in.settings.timeSeconds;
    f.frameIndex = in.frameIndex;
    f.seed = in.lighting.seed;
    f.grid = &in.scene.grid;
    f.editedCellMins.clear();
    // Static rays through an edited cell are stale (a new world starts empty instead).
    if (!changes.newWorld) {
        for (const glm::ivec3& cell : changes.editedCells)
            f.editedCellMins.push_back(cell * world::kBrickDim);
    }
    f.objectsMoved = changes.objectsMoved;
    f.lightsChanged = changes.lightsEdited || changes.skyChanged;
}

void IrradianceCache::record(FrameCommands& commands, const FrameBuffers& frame) {
    mSplitFrame = !(mGBufferHostValid && mConfigured);
    const VkBufferCopy wholeGBuffer{0, 0, frame.gbuffer.size()};
    if (mSplitFrame) commands.current().copyBuffer(frame.gbuffer, mGBufferHost, {wholeGBuffer});
    // The host picks while the GPU runs what was recorded so far (or, split, after it ran).
    gpu::CommandList& cmd = commands.submitAndContinue(mSplitFrame);
    cmd.beginPass("cache.prepare");
    const auto start = std::chrono::steady_clock::now();
    mFrameInput.gbuffer = mGBufferHost.view<shared::GBufferTexel>();
    pickUpdates(mFrameSettings, mFrameInput, mUploader, cmd);
    mPickMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    mUploader.record(cmd);
    cmd.endPass();
    recordPasses(cmd, frame.scene,
                 {frame.frameParams, frame.gbuffer, frame.radiance, frame.indirect});
    // This frame's visible voxels, for the next frame's pick.
    cmd.copyBuffer(frame.gbuffer, mGBufferHost, {wholeGBuffer});
}

void IrradianceCache::collect(FrameResult& result) {
    mStats.raysTraced = mCountersHost.view<std::uint32_t>()[shared::CACHE_COUNTER_RAYS];
    mGBufferHostValid = true;
    result.cacheUsed = true;
    result.cacheSplitFrame = mSplitFrame;
    result.cachePrepareMs = mPickMs;
    result.cache = mStats;
}

void IrradianceCache::recordPasses(gpu::CommandList& cmd, const SceneBindings& scene,
                                   const Io& io) {
    CHECK(mConfigured);
    const CachePassIo own{mParams,    io.frameParams, mDirectionBuffer, mEntries,    mTable,
                          mLists,     mStaticHits,    mSelectedHits,    mIrradiance, mFiltered,
                          io.gbuffer, io.radiance,    io.indirect,      mCounters,   mLatePixels};
    const auto bindings = own.bindings();
    const std::uint64_t faces = shared::CACHE_FACES;
    cmd.fillBuffer(mCounters, 0);
    // The passes with ray loops run over the face lists this pass builds, in the workgroups
    // cache.list_dispatch counts for them (CACHE_COUNTER_ARGS_*).
    mFaces.record(cmd, scene, bindings,
                  threadGroups(std::max(mUpdate.size(), mTrace.size()) * faces));
    mListDispatch.record(cmd, scene, bindings, {1, 1});
    auto args = [](std::uint32_t counter) { return std::uint64_t(counter) * 4; };
    mTraceStatic.recordIndirect(cmd, scene, bindings, mCounters,
                                args(shared::CACHE_COUNTER_ARGS_TRACE));
    (mSettings.fullRetrace ? mVisibilityStaticFull : mVisibilityStatic)
        .recordIndirect(cmd, scene, bindings, mCounters, args(shared::CACHE_COUNTER_ARGS_STATIC));
    (mSettings.fullRetrace ? mVisibilityDynamicFull : mVisibilityDynamic)
        .recordIndirect(cmd, scene, bindings, mCounters, args(shared::CACHE_COUNTER_ARGS_DYNAMIC));
    mBounce.recordIndirect(cmd, scene, bindings, mCounters,
                           args(shared::CACHE_COUNTER_ARGS_UPDATES));
    mFilter.recordIndirect(cmd, scene, bindings, mCounters,
                           args(shared::CACHE_COUNTER_ARGS_UPDATES));
    mGather.record(cmd, scene, bindings, screenGroups(mImage));
    // The pixels the gather found no value for, in as many workgroups as it counted.
    mGatherLate.recordIndirect(cmd, scene, bindings, mCounters,
                               shared::CACHE_COUNTER_LATE_GROUPS * 4);
    cmd.copyBuffer(mCounters, mCountersHost, {{0, 0, mCounters.size()}});  // read by collect()
}

}  // namespace engine::render
