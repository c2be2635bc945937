#include "rays/util/stack_room.h"

#include <pthread.h>

#include <algorithm>

namespace rays {

uintptr_t threadStackFloor() {
    thread_local const uintptr_t floor = [] {
        pthread_attr_t attr;
        if (pthread_getattr_np(pthread_self(), &attr) != 0) return uintptr_t(0);
        void* low = nullptr;
        size_t size = 0;
        const bool known = pthread_attr_getstack(&attr, &low, &size) == 0 && low;
        pthread_attr_destroy(&attr);
        return known ? uintptr_t(low) + std::min(kStackReserve, size / 2) : uintptr_t(0);
    }();
    return floor;
}

}  // namespace rays
