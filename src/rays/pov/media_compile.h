// POV-Ray media items (POV-Ray 3.7 reference, "Media", "Media Types", "Sampling Parameters &
// Methods", "Density") read into the values the renderer samples, their densities compiled as
// pigment nodes (a density is a pattern whose colour is the density) and placed like pigments: the
// media's and then the object's transformations move them.
#pragma once
#include <vector>

#include "rays/pov/item_values.h"
#include "rays/pov/not_rendered.h"
#include "rays/pov/pigment_compile.h"
#include "rays/scene/pov_media.h"

namespace rays::pov {

/// A density: its node in the PigmentTable and its space → the space the media was given in.
struct DensityLook {
    int node = -1;
    Transform toObject;
};

/// A media as read: its values (densityFirst/densityCount not set yet) and its densities.
struct MediaLook {
    PovMedia media;
    std::vector<DensityLook> densities;
    int samplesMin = 10, samplesMax = 10;  ///< `samples min, max` as written (method 3 uses min)
};

/// Reads a media item (a media identifier first: its base) over out. Without `pigments` the
/// densities are left out (density 1). Methods 1 and 2 are drawn by method 3's scheme without its
/// refinement: `samples`' maximum equal steps per interval, method 1's jittered in full (its
/// samples are random).
void readMedia(const Item& media, MediaLook& out, PigmentCompiler* pigments, NotRendered& notes, int depth = 0);
/// The media moved by `outer`, applied after what moves it already.
void moveMedia(MediaLook& m, const Transform& outer);

}  // namespace rays::pov
