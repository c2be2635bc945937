// The names of one parse: keywords first (ids 0 .. kKeywordCount−1, in keywords.def order), then
// every identifier the lexer meets, each interned once so that tokens and symbol tables compare
// names by id.
#pragma once
#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <unordered_map>

#include "rays/sdl/keywords.h"

namespace rays::sdl {

class Names {
public:
    Names();
    /// The id of name, interning it when new.
    uint32_t intern(std::string_view name);
    std::string_view name(uint32_t id) const { return spelled_[id]; }
    static bool isKeyword(uint32_t id) { return id < kKeywordCount; }
    size_t size() const { return spelled_.size(); }

private:
    std::deque<std::string> storage_;           ///< identifier spellings (stable addresses)
    std::deque<std::string_view> spelled_;      ///< by id
    std::unordered_map<std::string_view, uint32_t> ids_;
};

}  // namespace rays::sdl
