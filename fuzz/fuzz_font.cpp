// libFuzzer target: see fuzzFont in entry_points.h.
#include <cstddef>
#include <cstdint>

#include "entry_points.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    rays::fuzz::run(rays::fuzz::fuzzFont, data, size);  // scaled when RAYS_FUZZ_SCALE is set
    return 0;
}
