#include "rays/npr/edge_settings.h"

#include "rays/error.h"

namespace rays {
namespace {

const char* kNames[] = {"silhouette", "occlusion", "intersection", "crease", "material", "shadow", "reflection"};

}  // namespace

const char* edgeTypeName(int bit) { return bit >= 0 && bit < 7 ? kNames[bit] : "?"; }

uint32_t parseEdgeTypes(const std::string& list) {
    uint32_t mask = 0;
    size_t start = 0;
    while (start <= list.size()) {
        size_t end = list.find(',', start);
        if (end == std::string::npos) end = list.size();
        const std::string name = list.substr(start, end - start);
        if (name == "all") {
            mask |= kEdgeAll;
        } else if (name == "none") {
        } else {
            int bit = -1;
            for (int b = 0; b < 7; ++b)
                if (name == kNames[b]) bit = b;
            if (bit < 0)
                throw Error("rays: error: unknown edge type '" + name +
                            "' (use silhouette, occlusion, intersection, crease, material, shadow, reflection, all or none)");
            mask |= 1u << bit;
        }
        start = end + 1;
    }
    return mask;
}

void validateEdgeSettings(const EdgeSettings& e) {
    if (!(e.width >= 0.5 && e.width <= 8))
        throw Error("rays: error: edge width must be between 0.5 and 8 pixels, got " + std::to_string(e.width));
    if (!(e.creaseAngle > 0 && e.creaseAngle < 180))
        throw Error("rays: error: crease angle must be between 0 and 180 degrees, got " + std::to_string(e.creaseAngle));
}

}  // namespace rays
