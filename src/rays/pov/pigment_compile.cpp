#include "rays/pov/pigment_compile.h"

#include <cmath>
#include <string>
#include <vector>

#include "rays/pattern/default_maps.h"
#include "rays/pattern/tiling.h"
#include "rays/pov/normal_compile.h"
#include "rays/pov/pigment_compile_state.h"
#include "rays/pov/grammar.h"
#include "rays/pov/specs.h"
#include "rays/sdl/function_value.h"

namespace rays::pov {

using pattern::MapEntry;
using pattern::PatternKind;
using pattern::WaveType;
using sdl::VType;

namespace {

constexpr int kMaxDepth = 64;

// The pattern kinds Rays renders, from their keywords; false for the others.
bool patternKind(Kw k, PatternKind& out) {
    switch (k) {
        case Kw::checker: out = PatternKind::Checker; return true;
        case Kw::hexagon: out = PatternKind::Hexagon; return true;
        case Kw::brick: out = PatternKind::Brick; return true;
        case Kw::square: out = PatternKind::Square; return true;
        case Kw::triangular: out = PatternKind::Triangular; return true;
        case Kw::cubic: out = PatternKind::Cubic; return true;
        case Kw::gradient: out = PatternKind::Gradient; return true;
        case Kw::radial: out = PatternKind::Radial; return true;
        case Kw::onion: out = PatternKind::Onion; return true;
        case Kw::spherical: out = PatternKind::Spherical; return true;
        case Kw::cylindrical: out = PatternKind::Cylindrical; return true;
        case Kw::planar: out = PatternKind::Planar; return true;
        case Kw::boxed: out = PatternKind::Boxed; return true;
        case Kw::leopard: out = PatternKind::Leopard; return true;
        case Kw::bozo: case Kw::spotted: case Kw::bumps: out = PatternKind::Bozo; return true;
        case Kw::granite: out = PatternKind::Granite; return true;
        case Kw::marble: out = PatternKind::Marble; return true;
        case Kw::wood: out = PatternKind::Wood; return true;
        case Kw::agate: out = PatternKind::Agate; return true;
        case Kw::wrinkles: out = PatternKind::Wrinkles; return true;
        case Kw::crackle: out = PatternKind::Crackle; return true;
        case Kw::ripples: out = PatternKind::Ripples; return true;
        case Kw::waves: out = PatternKind::Waves; return true;
        case Kw::dents: out = PatternKind::Dents; return true;
        case Kw::cells: out = PatternKind::Cells; return true;
        case Kw::average: out = PatternKind::Average; return true;
        case Kw::function: out = PatternKind::Function; return true;
        case Kw::mandel: out = PatternKind::Mandel; return true;
        case Kw::julia: out = PatternKind::Julia; return true;
        case Kw::magnet: out = PatternKind::Magnet; return true;
        case Kw::spiral1: out = PatternKind::Spiral1; return true;
        case Kw::spiral2: out = PatternKind::Spiral2; return true;
        case Kw::quilted: out = PatternKind::Quilted; return true;
        case Kw::slope: out = PatternKind::Slope; return true;
        case Kw::aoi: out = PatternKind::Aoi; return true;
        case Kw::pigment_pattern: out = PatternKind::PigmentPattern; return true;
        case Kw::tiling: out = PatternKind::Tiling; return true;
        case Kw::pavement: out = PatternKind::Pavement; return true;
        default: return false;
    }
}

// True when the program or a function it calls calls a pattern or pigment function of a pattern
// Rays does not render (its stand-in gives 0). Pattern and pigment functions of rendered patterns
// run for real at any depth: each nesting level has its own scratch (pattern.cpp, functionValue),
// and their tables are immutable and owned by the functions (HostFunction::keep).
bool callsPatternFunction(const fn::Program& p, int depth = 0) {
    for (const fn::HostFunction& h : p.hosts)
        if (sdl::isPatternStub(h)) return true;
    for (const auto& c : p.callees)
        if (c && depth < 64 && callsPatternFunction(*c, depth + 1)) return true;
    return false;
}

// slope <Direction> (the old form) or slope { <Direction> [, Lo_slope, Hi_slope] [altitude
// <Altitude> [, Lo_alt, Hi_alt]] } (POV-Ray 3.7 reference, "Slope").
pattern::Slope readSlope(const Value& v) {
    if (v.type != VType::Item) return pattern::makeSlope(toVec3(v), 0, 1, {}, 0, 1);
    std::vector<const Value*> values;  // the direction and the slope range, in order
    Vec3 altitude;
    double range[4] = {0, 1, 0, 1};
    for (const Entry& e : v.item().entries) {
        if (e.positional()) {
            for (const Value& a : e.args)
                if (a.isNumeric()) values.push_back(&a);
        } else if (e.kw() == Kw::altitude && !e.args.empty()) {
            altitude = toVec3(e.args[0]);
            if (e.args.size() >= 3) range[2] = toFloat(e.args[1]), range[3] = toFloat(e.args[2]);
        }
    }
    const Vec3 direction = values.empty() ? Vec3{0, 1, 0} : toVec3(*values[0]);
    if (values.size() >= 3) range[0] = toFloat(*values[1]), range[1] = toFloat(*values[2]);
    return pattern::makeSlope(direction, range[0], range[1], altitude, range[2], range[3]);
}

pattern::Rgbft toPatternColor(const Value& v) {
    const Rgbft c = toColor(v);
    return {c.rgb, c.filter, c.transmit};
}

}  // namespace


PigmentCompiler::PigmentCompiler(pattern::PigmentTable& table, NotRendered& notes, pattern::NormalTable* normals)
    : table_(table), notes_(notes), normalTable_(normals) {}

PigmentCompiler::~PigmentCompiler() = default;

int PigmentCompiler::compileNormal(const Item& normal, double inherited) {
    if (!normalTable_) return -1;
    if (!normals_) normals_ = std::make_unique<NormalCompiler>(*normalTable_, *this, notes_);
    return normals_->compile(normal, inherited);
}

std::pair<double, bool> PigmentCompiler::normalAmount(const Item& normal) {
    if (!normalTable_) return {0.5, false};
    if (!normals_) normals_ = std::make_unique<NormalCompiler>(*normalTable_, *this, notes_);
    const NormalCompiler::Amount a = normals_->amountOf(normal);
    return {a.value, a.given};
}

int PigmentCompiler::compile(std::shared_ptr<const Item> made) {
    made_.push_back(std::move(made));
    return compile(*made_.back());
}

int PigmentCompiler::compileNormal(std::shared_ptr<const Item> made, double inherited) {
    made_.push_back(std::move(made));
    return compileNormal(*made_.back(), inherited);
}

// A pavement whose tile or corners Rays does not draw: noted, the pigment left flat.
void PigmentCompiler::checkPavement(State& s) {
    if (!s.pattern || s.node.kind != PatternKind::Pavement || !s.pavement) return;
    const pattern::Pavement& m = s.node.params.pavement;
    if (pattern::pavementDrawn(m)) return;
    s.pattern = false;
    s.unrendered = true;
    notes_.note(std::string(s.what) + " pattern pavement number_of_sides " + std::to_string(m.sides) +
                    " number_of_tiles " + std::to_string(m.tiles) + " exterior " + std::to_string(m.exterior) +
                    " form " + std::to_string(m.form),
                s.pavement->loc, s.density ? "(density 0: no media there)" : "(drawn in its mean colour)");
}

int PigmentCompiler::compile(const Item& pigment) {
    if (const int* done = done_.find(pigment)) return *done;
    State s;
    readWhole(pigment, s, 0);
    const int n = s.pattern && !s.unrendered ? emit(s) : -1;
    // A flat colour is read again each time (cheap); keeping it would keep every object's own
    // `pigment { rgb ... }` alive to the end of the build.
    if (n >= 0) done_.put(pigment, n);
    return n;
}

int PigmentCompiler::compileFunction(const Item& item) {
    State s;
    readWhole(item, s, 0);
    return s.unrendered ? -1 : emit(s);
}

// A density (POV-Ray 3.7 reference, "Density"): read as a pigment whose colour is the density, 1
// (white) where no pattern or colour is given, 0 for a pattern Rays does not render. Always a node.
int PigmentCompiler::compileDensity(const Item& density) {
    State s;
    s.what = "density";
    s.density = true;
    s.node.color = pattern::Rgbft{Vec3(1.0), 0, 0};
    readWhole(density, s, 0);
    if (s.unrendered) {  // a pattern Rays does not render (noted): no media there rather than a guess
        s.pattern = false;
        s.node.color = pattern::Rgbft{};
    }
    return emit(s);
}

// A pigment inside a map or list: always a node (a flat colour becomes a Solid node).
int PigmentCompiler::nested(const Item& pigment, int depth) {
    State s;
    readWhole(pigment, s, depth + 1);
    if (s.unrendered) s.pattern = false;
    return emit(s);
}

void PigmentCompiler::readColorMap(const Item& map, State& s, int depth) {
    s.map.clear();
    s.mapSet = true;
    // A map written as an identifier inside another map's braces: its entries come first.
    for (const Entry& e : map.entries)
        if (e.positional())
            for (const Value& v : e.args)
                if (v.type == VType::Item && depth < kMaxDepth) readColorMap(v.item(), s, depth + 1);
    for (const Entry& e : map.entries) {
        if (e.key != kMapEntry || e.args.empty()) continue;
        const double a = e.args[0].type == VType::Undefined ? 0 : toFloat(e.args[0]);
        // Old style `[a b color C1 color C2]`: C1 at a, C2 at b.
        if (e.args.size() >= 4 && e.args[1].type == VType::Float) {
            s.map.push_back(MapEntry{a, toPatternColor(e.args[2]), -1});
            s.map.push_back(MapEntry{toFloat(e.args[1]), toPatternColor(e.args[3]), -1});
            continue;
        }
        if (e.args.size() >= 2) s.map.push_back(MapEntry{a, toPatternColor(e.args[1]), -1});
    }
}

void PigmentCompiler::readPigmentMap(const Item& map, State& s, int depth) {
    s.map.clear();
    s.mapSet = true;
    for (const Entry& e : map.entries) {
        if (e.positional()) {
            for (const Value& v : e.args)
                if (v.type == VType::Item && (v.item().kind == Kw::pigment_map || v.item().kind == Kw::density_map) &&
                    depth < kMaxDepth)
                    readPigmentMap(v.item(), s, depth + 1);
            continue;
        }
        if (e.key != kMapEntry || e.args.size() < 2 || e.args[1].type != VType::Item) continue;
        // An average's entries may leave their weight out: 1.
        const double v = e.args[0].type == VType::Undefined ? 1 : toFloat(e.args[0]);
        s.map.push_back(MapEntry{v, {}, nested(e.args[1].item(), depth)});
    }
}

void PigmentCompiler::read(const Item& p, State& s, int depth) {
    if (depth > kMaxDepth) return;
    for (const Entry& e : p.entries) readEntry(e, s, depth);
}

void PigmentCompiler::readWhole(const Item& p, State& s, int depth) {
    read(p, s, depth);
    checkPavement(s);
}

void PigmentCompiler::readEntry(const Entry& e, State& s, int depth) {
    if (e.positional()) {
        for (const Value& v : e.args) {
            if (v.type == VType::Item) {
                const Kw k = v.item().kind;
                if (k == Kw::pigment || k == Kw::density || (s.normal && k == Kw::normal)) read(v.item(), s, depth + 1);  // the base
                else if (k == Kw::color_map || k == Kw::colour_map) readColorMap(v.item(), s, depth);
                else if (k == Kw::pigment_map || k == Kw::density_map) readPigmentMap(v.item(), s, depth);
            } else if (v.isNumeric()) {
                if (s.pattern || s.unrendered) {
                    s.list.push_back(MapEntry{0, toPatternColor(v), -1});
                } else {
                    s.node.kind = PatternKind::Solid;
                    s.node.color = toPatternColor(v);
                }
            }
        }
        return;
    }
    if (e.key == kMapEntry) return;
    if (isTransformEntry(e)) {
        Transform t;
        applyTransform(e, t);
        s.transform = t * s.transform;
        s.transformed = true;
        if (!s.steps.empty() && s.steps.back().kind == pattern::WarpStep::Kind::Transform) {
            s.steps.back().toInner = t * s.steps.back().toInner;  // forward until emit inverts it
        } else {
            pattern::WarpStep step;
            step.toInner = t;
            s.steps.push_back(step);
        }
        return;
    }
    const Kw k = e.kw();
    const auto num = [&](size_t i) { return i < e.args.size() ? toFloat(e.args[i]) : 0.0; };
    PatternKind kind;
    // slope and aoi read the surface normal: as normal patterns they are not rendered (noted below).
    // tiling N: the Penrose tilings (25 to 27) are not drawn (noted below).
    const bool known = patternKind(k, kind) && !(s.normal && (kind == PatternKind::Slope || kind == PatternKind::Aoi)) &&
                       !(kind == PatternKind::Tiling && !pattern::tilingDrawn(int(num(0))));
    if (known) {
        s.pattern = true;
        s.unrendered = false;
        s.node.kind = kind;
        s.list.clear();
        // Measured with POV-Ray 3.7's pigment functions: spotted and bumps without a map are grey.
        s.greyDefault = k == Kw::spotted || k == Kw::bumps;
        if (kind == PatternKind::Gradient) {
            const Vec3 d = toVec3(e.args[0]);
            s.node.params.vector = length(d) > 0 ? normalize(d) : Vec3{0, 0, 0};
        }
        if (kind == PatternKind::Mandel) s.node.params.iterations = int(std::clamp(toFloat(e.args[0]), 0.0, 1e6));
        if (kind == PatternKind::Magnet) {  // magnet 1|2, 0 (mandel) | 1 (julia) [, <c>], ITERATIONS (specs_texture)
            s.node.params.magnetFormula = num(0) == 2 ? 2 : 1;
            s.node.params.magnetJulia = num(1) != 0;
            if (s.node.params.magnetJulia && e.args.size() > 3) {
                const Vec3 c = toVec3(e.args[2]);
                s.node.params.juliaR = c.x;
                s.node.params.juliaI = c.y;
            }
            s.node.params.iterations = int(std::clamp(toFloat(e.args.back()), 0.0, 1e6));
        }
        if (kind == PatternKind::Julia) {  // julia <c>, ITERATIONS
            const Vec3 c = toVec3(e.args[0]);
            s.node.params.juliaR = c.x;
            s.node.params.juliaI = c.y;
            s.node.params.iterations = e.args.size() > 1 ? int(std::clamp(toFloat(e.args[1]), 0.0, 1e6)) : 0;
        }
        // The number of arms is cut to an integer (measured: spiral1 1.5 and spiral2 1.5 are 1's).
        if (kind == PatternKind::Spiral1 || kind == PatternKind::Spiral2) s.node.params.arms = std::trunc(toFloat(e.args[0]));
        if (kind == PatternKind::Tiling) s.node.params.tiling = int(num(0));
        s.pavement = kind == PatternKind::Pavement ? &e : nullptr;
        if (kind == PatternKind::Slope) s.node.params.slope = readSlope(e.args[0]);
        if (kind == PatternKind::PigmentPattern) s.node.params.source = nested(e.args[0].item(), depth);
        if (kind == PatternKind::Function) {
            const sdl::FunctionValue& f = e.args[0].fn();
            if (f.kind != sdl::FunctionValue::Kind::Float || !f.table || f.index < 0 ||
                callsPatternFunction(f.table->program(f.index))) {
                s.pattern = false;
                s.unrendered = true;
                notes_.note(std::string(s.what) +
                                " pattern function calling a pattern or pigment function of a pattern Rays does not render",
                            e.loc, "(drawn in its mean colour)");
                return;
            }
            table_.programs.push_back(f.table->shared(f.index));
            s.node.params.function = table_.programs.back().get();
        }
        if (!s.waveSet)
            s.node.wave.type =
                kind == PatternKind::Wood || kind == PatternKind::Marble || kind == PatternKind::Spiral1 ||
                        kind == PatternKind::Spiral2
                    ? WaveType::Triangle
                    : WaveType::Ramp;
        return;
    }
    if (k == Kw::image_map && !s.normal) {
        readImageMap(e.args[0].item(), s);
        return;
    }
    if (k == Kw::density_file) {  // density_file df3 "NAME" [interpolate N]
        s.pattern = true;
        s.unrendered = false;
        s.node.kind = PatternKind::DensityFile;
        s.list.clear();
        table_.grids.push_back(densityFiles_.load(e.args[0].str(), e.loc));
        s.node.params.grid = table_.grids.back().get();
        if (e.args.size() > 1) s.node.params.interpolate = int(std::clamp(toFloat(e.args[1]), 0.0, 2.0));
        if (!s.waveSet) s.node.wave.type = WaveType::Ramp;
        return;
    }
    if (k == Kw::image_pattern) {
        readImageMap(e.args[0].item(), s, true);
        return;
    }
    if (k == Kw::object && !e.args.empty() && e.args[0].type == VType::Item && buildObject_) {
        readObjectPattern(e, s, depth);
        return;
    }
    if (k == Kw::bump_map && s.normal) {  // the heights of a normal's bump_map (NormalKind::BumpMap)
        readImageMap(e.args[0].item(), s, true, true);
        return;
    }
    if (isPatternType(k) || k == Kw::image_map) {
        s.unrendered = true;
        s.pattern = false;
        const std::string number = k == Kw::tiling ? " " + std::to_string(int(num(0))) : "";
        notes_.note(std::string(s.what) + " pattern " + std::string(sdl::keywordName(k)) + number, e.loc,
                    s.normal ? "(drawn smooth)" : s.density ? "(density 0: no media there)" : "(drawn in its mean colour)");
        return;
    }
    pattern::PatternParams& pp = s.node.params;
    switch (k) {
        case Kw::color_map: case Kw::colour_map: readColorMap(e.args[0].item(), s, depth); break;
        case Kw::pigment_map: case Kw::density_map: readPigmentMap(e.args[0].item(), s, depth); break;
        case Kw::pigment: case Kw::density: s.list.push_back(MapEntry{0, {}, nested(e.args[0].item(), depth)}); break;
        case Kw::turbulence: pp.turbulence.amount = toVec3(e.args[0]); break;
        case Kw::interpolate: pp.interpolate = int(std::clamp(num(0), 0.0, 2.0)); break;  // density_file's
        case Kw::octaves: pp.turbulence.octaves = int(std::clamp(num(0), 1.0, 10.0)); break;
        case Kw::omega: pp.turbulence.omega = num(0); break;
        case Kw::lambda: pp.turbulence.lambda = num(0); break;
        case Kw::frequency: s.node.wave.frequency = num(0); break;
        case Kw::phase: s.node.wave.phase = num(0); break;
        case Kw::ramp_wave: s.node.wave.type = WaveType::Ramp; s.waveSet = true; break;
        case Kw::triangle_wave: s.node.wave.type = WaveType::Triangle; s.waveSet = true; break;
        case Kw::sine_wave: s.node.wave.type = WaveType::Sine; s.waveSet = true; break;
        case Kw::scallop_wave: s.node.wave.type = WaveType::Scallop; s.waveSet = true; break;
        case Kw::cubic_wave: s.node.wave.type = WaveType::Cubic; s.waveSet = true; break;
        case Kw::poly_wave:
            s.node.wave.type = WaveType::Poly;
            s.node.wave.exponent = e.args.empty() ? 1.0 : num(0);
            s.waveSet = true;
            break;
        case Kw::brick_size: pp.brickSize = toVec3(e.args[0]); break;
        case Kw::mortar: pp.mortar = num(0); break;
        case Kw::agate_turb: pp.agateTurb = num(0); break;
        case Kw::noise_generator: pp.noiseGenerator = std::clamp(int(num(0)), 1, 3); break;
        case Kw::control0: pp.quilt.control0 = num(0); break;
        case Kw::control1: pp.quilt.control1 = num(0); break;
        case Kw::exponent: pp.exponent = int(std::clamp(num(0), 2.0, 33.0)); break;
        case Kw::number_of_sides: pp.pavement.sides = int(num(0)); break;
        case Kw::number_of_tiles: pp.pavement.tiles = int(num(0)); break;
        case Kw::pattern: pp.pavement.pattern = int(num(0)); break;
        case Kw::form:  // pavement's form number, crackle's form vector
            pp.pavement.form = int(num(0));
            pp.crackle.form = toVec3(e.args[0]);
            break;
        case Kw::metric: pp.crackle.metric = num(0); break;
        case Kw::offset: pp.crackle.offset = num(0); break;
        case Kw::solid: pp.crackle.solid = true; break;
        case Kw::exterior:
            pp.pavement.exterior = int(num(0));
            pp.exterior = int(num(0));
            pp.exteriorFactor = e.args.size() > 1 ? num(1) : 1;
            break;
        case Kw::interior:
            pp.pavement.interior = int(num(0));
            pp.interior = int(num(0));
            pp.interiorFactor = e.args.size() > 1 ? num(1) : 1;
            break;
        case Kw::warp: readWarp(e.args[0].item(), s); break;
        default: break;
    }
}

// The object pattern (POV-Ray 3.7 reference, "Object Pattern"): a list pattern of two entries,
// the first outside the object, the second inside (measured: `object { sphere { 0, 1 } rgb <1,0,0>,
// rgb <0,1,0> }` is green at the origin, red at <2, 0, 0>). Its list's items are written inside
// its braces after the object; without them it is blue outside, green inside (measured).
void PigmentCompiler::readObjectPattern(const Entry& e, State& s, int depth) {
    const Item& item = e.args[0].item();
    std::shared_ptr<const pattern::PatternObject> object;
    if (const auto* done = objects_.find(item)) {
        object = *done;
    } else {
        const BuiltPatternObject built = buildObject_(item);
        if (built.object && !built.complete)
            notes_.note(std::string(s.what) + " pattern object of shapes Rays does not render", e.loc,
                        "(the object without them)");
        object = built.object;
        objects_.put(item, object);
    }
    if (!object) {
        s.unrendered = true;
        s.pattern = false;
        notes_.note(std::string(s.what) + " pattern object", e.loc, "(no object Rays renders: drawn in its mean colour)");
        return;
    }
    s.pattern = true;
    s.unrendered = false;
    s.node.kind = PatternKind::Object;
    s.list.clear();
    table_.objects.push_back(object);
    s.node.params.object = object.get();
    for (const Entry& le : item.entries) {
        if (!isObjectPatternListEntry(le)) continue;
        if (le.positional()) {
            for (const Value& v : le.args)
                if (v.isNumeric()) s.list.push_back(MapEntry{0, toPatternColor(v), -1});
        } else if ((le.kw() == Kw::pigment || le.kw() == Kw::density) && !le.args.empty() &&
                   le.args[0].type == VType::Item) {
            s.list.push_back(MapEntry{0, {}, nested(le.args[0].item(), depth)});
        }
    }
}

// warp { turbulence ... }, warp { repeat ... }, black_hole and the mapping warps planar,
// cylindrical, spherical, toroidal (with orientation, dist_exp, major_radius) and cubic.
void PigmentCompiler::readWarp(const Item& warp, State& s) {
    pattern::WarpStep step;
    bool known = false;
    auto mapping = [&](pattern::MappingKind kind) {
        step.kind = pattern::WarpStep::Kind::Mapping;
        step.mapping.kind = kind;
        known = true;
    };
    Vec3 orientation{0, 0, 1};
    for (const Entry& e : warp.entries) {
        if (e.positional()) continue;
        const auto num = [&](size_t i) { return i < e.args.size() ? toFloat(e.args[i]) : 0.0; };
        switch (e.kw()) {
            case Kw::turbulence:  // a black hole's turbulence moves each repeated hole at random
                if (step.kind == pattern::WarpStep::Kind::BlackHole) {
                    step.hole.jitter = toVec3(e.args[0]);
                    break;
                }
                step.kind = pattern::WarpStep::Kind::Turbulence;
                step.turbulence.amount = toVec3(e.args[0]);
                known = true;
                break;
            case Kw::octaves: step.turbulence.octaves = int(std::clamp(num(0), 1.0, 10.0)); break;
            case Kw::omega: step.turbulence.omega = num(0); break;
            case Kw::lambda: step.turbulence.lambda = num(0); break;
            case Kw::repeat: {
                if (step.kind == pattern::WarpStep::Kind::BlackHole) {
                    step.hole.repeat = toVec3(e.args[0]);
                    break;
                }
                const Vec3 v = toVec3(e.args[0]);
                step.kind = pattern::WarpStep::Kind::Repeat;
                step.axis = v.x != 0 ? 0 : (v.y != 0 ? 1 : 2);
                step.width = std::fabs(v[step.axis]);
                known = true;
                break;
            }
            case Kw::offset: step.offset = toVec3(e.args[0]); break;
            case Kw::flip: step.flip = toVec3(e.args[0]); break;
            case Kw::planar:  // planar [<normal>, distance]
                mapping(pattern::MappingKind::Planar);
                if (!e.args.empty()) orientation = toVec3(e.args[0]);
                step.mapping.distance = num(1);
                break;
            case Kw::cylindrical: mapping(pattern::MappingKind::Cylindrical); break;
            case Kw::spherical: mapping(pattern::MappingKind::Spherical); break;
            case Kw::orientation: orientation = toVec3(e.args[0]); break;
            case Kw::dist_exp: step.mapping.distExp = num(0); break;
            case Kw::black_hole:  // black_hole <location>, radius
                step.kind = pattern::WarpStep::Kind::BlackHole;
                step.hole.center = toVec3(e.args[0]);
                step.hole.radius = num(1);
                known = true;
                break;
            case Kw::falloff: step.hole.falloff = num(0); break;
            case Kw::strength: step.hole.strength = num(0); break;
            case Kw::inverse: step.hole.inverse = true; break;
            case Kw::toroidal: mapping(pattern::MappingKind::Toroidal); break;
            case Kw::cubic: mapping(pattern::MappingKind::Cubic); break;
            case Kw::major_radius: step.mapping.majorRadius = num(0); break;
            default: break;
        }
    }
    if (!known) return;
    if (step.kind == pattern::WarpStep::Kind::Mapping)
        step.mapping.orientation = length(orientation) > 0 ? normalize(orientation) : Vec3{0, 0, 1};
    s.steps.push_back(step);
    s.warped = true;
}

int PigmentCompiler::patternedTexture(const Item& texture, const std::vector<Placed>& entries,
                                      const std::vector<double>& values) {
    State s;
    s.what = "texture";
    for (const Entry& e : texture.entries) {
        if (e.positional() || e.key == kMapEntry) continue;
        const Kw k = e.kw();
        if (k == Kw::texture || k == Kw::texture_map || k == Kw::pigment || k == Kw::normal || k == Kw::finish) continue;
        readEntry(e, s, 0);
    }
    checkPavement(s);
    if (!s.pattern || s.unrendered || entries.empty()) return -1;
    std::vector<MapEntry> list;
    for (size_t i = 0; i < entries.size(); ++i)
        list.push_back(MapEntry{i < values.size() ? values[i] : 0.0, {}, placed(entries[i])});
    if (pattern::isBlockPattern(s.node.kind)) s.list = list;
    else s.map = list, s.mapSet = true;
    return emit(s);
}

int PigmentCompiler::tilesTexture(const Item& texture, const Item& tiles, const std::vector<Placed>& entries) {
    if (entries.size() != 2) return -1;
    State s;
    s.what = "texture";
    for (const Item* block : {&tiles, &texture})
        for (const Entry& e : block->entries)
            if (!e.positional() && e.key != kMapEntry && isTransformEntry(e)) readEntry(e, s, 0);
    s.node.kind = PatternKind::Checker;
    s.pattern = true;
    for (const Placed& p : entries) s.list.push_back(MapEntry{0, {}, placed(p)});
    return emit(s);
}

int PigmentCompiler::materialMapTexture(const Item& texture, const Item& map, const std::vector<Placed>& entries) {
    if (entries.empty()) return -1;
    State s;
    s.what = "texture";
    const ImageFile* file = readImageMap(map, s);
    if (!file || !s.pattern || s.unrendered) return -1;
    // A palette image's indices choose; other images their grey (materialIndex).
    if (auto indices = images_.paletteIndices(*file)) table_.images[size_t(s.node.image)].image = std::move(indices);
    s.node.kind = PatternKind::MaterialMap;
    for (const Item* block : {&map, &texture})
        for (const Entry& e : block->entries)
            if (!e.positional() && e.key != kMapEntry && isTransformEntry(e)) readEntry(e, s, 0);
    s.map.clear();
    for (const Placed& p : entries) s.map.push_back(MapEntry{0, {}, placed(p)});
    s.mapSet = true;
    return emit(s);
}

int PigmentCompiler::normalPattern(const Item& normal) {
    State s;
    s.what = "normal";
    s.normal = true;
    read(normal, s, 0);
    if (!s.pattern || s.unrendered) return -1;
    s.list.clear();  // the map and list are the normal's: not pigments
    s.map.clear();
    s.mapSet = false;
    return emit(s);
}

// A node for p in the enclosing space: a Solid node for a flat colour, the node itself when it is
// not moved, else a one-entry average that moves the point first.
int PigmentCompiler::placed(const Placed& p) {
    pattern::PigmentNode n;
    if (p.node < 0) {
        n.color = {p.flat.rgb, p.flat.filter, p.flat.transmit};
    } else {
        if (p.toEnclosing.isIdentity()) return p.node;
        n.kind = PatternKind::Average;
        n.transformed = p.toEnclosing.determinant() != 0;
        if (n.transformed) n.toPattern = p.toEnclosing.inverse();
        n.mapBegin = int(table_.entries.size());
        n.mapCount = 1;
        table_.entries.push_back(MapEntry{1, {}, p.node});
    }
    table_.nodes.push_back(n);
    return int(table_.nodes.size()) - 1;
}

int PigmentCompiler::layered(const Placed& below, const Placed& top) {
    const int b = placed(below), t = placed(top);
    pattern::PigmentNode n;
    n.kind = PatternKind::Layered;
    n.mapBegin = int(table_.entries.size());
    n.mapCount = 2;
    table_.entries.push_back(MapEntry{0, {}, b});
    table_.entries.push_back(MapEntry{1, {}, t});
    table_.nodes.push_back(n);
    return int(table_.nodes.size()) - 1;
}

// The node's warps (with its transformations among them) or its transformation.
void PigmentCompiler::place(const State& s, pattern::PigmentNode& node) {
    if (s.warped) {
        // The point meets the steps written last first; transformations are inverted.
        node.warpBegin = int(table_.warps.size());
        for (auto it = s.steps.rbegin(); it != s.steps.rend(); ++it) {
            pattern::WarpStep step = *it;
            if (step.kind == pattern::WarpStep::Kind::Transform) {
                if (step.toInner.determinant() == 0) continue;
                step.toInner = step.toInner.inverse();
            }
            table_.warps.push_back(step);
        }
        node.warpCount = int(table_.warps.size()) - node.warpBegin;
    } else if (s.transformed && s.transform.determinant() != 0) {
        node.transformed = true;
        node.toPattern = s.transform.inverse();
    }
}

int PigmentCompiler::emit(State& s) {
    pattern::PigmentNode node = s.node;
    if (!s.pattern) {
        node.kind = PatternKind::Solid;
        node.mapCount = 0;
    } else if (node.kind == PatternKind::ImageMap) {
        place(s, node);
    } else {
        std::vector<MapEntry> entries;
        if (pattern::isBlockPattern(node.kind)) {
            // The list's colours or pigments replace the built-in ones from the first on.
            entries = pattern::defaultMap(node.kind);
            for (size_t i = 0; i < s.list.size() && i < entries.size(); ++i) entries[i] = s.list[i];
        } else if (s.mapSet && !s.map.empty()) {
            entries = s.map;
        } else {
            // (gradient has no built-in map: the grey ramp)
            entries = pattern::defaultMap(s.greyDefault ? PatternKind::Gradient : node.kind);
        }
        node.mapBegin = int(table_.entries.size());
        node.mapCount = int(entries.size());
        table_.entries.insert(table_.entries.end(), entries.begin(), entries.end());
        place(s, node);
    }
    table_.nodes.push_back(node);
    return int(table_.nodes.size()) - 1;
}

}  // namespace rays::pov
