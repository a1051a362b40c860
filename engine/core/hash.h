// Deterministic hashing and random numbers. All randomness in the engine is a hash of
// (what, where, when, seed), so runs repeat exactly. The same PCG hash is in
// shaders/common/hash.glsl.
#pragma once

#include <cstdint>
#include <string_view>

namespace engine {

// PCG-style integer hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering").
constexpr std::uint32_t pcgHash(std::uint32_t v) {
    std::uint32_t state = v * 747796405u + 2891336453u;
    std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

constexpr std::uint32_t hashCombine(std::uint32_t a, std::uint32_t b) {
    return pcgHash(a ^ (b + 0x9e3779b9u + (a << 6) + (a >> 2)));
}

// FNV-1a, 64 bits: names made from names (a shortened file name, a world's save), the same in
// every run and build.
constexpr std::uint64_t fnv1a64(std::string_view bytes) {
    std::uint64_t h = 14695981039346656037ull;
    for (char c : bytes) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    return h;
}

// Small seeded generator for host-side sampling (tests, generators).
class Rng {
public:
    explicit Rng(std::uint64_t seed)
        : mState(seed * 6364136223846793005ull + 1442695040888963407ull) {}
    std::uint32_t nextU32() {
        // PCG32 (O'Neill 2014), XSH-RR output.
        std::uint64_t old = mState;
        mState = old * 6364136223846793005ull + 1442695040888963407ull;
        auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }
    // Uniform in [0, 1).
    float nextFloat() { return static_cast<float>(nextU32() >> 8) * (1.0f / 16777216.0f); }
    float uniform(float lo, float hi) { return lo + (hi - lo) * nextFloat(); }
    int uniformInt(int lo, int hiInclusive) {
        auto span = static_cast<std::uint32_t>(hiInclusive - lo + 1);
        return lo + static_cast<int>(nextU32() % span);
    }

private:
    std::uint64_t mState;
};

}  // namespace engine
