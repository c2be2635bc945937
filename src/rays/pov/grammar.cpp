// The generic block reader: one loop for every POV-Ray block, driven by its BlockSpec.
#include "rays/pov/grammar.h"

#include <algorithm>
#include <string>

namespace rays::pov {

using sdl::Entry;
using sdl::Interpreter;
using sdl::Item;
using sdl::Value;
using sdl::VType;

void BlockSpec::seal() {
    index.fill(-1);
    for (size_t i = 0; i < rules.size(); ++i) index[size_t(rules[i].kw)] = int16_t(i);
}

BlockSpec makeSpec(const char* name, Kw kind, std::initializer_list<const RuleGroup*> groups, bool positionals,
                   bool children, BlockSpec::Map map, const BlockSpec* mapBody) {
    BlockSpec s;
    s.name = name;
    s.kind = kind;
    s.positionals = positionals;
    s.children = children;
    s.map = map;
    s.mapBody = mapBody;
    for (const RuleGroup* g : groups) s.rules.insert(s.rules.end(), g->begin(), g->end());
    s.seal();
    return s;
}

namespace {

bool isItemValue(Interpreter& in) {
    const sdl::Binding* b = in.identBinding();
    return b && (b->value.type == VType::Item || b->value.type == VType::Function || b->value.type == VType::Spline);
}

void readArgs(Interpreter& in, const Rule& r, Entry& e) {
    switch (r.arg) {
        case Arg::Flag:
            return;
        case Arg::Bool:
            e.args.push_back(Value::number(in.parseOptionalBool() ? 1 : 0));
            return;
        case Arg::Float:
            e.args.push_back(Value::number(in.parseFloat()));
            return;
        case Arg::OptFloat:
        case Arg::OptExpr:
            if (in.atNumericStart()) e.args.push_back(in.parseNumeric(false));
            return;
        case Arg::Expr:
            e.args.push_back(in.parseNumeric(false));
            return;
        case Arg::List:
            e.args.push_back(in.parseNumeric(false));
            // A list of a fixed length takes its items with or without commas, as POV-Ray does
            // (`julia <0.3, 0.44> 30`); an open-ended list needs them.
            while (r.n == 0 || int(e.args.size()) < r.n) {
                if (in.isSym(',')) in.next();
                else if (r.n == 0 || !in.atNumericStart()) return;
                if (!in.atNumericStart()) return;
                e.args.push_back(in.parseNumeric(false));
            }
            return;
        case Arg::Color:
            e.args.push_back(in.parseColor());
            return;
        case Arg::String:
            e.args.push_back(Value::string(in.parseString()));
            return;
        case Arg::Sub:
            e.args.push_back(Value::item(readBlockBody(in, *r.sub, r.kw)));
            return;
        case Arg::SubOrExpr:
            if (in.isSym('{')) e.args.push_back(Value::item(readBlockBody(in, *r.sub, r.kw)));
            else e.args.push_back(in.parseNumeric(true));
            return;
        case Arg::Item: {
            Interpreter::NestGuard guard(in);
            e.args.push_back(Value::item(in.host().readItem(in)));
            return;
        }
        case Arg::Function:
            e.args.push_back(in.parseFunction());
            return;
        case Arg::Custom:
            r.custom(in, e);
            return;
    }
}

// `< a, b, c, ... >` with any number of floats (the coefficients of cubic, quartic and poly).
void readCoefficients(Interpreter& in, Entry& e) {
    const sdl::Loc at = in.loc();
    in.next();  // '<'
    while (!in.isSym('>')) {
        if (in.atEnd()) in.error(at, "'<' of the coefficients is never closed");
        if (e.args.size() >= 1024) in.error(at, "more than 1024 coefficients");
        e.args.push_back(Value::number(in.parseFloat()));
        in.acceptSym(',');
    }
    in.next();
}

// `[ v BODY ]` of a colour, pigment, normal, texture, density or slope map.
void readMapEntry(Interpreter& in, const BlockSpec& spec, Item& item) {
    Entry e;
    e.key = kMapEntry;
    e.loc = in.loc();
    in.next();  // '['
    // The entry's value; an average pattern's entries may leave their weight out.
    if (in.atNumericStart() && !(spec.map == BlockSpec::Map::Colors && (in.isKw(Kw::color) || in.isKw(Kw::colour) || in.isKw(Kw::rgb))))
        e.args.push_back(Value::number(in.parseFloat()));
    else
        e.args.push_back(Value());
    in.acceptSym(',');
    switch (spec.map) {
        case BlockSpec::Map::Colors:
            // Old style `[a, b color C1 color C2]` has a second value and two colours.
            if (in.tok().kind == sdl::Tk::Number) {
                e.args.push_back(Value::number(in.parseFloat()));
                in.acceptSym(',');
            }
            while (!in.isSym(']')) {
                if (in.atEnd()) in.error(e.loc, "'[' of a map entry is never closed");
                e.args.push_back(in.parseColor());
                in.acceptSym(',');
            }
            break;
        case BlockSpec::Map::Slopes:
            e.args.push_back(in.parseNumeric(false));
            break;
        case BlockSpec::Map::Bodies: {
            auto body = std::make_shared<Item>();
            body->kind = spec.mapBody->kind;
            body->loc = in.loc();
            readBody(in, *body, *spec.mapBody, ']');
            e.args.push_back(Value::item(std::move(body)));
            break;
        }
        case BlockSpec::Map::None:
            break;
    }
    in.expectSym(']', "to close the map entry");
    item.entries.push_back(std::move(e));
}

// A bare number, vector, colour or string (a sphere's centre, a text object's string).
bool atBareValue(Interpreter& in) { return in.atNumericStart() || in.atStringStart(); }
void readBareValue(Interpreter& in, Entry& e) {
    if (in.atStringStart()) e.args.push_back(Value::string(in.parseString()));
    else e.args.push_back(in.parseNumeric(true));
}

// Most blocks hold a few entries (a sphere's centre, radius, texture and a transform): one
// allocation for them instead of the vector's 1, 2, 4 growth.
constexpr size_t kEntriesReserved = 4;

// Items nested at most this deep, counting those reached through identifiers: a file can nest a
// declared item in itself again and again without writing the levels out (#declare O = union {
// object { O } } in a loop); such chains overflowed the stack when freed (100,000 levels in a release
// build), and the scene builder renders 1000 levels at most. As deep as Limits::nesting allows
// items to be written out.
constexpr uint32_t kMaxItemDepth = 4000;

// Sets item.depth and item.size from its item arguments; throws past kMaxItemDepth. An argument
// held elsewhere too (an identifier's item: `object { O }`, `pigment { P }`) is a use that POV-Ray
// would copy; its size is counted (Interpreter::countItemCopy): a union of two uses of a union of two
// uses ... doubles at every level, for the builder to walk.
void setDepth(Interpreter& in, Item& item) {
    constexpr uint64_t kSaturated = uint64_t(1) << 62;
    uint32_t below = 0;
    uint64_t size = 1;
    for (const Entry& e : item.entries)
        for (const Value& v : e.args)
            if (v.type == sdl::VType::Item) {
                const Item& child = v.item();
                below = std::max(below, child.depth);
                size = std::min(size + child.size, kSaturated);
                if (v.ref.use_count() > 1) in.countItemCopy(child.size, item.loc);
            }
    item.depth = below + 1;
    item.size = size;
    if (item.depth > kMaxItemDepth)
        in.error(item.loc, "items nested deeper than " + std::to_string(kMaxItemDepth) +
                               " levels (a declared item used in itself again and again?)");
}

// `{ body }` (the '{' current) as an item of the given kind, opened at `at`.
sdl::ItemRef readBraced(Interpreter& in, const BlockSpec& spec, Kw kind, const sdl::Loc& at) {
    auto item = std::make_shared<Item>();
    item->kind = kind;
    item->loc = at;
    item->entries.reserve(kEntriesReserved);
    in.expectSym('{', std::string("after '") + std::string(sdl::keywordName(kind)) + "'");
    readBody(in, *item, spec, '}');
    in.next();
    return item;
}

// One entry of a block at the current token, into e; false when it went into item already (a map
// entry).
bool readEntry(Interpreter& in, Item& item, const BlockSpec& spec, Entry& e) {
    if (in.isKeyword()) {
        const Kw k = in.kw();
        if (const Rule* r = spec.find(k)) {
            e.key = uint16_t(k);
            if (r->arg != Arg::Item && r->arg != Arg::Function) in.next();  // those readers take their keyword
            readArgs(in, *r, e);
            return true;
        }
        if (spec.children && in.host().startsItem(k)) {
            Interpreter::NestGuard guard(in);
            e.key = uint16_t(k);
            e.args.push_back(Value::item(in.host().readItem(in)));
            return true;
        }
        if (!spec.positionals || !atBareValue(in))
            in.errorHere("'" + std::string(sdl::keywordName(k)) + "' is not allowed in " + spec.name);
        readBareValue(in, e);
        return true;
    }
    if (in.isIdentifier()) {
        if (!in.identBinding()) in.errorHere("undeclared identifier '" + std::string(in.spelling(in.tok().id)) + "'");
        if (isItemValue(in) && !in.atNumericStart()) {
            e.args.push_back(in.identBinding()->value);
            in.next();
            return true;
        }
        if (!spec.positionals) in.errorHere(in.describe() + " is not allowed in " + spec.name);
        e.args.push_back(in.parseRValue());
        return true;
    }
    if (in.isSym('[') && spec.map != BlockSpec::Map::None) {
        readMapEntry(in, spec, item);
        return false;
    }
    if (spec.coefficients && in.isSym('<')) {
        readCoefficients(in, e);
        return true;
    }
    if (!spec.positionals || !atBareValue(in)) in.errorHere("unexpected " + in.describe() + " in " + spec.name);
    readBareValue(in, e);
    return true;
}

}  // namespace

sdl::ItemRef readBlockBody(Interpreter& in, const BlockSpec& spec, Kw kind) {
    Interpreter::NestGuard guard(in);  // sub-blocks nest too: pigment_pattern { pigment_pattern { ... } }
    return readBraced(in, spec, kind, in.loc());
}

sdl::ItemRef readBlock(Interpreter& in, const BlockSpec& spec) {
    const Kw kind = in.kw();
    const sdl::Loc at = in.loc();
    in.next();
    return readBraced(in, spec, kind, at);
}

// Textures written one after another are layers, each over the one before (POV-Ray 3.7 reference,
// "Layered Textures"): `#declare T = texture { A } texture { B };` declares one layered texture,
// as textures.inc does. They become one texture item whose bare entries are the layers in order.
sdl::ItemRef readTextureLayers(Interpreter& in, const BlockSpec& spec, sdl::ItemRef first) {
    auto layered = std::make_shared<Item>();
    layered->kind = Kw::texture;
    layered->loc = first->loc;
    auto addLayer = [&](sdl::ItemRef layer) {
        Entry e;
        e.loc = layer->loc;
        e.args.push_back(Value::item(std::move(layer)));
        layered->entries.push_back(std::move(e));
    };
    addLayer(std::move(first));
    while (in.peekRawKw(Kw::texture)) addLayer(readBlock(in, spec));
    setDepth(in, *layered);
    return layered;
}

void readBody(Interpreter& in, Item& item, const BlockSpec& spec, char terminator) {
    const sdl::Loc open = item.loc;
    for (;;) {
        if (in.isSym(terminator)) return setDepth(in, item);
        if (in.atEnd())
            in.error(open, std::string("'") + (terminator == ']' ? "[" : "{") + "' of '" +
                               std::string(sdl::keywordName(item.kind)) + "' is never closed (end of file reached)");
        if (in.isSym(',') || in.isSym(';')) {
            in.next();
            continue;
        }
        Entry e;
        e.loc = in.loc();
        if (readEntry(in, item, spec, e)) item.entries.push_back(std::move(e));
    }
}

}  // namespace rays::pov
