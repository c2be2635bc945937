// image_map and image_pattern items read into the pigment table's image maps (PigmentCompiler).
#include <string>
#include <utility>

#include "rays/pov/pigment_compile.h"
#include "rays/pov/pigment_compile_state.h"
#include "rays/pov/specs.h"
#include "rays/sdl/keywords.h"

namespace rays::pov {

using pattern::PatternKind;
using sdl::VType;

// image_map { TYPE "file" [gamma G] [map_type M] [once] [interpolate N] [filter|transmit all|N, A] }
// (POV-Ray 3.7 reference, "Image Map", "Bitmap Modifiers"). The node has no map: the image gives
// the colour. As image_pattern { ... [use_alpha] } (asPattern) the image's grey is the pattern's value.
const ImageFile* PigmentCompiler::readImageMap(const Item& map, State& s, bool asPattern, bool bump) {
    pattern::ImageMap m;
    const ImageFile* file = nullptr;
    bool gammaSet = false;
    bool useIndex = false;  ///< bump_map's use_index
    for (const Entry& e : map.entries) {
        if (e.positional()) {  // `image_map { "file.png" }`: the file without its type (png)
            for (const Value& v : e.args)
                if (v.type == VType::String) file = &images_.load(v.str(), Kw::png, e.loc);
            continue;
        }
        const Kw k = e.kw();
        const auto num = [&](size_t i) { return i < e.args.size() ? toFloat(e.args[i]) : 0.0; };
        if (ImageFiles::isImageType(k) && !ImageFiles::isReadableType(k)) {
            s.unrendered = true;
            s.pattern = false;
            notes_.note(std::string(s.what) + " image_map of a " + std::string(sdl::keywordName(k)) + " file", e.loc,
                        "(drawn in its mean colour)");
            return nullptr;
        }
        if (ImageFiles::isImageType(k)) {
            file = &images_.load(e);
            continue;
        }
        switch (k) {
            case Kw::function:
                s.unrendered = true;
                s.pattern = false;
                notes_.note(std::string(s.what) + " image_map of a function", e.loc, "(drawn in its mean colour)");
                return nullptr;
            case Kw::map_type: m.mapType = int(num(0)); break;
            case Kw::once: m.once = true; break;
            case Kw::use_alpha: m.useAlpha = true; break;
            case Kw::use_index: useIndex = true; break;
            case Kw::use_color: case Kw::use_colour: useIndex = false; break;
            case Kw::interpolate: m.interpolate = int(num(0)); break;
            case Kw::gamma: {
                const double g = num(0);
                // `gamma srgb` reads as a negative number (as assumed_gamma's).
                m.fileGamma = g <= 0 ? pattern::FileGamma{pattern::FileGamma::Kind::Srgb, 1}
                                     : pattern::FileGamma{pattern::FileGamma::Kind::Power, g};
                gammaSet = true;
                break;
            }
            case Kw::filter: case Kw::transmit: {
                const double index = num(0), amount = num(1);
                if (index < 0) {
                    (k == Kw::filter ? m.filterAll : m.transmitAll) = amount;
                } else if (file) {
                    const size_t i = size_t(index);
                    if (i < file->png.palette.size()) {
                        const auto& c = file->png.palette[i];
                        m.palette.push_back({c[0], c[1], c[2], k == Kw::transmit, float(amount)});
                    }
                }
                break;
            }
            default: break;
        }
    }
    if (!file) throw Error(notes_.where(map.loc) + ": error: image_map needs an image file (png \"FILE\" ...)");
    if (m.mapType != 0 && m.mapType != 1 && m.mapType != 2 && m.mapType != 5) {
        notes_.note("image_map map_type " + std::to_string(m.mapType), map.loc, "(mapped as map_type 0)");
        m.mapType = 0;
    }
    m.image = file->image;
    m.setPatternGamma(gammaSet && m.fileGamma.kind == pattern::FileGamma::Kind::Power ? m.fileGamma.gamma : 1.0);
    // Without `gamma`, a scene of #version 3.7 decodes the file by its own gamma (sRGB unless it
    // says otherwise). An older scene decodes only a PNG that states its gamma (a gAMA or sRGB
    // chunk) and uses the bytes of any other file as they are in its working space, whatever its
    // assumed_gamma (measured with POV-Ray 3.7, #version 3.6 and assumed_gamma 1.0: a texel of 85
    // shows as 156 from a PNG without those chunks, a TGA, GIF, JPEG or PPM file, as 84 from a PNG
    // with gAMA 0.45455, as 85 from one with an sRGB chunk; under #version 3.7 as 85 from all
    // but the PPM).
    if (!gammaSet) {
        const bool statesGamma = file->png.png && (file->png.srgb || file->png.gamma > 0);
        m.fileGamma = version_ >= 3.7 || statesGamma ? ImageFiles::defaultGamma(*file)
                                                     : pattern::FileGamma{pattern::FileGamma::Kind::Linear, 1};
    }
    m.setWorkingGamma(1.0);  // until the scene's assumed_gamma is known (PigmentTable::setWorkingGamma)
    // use_index: a palette image's index itself is the height (measured with POV-Ray 3.7: a bump_map
    // texel of palette index 5 with bump_size 1 tilts the normal by atan 5, of index 6 by atan 6).
    if (bump && useIndex) {
        if (auto indices = images_.paletteIndices(*file)) {
            m.image = std::move(indices);
            for (int i = 0; i < 256; ++i) m.patternDecode[size_t(i)] = float(i);
        }
    }
    s.pattern = true;
    s.unrendered = false;
    s.node.kind = asPattern ? PatternKind::ImagePattern : PatternKind::ImageMap;
    s.node.image = int(table_.images.size());
    s.list.clear();
    table_.images.push_back(std::move(m));
    return file;
}

}  // namespace rays::pov
