// Deterministic per-sample random numbers: a hash of (pixel, sample index, seed), so any sample can
// be replayed and images do not depend on the number of threads.
#pragma once
#include <cstdint>

namespace rays {

/// SplitMix64 finaliser (Steele et al. 2014): a well-mixed 64-bit hash.
constexpr uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/// Small counter-based generator for one pixel sample.
class SampleRng {
public:
    SampleRng(uint32_t px, uint32_t py, uint32_t sample, uint64_t seed)
        : state_(mix64(seed ^ mix64((uint64_t(px) << 32 | py) ^ mix64(sample + 0x9e3779b97f4a7c15ULL)))) {}
    /// Uniform double in [0, 1).
    double next() {
        state_ += 0x9e3779b97f4a7c15ULL;
        return double(mix64(state_) >> 11) * 0x1.0p-53;
    }

private:
    uint64_t state_;
};

}  // namespace rays
