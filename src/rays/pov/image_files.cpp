#include "rays/pov/image_files.h"

#include <filesystem>
#include <fstream>
#include <iterator>

#include "rays/error.h"
#include "rays/io/gif_read.h"
#include "rays/io/image_io.h"

namespace rays::pov {

bool ImageFiles::isImageType(Kw k) {
    switch (k) {
        case Kw::gif: case Kw::iff: case Kw::jpeg: case Kw::pgm: case Kw::png: case Kw::pot: case Kw::ppm:
        case Kw::sys: case Kw::tga: case Kw::tiff: case Kw::exr: case Kw::hdr:
            return true;
        default: return false;
    }
}

bool ImageFiles::isReadableType(Kw k) {
    return k == Kw::png || k == Kw::jpeg || k == Kw::gif || k == Kw::tga || k == Kw::ppm || k == Kw::pgm;
}

namespace {

bool isGifFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char head[6] = {};
    in.read(head, 6);
    return isGif(reinterpret_cast<const uint8_t*>(head), size_t(in.gcount()));
}

// A GIF's indices and their colours (GIFs are read here, not by readImage).
void readGif(const std::string& path, ImageFile& f) {
    std::ifstream in(path, std::ios::binary);
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    GifImage gif;
    try {
        gif = decodeGif(bytes.data(), bytes.size());
    } catch (const Error& e) {
        throw Error(path + ": error: " + e.what());
    }
    auto indices = std::make_shared<Image8>(gif.width, gif.height, 1);
    indices->pixels = gif.indices;
    auto rgb = std::make_shared<Image8>(gif.width, gif.height, 3);
    for (size_t i = 0; i < gif.indices.size(); ++i) {
        const uint8_t k = gif.indices[i];
        if (k < gif.palette.size())
            for (int c = 0; c < 3; ++c) rgb->pixels[3 * i + size_t(c)] = gif.palette[k][size_t(c)];
    }
    f.gifIndices = std::move(indices);
    f.image = std::move(rgb);
}

}  // namespace

const ImageFile& ImageFiles::load(const Entry& e) {
    if (e.args.empty() || e.args[0].type != sdl::VType::String)
        throw Error(notes_.where(e.loc) + ": error: " + std::string(sdl::keywordName(e.kw())) +
                    " needs the image file's name as a string");
    return load(e.args[0].str(), e.kw(), e.loc);
}

const ImageFile& ImageFiles::load(const std::string& name, Kw type, const sdl::Loc& at) {
    auto find = [&](const std::string& n) {
        std::string p = find_ ? find_(n) : std::string();
        if (p.empty() && std::filesystem::is_regular_file(n)) p = n;
        return p;
    };
    std::string path = find(name);
    // A name without an extension is tried with the image types' extensions too, as POV-Ray does
    // (cliche.pov's `image_map { "sign" }` reads sign.jpg); the file's bytes tell its format.
    if (path.empty() && !std::filesystem::path(name).has_extension())
        for (const char* ext : {".png", ".tga", ".jpg", ".jpeg", ".gif", ".ppm", ".pgm"})
            if (path.empty()) path = find(name + ext);
    if (path.empty())
        throw Error(notes_.where(at) + ": error: cannot find the image file \"" + name +
                    "\" (looked in the scene's folder and the library paths)");
    if (const auto it = files_.find(path); it != files_.end()) return it->second;
    ImageFile f;
    f.type = type;
    f.path = path;
    try {
        if (isGifFile(path)) readGif(path, f);
        else f.image = std::make_shared<const Image8>(readImage(path));
    } catch (const Error& err) {
        // readImage says "PATH: error: WHY": the keyword's place comes first.
        const std::string m = err.what();
        const size_t cut = m.find("error: ");
        throw Error(notes_.where(at) + ": error: " + path + ": " + (cut == std::string::npos ? m : m.substr(cut + 7)));
    }
    f.png = readPngInfo(path);
    return files_.emplace(path, std::move(f)).first->second;
}

pattern::FileGamma ImageFiles::defaultGamma(const ImageFile& f) {
    using pattern::FileGamma;
    if (f.png.png) {
        if (f.png.srgb || f.png.gamma == 0) return {FileGamma::Kind::Srgb, 1};
        return {FileGamma::Kind::Power, f.png.gamma};
    }
    if (f.type == Kw::ppm || f.type == Kw::pgm) return {FileGamma::Kind::Linear, 1};
    if (f.type == Kw::exr || f.type == Kw::hdr) return {FileGamma::Kind::Linear, 1};
    return {FileGamma::Kind::Srgb, 1};
}

std::shared_ptr<const Image8> ImageFiles::paletteIndices(const ImageFile& f) {
    if (const auto it = indices_.find(f.path); it != indices_.end()) return it->second;
    std::shared_ptr<const Image8> out;
    PngSamples s;
    if (f.png.png && !f.png.palette.empty() && readPngSamples(f.path, s, true) && s.maxValue == 255) {
        auto img = std::make_shared<Image8>(s.width, s.height, 1);
        for (size_t i = 0; i < s.samples.size(); ++i) img->pixels[i] = uint8_t(s.samples[i]);
        out = img;
    } else if (f.gifIndices) {
        out = f.gifIndices;
    }
    indices_.emplace(f.path, out);
    return out;
}

}  // namespace rays::pov
