#include "rays/pov/standalone_object.h"

#include "rays/pov/scene_builder.h"

namespace rays::pov {

StandaloneObject buildStandalone(const sdl::ItemRef& object, const std::function<std::string(const sdl::Loc&)>& where,
                                 const std::function<std::string(const std::string&)>& findFile, FontCache* fonts) {
    StandaloneObject out;
    std::function<std::string(const sdl::Loc&)> at = where;
    if (!at) at = [](const sdl::Loc&) { return std::string(); };
    NotRendered quiet(at, nullptr, false);
    SceneBuilder b(quiet);
    b.setFileFinder(findFile);
    b.setFontCache(fonts);
    b.add(ParsedScene::Top{object, nullptr, 0, 3.7});
    out.scene = b.finish("");
    out.complete = quiet.leftOut() == 0;
    return out;
}

}  // namespace rays::pov
