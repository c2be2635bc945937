// What the builder made from an item, found again by the item's address. Items of earlier
// top-level items are freed while the scene is built (load_pov.cpp): an entry keeps its item alive,
// so another item made later at the same address cannot take its place. Items not held by a
// shared pointer (made on the stack by the builder) are not kept.
#pragma once
#include <memory>
#include <unordered_map>
#include <utility>

#include "rays/sdl/item.h"

namespace rays::pov {

template <class V>
class ItemCache {
public:
    const V* find(const sdl::Item& item) const {
        const auto it = map_.find(&item);
        return it == map_.end() ? nullptr : &it->second.second;
    }
    /// Stores (or replaces) what item made; nothing when the item is not shared-owned.
    void put(const sdl::Item& item, V value) {
        std::shared_ptr<const sdl::Item> keep = item.weak_from_this().lock();
        if (!keep) return;
        map_.insert_or_assign(&item, std::make_pair(std::move(keep), std::move(value)));
    }

private:
    std::unordered_map<const sdl::Item*, std::pair<std::shared_ptr<const sdl::Item>, V>> map_;
};

}  // namespace rays::pov
