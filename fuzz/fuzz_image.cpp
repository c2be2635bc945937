// libFuzzer target: see fuzzImage in entry_points.h.
#include <cstddef>
#include <cstdint>

#include "entry_points.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    rays::fuzz::fuzzImage(data, size);
    return 0;
}
