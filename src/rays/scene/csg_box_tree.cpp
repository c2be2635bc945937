#include "rays/scene/csg_box_tree.h"

#include <algorithm>
#include <cmath>

namespace rays {

namespace {

bool finite(const Bounds& b) {
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(b.lo[a]) || !std::isfinite(b.hi[a])) return false;
    return true;
}

struct Item {
    Bounds box;
    Vec3 centre;
    int32_t id;
};

constexpr int32_t kLeafItems = 4;

// Appends the subtree over items[begin, end) (its root at the current end of out.nodes).
void split(std::vector<Item>& items, size_t begin, size_t end, CsgBoxTree& out) {
    const size_t self = out.nodes.size();
    out.nodes.emplace_back();
    Bounds box, centres;
    for (size_t i = begin; i < end; ++i) {
        box.extend(items[i].box);
        centres.extend(items[i].centre);
    }
    out.nodes[self].box = box;
    if (end - begin <= size_t(kLeafItems)) {
        out.nodes[self].first = int32_t(out.ids.size());
        out.nodes[self].count = int32_t(end - begin);
        for (size_t i = begin; i < end; ++i) out.ids.push_back(items[i].id);
        return;
    }
    const Vec3 e = centres.extent();
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    const size_t mid = begin + (end - begin) / 2;
    std::nth_element(items.begin() + std::ptrdiff_t(begin), items.begin() + std::ptrdiff_t(mid),
                     items.begin() + std::ptrdiff_t(end),
                     [axis](const Item& a, const Item& b) { return a.centre[axis] < b.centre[axis]; });
    split(items, begin, mid, out);  // the left child follows its parent
    out.nodes[self].first = int32_t(out.nodes.size());
    split(items, mid, end, out);
}

}  // namespace

CsgBoxTree CsgBoxTree::build(const std::vector<Bounds>& boxes, const std::vector<int32_t>& ids) {
    CsgBoxTree t;
    std::vector<Item> items;
    for (size_t i = 0; i < ids.size(); ++i) {
        const Bounds& b = boxes[i];
        if (b.empty()) continue;  // holds nothing: never visited
        if (!finite(b)) {
            t.unbounded.push_back(ids[i]);
            continue;
        }
        items.push_back(Item{b, b.centroid(), ids[i]});
    }
    if (items.empty()) return t;
    t.nodes.reserve(2 * items.size() / size_t(kLeafItems) + 1);
    split(items, 0, items.size(), t);
    return t;
}

}  // namespace rays
