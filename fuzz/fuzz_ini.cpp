// libFuzzer target: see fuzzIni in entry_points_ini.h.
#include <cstddef>
#include <cstdint>

#include "entry_points_ini.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    rays::fuzz::run(rays::fuzz::fuzzIni, data, size);  // scaled when RAYS_FUZZ_SCALE is set
    return 0;
}
