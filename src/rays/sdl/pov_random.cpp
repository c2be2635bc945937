#include "rays/sdl/pov_random.h"

#include "rays/sdl/pov_int.h"

namespace rays::sdl {

// seed(x): the int conversion's bit pattern is the state (seed(-1) starts from 0xFFFFFFFF).
RandomStream::RandomStream(double seedValue) : state_(static_cast<uint32_t>(povInt(seedValue))) {}

RandomStream RandomStream::fromState(uint32_t state) {
    RandomStream s;
    s.state_ = state;
    return s;
}

double RandomStreams::seed(double x) {
    streams_.emplace_back(x);
    return static_cast<double>(streams_.size() - 1);
}

Outcome<double> RandomStreams::rand(double id) {
    const int n = povInt(id);
    if (n < 0 || static_cast<size_t>(n) >= streams_.size())
        return Outcome<double>::failure("Illegal random number generator.");
    return {streams_[size_t(n)].next(), {}};
}

}  // namespace rays::sdl
