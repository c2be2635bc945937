#include "rays/io/ttf_font.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "rays/error.h"

namespace rays {

namespace {

// A glyph's outline in font units, filled on the left of each segment, with its metrics.
struct CachedGlyph {
    std::vector<TextSegment> segments;  // lines and quadratic Béziers, before the monotone split
    long advance = 0, leftBearing = 0;
};

// FT_Outline_Decompose's walk, collecting segments.
struct Walk {
    std::vector<TextSegment>* out;
    double x = 0, y = 0;
};

Walk& walkOf(void* user) { return *static_cast<Walk*>(user); }

int moveTo(const FT_Vector* to, void* user) {
    Walk& w = walkOf(user);
    w.x = double(to->x), w.y = double(to->y);
    return 0;
}

int lineTo(const FT_Vector* to, void* user) {
    Walk& w = walkOf(user);
    w.out->push_back(TextSegment{w.x, w.y, 0, 0, double(to->x), double(to->y), false});
    w.x = double(to->x), w.y = double(to->y);
    return 0;
}

int conicTo(const FT_Vector* c, const FT_Vector* to, void* user) {
    Walk& w = walkOf(user);
    w.out->push_back(TextSegment{w.x, w.y, double(c->x), double(c->y), double(to->x), double(to->y), true});
    w.x = double(to->x), w.y = double(to->y);
    return 0;
}

// Cubic Béziers (CFF outlines) become four quadratics, each through the cubic's piece's end
// points with the control point (3(c1 + c2) − (p0 + p3))/4 (the midpoint approximation).
int cubicTo(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
    Walk& w = walkOf(user);
    const double p[4][2] = {{w.x, w.y}, {double(c1->x), double(c1->y)}, {double(c2->x), double(c2->y)},
                            {double(to->x), double(to->y)}};
    auto at = [&](double s, int k) {
        const double u = 1 - s;
        return u * u * u * p[0][k] + 3 * u * u * s * p[1][k] + 3 * u * s * s * p[2][k] + s * s * s * p[3][k];
    };
    auto d = [&](double s, int k) {  // derivative / 3
        const double u = 1 - s;
        return u * u * (p[1][k] - p[0][k]) + 2 * u * s * (p[2][k] - p[1][k]) + s * s * (p[3][k] - p[2][k]);
    };
    constexpr int kPieces = 4;
    for (int i = 0; i < kPieces; ++i) {
        const double s0 = double(i) / kPieces, s1 = double(i + 1) / kPieces, h = s1 - s0;
        double q[4][2];
        for (int k = 0; k < 2; ++k) {
            q[0][k] = at(s0, k), q[3][k] = at(s1, k);
            q[1][k] = q[0][k] + h * d(s0, k);  // the piece's cubic control points
            q[2][k] = q[3][k] - h * d(s1, k);
        }
        const double cx = (3 * (q[1][0] + q[2][0]) - (q[0][0] + q[3][0])) / 4;
        const double cy = (3 * (q[1][1] + q[2][1]) - (q[0][1] + q[3][1])) / 4;
        w.out->push_back(TextSegment{q[0][0], q[0][1], cx, cy, q[3][0], q[3][1], true});
    }
    w.x = double(to->x), w.y = double(to->y);
    return 0;
}

}  // namespace

struct TtfFont::Impl {
    std::string path;
    FT_Library lib = nullptr;
    FT_Face face = nullptr;
    std::unordered_map<FT_UInt, CachedGlyph> glyphs;

    ~Impl() {
        if (face) FT_Done_Face(face);
        if (lib) FT_Done_FreeType(lib);
    }

    // The glyph of code point c: the Unicode map FreeType chose, else the font's other maps
    // (symbol fonts put their glyphs at 0xF000 + c); glyph 0 when none has it.
    FT_UInt index(char32_t c) {
        if (FT_UInt g = FT_Get_Char_Index(face, FT_ULong(c))) return g;
        FT_CharMap chosen = face->charmap;
        FT_UInt found = 0;
        for (int i = 0; i < face->num_charmaps && !found; ++i) {
            if (face->charmaps[i] == chosen || FT_Set_Charmap(face, face->charmaps[i]) != 0) continue;
            found = FT_Get_Char_Index(face, FT_ULong(c));
            if (!found && c < 0x100) found = FT_Get_Char_Index(face, FT_ULong(0xF000 + c));
        }
        if (chosen) FT_Set_Charmap(face, chosen);
        return found;
    }

