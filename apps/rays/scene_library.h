// The scenes shipped in scenes/: files named NN-name.pov whose first comment line describes them.
#pragma once
#include <string>
#include <vector>

namespace rays::cli {

struct LibraryScene {
    int number = 0;
    std::string name;         ///< "soft-shadows"
    std::string description;  ///< first // comment line
    std::string path;
};

/// The scene folder: $RAYS_SCENES if set, else the installed one (PREFIX/share/rays/scenes beside
/// the binary's PREFIX/bin) when it exists, else the source tree's scenes/.
std::string sceneDirectory();

/// All NN-name.pov files of the folder, by number.
std::vector<LibraryScene> listScenes(const std::string& dir);

/// The path of scene `key` (a number or a name); throws Error listing the scenes when unknown.
std::string findScene(const std::string& key);

}  // namespace rays::cli

namespace rays::cli {

/// Writes checker.png, bricks.png, bricks-height.png and bricks-normal.png (256×256) into dir.
int writeAssets(const std::string& dir);

}  // namespace rays::cli
