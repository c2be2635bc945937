#include "huge_pages.h"

#include <malloc.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

namespace rays::cli {

void enableHugePages(char** argv) {
    // Large blocks come from the heap and stay there when freed, so a later buffer of the
    // render reuses pages that are already mapped instead of faulting in fresh (zeroed) ones.
    mallopt(M_MMAP_THRESHOLD, 512 << 20);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    if (std::getenv("RAYS_NO_HUGEPAGES") != nullptr) return;
    const char* current = std::getenv("GLIBC_TUNABLES");
    const std::string tunables = current ? current : "";
    if (tunables.find("glibc.malloc.hugetlb") != std::string::npos) return;
    const std::string value = tunables.empty() ? "glibc.malloc.hugetlb=1" : tunables + ":glibc.malloc.hugetlb=1";
    if (setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0) return;
    execv("/proc/self/exe", argv);
    // exec failed (no /proc, say): carry on without huge pages.
    if (current) setenv("GLIBC_TUNABLES", current, 1);
    else unsetenv("GLIBC_TUNABLES");
}

}  // namespace rays::cli
