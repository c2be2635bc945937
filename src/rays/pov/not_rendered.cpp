#include "rays/pov/not_rendered.h"

#include "rays/error.h"

namespace rays::pov {

void NotRendered::note(const std::string& what, const sdl::Loc& at, const std::string& detail) {
    if (!seen_.insert(what).second) return;
    if (detail.find("left out") != std::string::npos) ++leftOut_;
    if (strict_) throw Error(where_(at) + ": error: not rendered yet: " + what + " (--strict)");
    if (warn_) warn_(where_(at) + ": warning: not rendered yet: " + what + (detail.empty() ? "" : " " + detail));
}

}  // namespace rays::pov
