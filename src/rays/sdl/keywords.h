// POV-Ray 3.7's reserved words as one enumeration (keywords.def). Identifiers share the name
// table with them: a name's id below kKeywordCount is a keyword, anything above an identifier.
#pragma once
#include <cstdint>
#include <string_view>

namespace rays::sdl {

enum class Kw : uint16_t {
#define X(name) name,
#define XR(name) name##_,
#include "rays/sdl/keywords.def"
#undef X
#undef XR
    Count
};

inline constexpr uint32_t kKeywordCount = uint32_t(Kw::Count);

/// The keyword's spelling ("sphere").
std::string_view keywordName(Kw k);

}  // namespace rays::sdl
