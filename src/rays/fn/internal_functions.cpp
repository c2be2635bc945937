#include "rays/fn/internal_functions.h"

#include <array>

#include "rays/fn/internal_impl.h"

namespace rays::fn {
namespace {

constexpr int kCount = 79;

constexpr std::array<InternalFunction, kCount> makeTable() {
    std::array<InternalFunction, kCount> t{};
#define RAYS_FN_ENTRY(number, name, params) t[number] = {"f_" #name, params, &internal::f_##name};
    RAYS_FN_INTERNAL_LIST(RAYS_FN_ENTRY)
#undef RAYS_FN_ENTRY
    return t;
}

constexpr std::array<InternalFunction, kCount> kTable = makeTable();

}  // namespace

const InternalFunction* internalFunction(int number) {
    if (number < 0 || number >= kCount || !kTable[number].fn) return nullptr;
    return &kTable[number];
}

int internalNumber(std::string_view name) {
    for (int i = 0; i < kCount; ++i)
        if (kTable[i].fn && kTable[i].name == name) return i;
    return -1;
}

}  // namespace rays::fn
