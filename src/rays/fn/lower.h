// Expr → Ir with constant folding and inlining (compile's second pass).
#pragma once
#include <memory>
#include <span>
#include <vector>

#include "rays/fn/compile.h"
#include "rays/fn/ir.h"

namespace rays::fn {

/// The folded, inlined tree of the nodes `reach` marks (checkExpr's result).
Ir lowerExpr(const Expr& e, const std::vector<char>& reach, std::span<const std::shared_ptr<const Program>> callable,
             const CompileOptions& options);

/// The tree without the nodes its root no longer reaches (after folding), for inlining elsewhere.
std::shared_ptr<Ir> compactIr(const Ir& ir);

}  // namespace rays::fn
