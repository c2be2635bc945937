// The image files a POV-Ray scene reads (image_map, height_field): each file found as `#include`
// files are (the scene's folder, the library paths), read once and shared as 8-bit texels, with
// its PNG chunks (palette, gamma). A missing or unreadable file is an error at the keyword.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "rays/image/image.h"
#include "rays/io/png_info.h"
#include "rays/pattern/image_map.h"
#include "rays/pov/item_values.h"
#include "rays/pov/not_rendered.h"

namespace rays::pov {

struct ImageFile {
    std::shared_ptr<const Image8> image;
    PngInfo png;
    Kw type = Kw::png;  ///< the keyword naming the file type
    std::string path;   ///< where it was found
    std::shared_ptr<const Image8> gifIndices;  ///< a GIF's palette indices (one channel)
};

class ImageFiles {
public:
    explicit ImageFiles(NotRendered& notes) : notes_(notes) {}
    void setFileFinder(std::function<std::string(const std::string&)> find) { find_ = std::move(find); }
    /// The file of an image type entry (`png "name"`), read on first use; throws Error
    /// "FILE:LINE:COL: error: ..." when it cannot be found or read.
    const ImageFile& load(const Entry& typeEntry);
    /// The file `name` of a type (png when none was written: POV-Ray's default output type), as load.
    const ImageFile& load(const std::string& name, Kw type, const sdl::Loc& at);
    /// True for the keywords naming an image file type (png, jpeg, gif, tga, ppm, pgm, sys, iff, tiff ...).
    static bool isImageType(Kw k);
    /// True for the types Rays reads (png, jpeg, gif, tga, ppm, pgm); the others (pot, sys, iff,
    /// tiff, exr, hdr) are noted by the callers.
    static bool isReadableType(Kw k);
    /// POV-Ray 3.7's default gamma of an image_map file: PNG by its sRGB or gAMA chunk (sRGB
    /// without), PPM and PGM as the working space (linear), other formats sRGB.
    static pattern::FileGamma defaultGamma(const ImageFile& f);
    /// The palette indices of a palette image (a PNG with a PLTE, a GIF) as a one-channel image,
    /// top row first, read once; nullptr for a file without a palette.
    std::shared_ptr<const Image8> paletteIndices(const ImageFile& f);

private:
    NotRendered& notes_;
    std::function<std::string(const std::string&)> find_;
    std::map<std::string, ImageFile> files_;  ///< by path found
    std::map<std::string, std::shared_ptr<const Image8>> indices_;  ///< paletteIndices by path
};

}  // namespace rays::pov
