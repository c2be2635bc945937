// Outcome: a value or the message of a scene-language error. The language's pure functions
// (pov_strings, pov_random, pov_datetime) know no source location; the parser that calls them
// turns a message into "FILE:LINE:COL: error: message" with rays::fail.
#pragma once
#include <string>
#include <utility>

namespace rays::sdl {

template <class T>
struct Outcome {
    T value{};          ///< meaningful only when ok()
    std::string error;  ///< POV-Ray's message, e.g. "Illegal parameters in substr."; empty when ok

    bool ok() const { return error.empty(); }
    /// A failed outcome carrying msg.
    static Outcome failure(std::string msg) { return Outcome{T{}, std::move(msg)}; }
};

}  // namespace rays::sdl
