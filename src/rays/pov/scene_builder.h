// Turns the items of a parsed POV-Ray scene into Rays' Scene under POV-Ray's rules (the course
// rules stay with the course reader): POV-Ray's camera (left-handed, direction, angle, sky,
// look_at), lights, objects with their transformations and textures, CSG unions, default
// texture, global settings and background. What Rays cannot render yet is noted (not_rendered.h):
// objects of unrendered kinds are left out, unrendered appearance is approximated.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>

#include "rays/io/ttf_font.h"
#include "rays/pov/appearance.h"
#include "rays/pov/build_shapes.h"
#include "rays/pov/not_rendered.h"
#include "rays/pov/pov_host.h"
#include "rays/scene/scene.h"
#include "rays/scene/shapes/blob.h"

namespace rays::pov {

class SceneBuilder {
public:
    /// maxObjects: objects it may make, copies of declared objects included (a mesh also counts its
    /// triangles); past it add() throws.
    /// Object patterns' objects are built alone (pattern_object.h) with this builder's file finder
    /// and fonts.
    explicit SceneBuilder(NotRendered& notes, uint64_t maxObjects = uint64_t(1) << 26);
    /// Room for about n objects (one per top-level item), so that a scene of many objects does
    /// not grow its arrays step by step.
    void reserve(size_t n);
    /// How file names in the scene (text's fonts) are found: the path, or "" when none is found.
    void setFileFinder(std::function<std::string(const std::string&)> find) {
        findFile_ = std::move(find);
        pigments_.imageFiles().setFileFinder(findFile_);
        pigments_.densityFiles().setFileFinder(findFile_);
    }
    /// Reads fonts through cache (kept by the caller, outliving the builder) instead of its own.
    void setFontCache(FontCache* cache) { fonts_ = cache ? cache : &ownFonts_; }
    /// Adds one top-level item.
    void add(const ParsedScene::Top& top);
    /// The scene, with POV-Ray's default camera when the file has none.
    Scene finish(const std::string& fileName);

private:
    void updateDefaults(const ParsedScene::Top& top);
    /// Applies entries [from, to) of the #default list to look.
    void applyDefaults(Appearance& look, size_t from, size_t to);
    const Appearance& defaultLookAt(uint32_t mark);
    void addCamera(const Item& camera);
    int cameraNormal(const Entry& normal);  ///< the root of a camera `normal { }` (-1: none)
    /// Sets the window or angles of a non-perspective camera from the camera block's vectors.
    static void finishProjection(Camera& c, Vec3 dir, Vec3 right, Vec3 up, Vec3 lookAt, bool rightOrUpSet,
                                 bool angleSet, const double angles[2]);
    /// A mesh_camera's distinct meshes (distributions 0–2 keep each one's faces once): a mesh's
    /// entries other than its transformations (the same entries for every copy of one declared
    /// mesh) and its stretch of MeshCamera::faces.
    struct CameraMeshShape {
        std::vector<const Entry*> entries;
        size_t first = 0, count = 0;
    };
    /// mesh_camera (scene_builder_mesh_camera.cpp): the block (its keyword at `at`) → its MeshCamera (offset and
    /// reversed left to the camera's location and direction); one of its meshes into mc, its
    /// faces' uvs appended to uvs (distribution 3), a new distinct mesh added to shapes.
    std::shared_ptr<MeshCamera> meshCamera(const Item& block, const sdl::Loc& at);
    void addCameraMesh(MeshCamera& mc, std::vector<double>& uvs, std::vector<CameraMeshShape>& shapes, const Item& item);
    void addLight(const Item& light, const Transform& toWorld);
    void addObject(const Item& object, const Transform& parent, const Appearance* inherited, int depth);
    void addPrimitive(Kw kind, const std::vector<const Value*>& args, const sdl::Loc& at, const Transform& toWorld,
                      const Appearance& look, bool open, bool inverse);
    /// Blobs (scene_builder_blob.cpp): keeps e in terms_ when it is one of a blob's components or
    /// its threshold; the object from them; one component with its own texture (own).
    bool collectBlobEntry(Kw kind, const Entry& e);
    void addBlob(const sdl::Loc& at, const Transform& toWorld, const Appearance& look, bool inverse);
    BlobComponent blobComponent(const Item& component, const Transform& toWorld, Appearance& own);
    /// Isosurfaces (scene_builder_iso.cpp): the object from the isosurface's entries.
    void addIsosurface(const std::vector<const Entry*>& entries, const sdl::Loc& at, const Transform& toWorld,
                       const Appearance& look, bool open, bool inverse);
    void addMesh(const Item& mesh, const Transform& toWorld, const Appearance& look, bool inverse);
    /// The look (texture space → world) of a texture that a mesh's triangle names.
    Appearance faceLook(const Item& texture, const Transform& toWorld);
    void addText(const Entry* font, const std::vector<const Value*>& args, const sdl::Loc& at, const Transform& toWorld,
                 const Appearance& look, bool inverse);
    /// CSG trees (scene/csg.h): the children of a node, the objects of a clipped_by block, the
    /// finished tree as one object, and a finished object put into the tree or the scene.
    void addCsgChildren(Kw kind, bool inverse, const std::vector<const Item*>& children, const Transform& toWorld,
                        const Appearance* own, int depth);
    void addClippers(const Entry& clip, const Entry* bounds, const Transform& toWorld, int depth);
    void finishCsg(Csg&& tree, Kw kind, const sdl::Loc& at);
    bool cameraMayStartInside(const Csg& tree) const;
    void emit(const Object& o, bool inverse);
    /// Whether POV-Ray keeps a bounded_by on this kind as a gate on its rays (measured).
    static bool gatedByBounds(Kw kind);
    /// A clipped_by entry and the object's transformation written before it.
    struct Clip {
        const Entry* entry;
        Transform before;
    };
    void globalSettings(const Item& g);
    void addFog(const Item& fog);
    /// A top-level media block: one more atmospheric media (PovGlobals::media).
    void addAtmosphericMedia(const Item& media);
    /// A media with its densities placed in the world as roots of Scene::pigments (a density with
    /// a singular transformation is left out).
    PovMedia placeMedia(const MediaLook& m);
    /// The look's interior media appended to Scene::povMedia (the last entries reused when they
    /// are the same): in's media range.
    void placeInteriorMedia(const InteriorLook& look, PovInterior& in);
    void addRainbow(const Item& rainbow);
    Material material(const Appearance& look);
    /// The scene's pigment root for a look with a pattern (its texture space completed to world
    /// space by SceneBuilder::addObject), or -1.
    int pigmentRoot(const Appearance& look);
    /// The scene's normal root for a look with a normal (like pigmentRoot), or -1.
    int normalRoot(const Appearance& look);
    /// The node of Scene::povTextures drawing a layered or patterned look on an object whose
    /// surface is `object` (its interior and flags go to every layer); -1 when it cannot be placed.
    int textureNode(const Appearance& look, const PovSurface& object, int depth);
    /// One plain look as a layer of Scene::povTextures.
    PovLayer layerOf(const Appearance& look, const PovSurface& object);
    /// True when some point of the texture node may let light through (every layer of a run, any
    /// texture of a pattern).
    bool textureMayLetLightThrough(int node) const;
    /// sky_sphere: its pigments (layers) and transformations → PovGlobals' sky roots.
    void addSkySphere(const Item& sky);
    /// Counts n more objects made at `at`; throws past maxObjects_.
    void countObjects(uint64_t n, const sdl::Loc& at);
    void placeTessellated(Object& o, std::unique_ptr<Mesh> mesh, const sdl::Loc& at);

