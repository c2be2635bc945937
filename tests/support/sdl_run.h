// Runs scene-language text through the interpreter with a small host that knows only a few
// items (sphere, box, camera, object, texture, pigment) and reads them generically, so that the
// language's tests need no renderer.
#pragma once
#include <string>
#include <vector>

#include "rays/error.h"
#include "rays/sdl/interpreter.h"

namespace rays::test {

struct SdlRun {
    std::string debug;                  ///< #debug text
    std::vector<std::string> warnings;  ///< warning lines
    std::vector<sdl::ItemRef> items;    ///< top-level items in order
    std::string error;                  ///< the Error's message, empty when none
};

class GenericHost : public sdl::ItemHost {
public:
    bool startsItem(sdl::Kw k) const override {
        return k == sdl::Kw::sphere || k == sdl::Kw::box || k == sdl::Kw::camera || k == sdl::Kw::object ||
               k == sdl::Kw::texture || k == sdl::Kw::pigment || k == sdl::Kw::union_;
    }
    // KEYWORD { positional values and nested items }
    sdl::ItemRef readItem(sdl::Interpreter& in) override {
        auto it = std::make_shared<sdl::Item>();
        it->kind = in.kw();
        it->loc = in.loc();
        in.next();
        in.expectSym('{', "after the item keyword");
        while (!in.isSym('}')) {
            if (in.atEnd()) in.errorHere("item never closed");
            sdl::Entry e;
            e.loc = in.loc();
            if (in.acceptSym(',')) continue;
            if (in.isKeyword() && startsItem(in.kw())) {
                sdl::Interpreter::NestGuard g(in);
                e.key = uint16_t(in.kw());
                e.args.push_back(sdl::Value::item(readItem(in)));
            } else if (in.isKeyword() && (in.kw() == sdl::Kw::translate || in.kw() == sdl::Kw::scale)) {
                e.key = uint16_t(in.kw());
                in.next();
                e.args.push_back(in.parseNumeric());
            } else {
                e.args.push_back(in.parseRValue());
            }
            it->entries.push_back(std::move(e));
        }
        in.next();
        return it;
    }
    void topLevel(sdl::Interpreter&, const sdl::ItemRef& item) override { items.push_back(item); }
    void setDefault(sdl::Interpreter&, const sdl::ItemRef& item) override { defaults.push_back(item); }
    TraceResult trace(const sdl::ItemRef&, const double*, const double*) override { return {}; }
    int inside(const sdl::ItemRef&, const double*) override { return -1; }
    bool extent(const sdl::ItemRef&, double*, double*) override { return false; }
    std::array<double, 12> transformMatrix(const sdl::Item&) override { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}; }

    std::vector<sdl::ItemRef> items, defaults;
};

/// Parses text (named "scene.pov") with the given options; errors are caught into `error`.
inline SdlRun runSdl(const std::string& text, sdl::LanguageOptions options = {}, const std::string& folder = ".",
                     sdl::Limits limits = {}) {
    SdlRun r;
    GenericHost host;
    sdl::Diagnostics d;
    d.warning = [&](const std::string& w) { r.warnings.push_back(w); };
    d.debug = [&](const std::string& s) { r.debug += s; };
    options.installedIncludeDir.clear();
    try {
        sdl::Interpreter in(options, host, d, limits);
        in.runText(text, "scene.pov", folder);
    } catch (const Error& e) {
        r.error = e.what();
    }
    r.items = host.items;
    return r;
}

}  // namespace rays::test
