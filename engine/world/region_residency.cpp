#include "world/region_residency.h"

#include <algorithm>

#include "core/check.h"

namespace engine::world {

namespace {
constexpr float kRegionVoxels = float(kRegionCells * kBrickDim);
}

RegionResidency::RegionResidency(std::unique_ptr<RegionSource> source,
                                 const ResidencySettings& settings)
    : mSource(std::move(source)),
      mSettings(settings),
      mSizeInCells(mSource->worldSizeInCells()),
      mRegionCounts(regionCount(mSizeInCells)),
      mReach(settings.radiusVoxels) {
    const std::size_t n = std::size_t(mRegionCounts.x) * mRegionCounts.y * mRegionCounts.z;
    mTable.resize(n);
    mState.assign(n, RegionState::Absent);
    mBytes.assign(n, 0);
    mPinned.assign(n, 0);
    mLoader = std::thread([this] { run(); });
}

RegionResidency::~RegionResidency() {
    {
        std::lock_guard lock(mMutex);
        mStop = true;
        mQueue.clear();
    }
    mWake.notify_all();
    mLoader.join();
}

std::uint64_t RegionResidency::tableBytes() const {
    return mTable.size() * (sizeof(std::unique_ptr<ResidentRegion>) + sizeof(RegionState));
}

MaterialId RegionResidency::get(glm::ivec3 p) const {
    if (glm::any(glm::lessThan(p, glm::ivec3(0))) ||
        glm::any(glm::greaterThanEqual(p, mSizeInCells * kBrickDim)))
        return kEmpty;
    const glm::ivec3 r = p / (kRegionCells * kBrickDim);
    const ResidentRegion* region = mTable[index({r.x, r.y, r.z})].get();
    return region ? region->get(p) : kEmpty;  // not resident: air (see the header)
}

float RegionResidency::distance(RegionKey key, glm::vec3 eye) const {
    const CellRange range = regionCells(key, mSizeInCells);
    const glm::vec3 lo(range.min * kBrickDim), hi(range.max * kBrickDim);
    const glm::vec3 d = glm::max(glm::max(lo - eye, eye - hi), glm::vec3(0.0f));
    return glm::length(d);
}

void RegionResidency::take(Loaded loaded, std::vector<std::string>* errors) {
    const std::size_t i = index(loaded.key);
    if (mState[i] == RegionState::Resident) {  // asked for twice: keep the first
        std::lock_guard lock(mMutex);
        mToFree.push_back(std::move(loaded.region));
        return;
    }
    if (!loaded.region) {
        mState[i] = RegionState::Failed;  // seen as empty; not asked for again
        if (errors) errors->push_back(std::move(loaded.error));
        return;
    }
    mBytes[i] = loaded.region->bytes();
    mResidentBytes += mBytes[i];
    mTable[i] = std::move(loaded.region);
    mState[i] = RegionState::Resident;
    mResident.push_back(loaded.key);
}

std::size_t RegionResidency::collect(std::vector<std::string>* errors) {
    std::vector<Loaded> done;
    {
        std::lock_guard lock(mMutex);
        done.swap(mDone);
    }
    for (Loaded& l : done) take(std::move(l), errors);
    return done.size();
}

std::size_t RegionResidency::waitIdle(std::vector<std::string>* errors) {
    {
        std::unique_lock lock(mMutex);
        mIdle.wait(lock, [&] { return mQueue.empty() && !mLoading; });
    }
    return collect(errors);
}

void RegionResidency::evictAt(std::size_t i) {
    const RegionKey key = mResident[i];
    const std::size_t t = index(key);
    mResidentBytes -= mBytes[t];
    mBytes[t] = 0;
    {
        std::lock_guard lock(mMutex);  // freed on the loader thread, not in the frame
        mToFree.push_back(std::move(mTable[t]));
    }
    mWake.notify_one();
    mState[t] = RegionState::Absent;
    mResident[i] = mResident.back();
    mResident.pop_back();
}

void RegionResidency::evict(RegionKey key) {
    auto it = std::find(mResident.begin(), mResident.end(), key);
    if (it != mResident.end()) evictAt(std::size_t(it - mResident.begin()));
}

void RegionResidency::setPinned(std::span<const RegionKey> keys) {
    for (RegionKey k : mPinnedKeys) mPinned[index(k)] = 0;
    mPinnedKeys.assign(keys.begin(), keys.end());
    for (RegionKey k : mPinnedKeys) mPinned[index(k)] = 1;
}

std::unique_ptr<ResidentRegion> RegionResidency::release(RegionKey key) {
    return std::move(mTable[index(key)]);
}

void RegionResidency::recycle(std::unique_ptr<ResidentRegion> region) {
    {
        std::lock_guard lock(mMutex);
        mToFree.push_back(std::move(region));
    }
    mWake.notify_one();
}

void RegionResidency::request(std::span<const RegionKey> keys) {
    std::lock_guard lock(mMutex);
    for (RegionKey k : mQueue)
        if (mState[index(k)] == RegionState::Requested) mState[index(k)] = RegionState::Absent;
    mQueue.clear();
    for (RegionKey k : keys) {
        RegionState& s = mState[index(k)];
        if (s == RegionState::Resident || s == RegionState::Requested) continue;
        s = RegionState::Requested;
        mQueue.push_back(k);
    }
    mWake.notify_one();
}

ResidencyReport RegionResidency::update(glm::vec3 eye) {
    ResidencyReport report;
    report.loaded = collect(&report.errors);

    // Over the budget: evict the farthest first. Evicting inside the radius means the budget
    // cannot hold the radius here: requests stop short of what was evicted until the eye moves
    // on by a region.
    if (mResidentBytes > mSettings.budgetBytes) {
        std::vector<std::pair<float, RegionKey>> byDistance;
        byDistance.reserve(mResident.size());
        for (RegionKey k : mResident) byDistance.push_back({distance(k, eye), k});
        std::sort(byDistance.begin(), byDistance.end(),
                  [](const auto& a, const auto& b) { return a.first > b.first; });
        for (const auto& [d, k] : byDistance) {
            if (mResidentBytes <= mSettings.budgetBytes) break;
            if (mPinned[index(k)]) continue;
            evict(k);
            ++report.evicted;
            if (d <= mReach) {
                mReach = d - 1.0f;  // below 0 when the eye's own region went: ask for nothing
                mReachEye = eye;
            }
        }
    } else if (mReach < mSettings.radiusVoxels && glm::length(eye - mReachEye) >= kRegionVoxels) {
        mReach = mSettings.radiusVoxels;
    }

    // What is wanted and missing, nearest first.
    const glm::ivec3 lo = glm::clamp(glm::ivec3(glm::floor((eye - mReach) / kRegionVoxels)),
                                     glm::ivec3(0), mRegionCounts - 1);
    const glm::ivec3 hi = glm::clamp(glm::ivec3(glm::floor((eye + mReach) / kRegionVoxels)),
                                     glm::ivec3(0), mRegionCounts - 1);
    std::vector<std::pair<float, RegionKey>> wanted;
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
                const RegionKey k{x, y, z};
                const RegionState s = mState[index(k)];
                if (s == RegionState::Resident || s == RegionState::Failed) continue;
                const float d = distance(k, eye);
                if (d <= mReach) wanted.push_back({d, k});
            }
    std::sort(wanted.begin(), wanted.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first < b.first : a.second < b.second;
    });
    std::vector<RegionKey> keys;
    keys.reserve(wanted.size());
    for (const auto& w : wanted) keys.push_back(w.second);
    request(keys);
    report.pending = keys.size();
    return report;
}

void RegionResidency::run() {
    for (;;) {
        std::vector<std::unique_ptr<ResidentRegion>> toFree;
        RegionKey key;
        {
            std::unique_lock lock(mMutex);
            mWake.wait(lock, [&] { return mStop || !mQueue.empty() || !mToFree.empty(); });
            if (mStop) return;
            toFree.swap(mToFree);
            if (mQueue.empty()) {
                lock.unlock();
                continue;  // toFree goes out of scope here, off the lock
            }
            key = mQueue.front();
            mQueue.pop_front();
            mLoading = true;
        }
        toFree.clear();
        Loaded loaded{key, nullptr, {}};
        Result<RegionSnapshot> voxels = mSource->load(key);
        if (voxels)
            loaded.region = std::make_unique<ResidentRegion>(std::move(*voxels));
        else
            loaded.error = voxels.error().message;
        {
            std::lock_guard lock(mMutex);
            mDone.push_back(std::move(loaded));
            mLoading = false;
        }
        mIdle.notify_all();
    }
}

}  // namespace engine::world
