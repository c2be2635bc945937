// TrueType (and TrueType collection, first face) fonts through FreeType, and the layout of a
// string into a TextShape as POV-Ray 3.7 lays out its `text` object (reference 3.4.5.1.16
// "Text", sizes and places measured with POV-Ray 3.7.0.10's min_extent, max_extent and trace):
// one unit is the font's EM; the pen starts so that the first glyph's left side bearing is
// dropped (its outline starts at x = 0); each glyph advances the pen by its advance width plus the
// font's kerning with the next glyph; glyph i is also moved by i·offset's x and y (its z is not
// used); the text lies between z = 0 and z = thickness (a negative thickness goes towards −z).
// Its box is the glyphs' outline boxes and the origins of glyphs without an outline (spaces).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>

#include "rays/math/vec3.h"
#include "rays/scene/text_shape.h"

namespace rays {

class TtfFont {
public:
    /// Opens the font file; throws Error("PATH: error: ...") when FreeType cannot read it.
    explicit TtfFont(const std::string& path);
    ~TtfFont();
    TtfFont(const TtfFont&) = delete;
    TtfFont& operator=(const TtfFont&) = delete;

    /// The text of `text` (UTF-8; bytes that are not valid UTF-8 count as Latin-1) laid out as
    /// POV-Ray does and extruded by thickness (0 gives flat letters), finished.
    TextShape layout(std::string_view text, double thickness, Vec3 offset);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// Fonts read so far and the files their names were found at (one parse's builders share them:
/// the objects built for trace() and the extents read the same fonts as the scene, and a scene of
/// many texts looks for each font once).
struct FontCache {
    std::unordered_map<std::string, std::unique_ptr<TtfFont>> byPath;  ///< the fonts loaded, by file
    std::unordered_map<std::string, std::string> pathOf;  ///< the file each font name was found at
};

/// Code points of s: UTF-8 sequences decoded, other bytes taken as Latin-1.
std::u32string decodeText(std::string_view s);

}  // namespace rays