    NotRendered& notes_;
    Scene scene_;
    PigmentCompiler pigments_{scene_.pigments, notes_, &scene_.normals};  ///< patterns → scene_.pigments, normals
    Appearance fallback_;      ///< the default texture of the item being added
    Csg* csg_ = nullptr;       ///< the CSG tree being built (objects go into it), or none
    int csgParent_ = -1;       ///< the node of csg_ new objects go under
    double version_ = 3.7;
    bool gammaSet_ = false;
    bool backgroundSet_ = false;
    std::vector<const Entry*> terms_;  ///< the xyz entries of the polynomial being added, a blob's components
    bool leafTextured_ = false;  ///< the primitive being added has a texture of its own or inherited
    PovPhotonFlags photons_;   ///< the photons block of the objects being added (and their parents')
    bool noShadow_ = false;    ///< the objects being added cast no shadow (no_shadow, looks_like)
    bool noImage_ = false;       ///< the objects being added are hidden from camera rays (no_image)
    bool noReflection_ = false;  ///< and from reflection rays (no_reflection)
    bool noRadiosity_ = false;   ///< and from radiosity's gathering rays (no_radiosity)
    bool doubleIlluminate_ = false;  ///< and lit from both sides (double_illuminate)
    bool hollow_ = false;            ///< and hollow: atmospheric media fill them (hollow)
    /// The light_group whose objects and lights are being added (-1: none), and its global_lights:
    /// its lights light only its objects (and no media), and the scene's lights light its objects
    /// only with global_lights.
    int lightGroup_ = -1;
    bool groupGlobalLights_ = true;
    int lightGroups_ = 0;  ///< light_groups met so far
    uint64_t maxObjects_, objects_ = 0;
    std::shared_ptr<const std::vector<sdl::Entry>> defaultsSeen_;  ///< the #default list applied to defaultsLook_
    size_t defaultsApplied_ = 0;                                   ///< how many of its entries
    Appearance defaultsLook_;
    std::map<uint32_t, Appearance> earlierDefaults_;  ///< defaultLookAt's looks, by #default count
    ShapeMemo shapeMemo_;  ///< shapes whose data copies share (build_shapes.h)
    std::function<std::string(const std::string&)> findFile_;
    FontCache ownFonts_;
    FontCache* fonts_ = &ownFonts_;
};

}  // namespace rays::pov
