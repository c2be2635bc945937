// The DF3 files of `density_file df3 "NAME"` patterns, found as image files are (the scene's
// folder, then the library paths) and read once per file.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "rays/pattern/density_file.h"
#include "rays/pov/not_rendered.h"
#include "rays/sdl/value.h"

namespace rays::pov {

class DensityFiles {
public:
    explicit DensityFiles(NotRendered& notes) : notes_(notes) {}
    void setFileFinder(std::function<std::string(const std::string&)> find) { find_ = std::move(find); }
    /// The grid of file `name`; throws Error "FILE:LINE:COL: error: ..." when it cannot be found,
    /// read or is not a DF3 file.
    std::shared_ptr<const pattern::DensityGrid> load(const std::string& name, const sdl::Loc& at);

private:
    NotRendered& notes_;
    std::function<std::string(const std::string&)> find_;
    std::map<std::string, std::shared_ptr<const pattern::DensityGrid>> files_;  ///< by path found
};

}  // namespace rays::pov
