#include "rays/sdl/keywords.h"

namespace rays::sdl {
namespace {
constexpr std::string_view kNames[] = {
#define X(name) #name,
#define XR(name) #name,
#include "rays/sdl/keywords.def"
#undef X
#undef XR
};
static_assert(sizeof(kNames) / sizeof(kNames[0]) == kKeywordCount);
}  // namespace

std::string_view keywordName(Kw k) { return uint32_t(k) < kKeywordCount ? kNames[uint32_t(k)] : "?"; }

}  // namespace rays::sdl
