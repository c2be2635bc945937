#include "rays/sdl/names.h"

namespace rays::sdl {

Names::Names() {
    ids_.reserve(4096);
    for (uint32_t k = 0; k < kKeywordCount; ++k) {
        const std::string_view s = keywordName(Kw(k));
        spelled_.push_back(s);
        ids_.emplace(s, k);
    }
}

uint32_t Names::intern(std::string_view name) {
    if (auto it = ids_.find(name); it != ids_.end()) return it->second;
    const std::string_view s = storage_.emplace_back(name);
    const uint32_t id = uint32_t(spelled_.size());
    spelled_.push_back(s);
    ids_.emplace(s, id);
    return id;
}

}  // namespace rays::sdl
