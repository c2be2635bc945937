// Transparent huge pages for the heap. Page faults are a large share of a render's time on the
// virtual machines Rays is measured on (a 2.5 MB scene touches ~100 MB of fresh memory); glibc's
// malloc can ask for huge pages, but only through a tunable read at process start. So the
// program re-executes itself once with GLIBC_TUNABLES=glibc.malloc.hugetlb=1 added.
#pragma once

namespace rays::cli {

/// Keeps large freed blocks in the heap for reuse, then re-executes the program with the
/// huge-page malloc tunable unless it is already set (or RAYS_NO_HUGEPAGES is set). Returns only
/// when no re-execution happened.
void enableHugePages(char** argv);

}  // namespace rays::cli
