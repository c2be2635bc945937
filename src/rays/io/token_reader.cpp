#include "rays/io/token_reader.h"

#include <cmath>
#include <iostream>
#include <numbers>
#include <unordered_set>

namespace rays::scenetext {
namespace {

// POV-Ray 3.7 keywords Rays reads but does not implement yet: they are skipped with a warning.
const std::unordered_set<std::string_view>& povrayKeywords() {
    static const std::unordered_set<std::string_view> k = {
        "adaptive", "agate", "all", "alpha", "angle", "aperture", "area_light", "background",
        "bicubic_patch", "blob", "blur_samples", "boxed", "brick", "brilliance", "bump_map",
        "bump_size", "bumps", "checker", "circular", "confidence", "conserve_energy", "crand",
        "cubic", "cylinder", "cylindrical", "dents", "difference", "direction", "disc",
        "double_illuminate", "emission", "fade_color", "fade_distance", "fade_power", "falloff",
        "focal_point", "fog", "gradient", "granite", "height_field", "hexagon", "hollow",
        "image_map", "interpolate", "intersection", "inverse", "irid", "isosurface", "jitter",
        "julia_fractal", "lathe", "leopard", "light_group", "looks_like", "map_type", "marble",
        "media", "merge", "mesh", "mesh2", "no_image", "no_reflection", "no_shadow", "normal",
        "normal_map", "object", "open", "orient", "orthographic", "parallel", "parametric",
        "perspective", "phong", "phong_size", "photons", "point_at", "poly", "polygon", "prism",
        "quadric", "radial", "radiosity", "radius", "ripples", "sky", "sky_sphere", "smooth_triangle",
        "sor", "spherical", "spotlight", "sphere_sweep", "superellipsoid", "text", "tightness",
        "torus", "transmit", "turbulence", "union", "uv_mapping", "warp", "waves", "wood",
        "wrinkles", "global_settings", "max_trace_level", "assumed_gamma", "ambient_light",
        "shadowless", "media_interaction", "media_attenuation", "subsurface", "specular_map",
        "texture_map", "pigment_map", "normal_map", "color_map", "colour_map", "finish_map",
        "material", "clipped_by", "bounded_by", "sturm", "caustics", "dispersion", "metallic_map",
    };
    return k;
}

}  // namespace

std::string nestedMessage(const Error& e) {
    std::string m = e.what();
    if (const size_t at = m.find(": error: "); at != std::string::npos) m.replace(at, 9, ": ");
    return m;
}

TokenReader::TokenReader(std::string_view text, const std::string& file, const ParseOptions& opt, int firstLine)
    : lex_(text, file, firstLine), opt_(opt) {
    advance();
}

void TokenReader::expectSymbol(char c, std::string_view context) {
    if (!isSymbol(c))
        error("expected '" + std::string(1, c) + "'" + (std::string(context).empty() ? "" : " " + std::string(context)) +
              ", found " + describe(tok_));
    advance();
}

// ---- warnings --------------------------------------------------------------------------
void TokenReader::warn(const SourceLoc& at, const std::string& msg) {
    const std::string text = formatWarning(at, msg);
    if (opt_.warn) opt_.warn(text);
    else std::cerr << text << '\n';
}
void TokenReader::warnUnsupported(const Token& t) {
    const std::string name(t.text);
    if (warnedCount_[name]++ == 0)
        warn(loc(t), "'" + name + "' is valid POV-Ray but not supported by Rays yet; ignored");
}
void TokenReader::flushWarnings() {
    for (const auto& [name, count] : warnedCount_)
        if (count > 1)
            warn(SourceLoc{lex_.fileName(), 0, 0},
                 "'" + name + "' ignored " + std::to_string(count - 1) + " more time(s)");
}

// Skips what follows an unsupported keyword: a balanced { } block, or scalar/vector
// arguments (numbers, strings, <...>, commas and arithmetic).
void TokenReader::skipUnsupported() {
    const Token kw = tok_;
    warnUnsupported(kw);
    advance();
    if (isSymbol('{')) {
        skipBlock();
        return;
    }
    for (;;) {
        if (tok_.kind == TokenKind::Number || tok_.kind == TokenKind::String) {
            advance();
        } else if (tok_.kind == TokenKind::Symbol && std::string_view("<>,-+*/()").find(tok_.text[0]) != std::string_view::npos) {
            advance();
        } else if (tok_.kind == TokenKind::Identifier &&
                   (tok_.text == "x" || tok_.text == "y" || tok_.text == "z" || tok_.text == "pi" ||
                    tok_.text == "rgb" || tok_.text == "rgbf" || tok_.text == "rgbt" ||
                    tok_.text == "rgbft" || tok_.text == "color" || tok_.text == "colour" ||
                    tok_.text == "png" || tok_.text == "jpeg" || tok_.text == "tga" || tok_.text == "gif")) {
            advance();
        } else {
            return;
        }
    }
}
void TokenReader::skipBlock() {
    const Token open = tok_;
    expectSymbol('{', "");
    int depth = 1;
    while (depth > 0) {
        if (tok_.kind == TokenKind::End) fail(loc(open), "'{' is never closed (end of file reached)");
        if (isSymbol('{')) ++depth;
        if (isSymbol('}')) --depth;
        advance();
    }
}

// ---- expressions -------------------------------------------------------------------------
Value TokenReader::expr() {
    Value v = term();
    while (isSymbol('+') || isSymbol('-')) {
        const bool minus = isSymbol('-');
        advance();
        Value r = term();
        v = combine(v, r, minus ? '-' : '+');
    }
    return v;
}
Value TokenReader::term() {
    Value v = factor();
    while (isSymbol('*') || isSymbol('/')) {
        const char op = tok_.text[0];
        const Token at = tok_;
        advance();
        Value r = factor();
        if (op == '/') {
            for (int i = 0; i < r.n; ++i)
                if (r.c[i] == 0) fail(loc(at), "division by zero");
        }
        v = combine(v, r, op);
    }
    return v;
}
Value TokenReader::combine(const Value& a, const Value& b, char op) {
    if (!a.isScalar() && !b.isScalar() && a.n != b.n)
        error("vector sizes differ (" + std::to_string(a.n) + " and " + std::to_string(b.n) + ")");
    Value r;
    r.n = std::max(a.n, b.n);
    for (int i = 0; i < r.n; ++i) {
        const double x = a.c[a.isScalar() ? 0 : i], y = b.c[b.isScalar() ? 0 : i];
        switch (op) {
            case '+': r.c[i] = x + y; break;
            case '-': r.c[i] = x - y; break;
            case '*': r.c[i] = x * y; break;
            default: r.c[i] = x / y; break;
        }
    }
    return r;
}
Value TokenReader::factor() {
    // Parentheses, vectors and unary signs recurse: bound the depth (a stack overflow otherwise).
    struct Nesting {
        int& depth;
        explicit Nesting(int& d) : depth(++d) {}
        ~Nesting() { --depth; }
    } nesting(nesting_);
    if (nesting_ > kMaxNesting)
        error("expression nested too deeply (more than " + std::to_string(kMaxNesting) + " levels)");
    Value v;
    if (tok_.kind == TokenKind::Number) {
        v.c[0] = tok_.number;
        advance();
        return v;
    }
    if (isSymbol('-') || isSymbol('+')) {
        const bool neg = isSymbol('-');
        advance();
        v = factor();
        if (neg)
            for (int i = 0; i < v.n; ++i) v.c[i] = -v.c[i];
        return v;
    }
    if (isSymbol('(')) {
        advance();
        v = expr();
        expectSymbol(')', "to close '('");
        return v;
    }
    if (isSymbol('<')) {
        const Token open = tok_;
        advance();
        v.n = 0;
        for (;;) {
            const Token at = tok_;
            Value comp = expr();
            if (!comp.isScalar()) fail(loc(at), "vector component must be a number");
            if (v.n == 5) fail(loc(at), "vector has more than 5 components");
            v.c[v.n++] = comp.c[0];
            if (isSymbol(',')) {
                advance();
                continue;
            }
            if (isSymbol('>')) break;
            error("expected ',' or '>' in vector, found " + describe(tok_));
        }
        advance();
        if (v.n < 2) fail(loc(open), "vector needs at least 2 components");
        return v;
    }
    if (tok_.kind == TokenKind::Identifier) {
        if (tok_.text == "x" || tok_.text == "y" || tok_.text == "z") {
            v.n = 3;
            v.c[tok_.text[0] - 'x'] = 1;
            advance();
            return v;
        }
        if (tok_.text == "pi") {
            v.c[0] = std::numbers::pi;
            advance();
            return v;
        }
    }
    if (tok_.kind == TokenKind::End) error("expected a number or vector, found end of file");
    error("expected a number or vector, found " + describe(tok_));
}

// True when the current token can start an expression.
bool TokenReader::atExpression() const {
    return tok_.kind == TokenKind::Number ||
           (tok_.kind == TokenKind::Symbol && std::string_view("-+(<").find(tok_.text[0]) != std::string_view::npos) ||
           isIdent("x") || isIdent("y") || isIdent("z") || isIdent("pi");
}
void TokenReader::expectExpression(std::string_view what) {
    if (!atExpression()) error("expected " + std::string(what) + ", found " + describe(tok_));
}

double TokenReader::number(std::string_view what) {
    expectExpression(what);
    const Token at = tok_;
    const Value v = expr();
    if (!v.isScalar()) fail(loc(at), "expected a number for " + std::string(what) + ", found a vector");
    if (!std::isfinite(v.c[0])) fail(loc(at), std::string(what) + " is not a finite number");
    return v.c[0];
}
Vec3 TokenReader::vector3(std::string_view what, bool allowScalar) {
    expectExpression(what);
    const Token at = tok_;
    const Value v = expr();
    if (v.isScalar() && allowScalar) return Vec3(v.c[0]);
    if (v.n != 3)
        fail(loc(at), "expected a 3-component vector for " + std::string(what) + ", found " +
                          (v.isScalar() ? std::string("a number") : std::to_string(v.n) + " components"));
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(v.c[i])) fail(loc(at), std::string(what) + " has a non-finite component");
    return {v.c[0], v.c[1], v.c[2]};
}

void TokenReader::unknown(std::string_view where) {
    if (tok_.kind == TokenKind::Identifier)
        error("unknown keyword " + describe(tok_) + " in " + std::string(where));
    error("unexpected " + describe(tok_) + " in " + std::string(where));
}
bool TokenReader::unsupportedHere() {
    if (tok_.kind == TokenKind::Identifier && povrayKeywords().count(tok_.text)) {
        skipUnsupported();
        return true;
    }
    return false;
}

}  // namespace rays::scenetext
