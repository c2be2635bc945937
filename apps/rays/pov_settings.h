// How POV-Ray's options become a Rays render job: image size, anti-aliasing (the closest Rays
// sampling), threads, JPEG quality, the scene, the output file name (POV-Ray's naming rules) and
// the scene-language options (library paths, declarations).
#pragma once
#include <string>

#include "pov_options.h"
#include "render_command.h"

namespace rays::cli {

/// Rays' sampling chosen for POV-Ray's anti-aliasing.
struct AaChoice {
    AaMode mode = AaMode::Grid;
    int spp = 1;
    bool edges = false;      ///< one sample per pixel first, then supersample where the threshold says
    double threshold = -1;   ///< with edges: POV-Ray's colour threshold (RenderSettings::aaThreshold)
    double gamma = 2.5;      ///< Antialias_Gamma
};

/// POV-Ray's adaptive anti-aliasing (reference 3.2.8.7, method 1): one sample per pixel, then
/// every pixel whose colour differs from its left or upper neighbour's by more than the threshold
/// (|Δr| + |Δg| + |Δb| of linear colours raised to 1/Antialias_Gamma), and that neighbour, is
/// supersampled. Threshold 0 supersamples every pixel, 3 or more none. Samples: depth² (method 1)
/// or (depth+1)² (method 2; Rays does not recurse), at least 4; jitter picks stratified samples,
/// no jitter a regular grid.
AaChoice mapPovAntialias(const PovAntialias& aa);

/// The extension of Output_File_Type `type` (0: PNG): ".png", ".ppm", ".tga", ".jpg" or ".bmp".
std::string fileTypeExtension(char type);

/// The image file named by the options. Render's -o is used as written. +O / Output_File_Name
/// follows POV-Ray: a folder (ending in '/' or existing) gets the scene's name; with an
/// Output_File_Type the type's extension is added unless the name already ends in it ("out.png"
/// with +FT is "out.png.tga"); without one a name Rays can write (.png .jpg .jpeg .ppm .tga .bmp)
/// is kept and any other gets ".png". With no name: POV-Ray's form (povForm) writes the scene's
/// name with the type's extension in the current folder, `rays render` writes "output" with it.
std::string povOutputPath(const PovOptions& o, bool povForm);

/// The part of the image the options ask for (+SR +ER +SC +EC), set in s (whose size is set);
/// nothing for the whole image. Throws Error when the part is empty.
void setImageRegion(const PovOptions& o, RenderSettings& s);

/// Applies the options to job: scene, size (640×480 when not given), anti-aliasing (when a POV-Ray
/// AA option came after render's own --spp/--aa/-ss; it then also decides --aa-edges), threads, JPEG quality, output path, library
/// paths, declarations and the part of the image to render. Throws Error for an empty part.
void applyPovOptions(const PovOptions& o, bool povForm, RenderJob& job);

}  // namespace rays::cli
