// Notes of what a POV-Ray scene asks for that Rays does not render yet: one warning per kind of
// feature, at its first use in something rendered (`FILE:LINE:COL: warning: not rendered yet:
// isosurface`), or an error with --strict. Declarations never reach here unless used.
#pragma once
#include <functional>
#include <set>
#include <string>

#include "rays/sdl/source_file.h"

namespace rays::pov {

class NotRendered {
public:
    /// where(loc) formats "file:line:col"; warn receives each warning line.
    NotRendered(std::function<std::string(const sdl::Loc&)> where, std::function<void(const std::string&)> warn,
                bool strict)
        : where_(std::move(where)), warn_(std::move(warn)), strict_(strict) {}

    /// Notes feature at loc (what: "isosurface", "pigment pattern wood", ...); detail is added to
    /// the first note only (what Rays does instead, e.g. "(left out)").
    void note(const std::string& what, const sdl::Loc& at, const std::string& detail = "");
    size_t count() const { return seen_.size(); }
    /// How many of the kinds noted left something out of the scene ("(left out)": a shape or a
    /// CSG object), as against drawing it otherwise (a pattern in its mean colour, ...).
    size_t leftOut() const { return leftOut_; }
    /// "file:line:col" of a location (for the builder's errors).
    std::string where(const sdl::Loc& at) const { return where_(at); }

private:
    std::function<std::string(const sdl::Loc&)> where_;
    std::function<void(const std::string&)> warn_;
    bool strict_;
    std::set<std::string> seen_;
    size_t leftOut_ = 0;
};

}  // namespace rays::pov
