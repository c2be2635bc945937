// POV-Ray's seed()/rand() streams, checked bit-exactly against values measured from POV-Ray 3.7
// (tests/data/povray/pov_random.pov wrote tests/data/povray/pov_random.txt).
#include "rays/sdl/pov_random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using rays::sdl::RandomStream;
using rays::sdl::RandomStreams;

namespace { namespace RAYS_TEST_UNIT {

const std::string kData = std::string(RAYS_SOURCE_DIR) + "/tests/data/povray/pov_random.txt";

/// One generator variant: the first state from a seed, and one step from a state to a value.
struct Generator {
    std::function<uint32_t(double)> seed;
    std::function<double(uint32_t&)> step;
};

Generator raysGenerator() {
    return {[](double x) { return RandomStream(x).state(); },
            [](uint32_t& s) {
                RandomStream r = RandomStream::fromState(s);
                const double v = r.next();
                s = r.state();
                return v;
            }};
}

/// The same form with other constants, to show that the data tells them apart.
Generator variant(uint32_t mul, uint32_t inc, double divisor) {
    return {[](double x) { return RandomStream(x).state(); },
            [=](uint32_t& s) {
                s = mul * s + inc;
                return s / divisor;
            }};
}

/// How many measured numbers g reproduces wrongly (values, and per summed block its two sums).
/// Fails the test if the data file cannot be read or is malformed.
int mismatches(const Generator& g, int* checked = nullptr) {
    std::ifstream in(kData);
    EXPECT_TRUE(in.good()) << kData;
    std::map<std::string, uint32_t> states;
    std::string line;
    int bad = 0, n = 0;
    while (std::getline(in, line)) {
        std::istringstream f(line);
        std::string head;
        f >> head;
        if (head == "stream") {
            std::string name, seed;
            f >> name >> seed;
            states[name] = g.seed(std::strtod(seed.c_str(), nullptr));
        } else if (head == "sum") {
            std::string name, values;
            long count = 0;
            double stateSum = 0;
            f >> name >> count >> stateSum >> values;
            double s = 0, v = 0;
            for (long i = 0; i < count; ++i) {
                v += g.step(states.at(name));
                s += states.at(name);
            }
            bad += (s != stateSum) + (v != std::strtod(values.c_str(), nullptr));
            n += int(count);
        } else {
            std::string value;
            f >> value;
            EXPECT_TRUE(states.count(head)) << line;
            bad += g.step(states[head]) != std::strtod(value.c_str(), nullptr);
            ++n;
        }
    }
    if (checked) *checked = n;
    return bad;
}

TEST(PovRandom, MatchesPovRayBitExactly) {
    int checked = 0;
    EXPECT_EQ(mismatches(raysGenerator(), &checked), 0);
    EXPECT_GT(checked, 120000);  // 12 seeds × (40 + 10000) values and 200 interleaved
}

TEST(PovRandom, DataRejectsNearbyConstants) {
    const uint32_t a = RandomStream::kMultiplier, c = RandomStream::kIncrement;
    EXPECT_EQ(mismatches(variant(a, c, 4294967295.0)), 0);  // the variant helper itself is right
    EXPECT_GT(mismatches(variant(a + 2, c, 4294967295.0)), 0);
    EXPECT_GT(mismatches(variant(a, c + 2, 4294967295.0)), 0);
    EXPECT_GT(mismatches(variant(1103515245u, c, 4294967295.0)), 0);  // the C library's multiplier
    EXPECT_GT(mismatches(variant(a, c, 4294967296.0)), 0);             // division by 2^32
}

TEST(PovRandom, FirstValueFromSeedZeroIsTheIncrement) {
    RandomStream s(0);
    EXPECT_EQ(s.next(), 12345 / 4294967295.0);
    EXPECT_EQ(s.state(), 12345u);
}

TEST(PovRandom, SeedTruncatesTowardZero) {
    EXPECT_EQ(RandomStream(1.9999).state(), 1u);
    EXPECT_EQ(RandomStream(-1.5).state(), 0xFFFFFFFFu);
    EXPECT_EQ(RandomStream(-0.5).state(), 0u);
    EXPECT_EQ(RandomStream(2147483647.0).state(), 2147483647u);
    EXPECT_EQ(RandomStream(-2147483648.0).state(), 0x80000000u);
}

TEST(PovRandom, SeedOutsideInt32StartsFromTwoToThe31) {
    for (double x : {2147483648.0, 4294967297.0, 1e10, -2147483649.0, -1e300,
                     std::numeric_limits<double>::infinity(), std::nan("")})
        EXPECT_EQ(RandomStream(x).state(), 0x80000000u) << x;
}

TEST(PovRandom, BothEndsOfTheRangeAreReachable) {
    // States 0 and 2^32 − 1 are the values 0 and 1 (POV-Ray documents rand as inclusive).
    // Step back from a state: s = (t − c) · a⁻¹ (mod 2^32); a⁻¹ by Newton's iteration.
    uint32_t inv = RandomStream::kMultiplier;
    for (int i = 0; i < 5; ++i) inv *= 2u - RandomStream::kMultiplier * inv;
    ASSERT_EQ(inv * RandomStream::kMultiplier, 1u);
    auto before = [&](uint32_t t) { return (t - RandomStream::kIncrement) * inv; };
    EXPECT_EQ(RandomStream::fromState(before(0u)).next(), 0.0);
    EXPECT_EQ(RandomStream::fromState(before(0xFFFFFFFFu)).next(), 1.0);
}

TEST(PovRandom, StreamsAreNumberedInSeedOrderAndIndependent) {
    RandomStreams streams;
    EXPECT_EQ(streams.seed(0), 0.0);
    EXPECT_EQ(streams.seed(0), 1.0);
    EXPECT_EQ(streams.seed(5), 2.0);
    RandomStream ref(0);
    const double first = ref.next(), second = ref.next();
    EXPECT_EQ(streams.rand(0).value, first);
    EXPECT_EQ(streams.rand(1).value, first);    // same seed, own state
    EXPECT_EQ(streams.rand(0.7).value, second); // the number is truncated: stream 0 again
    EXPECT_EQ(streams.rand(2).value, RandomStream(5).next());
}

TEST(PovRandom, UnknownStreamIsPovRaysError) {
    RandomStreams streams;
    streams.seed(1);
    streams.seed(2);
    EXPECT_TRUE(streams.rand(1.99).ok());
    EXPECT_TRUE(streams.rand(-0.5).ok());  // truncates to stream 0
    for (double id : {2.0, -1.0, 1e10}) {
        const auto r = streams.rand(id);
        EXPECT_FALSE(r.ok()) << id;
        EXPECT_EQ(r.error, "Illegal random number generator.");
    }
}

}}  // namespace RAYS_TEST_UNIT, namespace
