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
    /// `inherited`: the amount of a normal without one of its own, and of the normals nested in
    /// it (POV-Ray's normals start as a copy of the default one; 0.5 without a default).
    int compile(const Item& normal, double inherited = 0.5);
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
    int build(const Item& normal);

    pattern::NormalTable& table_;
    PigmentCompiler& patterns_;
    NotRendered& notes_;
    ItemCache<int> done_;
    ItemCache<std::vector<std::pair<double, int>>> doneWith_;  ///< compiled with another inherited amount
    double inherited_ = 0.5;  ///< the inherited amount of the normal being compiled
};

}  // namespace rays::pov
