#include "io/colour_quantizer.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace engine::io {

namespace {
constexpr std::size_t kMaxExactColours = 65536;
constexpr int kBinBits = 6;

double distance2(glm::dvec3 a, glm::dvec3 b) {
    glm::dvec3 d = a - b;
    return glm::dot(d, d);
}
}  // namespace

glm::vec3 clampAlbedo(glm::vec3 c) {
    for (int i = 0; i < 3; ++i) c[i] = std::isnan(c[i]) ? 0.0f : std::clamp(c[i], 0.0f, 1.0f);
    return c;
}

std::uint64_t ColourHistogram::exactKey(glm::vec3 c) {
    // Three floats do not fit in 64 bits; hash them (collisions only merge two colours' means).
    std::uint64_t h = 1469598103934665603ull;
    for (int i = 0; i < 3; ++i) {
        h ^= std::bit_cast<std::uint32_t>(c[i]);
        h *= 1099511628211ull;
        h ^= h >> 29;
    }
    return h;
}

std::uint64_t ColourHistogram::binKey(glm::vec3 c) {
    constexpr float levels = float((1 << kBinBits) - 1);
    std::uint64_t key = 0;
    for (int i = 0; i < 3; ++i) key = (key << kBinBits) | std::uint64_t(std::lround(c[i] * levels));
    return key;
}

void ColourHistogram::add(glm::vec3 colour, std::uint64_t weight) {
    if (weight == 0) return;
    colour = clampAlbedo(colour);
    mTotal += weight;
    Entry& e = mEntries[mBinned ? binKey(colour) : exactKey(colour)];
    e.sum += glm::dvec3(colour) * double(weight);
    e.weight += weight;
    if (!mBinned && mEntries.size() > kMaxExactColours) switchToBins();
}

void ColourHistogram::switchToBins() {
    std::unordered_map<std::uint64_t, Entry> bins;
    for (const auto& [key, e] : mEntries) {
        Entry& b = bins[binKey(e.mean())];
        b.sum += e.sum;
        b.weight += e.weight;
    }
    mEntries.swap(bins);
    mBinned = true;
}

std::vector<ColourHistogram::Entry> ColourHistogram::entries() const {
    std::vector<Entry> out;
    out.reserve(mEntries.size());
    for (const auto& [key, e] : mEntries) out.push_back(e);
    // Deterministic order regardless of hashing.
    std::sort(out.begin(), out.end(), [](const Entry& a, const Entry& b) {
        glm::vec3 ma = a.mean(), mb = b.mean();
        if (ma.x != mb.x) return ma.x < mb.x;
        if (ma.y != mb.y) return ma.y < mb.y;
        return ma.z < mb.z;
    });
    return out;
}

std::vector<glm::vec3> quantizeColours(const ColourHistogram& histogram, int maxColours) {
    std::vector<ColourHistogram::Entry> entries = histogram.entries();
    std::vector<glm::vec3> palette;
    if (entries.empty() || maxColours < 1) return palette;
    if (!histogram.binned() && entries.size() <= std::size_t(maxColours)) {
        for (const auto& e : entries) palette.push_back(e.mean());
        return palette;
    }

    // Median cut: split the box with the widest colour range at the weighted median until there
    // are maxColours boxes (or nothing left to split).
    struct Span {
        std::size_t begin, end;
    };
    std::vector<Span> boxes{{0, entries.size()}};
    auto widest = [&](const Span& s, int& axis) {
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (std::size_t i = s.begin; i < s.end; ++i) {
            lo = glm::min(lo, entries[i].mean());
            hi = glm::max(hi, entries[i].mean());
        }
        glm::vec3 range = hi - lo;
        axis = range.x >= range.y && range.x >= range.z ? 0 : (range.y >= range.z ? 1 : 2);
        return double(range[axis]) * double(s.end - s.begin > 1);
    };
    while (boxes.size() < std::size_t(maxColours)) {
        std::size_t best = 0;
        int bestAxis = 0;
        double bestRange = -1.0;
        for (std::size_t b = 0; b < boxes.size(); ++b) {
            int axis;
            double r = widest(boxes[b], axis);
            if (r > bestRange) {
                bestRange = r;
                best = b;
                bestAxis = axis;
            }
        }
        if (bestRange <= 0.0) break;
        Span s = boxes[best];
        std::sort(
            entries.begin() + std::ptrdiff_t(s.begin), entries.begin() + std::ptrdiff_t(s.end),
            [&](const auto& a, const auto& b) { return a.mean()[bestAxis] < b.mean()[bestAxis]; });
        std::uint64_t total = 0, acc = 0;
        for (std::size_t i = s.begin; i < s.end; ++i) total += entries[i].weight;
        std::size_t cut = s.begin + 1;
        for (std::size_t i = s.begin; i < s.end - 1; ++i) {
            acc += entries[i].weight;
            cut = i + 1;
            if (acc * 2 >= total) break;
        }
        boxes[best] = {s.begin, cut};
        boxes.push_back({cut, s.end});
    }
    std::vector<glm::dvec3> centres;
    for (const Span& s : boxes) {
        glm::dvec3 sum(0.0);
        std::uint64_t w = 0;
        for (std::size_t i = s.begin; i < s.end; ++i) {
            sum += entries[i].sum;
            w += entries[i].weight;
        }
        centres.push_back(sum / double(std::max<std::uint64_t>(w, 1)));
    }

    // Lloyd iterations over the histogram entries, weighted by voxel count.
    for (int iteration = 0; iteration < 10; ++iteration) {
        std::vector<glm::dvec3> sums(centres.size(), glm::dvec3(0.0));
        std::vector<std::uint64_t> weights(centres.size(), 0);
        for (const auto& e : entries) {
            glm::dvec3 m = e.sum / double(e.weight);
            std::size_t nearest = 0;
            double best = std::numeric_limits<double>::max();
            for (std::size_t c = 0; c < centres.size(); ++c) {
                double d = distance2(m, centres[c]);
                if (d < best) {
                    best = d;
                    nearest = c;
                }
            }
            sums[nearest] += e.sum;
            weights[nearest] += e.weight;
        }
        bool moved = false;
        for (std::size_t c = 0; c < centres.size(); ++c) {
            if (!weights[c]) continue;
            glm::dvec3 next = sums[c] / double(weights[c]);
            moved |= distance2(next, centres[c]) > 1e-12;
            centres[c] = next;
        }
        if (!moved) break;
    }
    for (const glm::dvec3& c : centres) palette.push_back(clampAlbedo(glm::vec3(c)));
    return palette;
}

ColourMapper::ColourMapper(std::vector<glm::vec3> palette) : mPalette(std::move(palette)) {}

int ColourMapper::nearest(glm::vec3 colour) {
    colour = clampAlbedo(colour);
    const Key key{std::bit_cast<std::uint32_t>(colour.x), std::bit_cast<std::uint32_t>(colour.y),
                  std::bit_cast<std::uint32_t>(colour.z)};
    if (auto it = mMemo.find(key); it != mMemo.end()) return it->second;
    int best = 0;
    double bestD = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < mPalette.size(); ++i) {
        double d = distance2(glm::dvec3(colour), glm::dvec3(mPalette[i]));
        if (d < bestD) {
            bestD = d;
            best = int(i);
        }
    }
    if (mMemo.size() < (1u << 20))
        mMemo.emplace(key, best);  // bounded: smooth gradients repeat little
    return best;
}

}  // namespace engine::io
