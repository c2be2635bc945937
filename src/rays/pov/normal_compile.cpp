#include "rays/pov/normal_compile.h"

#include <cmath>

#include "rays/pov/grammar.h"
#include "rays/pov/item_values.h"
#include "rays/pov/specs.h"

namespace rays::pov {

using pattern::NormalKind;
using sdl::VType;

namespace {

constexpr int kMaxDepth = 64;

// The normal kind a pattern keyword gives: POV-Ray's specialised normals, average, or any other.
NormalKind kindOf(Kw k) {
    switch (k) {
        case Kw::bumps: return NormalKind::Bumps;
        case Kw::dents: return NormalKind::Dents;
        case Kw::ripples: return NormalKind::Ripples;
        case Kw::waves: return NormalKind::Waves;
        case Kw::wrinkles: return NormalKind::Wrinkles;
        case Kw::quilted: return NormalKind::Quilted;
        case Kw::average: return NormalKind::Average;
        default: return NormalKind::Pattern;
    }
}

bool isBlock(Kw k) {
    return k == Kw::checker || k == Kw::hexagon || k == Kw::brick || k == Kw::square || k == Kw::triangular ||
           k == Kw::cubic || k == Kw::object;
}

}  // namespace

// What a normal's entries have set so far (a base normal's first).
struct NormalCompiler::State {
    NormalKind kind = NormalKind::Pattern;
    bool block = false;       ///< checker, hexagon or brick
    bool pattern = false;     ///< a pattern type was given
    double amount = 0.5;      ///< the pattern's amount (POV-Ray's default 0.5)
    bool amountSet = false;   ///< an amount was written after the pattern type
    double bumpSize = 0;      ///< bump_size, when set
    bool bumpSizeSet = false;
    double accuracy = 0.02;
    bool noBumpScale = false;  ///< no_bump_scale
    std::vector<pattern::SlopeEntry> slopes;
    std::vector<pattern::NormalEntry> map;   ///< normal_map entries
    std::vector<pattern::NormalEntry> list;  ///< a block pattern's normals
    bool mapSet = false;
};

int NormalCompiler::compile(const Item& normal, double inherited) {
    if (inherited != 0.5) {  // made once per item and inherited amount
        if (const std::vector<std::pair<double, int>>* done = doneWith_.find(normal))
            for (const auto& [amount, node] : *done)
                if (amount == inherited) return node;
    } else if (const int* done = done_.find(normal)) {
        return *done;
    }
    // What it was made with is remembered before it is built (-1 meanwhile), so that a normal
    // containing itself stays smooth there, as with the plain cache.
    const auto remember = [&](int node) {
        std::vector<std::pair<double, int>> list;
        if (const auto* done = doneWith_.find(normal)) list = *done;
        bool found = false;
        for (auto& [amount, n] : list)
            if (amount == inherited) n = node, found = true;
        if (!found) list.emplace_back(inherited, node);
        doneWith_.put(normal, std::move(list));
    };
    if (inherited != 0.5) remember(-1);
    const double outer = inherited_;
    inherited_ = inherited;
    const int n = build(normal);
    inherited_ = outer;
    if (inherited != 0.5) remember(n);
    return n;
}

int NormalCompiler::build(const Item& normal) {
    const bool plain = inherited_ == 0.5;
    if (plain) done_.put(normal, -1);  // a normal containing itself stays smooth there
    State s;
    s.amount = inherited_;
    read(normal, s, 0);
    int n = -1;
    const int pat = s.pattern ? patterns_.normalPattern(normal) : -1;
    if (pat >= 0) {
        pattern::NormalNode node;
        node.pattern = pat;
        const pattern::PigmentNode& pn = patterns_.table().nodes[size_t(pat)];
        // The linear part of the pattern's transformations (warps: their transformation steps).
        Transform toPattern;
        if (pn.warpCount > 0) {
            for (int i = pn.warpCount - 1; i >= 0; --i) {
                const pattern::WarpStep& w = patterns_.table().warps[size_t(pn.warpBegin + i)];
                if (w.kind == pattern::WarpStep::Kind::Transform) toPattern = w.toInner * toPattern;
            }
        } else if (pn.transformed) {
            toPattern = pn.toPattern;
        }
        for (auto& row : toPattern.m) row[3] = 0;
        node.toPattern = toPattern;
        node.fromPattern = toPattern.determinant() != 0 ? toPattern.inverse() : Transform{};
        node.amount = s.bumpSizeSet ? s.bumpSize : s.amount;
        node.accuracy = s.accuracy;
        node.noBumpScale = s.noBumpScale;
        node.kind = s.kind;
        if (s.kind == NormalKind::BumpMap) node.amount = s.amount;  // bump_map's own bump_size
        if (s.kind == NormalKind::Pattern && s.block && !s.list.empty()) node.kind = NormalKind::Block;
        if (s.kind == NormalKind::Pattern && !s.block && s.mapSet && !s.map.empty()) node.kind = NormalKind::Map;
        const std::vector<pattern::NormalEntry>& entries = node.kind == NormalKind::Block ? s.list : s.map;
        if (node.kind == NormalKind::Block || node.kind == NormalKind::Map || node.kind == NormalKind::Average) {
            node.mapBegin = int(table_.entries.size());
            node.mapCount = int(entries.size());
            table_.entries.insert(table_.entries.end(), entries.begin(), entries.end());
        }
        if (node.kind == NormalKind::Pattern) {
            node.slopeBegin = int(table_.slopes.size());
            node.slopeCount = int(s.slopes.size());
            table_.slopes.insert(table_.slopes.end(), s.slopes.begin(), s.slopes.end());
        }
        table_.nodes.push_back(node);
        n = int(table_.nodes.size()) - 1;
    }
    if (plain) done_.put(normal, n);
    return n;
}

NormalCompiler::Amount NormalCompiler::amountOf(const Item& normal) {
    State s;
    read(normal, s, 0);
    return {s.bumpSizeSet ? s.bumpSize : s.amount, s.amountSet || s.bumpSizeSet};
}

int NormalCompiler::nested(const Item& normal, int depth) {
    if (depth > kMaxDepth) return -1;
    return compile(normal, inherited_);
}

void NormalCompiler::read(const Item& normal, State& s, int depth) {
    if (depth > kMaxDepth) return;
    for (const Entry& e : normal.entries) {
        if (e.positional()) {
            for (const Value& v : e.args) {
                if (v.type == VType::Item && v.item().kind == Kw::normal) read(v.item(), s, depth + 1);  // the base
                else if (v.type == VType::Item && v.item().kind == Kw::normal_map) {
                    s.map.clear();
                    s.mapSet = true;
                    for (const Entry& me : v.item().entries)
                        if (me.key == kMapEntry && me.args.size() > 1 && me.args[1].type == VType::Item)
                            s.map.push_back({me.args[0].type == VType::Undefined ? 1.0 : toFloat(me.args[0]),
                                             nested(me.args[1].item(), depth + 1)});
                } else if (v.isNumeric() && v.type != VType::Item && s.pattern) {
                    s.amount = toFloat(v);  // the amount after the pattern type
                    s.amountSet = true;
                }
            }
            continue;
        }
        if (e.key == kMapEntry) continue;
        const Kw k = e.kw();
        if (isPatternType(k)) {
            s.pattern = true;
            s.kind = kindOf(k);
            s.block = isBlock(k);
            s.list.clear();
            // bumps, dents, ripples, waves and wrinkles take their amount as an argument.
            if (s.kind >= NormalKind::Bumps && !e.args.empty() && e.args[0].type == VType::Float) {
                s.amount = toFloat(e.args[0]);
                s.amountSet = true;
            }
            // spiral1 N, AMOUNT and spiral2 N, AMOUNT (measured: `spiral2 5, 1.0` tilts as `spiral2 5 1.0`).
            if ((k == Kw::spiral1 || k == Kw::spiral2) && e.args.size() > 1 && e.args[1].isNumeric()) {
                s.amount = toFloat(e.args[1]);
                s.amountSet = true;
            }
            // object { OBJECT normal { A }, normal { B } }: its list is inside its braces.
            if (k == Kw::object && !e.args.empty() && e.args[0].type == VType::Item)
                for (const Entry& le : e.args[0].item().entries)
                    if (!le.positional() && le.kw() == Kw::normal && !le.args.empty() && le.args[0].type == VType::Item)
                        s.list.push_back({0, nested(le.args[0].item(), depth + 1)});
            continue;
        }
        switch (k) {
            case Kw::bump_size:
                s.bumpSize = toFloat(e.args[0]);
                s.bumpSizeSet = true;
                break;
            case Kw::accuracy: s.accuracy = toFloat(e.args[0]); break;
            case Kw::no_bump_scale: s.noBumpScale = isOn(e); break;
            case Kw::normal: s.list.push_back({0, nested(e.args[0].item(), depth + 1)}); break;
            case Kw::normal_map: {
                Entry inner;
                inner.args = {e.args[0]};
                Item wrap;
                wrap.entries.push_back(inner);
                read(wrap, s, depth + 1);
                break;
            }
            case Kw::slope_map: {
                s.slopes.clear();
                for (const Entry& me : e.args[0].item().entries) {
                    if (me.key != kMapEntry || me.args.size() < 2) continue;
                    const double v = me.args[0].type == VType::Undefined ? 0 : toFloat(me.args[0]);
                    if (me.args[1].type == VType::Float) s.slopes.push_back({v, toFloat(me.args[1]), 0});
                    else {
                        const Vec3 hs = toVec3(me.args[1]);
                        s.slopes.push_back({v, hs.x, hs.y});
                    }
                }
                break;
            }
            case Kw::bump_map: {  // the image's heights (PigmentCompiler reads the image itself)
                s.pattern = true;
                s.kind = NormalKind::BumpMap;
                s.block = false;
                s.list.clear();
                s.amount = 0.5;  // bump_size's default (measured: a bump_map without it tilts half as much as with bump_size 1)
                for (const Entry& be : e.args[0].item().entries)
                    if (!be.positional() && be.kw() == Kw::bump_size && !be.args.empty()) s.amount = toFloat(be.args[0]);
                break;
            }
            default: break;
        }
    }
}

}  // namespace rays::pov
