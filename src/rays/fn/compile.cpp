// The compiler's entry: check (fn/check.h), lower (fn/lower.h), emit (fn/ir.h: emitProgram).
#include "rays/fn/compile.h"

#include <string>

#include "rays/fn/check.h"
#include "rays/fn/ir.h"
#include "rays/fn/lower.h"

namespace rays::fn {

std::shared_ptr<const Program> compile(const Expr& body, int params,
                                       std::span<const std::shared_ptr<const Program>> callable,
                                       const CompileOptions& options) {
    int callDepth = 1;
    const std::vector<char> reach = checkExpr(body, params, callable, callDepth);
    Ir ir = lowerExpr(body, reach, callable, options);
    auto p = std::make_shared<Program>();
    p->params = params;
    p->callDepth = callDepth;
    p->callees = ir.callees;
    p->hosts = ir.hosts;
    p->callsHost = !ir.hosts.empty();
    for (const auto& c : ir.callees) p->callsHost = p->callsHost || c->callsHost;
    emitProgram(ir, *p, options.branches);
    std::shared_ptr<Ir> small = compactIr(ir);
    if (static_cast<int>(small->nodes.size()) <= options.inlineLimit) p->inlineBody = std::move(small);
    return p;
}

std::shared_ptr<const Program> hostProgram(const HostFunction& host) {
    if (!host.fn || host.inputs < 1 || host.inputs > kMaxParams || host.outputs < 1 || host.outputs > 5)
        throw CompileError("host function needs 1 to " + std::to_string(kMaxParams) + " inputs and 1 to 5 outputs", 0);
    Ir ir;
    ir.hosts.push_back(host);
    for (int i = 0; i < host.inputs; ++i) {
        IrNode n;
        n.op = irOp(Op::Param);
        n.id = i;
        n.cost = 0;
        ir.nodes.push_back(n);
        ir.kids.push_back(i);
    }
    IrNode call;
    call.op = IrOp::Host;
    call.id = 0;
    call.member = Member::X;
    call.first = 0;
    call.count = host.inputs;
    ir.nodes.push_back(call);
    ir.root = host.inputs;
    auto p = std::make_shared<Program>();
    p->params = host.inputs;
    p->outputs = host.outputs;
    p->hosts = ir.hosts;
    p->hostWrapper = true;
    p->callsHost = true;
    emitProgram(ir, *p, true);
    return p;
}

}  // namespace rays::fn
