#include "rays/pov/build_height_field.h"

#include <algorithm>
#include <cmath>

#include "rays/error.h"
#include "rays/fn/compile.h"
#include "rays/scene/shapes/height_field.h"
#include "rays/image/parallel.h"
#include "rays/sdl/function_value.h"

namespace rays::pov {

namespace {

constexpr int kMaxSide = 65536;

// Heights of an image, row iz = 0 (the image's bottom row) first.
void imageHeights(const ImageFile& f, int& nx, int& nz, std::vector<double>& heights) {
    PngSamples s;
    if (f.png.png && readPngSamples(f.path, s)) {
        nx = s.width;
        nz = s.height;
        heights.resize(s.samples.size());
        for (int j = 0; j < nz; ++j)
            for (int i = 0; i < nx; ++i)
                heights[size_t(nz - 1 - j) * size_t(nx) + size_t(i)] =
                    double(s.samples[size_t(j) * size_t(nx) + size_t(i)]) / s.maxValue;
        return;
    }
    const Image8& img = *f.image;
    nx = img.width;
    nz = img.height;
    heights.resize(size_t(nx) * size_t(nz));
    for (int j = 0; j < nz; ++j) {
        const uint8_t* row = img.row(j);
        for (int i = 0; i < nx; ++i) {
            const uint8_t* p = row + size_t(i) * size_t(img.channels);
            const double v = img.channels >= 3 ? 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2] : p[0];
            heights[size_t(nz - 1 - j) * size_t(nx) + size_t(i)] = v / 255;
        }
    }
}

// Heights of a Fractint continuous-potential file (`pot "file"`; POV-Ray 3.7 reference, "Height
// Field": a GIF twice as wide as the field, its palette indices the 16-bit heights' high bytes in
// the left half and their low bytes in the right half). Measured with POV-Ray 3.7 (trace() down onto
// mtmand.pot's grid points): the height is (256·high + low) / 65536. False for a file without
// a palette or of odd width.
bool potHeights(const ImageFile& f, ImageFiles& files, int& nx, int& nz, std::vector<double>& heights) {
    const std::shared_ptr<const Image8> indices = files.paletteIndices(f);
    if (!indices || indices->width < 4 || indices->width % 2 != 0) return false;
    const Image8& img = *indices;
    nx = img.width / 2;
    nz = img.height;
    heights.resize(size_t(nx) * size_t(nz));
    for (int j = 0; j < nz; ++j) {
        const uint8_t* row = img.row(j);
        for (int i = 0; i < nx; ++i)
            heights[size_t(nz - 1 - j) * size_t(nx) + size_t(i)] = (256.0 * row[i] + row[i + nx]) / 65536.0;
    }
    return true;
}

// Heights of `function W, H { f }`: f(x, y, 0) at x = ix/(W−1), y = iz/(H−1), clamped to [0, 1];
// of a pigment function, its colour's gray (0.297 r + 0.589 g + 0.114 b: measured with POV-Ray
// 3.7, pure red gives 0.297).
void functionHeights(const Entry& e, const std::string& where, uint64_t budget, int& nx, int& nz,
                     std::vector<double>& heights) {
    if (e.args.size() < 3 || e.args[2].type != sdl::VType::Function)
        throw Error(where + ": error: height_field's function needs a resolution and a function");
    const double w = toFloat(e.args[0]), h = toFloat(e.args[1]);
    if (!(w >= 2 && h >= 2 && w <= kMaxSide && h <= kMaxSide && w * h <= double(1 << 26)))
        throw Error(where + ": error: height_field's function resolution must be 2 to 65536 per side (" +
                    std::to_string(w) + " x " + std::to_string(h) + ")");
    if (w * h > double(budget))
        throw Error(where + ": error: height_field's function of " + std::to_string(int(w)) + " x " + std::to_string(int(h)) +
                    " samples goes past the scene's object limit (" + std::to_string(budget) +
                    " left; each sample counts, as a mesh's triangles do)");
    nx = int(w);
    nz = int(h);
    const sdl::FunctionValue& f = e.args[2].fn();
    if (!f.table || f.index < 0) throw Error(where + ": error: height_field's function is not a float function");
    const fn::Program& program = f.table->program(f.index);
    heights.resize(size_t(nx) * size_t(nz));
    // Rows in parallel on every core (the table is complete and read-only while it runs; each
    // row writes only its own heights, so the result does not depend on the thread count): a
    // noisy function on a fine grid is most of some scenes' parse (advanced/balcony).
    parallelFor(nz, 0, [&](int iz) {
        fn::Scratch scratch;
        scratch.fit(program);
        for (int ix = 0; ix < nx; ++ix) {
            // The function's y runs against the field's z: h(x, z) = f(x, 1 − z, 0) (measured with
            // POV-Ray 3.7 by trace() on fields of f = y and of a gradient y pigment).
            double args[fn::kMaxParams] = {double(ix) / (nx - 1), 1.0 - double(iz) / (nz - 1), 0};
            double v = 0;
            if (f.kind == sdl::FunctionValue::Kind::Pigment) {
                double c[5] = {};
                fn::evalVector(program, args, c, scratch);
                v = 0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2];
            } else {
                v = fn::eval(program, args, scratch);
            }
            heights[size_t(iz) * size_t(nx) + size_t(ix)] = std::isnan(v) ? 0 : std::clamp(v, 0.0, 1.0);
        }
    });
}

}  // namespace

bool buildHeightField(const std::vector<const Entry*>& entries, const std::string& name, const sdl::Loc& at,
                      ImageFiles& files, NotRendered& notes, ShapeData& data, bool& smooth, uint64_t sampleBudget) {
    const std::string where = notes.where(at);
    int nx = 0, nz = 0;
    std::vector<double> heights;
    double water = 0;
    bool source = false;
    smooth = false;
    if (!name.empty()) {
        imageHeights(files.load(name, Kw::png, at), nx, nz, heights);
        source = true;
    }
    for (const Entry* e : entries) {
        const Kw k = e->kw();
        if (k == Kw::pot) {
            if (!potHeights(files.load(*e), files, nx, nz, heights))
                throw Error(notes.where(e->loc) + ": error: the pot file is not a palette image of even width");
            source = true;
            continue;
        }
        if (ImageFiles::isImageType(k) && !ImageFiles::isReadableType(k)) {
            notes.note("height_field from a " + std::string(sdl::keywordName(k)) + " file", e->loc, "(left out)");
            return false;
        }
        if (ImageFiles::isImageType(k)) {
            imageHeights(files.load(*e), nx, nz, heights);
            source = true;
        } else if (k == Kw::function) {
            functionHeights(*e, where, sampleBudget, nx, nz, heights);
            source = true;
        } else if (k == Kw::smooth) {
            smooth = true;
        } else if (k == Kw::water_level && !e->args.empty()) {
            water = toFloat(e->args[0]);
        }
    }
    if (!source) throw Error(where + ": error: height_field needs an image file (png \"FILE\" ...) or a function");
    return makeHeightField(nx, nz, heights, water, data);
}

}  // namespace rays::pov
