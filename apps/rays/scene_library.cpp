#include "scene_library.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "rays/error.h"

namespace rays::cli {

std::string sceneDirectory() {
    if (const char* env = std::getenv("RAYS_SCENES"); env && *env) return env;
    // An installed rays (cmake --install) finds PREFIX/share/rays/scenes beside its bin folder.
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const std::filesystem::path installed = (exe.parent_path() / RAYS_SCENES_FROM_BIN).lexically_normal();
        if (std::filesystem::is_directory(installed, ec)) return installed.string();
    }
    return RAYS_SCENES_DIR;
}

std::vector<LibraryScene> listScenes(const std::string& dir) {
    std::vector<LibraryScene> out;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
        const std::string file = entry.path().filename().string();
        if (entry.path().extension() != ".pov" || file.size() < 4 || !std::isdigit(static_cast<unsigned char>(file[0])))
            continue;
        const size_t dash = file.find('-');
        if (dash == std::string::npos) continue;
        LibraryScene s;
        s.number = std::atoi(file.substr(0, dash).c_str());
        s.name = entry.path().stem().string().substr(dash + 1);
        s.path = entry.path().string();
        std::ifstream in(entry.path());
        std::string line;
        while (std::getline(in, line)) {
            if (line.rfind("//", 0) == 0) {
                s.description = line.substr(line.find_first_not_of("/ "));
                break;
            }
        }
        out.push_back(s);
    }
    std::sort(out.begin(), out.end(), [](const LibraryScene& a, const LibraryScene& b) { return a.number < b.number; });
    return out;
}

std::string findScene(const std::string& key) {
    const std::string dir = sceneDirectory();
    const auto scenes = listScenes(dir);
    for (const LibraryScene& s : scenes)
        if (s.name == key || std::to_string(s.number) == key) return s.path;
    std::string names;
    for (const LibraryScene& s : scenes) names += (names.empty() ? "" : ", ") + std::to_string(s.number) + " " + s.name;
    throw Error("rays: error: no scene '" + key + "' in " + dir + " (scenes: " + (names.empty() ? "none" : names) + ")");
}

}  // namespace rays::cli

#include "rays/image/procedural.h"
#include "rays/io/image_io.h"
#include "rays/io/output_files.h"

namespace rays::cli {

int writeAssets(const std::string& dir) {
    std::error_code ec;
    if (!std::filesystem::exists(dir, ec)) failFile(dir, "does not exist (create the folder first)");
    if (!std::filesystem::is_directory(dir, ec)) failFile(dir, "is not a folder");
    const std::filesystem::path d(dir);
    const uint8_t light[3] = {230, 230, 220}, dark[3] = {40, 60, 110};
    const Image8 height = brickHeightImage(256, 256, 8);
    OutputFiles files;  // the four are replaced together, once all are written
    auto stage = [&](const char* name, const Image8& img) {
        const std::string path = (d / name).string();
        files.stage(path, encodeImageFile(path, img));
    };
    stage("checker.png", checkerImage(256, 8, light, dark));
    stage("bricks.png", brickColorImage(256, 256, 8));
    stage("bricks-height.png", height);
    stage("bricks-normal.png", normalMapFromHeight(height, 6.0));
    files.commit();
    std::fprintf(stderr, "rays: wrote checker.png, bricks.png, bricks-height.png, bricks-normal.png in %s\n", printableMessage(dir).c_str());
    return 0;
}

}  // namespace rays::cli
