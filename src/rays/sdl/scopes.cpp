#include "rays/sdl/scopes.h"

namespace rays::sdl {

void Scopes::popLevel() {
    const uint32_t lvl = level();
    for (uint32_t name : levelNames_[lvl]) {
        auto& st = stacks_[name];
        if (!st.empty() && st.back().level == lvl) st.pop_back();
    }
    --levels_;
}

Binding* Scopes::findSerial(uint32_t name, uint32_t serial) {
    if (name >= stacks_.size()) return nullptr;
    for (Binding& b : stacks_[name])
        if (b.serial == serial) return &b;
    return nullptr;
}

Binding& Scopes::push(uint32_t name, Value v, uint32_t lvl) {
    if (name >= stacks_.size()) stacks_.resize(name + 1 + name / 2);
    auto& st = stacks_[name];
    Binding b;
    b.value = std::move(v);
    b.level = lvl;
    b.serial = ++serial_;
    // A global made while locals of the same name exist goes beneath them.
    Binding* made;
    if (st.empty() || st.back().level <= lvl) {
        made = &st.emplace_back(std::move(b));
    } else {
        auto at = st.begin();
        while (at != st.end() && at->level <= lvl) ++at;
        made = &*st.insert(at, std::move(b));
    }
    levelNames_[lvl].push_back(name);
    return *made;
}

Binding& Scopes::declare(uint32_t name, Value v) {
    if (Binding* b = find(name)) {
        b->value = std::move(v);
        return *b;
    }
    return push(name, std::move(v), 0);
}

Binding& Scopes::declareAt(uint32_t name, Value v, uint32_t lvl) {
    if (name < stacks_.size())
        for (auto it = stacks_[name].rbegin(); it != stacks_[name].rend(); ++it)
            if (it->level <= lvl) {
                it->value = std::move(v);
                return *it;
            }
    return push(name, std::move(v), 0);
}

Binding& Scopes::localAt(uint32_t name, Value v, uint32_t lvl) {
    if (name < stacks_.size())
        for (auto it = stacks_[name].rbegin(); it != stacks_[name].rend(); ++it) {
            if (it->level > lvl) continue;
            if (it->level == lvl) {
                it->value = std::move(v);
                return *it;
            }
            break;
        }
    return push(name, std::move(v), lvl);
}

bool Scopes::undef(uint32_t name) {
    if (!find(name)) return false;
    stacks_[name].pop_back();
    return true;
}

}  // namespace rays::sdl
