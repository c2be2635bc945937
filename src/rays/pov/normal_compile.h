// POV-Ray normal items → the scene's pattern::NormalTable (POV-Ray 3.7 reference, "Normal",
// "Normal Map", "Slope Map", "Bump_Size", "Normals, Accuracy"): the pattern part is compiled by
// the PigmentCompiler; this adds the amount, bump_size, accuracy, slope_map, normal_map, average
// and block-pattern normal lists. Each normal item is compiled once.
#pragma once
#include <unordered_map>

#include "rays/pattern/normal.h"
#include "rays/pov/pigment_compile.h"

namespace rays::pov {

class NormalCompiler {
public:
    NormalCompiler(pattern::NormalTable& table, PigmentCompiler& patterns, NotRendered& notes)
        : table_(table), patterns_(patterns), notes_(notes) {}
    /// The node of a normal with a rendered pattern or a bump_map, or -1 (the surface stays
    /// smooth; patterns Rays does not render are noted).
    int compile(const Item& normal);
    /// A normal's amount (bump_size, or the amount after its pattern type; 0.5 when neither) and
    /// whether it writes one.
    struct Amount {
        double value = 0.5;
        bool given = false;
    };
    Amount amountOf(const Item& normal);

private:
    struct State;
    void read(const Item& normal, State& s, int depth);
    int nested(const Item& normal, int depth);

    pattern::NormalTable& table_;
    PigmentCompiler& patterns_;
    NotRendered& notes_;
    ItemCache<int> done_;
};

}  // namespace rays::pov
