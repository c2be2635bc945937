#include "rays/pov/density_files.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "rays/error.h"

namespace rays::pov {

std::shared_ptr<const pattern::DensityGrid> DensityFiles::load(const std::string& name, const sdl::Loc& at) {
    std::string path = find_ ? find_(name) : std::string();
    if (path.empty() && std::filesystem::is_regular_file(name)) path = name;
    if (path.empty())
        throw Error(notes_.where(at) + ": error: cannot find the density file \"" + name +
                    "\" (looked in the scene's folder and the library paths)");
    if (const auto it = files_.find(path); it != files_.end()) return it->second;
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    // Six header bytes and up to kMaxDensityValues 32-bit values.
    if (!ec && size > 6 + 4 * pattern::kMaxDensityValues)
        throw Error(notes_.where(at) + ": error: " + path + ": the density file is larger than a DF3 grid of " +
                    std::to_string(pattern::kMaxDensityValues) + " values can be");
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (!in && !in.eof()) throw Error(notes_.where(at) + ": error: " + path + ": cannot read the density file");
    auto grid = std::make_shared<pattern::DensityGrid>();
    std::string why;
    if (!pattern::readDf3(bytes.str(), *grid, why)) throw Error(notes_.where(at) + ": error: " + path + ": " + why);
    return files_.emplace(path, std::move(grid)).first->second;
}

}  // namespace rays::pov
