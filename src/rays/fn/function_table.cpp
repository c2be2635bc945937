#include "rays/fn/function_table.h"

namespace rays::fn {

int FunctionTable::addFloat(const Expr& body, int params, const CompileOptions& options) {
    programs_.push_back(compile(body, params, programs_, options));
    return size() - 1;
}

int FunctionTable::addHost(const HostFunction& host) {
    programs_.push_back(hostProgram(host));
    return size() - 1;
}

Scratch FunctionTable::makeScratch() const {
    Scratch s;
    for (const auto& p : programs_) s.fit(*p);
    return s;
}

}  // namespace rays::fn
