// Scene: everything a scene file describes. Built by the parser, then immutable while rendering.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "rays/npr/edge_settings.h"
#include "rays/pattern/normal.h"
#include "rays/pattern/pigment.h"
#include "rays/scene/camera.h"
#include "rays/scene/csg.h"
#include "rays/scene/light.h"
#include "rays/scene/mesh.h"
#include "rays/scene/object.h"
#include "rays/scene/pov_surface.h"
#include "rays/scene/pov_texture.h"
#include "rays/scene/text_shape.h"
#include "rays/scene/shapes/shape_data.h"
#include "rays/scene/texture.h"

namespace rays {

struct Scene {
    std::string fileName;
    std::vector<Camera> cameras;  ///< the first is the default; later ones are alternatives
    std::vector<Light> lights;
    std::vector<Object> objects;  ///< course object ID = index + 1
    std::vector<Object> projectors;  ///< POV-Ray lights' projected_through objects (not drawn: Light)
    std::vector<Texture> textures;  ///< image, normal and bump maps referenced by materials
    std::vector<std::unique_ptr<Mesh>> meshes;  ///< geometry of Mesh objects (stable addresses)
    std::vector<std::unique_ptr<Csg>> csgs;     ///< trees of Csg objects (stable addresses)
    std::vector<std::unique_ptr<TextShape>> texts;  ///< outlines of Text objects (stable addresses)
    std::vector<std::unique_ptr<ShapeData>> shapeData;  ///< numbers of Polygon and Poly objects
    /// Transforms written inside pigment / normal blocks: texture space → object space (M) and back.
    struct TextureTransform {
        Transform toObject, toTexture;
    };
    std::vector<TextureTransform> textureTransforms;
    EdgeSettings edges;           ///< feature lines asked for by an `edges { }` block (CLI overrides)
    /// POV-Ray scenes: surfaces referenced by Material::pov, and the scene-wide settings.
    std::vector<PovSurface> povSurfaces;
    std::vector<PovMedia> povMedia;  ///< interior media, referenced by PovInterior::mediaFirst
    PovGlobals pov;
    PovTextures povTextures;  ///< layered and patterned textures referenced by PovSurface::texture
    pattern::PigmentTable pigments;  ///< POV-Ray pigment patterns referenced by PovSurface::pigment
    pattern::NormalTable normals;    ///< POV-Ray normals referenced by PovSurface::normal
};

}  // namespace rays
