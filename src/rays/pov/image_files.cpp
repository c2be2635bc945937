#include "rays/pov/image_files.h"

#include <filesystem>

#include "rays/error.h"
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
        f.image = std::make_shared<const Image8>(readImage(path));
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

}  // namespace rays::pov
