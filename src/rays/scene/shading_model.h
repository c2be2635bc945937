// The shading models Rays implements (closed set, dispatched by switch).
#pragma once

namespace rays {

/// Numbers as in the original system's positional form: 0 Blinn-Phong, 1 Cook-Torrance,
/// 2 Oren-Nayar, 3 Lambert, 4 flat, 5 normals. (POV-Ray scenes are lit by POV-Ray's own model,
/// render/tracer_povray.cpp, whatever their materials' shading says.)
enum class ShadingModel { BlinnPhong = 0, CookTorrance = 1, OrenNayar = 2, Lambert = 3, Flat = 4, Normals = 5 };

/// Name printed by the course commands ("Blinn-Phong", "Cook-Torrance", ...).
const char* shadingName(ShadingModel m);

/// Parses a CLI or scene name: blinn-phong, cook-torrance, oren-nayar, lambert, flat, normals
/// (underscores accepted for dashes). Returns false for an unknown name.
bool parseShadingName(const char* name, ShadingModel& out);

}  // namespace rays
