// Checks of a function body against POV-Ray's rules and limits (compile's first pass).
#pragma once
#include <memory>
#include <span>
#include <vector>

#include "rays/fn/expr.h"
#include "rays/fn/program.h"

namespace rays::fn {

/// Which nodes the root reaches (1) — the only ones later passes read. Throws CompileError for a
/// malformed tree, a wrong argument count, an undeclared or later callee, a wrong member, a
/// parameter or iteration-variable number out of range, and POV-Ray's limits; sets callDepth to
/// 1 + the deepest chain of calls below.
std::vector<char> checkExpr(const Expr& e, int params, std::span<const std::shared_ptr<const Program>> callable,
                            int& callDepth);

}  // namespace rays::fn