    const CachedGlyph& glyph(FT_UInt g) {
        auto it = glyphs.find(g);
        if (it != glyphs.end()) return it->second;
        CachedGlyph cg;
        if (FT_Load_Glyph(face, g, FT_LOAD_NO_SCALE | FT_LOAD_NO_BITMAP) == 0 &&
            face->glyph->format == FT_GLYPH_FORMAT_OUTLINE) {
            cg.advance = face->glyph->metrics.horiAdvance;
            cg.leftBearing = face->glyph->metrics.horiBearingX;
            FT_Outline_Funcs funcs{};
            funcs.move_to = moveTo;
            funcs.line_to = lineTo;
            funcs.conic_to = conicTo;
            funcs.cubic_to = cubicTo;
            Walk w{&cg.segments};
            FT_Outline_Decompose(&face->glyph->outline, &funcs, &w);
            // TrueType fills to the right of its contours; the shape wants the filled side on the left.
            if (FT_Outline_Get_Orientation(&face->glyph->outline) == FT_ORIENTATION_TRUETYPE)
                for (TextSegment& e : cg.segments) std::swap(e.ax, e.bx), std::swap(e.ay, e.by);
        }
        return glyphs.emplace(g, std::move(cg)).first->second;
    }
};

TtfFont::TtfFont(const std::string& path) : impl_(std::make_unique<Impl>()) {
    impl_->path = path;
    if (FT_Init_FreeType(&impl_->lib) != 0) throw Error(path + ": error: FreeType could not start");
    if (FT_New_Face(impl_->lib, path.c_str(), 0, &impl_->face) != 0)
        throw Error(path + ": error: not a font FreeType can read");
    if (!FT_IS_SCALABLE(impl_->face)) throw Error(path + ": error: the font has no outlines");
}

TtfFont::~TtfFont() = default;

TextShape TtfFont::layout(std::string_view text, double thickness, Vec3 offset) {
    FT_Face face = impl_->face;
    const double scale = 1.0 / double(face->units_per_EM ? face->units_per_EM : 1000);
    TextShape s;
    s.thickness = std::fabs(thickness);  // a negative thickness extrudes towards −z (measured)
    const std::u32string codes = decodeText(text);
    double pen = 0;  // font units
    FT_UInt prev = 0;
    std::vector<Vec3> blanks;  // origins of glyphs without an outline (spaces)
    for (size_t i = 0; i < codes.size(); ++i) {
        const FT_UInt g = impl_->index(codes[i]);
        const CachedGlyph& cg = impl_->glyph(g);
        if (i == 0) pen = -double(cg.leftBearing);
        if (i > 0 && FT_HAS_KERNING(face)) {
            FT_Vector k{0, 0};
            if (FT_Get_Kerning(face, prev, g, FT_KERNING_UNSCALED, &k) == 0) pen += double(k.x);
        }
        const double ox = pen * scale + double(i) * offset.x, oy = double(i) * offset.y;
        TextGlyph tg;
        tg.first = uint32_t(s.segments.size());
        tg.z0 = std::min(thickness, 0.0);  // offset's z is not used (measured)
        s.glyphs.push_back(tg);
        for (const TextSegment& e : cg.segments) {
            if (e.quad)
                s.addQuad(ox + e.ax * scale, oy + e.ay * scale, ox + e.cx * scale, oy + e.cy * scale,
                          ox + e.bx * scale, oy + e.by * scale);
            else
                s.addLine(ox + e.ax * scale, oy + e.ay * scale, ox + e.bx * scale, oy + e.by * scale);
        }
        if (cg.segments.empty()) blanks.push_back(Vec3{ox, oy, tg.z0});
        pen += double(cg.advance);
        prev = g;
    }
    s.finish();
    // POV-Ray's box holds the origin of a glyph without an outline too ("I " is 0.319 wide, not
    // 0.296; " " alone is a point): measured with min_extent / max_extent.
    for (const Vec3& b : blanks) {
        s.bounds.extend(b);
        s.bounds.extend(b + Vec3{0, 0, s.thickness});
    }
    return s;
}

std::u32string decodeText(std::string_view s) {
    std::u32string out;
    for (size_t i = 0; i < s.size();) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        const int len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
        bool ok = len > 1 && i + size_t(len) <= s.size();
        char32_t v = len == 2 ? c & 0x1F : len == 3 ? c & 0x0F : c & 0x07;
        for (int k = 1; ok && k < len; ++k) {
            const unsigned char n = static_cast<unsigned char>(s[i + size_t(k)]);
            ok = (n >> 6) == 2;
            v = (v << 6) | (n & 0x3F);
        }
        if (ok) {
            out.push_back(v);
            i += size_t(len);
        } else {
            out.push_back(c);
            ++i;
        }
    }
    return out;
}

}  // namespace rays
