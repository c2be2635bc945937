// The host the scene language reads POV-Ray scenes for: it reads every item with the grammar
// (grammar.h, specs.h) and hands the scene's top-level items, each with the default texture in
// force where it appeared (#default), to the builder (scene_builder.h) as they are read.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "rays/io/ttf_font.h"
#include "rays/pov/pattern_object.h"
#include "rays/sdl/host.h"
#include "rays/sdl/interpreter.h"

namespace rays::pov {

/// What a POV-Ray scene file holds: its top-level items in order. With a sink, each item goes to
/// it as soon as it is read (the builder makes it at once, as POV-Ray does, and an item no
/// identifier holds is freed before the next is read); without one they are collected in `items`.
struct ParsedScene {
    struct Top {
        sdl::ItemRef item;
        /// The #default texture in force: the first defaultsCount entries of `defaults`, applied in
        /// order (null: POV-Ray's own). #default only appends, so all items share one list.
        std::shared_ptr<const std::vector<sdl::Entry>> defaults;
        size_t defaultsCount = 0;
        double version = 3.7;  ///< #version in force
    };
    std::vector<Top> items;
    std::function<void(const Top&)> sink;
};

class PovHost : public sdl::ItemHost {
public:
    explicit PovHost(ParsedScene& out);
    ~PovHost() override;
    bool startsItem(sdl::Kw k) const override;
    sdl::ItemRef readItem(sdl::Interpreter& in) override;
    void topLevel(sdl::Interpreter& in, const sdl::ItemRef& item) override;
    void setDefault(sdl::Interpreter& in, const sdl::ItemRef& item) override;
    TraceResult trace(const sdl::ItemRef& object, const double origin[3], const double dir[3]) override;
    int inside(const sdl::ItemRef& object, const double point[3]) override;
    bool extent(const sdl::ItemRef& object, double lo[3], double hi[3]) override;
    std::array<double, 12> transformMatrix(const sdl::Item& transform) override;
    fn::HostFunction patternFunction(const sdl::Item& item, bool pigment) override;
    bool turbulence(const double p[3], double lambda, double omega, int octaves, double out[3]) override;
    /// How the objects built for trace() and the extents find files (text's fonts).
    void setFileFinder(std::function<std::string(const std::string&)> find) { findFile_ = std::move(find); }
    /// The fonts read while parsing, for the scene's builder to reuse.
    FontCache* fontCache() { return &fonts_; }
    /// How those objects' errors name a place ("FILE:LINE:COL").
    void setWhere(std::function<std::string(const sdl::Loc&)> where) { where_ = std::move(where); }

private:
    struct Probe;  // an object built alone, for trace() and min_extent() / max_extent()
    const Probe& probe(const sdl::ItemRef& object);

    ParsedScene& out_;
    std::shared_ptr<std::vector<sdl::Entry>> defaults_;
    std::unordered_map<const sdl::Item*, std::unique_ptr<Probe>> probes_;
    struct InsideProbe {  // an object built alone for inside(), as the object pattern's
        sdl::ItemRef object;  ///< keeps the item (the cache's key) alive
        BuiltPatternObject test;
    };
    std::unordered_map<const sdl::Item*, InsideProbe> insides_;
    std::function<std::string(const std::string&)> findFile_;
    int noiseGenerator_ = 2;  ///< global_settings' noise_generator as read so far
    std::function<std::string(const sdl::Loc&)> where_;
    FontCache fonts_;
};

}  // namespace rays::pov
