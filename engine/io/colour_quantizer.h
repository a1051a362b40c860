// Colour quantisation for importing colour grids: reduce the colours of many voxels to a palette
// of at most N materials and measure what that costs.
//
// The histogram keeps exact colours while there are few of them (so a grid with <= N distinct
// colours comes back exactly, error 0) and falls back to 6-bit-per-channel bins holding the mean
// of their members beyond 65 536 distinct colours. The palette is Heckbert's median cut
// (Heckbert 1982, "Color image quantization for frame buffer display") refined by weighted
// k-means (Lloyd) iterations; each voxel then takes the nearest palette colour (Euclidean in
// linear RGB), and ColourError accumulates the distances actually incurred.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <unordered_map>
#include <vector>

namespace engine::io {

// Albedo must lie in [0, 1]; NaN becomes 0.
glm::vec3 clampAlbedo(glm::vec3 c);

class ColourHistogram {
public:
    struct Entry {
        glm::dvec3 sum{0.0};  // sum of member colours (exact entries: colour * weight)
        std::uint64_t weight = 0;
        glm::vec3 mean() const { return glm::vec3(sum / double(weight)); }
    };

    void add(glm::vec3 colour, std::uint64_t weight = 1);
    bool binned() const { return mBinned; }
    std::uint64_t total() const { return mTotal; }
    std::vector<Entry> entries() const;

private:
    static std::uint64_t exactKey(glm::vec3 c);
    static std::uint64_t binKey(glm::vec3 c);
    void switchToBins();

    std::unordered_map<std::uint64_t, Entry> mEntries;
    bool mBinned = false;
    std::uint64_t mTotal = 0;
};

// At most maxColours colours; exactly the distinct colours when there are no more than that.
std::vector<glm::vec3> quantizeColours(const ColourHistogram& histogram, int maxColours);

// Nearest palette entry, memoised per exact colour (a voxel grid repeats its colours a lot).
class ColourMapper {
public:
    explicit ColourMapper(std::vector<glm::vec3> palette);
    int nearest(glm::vec3 colour);
    const std::vector<glm::vec3>& palette() const { return mPalette; }

private:
    struct Key {
        std::uint32_t r, g, b;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const {
            return std::size_t((std::uint64_t(k.r) * 0x9E3779B97F4A7C15ull) ^
                               (std::uint64_t(k.g) * 0xC2B2AE3D27D4EB4Full) ^
                               (std::uint64_t(k.b) * 0x165667B19E3779F9ull));
        }
    };
    std::vector<glm::vec3> mPalette;
    std::unordered_map<Key, int, KeyHash> mMemo;
};

struct ColourError {
    std::uint64_t count = 0;
    double sum = 0.0;
    double max = 0.0;
    void add(double e, std::uint64_t voxels = 1) {
        count += voxels;
        sum += e * double(voxels);
        if (e > max) max = e;
    }
    double mean() const { return count ? sum / double(count) : 0.0; }
};

}  // namespace engine::io
