#include "huge_pages.h"

#include <unistd.h>

#include <cstdlib>
#include <string>

namespace rays::cli {

void enableHugePages(char** argv) {
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
