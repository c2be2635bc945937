#include "rays/pov/pov_host.h"

#include "rays/pov/grammar.h"
#include "rays/pov/item_values.h"

namespace rays::pov {

using sdl::Kw;

bool PovHost::startsItem(Kw k) const { return itemSpec(k) != nullptr; }

sdl::ItemRef PovHost::readItem(sdl::Interpreter& in) {
    const BlockSpec* spec = itemSpec(in.kw());
    if (!spec) in.errorHere("expected a scene item, found " + in.describe());
    return readBlock(in, *spec);
}

void PovHost::topLevel(sdl::Interpreter& in, const sdl::ItemRef& item) {
    if (item->kind == Kw::global_settings) {
        // srgb colours read later in the file need the working gamma.
        for (const sdl::Entry& e : item->entries)
            if (e.key == uint16_t(Kw::assumed_gamma) && !e.args.empty()) in.setAssumedGamma(e.args[0].c[0]);
    }
    out_.items.push_back(ParsedScene::Top{item, defaults_, defaults_ ? defaults_->size() : 0, in.version()});
}

// Each #default adds to the defaults in force (POV-Ray 3.7 reference, "Default Directive"): the
// default texture is one list of texture entries applied in order. Items read so far keep their
// prefix of it: the list is appended to, never copied (a loop of #default and objects stays linear).
void PovHost::setDefault(sdl::Interpreter&, const sdl::ItemRef& item) {
    if (!defaults_) defaults_ = std::make_shared<std::vector<sdl::Entry>>();
    sdl::Entry e;
    e.key = uint16_t(item->kind);
    e.loc = item->loc;
    e.args.push_back(sdl::Value::item(item));
    defaults_->push_back(std::move(e));
}

PovHost::TraceResult PovHost::trace(const sdl::Item&, const double*, const double*) { return {}; }
int PovHost::inside(const sdl::Item&, const double*) { return -1; }
bool PovHost::extent(const sdl::Item&, double*, double*) { return false; }

std::array<double, 12> PovHost::transformMatrix(const sdl::Item& t) {
    const Transform m = transformOf(t);
    std::array<double, 12> out{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) out[size_t(r * 4 + c)] = m.m[r][c];
    return out;
}

}  // namespace rays::pov
