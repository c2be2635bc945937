// What a pigment's entries have set so far while PigmentCompiler reads them: shared by the files
// that read parts of a pigment (pigment_compile.cpp, image_map_compile.cpp). Internal to them.
#pragma once
#include <vector>

#include "rays/math/transform.h"
#include "rays/pattern/pigment.h"
#include "rays/pov/pigment_compile.h"

namespace rays::pov {

// What a pigment's entries have set so far.
struct PigmentCompiler::State {
    pattern::PigmentNode node;
    bool pattern = false;      ///< a rendered pattern was given
    bool unrendered = false;   ///< a pattern Rays does not render was given (the pigment stays flat)
    bool mapSet = false;
    std::vector<pattern::MapEntry> map;   ///< colour map or pigment map
    std::vector<pattern::MapEntry> list;  ///< a block pattern's colours or pigments, in order
    Transform transform;         ///< pattern space → the enclosing space
    bool transformed = false;
    std::vector<pattern::WarpStep> steps;  ///< transformations and warps in file order (when warped)
    bool warped = false;
    bool waveSet = false;
    const char* what = "pigment";  ///< for notes: "pigment pattern X" or "texture pattern X"
    bool normal = false;           ///< reading a normal: its specialised patterns are accepted
    bool density = false;          ///< reading a media's density (unrendered patterns give 0)
    const Entry* pavement = nullptr;  ///< the pavement keyword (its modifiers are checked once all are read)
    bool greyDefault = false;  ///< spotted and bumps: bozo's noise with the grey ramp, not bozo's map
};

}  // namespace rays::pov
