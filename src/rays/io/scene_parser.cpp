// The scene structure of the course dialect and POV-Ray: top level, camera, lights, objects and
// their modifiers, materials and textures, obj_mesh; tokens and expressions come from TokenReader
// (token_reader.h), inline mesh bodies from mesh_blocks.h.
#include "rays/io/scene_parser.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>

#include "rays/io/file_text.h"
#include "rays/io/lexer.h"
#include "rays/io/mesh_blocks.h"
#include "rays/io/mesh_from_obj.h"
#include "rays/io/obj_loader.h"
#include "rays/io/scene_pieces.h"
#include "rays/io/token_reader.h"
#include "rays/pov/load_pov.h"

namespace rays {
namespace {

using namespace scenetext;

// A number as messages quote it: "1e+31", "0.5".
std::string numberText(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// "must be between LO and HI" for a value with no rule of its own.
std::string betweenRule(double lo, double hi) { return "must be between " + numberText(lo) + " and " + numberText(hi); }

class Parser : TokenReader {
public:
    /// text: the file, or a piece of it starting at line firstLine; reserveBytes: the length of the
    /// text whose objects scene_ will end up holding.
    Parser(std::string_view text, const std::string& file, const ParseOptions& opt, int firstLine = 1,
           size_t reserveBytes = 0)
        : TokenReader(text, file, opt, firstLine) {
        scene_.fileName = file;
        // Course files spend 150-250 bytes per object; reserving for 64 avoids every reallocation
        // (untouched capacity costs address space only).
        scene_.objects.reserve(std::max(reserveBytes, text.size()) / 64 + 16);
    }

    Scene run() {
        readAll();
        flushWarnings();
        if (scene_.cameras.empty()) fail(SourceLoc{lex_.fileName(), 0, 0}, "scene has no camera");
        return std::move(scene_);
    }

    /// A piece of a file: its items, without the whole file's checks.
    Scene runPiece() {
        readAll();
        return std::move(scene_);
    }
    bool sawEdges() const { return sawEdges_; }

private:
    // ---- colours    // ---- colours -------------------------------------------------------------------------------
    // `color` / `colour` is optional; then rgb / rgbf / rgbt / rgbft and a vector (or a bare vector).
    void colorSpec(Material& m) {
        if (isIdent("color") || isIdent("colour")) advance();
        int want = 3;
        bool hasFilter = false, hasTransmit = false;
        const Token kw = tok_;
        if (isIdent("rgb")) {
            advance();
        } else if (isIdent("rgbf")) {
            want = 4;
            hasFilter = true;
            advance();
        } else if (isIdent("rgbt")) {
            want = 4;
            hasTransmit = true;
            advance();
        } else if (isIdent("rgbft")) {
            want = 5;
            hasFilter = hasTransmit = true;
            advance();
        } else if (!isSymbol('<')) {
            error("expected a colour (rgb, rgbf, rgbt, rgbft or <r, g, b>), found " + describe(tok_));
        }
        const Token at = tok_;
        const Value v = expr();
        Vec3 rgb;
        double f = 0;
        if (v.isScalar()) {
            if (want != 3) fail(loc(at), "expected a " + std::to_string(want) + "-component colour");
            rgb = Vec3(v.c[0]);
        } else if (want == 3 && v.n == 4) {
            rgb = {v.c[0], v.c[1], v.c[2]};  // 4-component rgb means rgbf (seen in course scenes)
            f = v.c[3];
        } else if (v.n < 3 || v.n > want) {
            fail(loc(at), "expected a " + std::to_string(want) + "-component colour, found " +
                              std::to_string(v.n) + " components");
        } else {
            // Missing filter / transmit components are 0, as in POV-Ray (`rgbf <1, 1, 1>` occurs).
            rgb = {v.c[0], v.c[1], v.c[2]};
            if (hasFilter) f = v.c[3];
            if (hasTransmit && v.c[want - 1] != 0) {
                warn(loc(kw), "transmit is treated as filter by Rays");
                f += v.c[want - 1];
            }
        }
        for (int i = 0; i < 3; ++i)
            if (!std::isfinite(rgb[i])) fail(loc(at), "colour has a non-finite component");
        if (!std::isfinite(f) || f < 0 || f > 1) fail(loc(at), "filter must be between 0 and 1");
        m.color = rgb;
        m.filter = f;
    }
    Vec3 lightColor() {
        Material m;
        colorSpec(m);
        return m.color;
    }

    void topLevel() {
        const Token t = tok_;
        if (t.kind == TokenKind::Identifier) {
            if (t.text == "camera") return camera();
            if (t.text == "edges") return edges();
            if (t.text == "light_source") return light();
            if (t.text == "sphere" || t.text == "plane" || t.text == "triangle" || t.text == "box" ||
                t.text == "cone" || t.text == "mesh" || t.text == "mesh2" || t.text == "obj_mesh")
                return object();
            if (unsupportedHere()) return;
            error("unknown keyword " + describe(t));
        }
        if (isSymbol('#')) return directive();
        if (isSymbol('}')) error("unbalanced '}': no block is open");
        error("unexpected " + describe(t));
    }

    void directive() {
        const Token hash = tok_;
        advance();
        if (tok_.kind != TokenKind::Identifier) error("expected a directive name after '#'");
        const Token name = tok_;
        if (name.text == "include") {
            advance();
            if (tok_.kind != TokenKind::String) error("expected a file name string after #include");
            warn(loc(hash), "#include is not supported by Rays yet; \"" + std::string(tok_.text) + "\" ignored");
            advance();
            return;
        }
        if (name.text == "version" || name.text == "declare" || name.text == "local" || name.text == "default") {
            warnUnsupported(name);
            advance();
            // Skip to the terminating ';' (or past a braced object declaration).
            int depth = 0;
            for (;;) {
                if (tok_.kind == TokenKind::End) {
                    if (depth > 0) fail(loc(hash), "'#" + std::string(name.text) + "' is never closed");
                    return;
                }
                if (isSymbol('{')) ++depth;
                if (isSymbol('}')) {
                    if (--depth == 0) {
                        advance();
                        if (isSymbol(';')) advance();
                        return;
                    }
                }
                if (depth == 0 && isSymbol(';')) {
                    advance();
                    return;
                }
                advance();
            }
        }
        fail(loc(hash), "unsupported directive '#" + std::string(name.text) + "'");
    }

    void camera() {
        const Token kw = tok_;
        advance();
        Camera c;
        block(kw, [&] {
            if (isIdent("location")) { advance(); c.location = vector3("location"); }
            else if (isIdent("up")) { advance(); c.up = vector3("up"); }
            else if (isIdent("right")) { advance(); c.right = vector3("right"); }
            else if (isIdent("look_at")) { advance(); c.lookAt = vector3("look_at"); }
            else if (isIdent("aperture")) {
                const Token at = tok_;
                advance();
                c.aperture = number("aperture");
                if (c.aperture < 0) fail(loc(at), "aperture must not be negative");
            } else if (isIdent("focal_point")) {
                advance();
                c.focalPoint = vector3("focal_point");
            } else if (isIdent("blur_samples")) {
                // blur_samples [min,] max: Rays uses max.
                const Token at = tok_;
                advance();
                double n = number("blur_samples");
                if (isSymbol(',')) {
                    advance();
                    n = number("blur_samples");
                }
                if (n < 1 || n != std::floor(n) || n > 65536) fail(loc(at), "blur_samples must be a whole number from 1 to 65536");
                c.blurSamples = int(n);
            }
            else if (!unsupportedHere()) unknown("camera");
        });
        const SourceLoc at = loc(kw);
        if (length(c.up) == 0) fail(at, "camera 'up' vector is zero");
        if (length(c.right) == 0) fail(at, "camera 'right' vector is zero");
        if (length(c.lookAt - c.location) == 0) fail(at, "camera 'look_at' equals its 'location'");
        const Vec3 l = c.forward();
        if (length(cross(normalize(c.up), l)) < 1e-9) fail(at, "camera 'up' is parallel to the view direction");
        if (length(cross(normalize(c.right), l)) < 1e-9)
            fail(at, "camera 'right' is parallel to the view direction");
        scene_.cameras.push_back(c);
    }

    // edges { silhouette crease ... | all | none  edge_method stencil|image  edge_width W
    //         edge_color rgb <r,g,b>  crease_angle DEG  lines_only }
    void edges() {
        const Token kw = tok_;
        advance();
        sawEdges_ = true;
        EdgeSettings& e = scene_.edges;
        block(kw, [&] {
            const Token item = tok_;
            if (isSymbol(',')) {
                advance();
            } else if (isIdent("edge_method")) {
                advance();
                if (isIdent("stencil")) e.method = EdgeMethod::Stencil;
                else if (isIdent("image")) e.method = EdgeMethod::Image;
                else error("edge_method must be stencil or image, found " + describe(tok_));
                advance();
            } else if (isIdent("edge_width")) {
                advance();
                e.width = number("edge_width");
                if (!(e.width >= 0.5 && e.width <= 8)) fail(loc(item), "edge_width must be between 0.5 and 8 pixels");
            } else if (isIdent("edge_color") || isIdent("edge_colour")) {
                advance();
                e.color = lightColor();
            } else if (isIdent("crease_angle")) {
                advance();
                e.creaseAngle = number("crease_angle");
                if (!(e.creaseAngle > 0 && e.creaseAngle < 180)) fail(loc(item), "crease_angle must be between 0 and 180 degrees");
            } else if (isIdent("lines_only")) {
                advance();
                e.linesOnly = true;
            } else if (tok_.kind == TokenKind::Identifier) {
                try {
                    e.types |= parseEdgeTypes(std::string(tok_.text));
                } catch (const Error&) {
                    error("unknown edge type or setting " + describe(tok_) +
                          " in edges (types: silhouette occlusion intersection crease material shadow reflection all none)");
                }
                advance();
            } else {
                unknown("edges");
            }
        });
    }

    void light() {
        const Token kw = tok_;
        advance();
        Light L;
        bool first = true;
        bool hasPointAt = false;
        block(kw, [&] {
            if (first) {
                first = false;
                L.position = vector3("light position");
                skipCommas();
                return;
            }
            if (isIdent("color") || isIdent("colour") || isIdent("rgb") || isIdent("rgbf") ||
                isIdent("rgbt") || isIdent("rgbft")) {
                L.color = lightColor();
            } else if (isSymbol(',')) {
                advance();
            } else if (isIdent("area_light")) {
                areaLight(L);
            } else if (isIdent("jitter")) {
                advance();
                L.jitter = true;
            } else if (isIdent("adaptive")) {
                const Token at = tok_;
                advance();
                const double k = number("adaptive level");
                if (k < 0 || k > 1000 || k != std::floor(k)) fail(loc(at), "adaptive level must be a whole number from 0 to 1000");
                L.adaptive = int(k);
            } else if (isIdent("circular")) {
                advance();
                L.circular = true;
            } else if (isIdent("orient")) {
                advance();
                L.orient = true;
            } else if (isIdent("parallel")) {
                advance();
                L.parallel = true;
            } else if (isIdent("point_at")) {
                advance();
                L.pointAt = vector3("point_at");
                hasPointAt = true;
            } else if (!unsupportedHere()) {
                unknown("light_source");
            }
        });
        if (L.parallel) {
            const Vec3 d = L.pointAt - L.position;
            if (length(d) == 0) fail(loc(kw), "parallel light: point_at equals the light position");
            L.direction = normalize(d);
        } else if (hasPointAt) {
            warn(loc(kw), "point_at without parallel (or spotlight) has no effect");
        }
        if (!L.area && (L.jitter || L.circular || L.orient || L.adaptive >= 0))
            warn(loc(kw), "jitter, adaptive, circular and orient apply to area lights only; ignored");
        scene_.lights.push_back(L);
    }

    // area_light <axis1>, <axis2>, n1, n2
    void areaLight(Light& L) {
        const Token kw = tok_;
        advance();
        L.axis1 = vector3("area_light axis 1");
        skipCommas();
        L.axis2 = vector3("area_light axis 2");
        skipCommas();
        Token at = tok_;
        const double n1 = number("area_light size 1");
        if (n1 < 1 || n1 != std::floor(n1) || n1 > 1024) fail(loc(at), "area_light sample counts must be whole numbers from 1 to 1024");
        skipCommas();
        at = tok_;
        const double n2 = number("area_light size 2");
        if (n2 < 1 || n2 != std::floor(n2) || n2 > 1024) fail(loc(at), "area_light sample counts must be whole numbers from 1 to 1024");
        if (length(cross(L.axis1, L.axis2)) == 0)
            fail(loc(kw), "area_light axes are degenerate (zero or parallel)");
        L.area = true;
        L.n1 = int(n1);
        L.n2 = int(n2);
    }

    void pigment(Material& m) {
        const Token kw = tok_;
        advance();
        Transform xf;
        block(kw, [&] {
            if (isIdent("color") || isIdent("colour") || isIdent("rgb") || isIdent("rgbf") ||
                isIdent("rgbt") || isIdent("rgbft") || isSymbol('<')) {
                colorSpec(m);
            } else if (isIdent("image_map")) {
                imageMap(m.pigmentMap, m.mapType, m.mapOnce, m.mapBilinear, nullptr, nullptr, true);
            } else if (isIdent("uv_mapping")) {
                advance();
                m.mapType = 3;
            } else if (!textureTransformItem(xf) && !unsupportedHere()) {
                unknown("pigment");
            }
        });
        m.pigmentTransform = storeTextureTransform(xf, m.pigmentTransform);
    }

    // scale / rotate / translate inside a pigment or normal block: accumulates into m.
    bool textureTransformItem(Transform& m) {
        const Token t = tok_;
        if (isIdent("scale")) {
            advance();
            const Vec3 sc = vector3("scale", true);
            if (sc.x == 0 || sc.y == 0 || sc.z == 0) fail(loc(t), "scale has a zero component");
            m = Transform::scale(sc) * m;
        } else if (isIdent("rotate")) {
            advance();
            m = rotation(vector3("rotate")) * m;
        } else if (isIdent("translate")) {
            advance();
            m = Transform::translate(vector3("translate", true)) * m;
        } else {
            return false;
        }
        checkTransform(m, t);
        return true;
    }
    // A transformation made singular or infinite by the item at `item` (scale 1e300 twice) would
    // make the object vanish: an error, as a zero scale is.
    void checkTransform(const Transform& m, const Token& item) {
        if (!m.isUsable()) fail(loc(item), "the transformation overflows or becomes singular here");
    }
    int storeTextureTransform(const Transform& m, int previous) {
        if (m.isIdentity()) return previous;
        scene_.textureTransforms.push_back({m, m.inverse()});
        return int(scene_.textureTransforms.size()) - 1;
    }

    // normal { normal_map { png "file" [strength S] [map_type M] } | bump_map { png "file" [bump_size S] ... } }
    void normal(Material& m) {
        const Token kw = tok_;
        advance();
        Transform xf;
        block(kw, [&] {
            bool once = false, bilinear = true;
            if (isIdent("normal_map")) {
                imageMap(m.normalMap, m.normalMapType, once, bilinear, &m.normalStrength, "strength", false);
            } else if (isIdent("bump_map")) {
                imageMap(m.bumpMap, m.normalMapType, once, bilinear, &m.bumpSize, "bump_size", false);
            } else if (isIdent("uv_mapping")) {
                advance();
                m.normalMapType = 3;
            } else if (!textureTransformItem(xf) && !unsupportedHere()) {
                unknown("normal");
            }
        });
        m.normalTransform = storeTextureTransform(xf, m.normalTransform);
    }

    // image_map / normal_map / bump_map { TYPE "file" [map_type M] [interpolate N] [once] [gamma G]
    //                                     [<amountName> S] }: loads the file (relative paths are
    // relative to the scene's folder) and stores its texture index.
    void imageMap(int& index, int& mapType, bool& once, bool& bilinear, double* amount, const char* amountName,
                  bool colour) {
        const Token kw = tok_;
        advance();
        double gamma = 1.0;
        std::string file;
        Token fileTok;
        block(kw, [&] {
            static const char* kTypes[] = {"png", "jpeg", "jpg", "tga", "ppm", "pgm", "gif", "bmp", "hdr", "exr", "tiff", "sys", "iff"};
            bool isType = false;
            for (const char* t : kTypes) isType |= isIdent(t);
            if (isType) {
                advance();
                if (tok_.kind != TokenKind::String) error("expected a file name string after the image type");
                fileTok = tok_;
                file = std::string(tok_.text);
                advance();
            } else if (tok_.kind == TokenKind::String) {
                fileTok = tok_;
                file = std::string(tok_.text);
                advance();
            } else if (isIdent("map_type")) {
                const Token at = tok_;
                advance();
                const double t = number("map_type");
                if (t != 0 && t != 1 && t != 2) fail(loc(at), "map_type must be 0 (planar), 1 (spherical) or 2 (cylindrical)");
                mapType = int(t);
            } else if (isIdent("interpolate")) {
                advance();
                bilinear = number("interpolate") >= 2;
            } else if (isIdent("once")) {
                advance();
                once = true;
            } else if (isIdent("gamma") && colour) {
                const Token at = tok_;
                advance();
                gamma = number("gamma");
                if (!(gamma > 0)) fail(loc(at), "gamma must be greater than 0");
            } else if (amount && isIdent(amountName)) {
                advance();
                *amount = number(amountName);
            } else if (isSymbol(',')) {
                advance();
            } else if (!unsupportedHere()) {
                unknown(std::string(kw.text));
            }
        });
        if (file.empty()) fail(loc(kw), std::string(kw.text) + " needs an image file");
        index = texture(file, fileTok, colour ? gamma : 1.0);
    }

    // Loads (once per file and gamma) a texture named in the scene.
    int texture(const std::string& file, const Token& at, double gamma) {
        namespace fs = std::filesystem;
        fs::path path(file);
        if (path.is_relative()) path = fs::path(lex_.fileName()).parent_path() / path;
        const std::string key = path.string() + "|" + std::to_string(gamma);
        if (auto it = textureIndex_.find(key); it != textureIndex_.end()) return it->second;
        std::error_code ec;
        if (!fs::is_regular_file(path, ec)) fail(loc(at), "cannot open image file '" + path.string() + "'");
        try {
            scene_.textures.push_back(loadTexture(path.string(), gamma));
        } catch (const Error& e) {
            fail(loc(at), nestedMessage(e));
        }
        const int index = int(scene_.textures.size()) - 1;
        textureIndex_[key] = index;
        return index;
    }

    void finish(Material& m) {
        const Token kw = tok_;
        advance();
        block(kw, [&] {
            if (isSymbol(',')) { advance(); return; }
            const Token item = tok_;
            auto value = [&](double& dst, bool& seen, double lo, double hi, const char* rule) {
                advance();
                if (isIdent("rgb") || isIdent("color") || isIdent("colour")) {
                    Material tmp;
                    colorSpec(tmp);
                    dst = tmp.color.x;
                    warn(loc(item), "a colour for '" + std::string(item.text) + "' uses its red component");
                } else {
                    const Token at = tok_;
                    const Value v = expr();
                    dst = v.c[0];
                    if (!std::isfinite(dst)) fail(loc(at), std::string(item.text) + " is not a finite number");
                    if (!(dst >= lo && dst <= hi))
                        fail(loc(at), std::string(item.text) + " " + (*rule ? std::string(rule) : betweenRule(lo, hi)) + ", got " + numberText(dst));
                }
                seen = true;
            };
            bool dummy = false;
            if (isIdent("ambient")) value(m.ambient, dummy, -1e30, 1e30, "");
            else if (isIdent("diffuse")) value(m.diffuse, dummy, -1e30, 1e30, "");
            else if (isIdent("specular")) value(m.specular, m.hasSpecular, -1e30, 1e30, "");
            else if (isIdent("roughness")) {
                value(m.roughness, m.hasRoughness, -1e30, 1e30, "");
                if (m.roughness <= 0) fail(loc(item), "roughness must be greater than 0");
            } else if (isIdent("reflection")) value(m.reflection, m.hasReflection, 0, 1, "must be between 0 and 1");
            else if (isIdent("refraction")) value(m.refraction, m.hasRefraction, -1e30, 1e30, "");
            else if (isIdent("ior")) {
                value(m.ior, m.hasIor, -1e30, 1e30, "");
                if (m.ior <= 0) fail(loc(item), "ior must be greater than 0");
            } else if (isIdent("sigma")) {
                value(m.sigma, dummy, 0, 90, "must be between 0 and 90 degrees");
            } else if (isIdent("metallic")) {
                // POV-Ray allows a bare `metallic` meaning 1.
                if (startsExpression(1)) value(m.metallic, m.hasMetallic, 0, 1, "must be between 0 and 1");
                else { advance(); m.metallic = 1; m.hasMetallic = true; }
            } else if (!unsupportedHere()) unknown("finish");
        });
    }
    // True when the token after the current one (offset 1) starts a number expression.
    bool startsExpression(int) {
        // Look ahead by copying the lexer state.
        Lexer copy = lex_;
        const Token n = copy.next();
        return n.kind == TokenKind::Number || (n.kind == TokenKind::Symbol && (n.text == "-" || n.text == "+" || n.text == "(" || n.text == "<"));
    }

    void interior(Material& m) {
        const Token kw = tok_;
        advance();
        block(kw, [&] {
            if (isIdent("ior")) {
                const Token item = tok_;
                advance();
                m.ior = number("ior");
                m.hasIor = true;
                if (m.ior <= 0) fail(loc(item), "ior must be greater than 0");
            } else if (!unsupportedHere()) unknown("interior");
        });
    }

    void textureBlock(Material& m) {
        const Token kw = tok_;
        advance();
        block(kw, [&] {
            if (isIdent("pigment")) pigment(m);
            else if (isIdent("finish")) finish(m);
            else if (isIdent("normal")) normal(m);
            else if (!unsupportedHere()) unknown("texture");
        });
    }

    Transform rotation(Vec3 deg) const {
        return opt_.rotation == RotationOrder::Course ? Transform::rotateCourse(deg) : Transform::rotatePovray(deg);
    }

    // Object modifiers; returns false when the current token is not one.
    bool modifier(Object& o, Transform& m) {
        const Token t = tok_;
        if (isIdent("pigment")) { pigment(o.material); return true; }
        if (isIdent("finish")) { finish(o.material); return true; }
        if (isIdent("interior")) { interior(o.material); return true; }
        if (isIdent("texture")) { textureBlock(o.material); return true; }
        if (isIdent("normal")) { normal(o.material); return true; }
        if (isIdent("shading")) {
            advance();
            ShadingModel model;
            if (tok_.kind != TokenKind::Identifier || !parseShadingName(std::string(tok_.text).c_str(), model))
                error("shading must be blinn_phong, cook_torrance, oren_nayar, lambert, flat or normals, found " + describe(tok_));
            o.material.shading = int(model);
            advance();
            return true;
        }
        if (isIdent("scale")) {
            advance();
            const Vec3 s = vector3("scale", true);
            if (s.x == 0 || s.y == 0 || s.z == 0) fail(loc(t), "scale has a zero component");
            m = Transform::scale(s) * m;
            return true;
        }
        if (isIdent("rotate")) {
            advance();
            m = rotation(vector3("rotate")) * m;
            return true;
        }
        if (isIdent("translate")) {
            advance();
            m = Transform::translate(vector3("translate", true)) * m;
            return true;
        }
        if (isIdent("matrix")) {
            advance();
            const Token at = tok_;
            const Value v = matrixValue();
            Transform x;
            for (int col = 0; col < 4; ++col)
                for (int row = 0; row < 3; ++row) x.m[row][col] = v12_[col * 3 + row];
            if (std::fabs(x.determinant()) < 1e-300) fail(loc(at), "matrix is singular");
            (void)v;
            m = x * m;
            return true;
        }
        return false;
    }
    // matrix <12 numbers>: read into v12_ (POV-Ray's row layout: 4 rows of 3).
    Value matrixValue() {
        const Token open = tok_;
        expectSymbol('<', "to start the 12 matrix values");
        for (int i = 0; i < 12; ++i) {
            v12_[i] = number("matrix value");
            if (i < 11) expectSymbol(',', "between matrix values");
        }
        if (!isSymbol('>')) fail(loc(open), "matrix needs exactly 12 values");
        advance();
        return Value{};
    }

    void object() {
        const Token kw = tok_;
        advance();
        Object o;
        o.line = kw.line;
        o.col = kw.col;
        Transform m;
        const std::string name(kw.text);
        const Token open = tok_;
        expectSymbol('{', "after '" + name + "'");
        auto arg = [&] { skipCommas(); };
        Token at = tok_;
        if (name == "sphere") {
            o.type = ShapeType::Sphere;
            o.p0 = vector3("sphere centre");
            arg();
            at = tok_;
            o.r0 = number("sphere radius");
            if (o.r0 <= 0) fail(loc(at), "sphere radius must be greater than 0");
        } else if (name == "plane") {
            o.type = ShapeType::Plane;
            const Vec3 n = vector3("plane normal");
            if (length(n) == 0) fail(loc(at), "plane normal has zero length");
            o.p0 = normalize(n);
            arg();
            o.r0 = number("plane distance");
        } else if (name == "triangle") {
            o.type = ShapeType::Triangle;
            o.p0 = vector3("triangle vertex");
            arg();
            o.p1 = vector3("triangle vertex");
            arg();
            o.p2 = vector3("triangle vertex");
            if (length(cross(o.p1 - o.p0, o.p2 - o.p0)) == 0)
                warn(loc(kw), "degenerate triangle (zero area) can never be hit");
        } else if (name == "box") {
            o.type = ShapeType::Box;
            const Vec3 a = vector3("box corner");
            arg();
            const Vec3 b = vector3("box corner");
            o.p0 = vmin(a, b);
            o.p1 = vmax(a, b);
        } else if (name == "mesh") {
            attachMesh(o, readMeshTriangles(*this), kw);
        } else if (name == "mesh2") {
            attachMesh(o, readMesh2Sections(*this), kw);
        } else if (name == "obj_mesh") {
            objMesh(o);
        } else {
            o.type = ShapeType::Cone;
            o.p0 = vector3("cone base");
            arg();
            at = tok_;
            o.r0 = number("cone base radius");
            if (o.r0 < 0) fail(loc(at), "cone base radius must not be negative");
            arg();
            o.p1 = vector3("cone cap");
            arg();
            at = tok_;
            o.r1 = number("cone cap radius");
            if (o.r1 < 0) fail(loc(at), "cone cap radius must not be negative");
            if (o.r0 == 0 && o.r1 == 0) fail(loc(at), "cone radii are both zero");
            if (length(o.p1 - o.p0) == 0) fail(loc(kw), "cone base and cap are the same point");
        }
        for (;;) {
            skipCommas();
            if (isSymbol('}')) {
                advance();
                break;
            }
            if (tok_.kind == TokenKind::End) fail(loc(open), "'{' of '" + name + "' is never closed (end of file reached)");
            const Token item = tok_;
            if (!modifier(o, m) && !unsupportedHere()) unknown(name);
            checkTransform(m, item);
        }
        prepareObject(o, m);
        scene_.objects.push_back(std::move(o));
    }

    // ---- meshes ----------------------------------------------------------------------------------
    // Finalizes a mesh built by the parser (errors point at the mesh keyword) and attaches it.
    void attachMesh(Object& o, std::unique_ptr<Mesh> mesh, const Token& kw) {
        if (mesh->triangleCount() == 0) fail(loc(kw), "mesh has no triangles");
        try {
            mesh->finalize();
        } catch (const Error& e) {
            fail(loc(kw), nestedMessage(e));
        }
        o.type = ShapeType::Mesh;
        o.mesh = mesh.get();
        scene_.meshes.push_back(std::move(mesh));
    }

    // obj_mesh { "file.obj" modifiers }: an OBJ file (relative to the scene's folder). Before the
    // modifiers the material is the MTL's first diffuse colour (and map_Kd as a uv image map),
    // else grey 0.8, with ambient 0.2 and diffuse 0.7.
    void objMesh(Object& o) {
        const Token kw = tok_;
        if (tok_.kind != TokenKind::String) error("expected the OBJ file name string, found " + describe(tok_));
        namespace fs = std::filesystem;
        fs::path path(std::string(tok_.text));
        if (path.is_relative()) path = fs::path(lex_.fileName()).parent_path() / path;
        std::error_code ec;
        if (!fs::is_regular_file(path, ec)) error("cannot open OBJ file '" + path.string() + "'");
        advance();
        const ObjMesh obj = loadObj(path.string());  // errors name the OBJ file and its line
        if (obj.faces.empty()) fail(loc(kw), "OBJ file '" + path.string() + "' has no faces (is it an OBJ file?)");
        Material& mat = o.material;
        mat.color = {0.8, 0.8, 0.8};
        mat.ambient = 0.2;
        mat.diffuse = 0.7;
        if (!obj.materials.empty()) {
            mat.color = obj.materials[0].diffuse;
            if (!obj.materials[0].diffuseTexture.empty()) {
                mat.pigmentMap = texture(obj.materials[0].diffuseTexture, kw, 1.0);
                mat.mapType = 3;
                mat.mapBilinear = true;
            }
        }
        std::unique_ptr<Mesh> mesh;
        try {
            mesh = meshFromObj(obj);
        } catch (const Error& e) {
            fail(loc(kw), nestedMessage(e));
        }
        skipCommas();
        if (isIdent("smooth")) {  // vertex normals from the faces when the file has none
            advance();
            if (!mesh->hasNormals()) {
                mesh->computeVertexNormals();
                mesh->finalize();
            }
        }
        o.type = ShapeType::Mesh;
        o.mesh = mesh.get();
        scene_.meshes.push_back(std::move(mesh));
    }

    void readAll() {
        while (tok_.kind != TokenKind::End) topLevel();
    }

    Scene scene_;
    std::map<std::string, int> textureIndex_;
    double v12_[12] = {};
    bool sawEdges_ = false;
};

}  // namespace

ScenePiece parseScenePiece(std::string_view text, const std::string& fileName, const ParseOptions& options,
                           int firstLine, size_t reserveBytes) {
    Parser parser(text, fileName, options, firstLine, reserveBytes);
    ScenePiece piece;
    piece.scene = parser.runPiece();
    piece.sawEdges = parser.sawEdges();
    return piece;
}

namespace {

Scene parseText(std::string_view text, const std::string& file, const ParseOptions& options) {
    if (std::optional<Scene> scene = parseInPieces(text, file, options)) return std::move(*scene);
    return Parser(text, file, options).run();
}

}  // namespace

Scene parseScene(const std::string& text, const std::string& fileName, const ParseOptions& options) {
    std::string source = text;  // as a file is read: byte-order mark skipped, lone CRs are line ends
    const size_t skip = makeSourceText(source.data(), source.size());
    return parseText(std::string_view(source).substr(skip), fileName, options);
}

Scene loadScene(const std::string& path, const ParseOptions& options) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) failFile(path, "is a directory, not a scene file");
    const FileText file(path, TextForm::Source);
    if (file.status() == FileText::Status::CannotOpen) failFile(path, "cannot open scene file");
    if (file.status() == FileText::Status::CannotRead) failFile(path, "cannot read scene file");
    if (file.status() == FileText::Status::TooLarge)
        failFile(path, "scene file is larger than " + FileText::describe(kMaxTextFileBytes) + " (the limit for scene text)");
    const sdl::Dialect dialect = options.language.dialect;
    if (dialect == sdl::Dialect::Povray || (dialect == sdl::Dialect::Auto && pov::looksLikePovray(file.text()))) {
        const std::filesystem::path p(path);
        return pov::parsePovText(file.text(), path, p.has_parent_path() ? p.parent_path().string() : ".", options);
    }
    return parseText(file.text(), path, options);
}

}  // namespace rays
