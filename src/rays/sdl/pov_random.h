// POV-Ray 3.7's seed() / rand() streams, reproduced exactly so that scenes which scatter objects
// with rand() put them where POV-Ray does.
//
// Found by black-box experiments with the installed povray binary (the scene and the measured
// values are in tests/data/povray/pov_random.*; docs/scene-language-numbers.md tells the story):
//   seed(x):  state = (uint32) povInt(x)            (truncation; out of int32 range → 2^31)
//   rand(s):  state = 1812433253 · state + 12345  (mod 2^32)
//             result = state / 4294967295.0         (double division, so 0 and 1 are both possible)
// rand(S) on seed(0) gives 12345/4294967295 = 0.000002874294297 first. The division (not a
// multiplication by 1/4294967295, not 2^32) was checked bit-exactly inside POV-Ray over 20000
// values. Streams are numbered 0, 1, 2, ... in the order seed() is called; copies of the number
// share the stream (#declare T = S; rand(T) advances S); rand truncates its argument (rand(0.7)
// is stream 0) and any number that names no stream is "Illegal random number generator.".
#pragma once
#include <cstdint>
#include <vector>

#include "rays/sdl/outcome.h"

namespace rays::sdl {

/// One pseudo-random stream: a 32-bit linear congruential generator.
class RandomStream {
public:
    static constexpr uint32_t kMultiplier = 1812433253u;  ///< 0x6C078965
    static constexpr uint32_t kIncrement = 12345u;
    static constexpr double kDivisor = 4294967295.0;      ///< 2^32 − 1

    /// The stream seed(seedValue) creates.
    explicit RandomStream(double seedValue);
    /// A stream whose next rand() steps from this raw state.
    static RandomStream fromState(uint32_t state);

    /// rand(): steps the state and returns it divided by 2^32 − 1, in [0, 1].
    double next() {
        state_ = kMultiplier * state_ + kIncrement;
        return state_ / kDivisor;
    }
    uint32_t state() const { return state_; }

private:
    RandomStream() = default;
    uint32_t state_ = 0;
};

/// A scene's streams, numbered in creation order as POV-Ray numbers them.
class RandomStreams {
public:
    /// seed(x): creates a stream and returns its number (0, 1, 2, ...).
    double seed(double x);
    /// rand(id): the next number of stream povInt(id), or "Illegal random number generator."
    Outcome<double> rand(double id);
    size_t size() const { return streams_.size(); }

private:
    std::vector<RandomStream> streams_;
};

}  // namespace rays::sdl
