// SceneBuilder's primitives: the shape an object item's keyword and values make (sphere, box,
// cone, torus, ... through build_shapes), text through FreeType, meshes, and the shapes drawn as
// the meshes they are tessellated into.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "rays/error.h"
#include "rays/pov/build_height_field.h"
#include "rays/pov/build_mesh.h"
#include "rays/pov/build_shapes.h"
#include "rays/pov/scene_builder.h"
#include "rays/pov/scene_builder_parts.h"

namespace rays::pov {

using sdl::VType;

// A shape drawn as the mesh it was tessellated into (parametric, bicubic_patch): its triangles
// count against the scene's object limit.
void SceneBuilder::placeTessellated(Object& o, std::unique_ptr<Mesh> mesh, const sdl::Loc& at) {
    countObjects(mesh->triangleCount(), at);
    mesh->finalize();
    o.type = ShapeType::Mesh;
    o.mesh = mesh.get();
    scene_.meshes.push_back(std::move(mesh));
}

void SceneBuilder::addPrimitive(Kw kind, const std::vector<const Value*>& a, const sdl::Loc& at,
                                const Transform& toWorld, const Appearance& look, bool open, bool inverse) {
    auto need = [&](size_t n) {
        if (a.size() < n)
            throw Error(notes_.where(at) + ": error: " + std::string(sdl::keywordName(kind)) + " needs " +
                        std::to_string(n) + " values, found " + std::to_string(a.size()));
    };
    Object o;
    o.line = int(at.line);
    o.col = int(at.col);
    switch (kind) {
        case Kw::sphere:
            need(2);
            o.type = ShapeType::Sphere;
            o.p0 = toVec3(*a[0]);
            o.r0 = toFloat(*a[1]);
            if (o.r0 <= 0) return;
            break;
        case Kw::box: {
            need(2);
            o.type = ShapeType::Box;
            const Vec3 p = toVec3(*a[0]), q = toVec3(*a[1]);
            o.p0 = vmin(p, q);
            o.p1 = vmax(p, q);
            break;
        }
        case Kw::cone:
            need(4);
            o.type = ShapeType::Cone;
            o.p0 = toVec3(*a[0]);
            o.r0 = std::fabs(toFloat(*a[1]));
            o.p1 = toVec3(*a[2]);
            o.r1 = std::fabs(toFloat(*a[3]));
            if (length(o.p1 - o.p0) == 0 || (o.r0 == 0 && o.r1 == 0)) return;
            break;
        case Kw::cylinder:
            need(3);
            o.type = ShapeType::Cone;
            o.p0 = toVec3(*a[0]);
            o.p1 = toVec3(*a[1]);
            o.r0 = o.r1 = std::fabs(toFloat(*a[2]));
            if (length(o.p1 - o.p0) == 0 || o.r0 == 0) return;
            break;
        case Kw::plane: {
            need(2);
            o.type = ShapeType::Plane;
            const Vec3 n = toVec3(*a[0]);
            if (length(n) == 0) throw Error(notes_.where(at) + ": error: the plane's normal is zero");
            o.p0 = normalize(n);
            o.r0 = toFloat(*a[1]);  // points with n̂·p = d
            break;
        }
        case Kw::triangle: case Kw::smooth_triangle: {
            const bool smooth = kind == Kw::smooth_triangle;
            need(smooth ? 6 : 3);
            o.type = ShapeType::Triangle;
            o.p0 = toVec3(*a[0]);
            o.p1 = toVec3(*a[smooth ? 2 : 1]);
            o.p2 = toVec3(*a[smooth ? 4 : 2]);
            if (length(cross(o.p1 - o.p0, o.p2 - o.p0)) == 0) return;
            if (smooth) {
                o.smooth = true;
                o.n0 = toVec3(*a[1]);
                o.n1 = toVec3(*a[3]);
                o.n2 = toVec3(*a[5]);
                if (length(o.n0) == 0 || length(o.n1) == 0 || length(o.n2) == 0) o.smooth = false;
                else o.n0 = normalize(o.n0), o.n1 = normalize(o.n1), o.n2 = normalize(o.n2);
            }
            break;
        }
        case Kw::parametric: {
            auto mesh = std::make_unique<Mesh>();
            const ShapeBuild made = buildParametric(a, terms_, *mesh, notes_.where(at));
            if (made == ShapeBuild::NotAShape)
                notes_.note("parametric function calling a pattern or pigment function of a pattern Rays does not render",
                            at, "(left out)");
            if (made != ShapeBuild::Made) return;
            placeTessellated(o, std::move(mesh), at);
            break;
        }
        case Kw::bicubic_patch: {
            auto mesh = std::make_unique<Mesh>();
            buildBicubicPatch(a, terms_, *mesh, notes_.where(at));
            placeTessellated(o, std::move(mesh), at);
            break;
        }
        case Kw::height_field: {
            auto data = std::make_unique<ShapeData>();
            std::string name;  // `height_field { "file.png" }`: the file without its type
            for (const Value* v : a)
                if (v->type == VType::String) name = v->str();
            if (!buildHeightField(terms_, name, at, pigments_.imageFiles(), notes_, *data, o.smooth,
                                  maxObjects_ > objects_ ? maxObjects_ - objects_ : 0))
                return;
            // Each sample counts, as a mesh's triangles do (values: nx, nz, water_level, heights).
            countObjects(data->values.size() > 3 ? uint64_t(data->values.size() - 3) : 0, at);
            o.type = ShapeType::HeightField;
            o.data = data.get();
            scene_.shapeData.push_back(std::move(data));
            break;
        }
        default: {
            std::unique_ptr<ShapeData> data;
            const ShapeBuild made = buildShape(kind, a, terms_, o, data, notes_.where(at), shapeMemo_);
            if (made == ShapeBuild::Empty) return;
            if (made == ShapeBuild::NotAShape) {
                notes_.note(std::string(sdl::keywordName(kind)), at, "(left out)");
                return;
            }
            if (data) {
                o.data = data.get();
                scene_.shapeData.push_back(std::move(data));
            }
            break;
        }
    }
    o.open = open && (o.type == ShapeType::Cone || o.type == ShapeType::Prism || o.type == ShapeType::Sor);
    o.material = material(look);
    prepareObject(o, toWorld);
    emit(o, inverse);
}

// ---- text -----------------------------------------------------------------------------------

namespace {

// POV-Ray 3.7's built-in fonts by number (reference 3.4.5.1.16 "Text"), out of range → 0; the
// Debian package fonts-povray holds the same files.
const char* internalFont(double n) {
    static const char* const kFonts[] = {"povlogo.ttf", "timrom.ttf", "cyrvetic.ttf", "crystal.ttf"};
    const int i = std::isnan(n) ? 0 : int(n);
    return kFonts[i >= 0 && i < 4 ? i : 0];
}

// Where fonts-povray installs its fonts: searched after the include path.
constexpr const char* kInstalledFonts = "/usr/share/fonts/truetype/povray";

}  // namespace

// `text { ttf FILE STRING thickness, offset }`: the font file is looked up as `#include` files
// are (the scene's folder, the library paths, the installed include folder), then in fonts-povray's folder.
void SceneBuilder::addText(const Entry* font, const std::vector<const Value*>& a, const sdl::Loc& at,
                           const Transform& toWorld, const Appearance& look, bool inverse) {
    if (!font || font->args.empty()) throw Error(notes_.where(at) + ": error: text needs ttf \"FILE\" or internal N");
    if (a.size() < 3 || a[0]->type != VType::String)
        throw Error(notes_.where(at) + ": error: text needs a string, a thickness and an offset after the font");
    std::string name;
    if (font->kw() == Kw::internal) name = internalFont(toFloat(font->args[0]));
    else if (font->args[0].type == VType::String) name = font->args[0].str();
    else throw Error(notes_.where(font->loc) + ": error: ttf needs the font file's name as a string");
    // A name without an extension is also tried with ".ttf" (POV-Ray's examples write "cyrvetic").
    // Found once per name (a scene of many texts looked in every folder for each).
    std::string& path = fonts_->pathOf[name];
    if (path.empty()) {
        std::vector<std::string> names{name};
        if (!std::filesystem::path(name).has_extension()) names.push_back(name + ".ttf");
        for (const std::string& n : names) {
            if (path.empty() && findFile_) path = findFile_(n);
            if (path.empty() && !std::filesystem::path(n).is_absolute()) {
                const std::string installed = (std::filesystem::path(kInstalledFonts) / n).string();
                if (std::filesystem::is_regular_file(installed)) path = installed;
            }
        }
    }
    if (path.empty())
        throw Error(notes_.where(font->loc) + ": error: cannot find the font file \"" + name +
                    "\" (looked in the scene's folder, the library paths and " + kInstalledFonts + ")");
    const double thickness = toFloat(*a[1]);
    const Vec3 offset = toVec3(*a[2]);
    if (!std::isfinite(thickness)) return;
    // The same string in the same font, thickness and offset shares its outlines (a key with a
    // NaN in it would not order: such a text gets outlines of its own).
    const bool keyed = std::isfinite(offset.x) && std::isfinite(offset.y) && std::isfinite(offset.z);
    const TextShape* own = nullptr;
    const TextShape*& shape = keyed ? shapeMemo_.texts[ShapeMemo::TextKey{path, a[0]->str(), thickness, offset.x, offset.y, offset.z}] : own;
    if (!shape) {
        std::unique_ptr<TtfFont>& f = fonts_->byPath[path];
        try {
            if (!f) f = std::make_unique<TtfFont>(path);
        } catch (const Error& err) {
            throw Error(notes_.where(font->loc) + ": " + err.what());
        }
        scene_.texts.push_back(std::make_unique<TextShape>(f->layout(a[0]->str(), thickness, offset)));
        shape = scene_.texts.back().get();
    }
    if (shape->bounds.empty()) return;  // "": nothing (a string of spaces is an empty box, as in POV-Ray)
    Object o;
    o.type = ShapeType::Text;
    o.text = shape;
    o.line = int(at.line);
    o.col = int(at.col);
    o.material = material(look);
    prepareObject(o, toWorld);
    emit(o, inverse);
}

void SceneBuilder::addMesh(const Item& m, const Transform& toWorld, const Appearance& look, bool inverse) {
    std::string problem;
    FaceTextures named;
    std::unique_ptr<Mesh> mesh = meshFromItem(m, problem, &named);
    if (!mesh) throw Error(notes_.where(m.loc) + ": error: " + problem);
    if (mesh->triangleCount() == 0) return;
    countObjects(mesh->triangleCount(), m.loc);
    try {
        mesh->finalize();
    } catch (const Error& err) {
        throw Error(notes_.where(m.loc) + ": error: " + err.what());
    }
    Object o;
    o.type = ShapeType::Mesh;
    o.mesh = mesh.get();
    o.line = int(m.loc.line);
    o.col = int(m.loc.col);
    o.material = material(look);
    // A texture that every face names is the mesh's (the mesh_camera demos bake a uv-mapped
    // texture so); else each named texture is a part of the mesh, found by the hit's triangle.
    const bool one = !named.face.empty() && named.face[0] >= 0 &&
                     std::all_of(named.face.begin(), named.face.end(), [&](int32_t t) { return t == named.face[0]; });
    if (one) o.material = material(faceLook(*named.textures[size_t(named.face[0])], toWorld));
    prepareObject(o, toWorld);
    const bool any = std::any_of(named.face.begin(), named.face.end(), [](int32_t t) { return t >= 0; });
    if (any && (!one || !named.corners.empty())) {
        auto data = std::make_unique<ShapeData>();
        for (const Item* t : named.textures) {
            Object part = o;
            part.material = material(faceLook(*t, toWorld));
            data->parts.push_back(part);
        }
        data->faceParts = std::move(named.face);
        data->cornerParts = std::move(named.corners);
        o.data = data.get();
        for (Object& part : data->parts) part.data = data.get();
        scene_.shapeData.push_back(std::move(data));
    }
    scene_.meshes.push_back(std::move(mesh));
    emit(o, inverse);
}

// The look of a texture a mesh's face names: the default texture under it, moved with the mesh.
Appearance SceneBuilder::faceLook(const Item& texture, const Transform& toWorld) {
    Appearance out = fallback_;
    applyTexture(texture, out, notes_, &pigments_, &fallback_);
    placeLook(out, toWorld);
    return out;
}

}  // namespace rays::pov
