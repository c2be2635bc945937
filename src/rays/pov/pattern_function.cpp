#include "rays/pov/pattern_function.h"

#include <memory>

#include "rays/pattern/pigment.h"
#include "rays/pov/pigment_compile.h"

namespace rays::pov {

namespace {

// What a pattern or pigment function evaluates: its own table, the item's node in it.
struct CompiledPattern {
    pattern::PigmentTable table;
    int node = -1;
};

// The pattern's value at (x, y, z) (measured with POV-Ray 3.7: the wave and the transformations
// apply, the colour map does not, checker gives 0 or 1, hexagon 0, 1 or 2).
void evalPatternValue(const void* data, const double* in, double* out) {
    const auto& c = *static_cast<const CompiledPattern*>(data);
    out[0] = c.table.value(c.node, Vec3{in[0], in[1], in[2]});
}

// The pigment's colour at (x, y, z): red, green, blue, filter, transmit.
void evalPigmentColor(const void* data, const double* in, double* out) {
    const auto& c = *static_cast<const CompiledPattern*>(data);
    const pattern::Rgbft col = c.table.evaluate(c.node, Vec3{in[0], in[1], in[2]});
    out[0] = col.rgb.x;
    out[1] = col.rgb.y;
    out[2] = col.rgb.z;
    out[3] = col.filter;
    out[4] = col.transmit;
}

}  // namespace

fn::HostFunction compilePatternFunction(const Item& item, bool pigment, NotRendered& notes,
                                        const std::function<std::string(const std::string&)>& findFile,
                                        const PatternObjectBuilder& buildObject, int noiseGenerator) {
    auto compiled = std::make_shared<CompiledPattern>();
    {
        PigmentCompiler compiler(compiled->table, notes);
        compiler.imageFiles().setFileFinder(findFile);
        compiler.densityFiles().setFileFinder(findFile);
        compiler.setObjectBuilder(buildObject);
        compiled->node = compiler.compileFunction(item);
    }
    if (compiled->node < 0) return {};
    for (pattern::PigmentNode& n : compiled->table.nodes)
        if (n.params.noiseGenerator == 0) n.params.noiseGenerator = noiseGenerator;
    fn::HostFunction h;
    h.fn = pigment ? evalPigmentColor : evalPatternValue;
    h.data = compiled.get();
    h.inputs = 3;
    h.outputs = pigment ? 5 : 1;
    h.keep = std::move(compiled);
    return h;
}

}  // namespace rays::pov
