#include "stdout_check.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

#include "rays/error.h"

namespace rays::cli {

void flushStdout() {
    errno = 0;
    std::cout.flush();  // through stdout (synced with stdio): a failure there sets errno
    const bool flushed = std::fflush(stdout) == 0;
    if (flushed && !std::ferror(stdout) && std::cout.good()) return;
    const int e = errno;
    throw Error(std::string("rays: error: cannot write to standard output: ") + (e != 0 ? std::strerror(e) : "write error"));
}

}  // namespace rays::cli
