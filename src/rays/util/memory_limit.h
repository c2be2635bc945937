// The memory a run may use: the limit every input and buffer is measured against before it is
// allocated (docs/errors.md "Limits").
#pragma once
#include <cstdint>
#include <string>

namespace rays {

/// The memory limit in bytes: $RAYS_MEMORY_LIMIT when set (a number with an optional K, M, G or T
/// suffix, powers of 1024), else the machine's physical memory (16 GiB when unknown). Throws
/// Error "rays: error: ..." for a malformed RAYS_MEMORY_LIMIT.
uint64_t memoryLimit();

/// Where the limit comes from: " (RAYS_MEMORY_LIMIT)" or " (physical memory)".
const char* memoryLimitSource();

/// "1.5 GiB", "312.0 MiB".
std::string formatBytes(double bytes);

}  // namespace rays
