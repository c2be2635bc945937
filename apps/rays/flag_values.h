// The checks every numeric command-line value goes through, so that no flag takes NaN, an
// infinity, a number out of its type's range (saturated silently by strtod/strtoull) or trailing
// text: one parser for decimal numbers and CLI11 validators built on it.
#pragma once
#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>

#include "rays/math/vec3.h"

namespace rays::cli {

/// text as a finite decimal number ("0.5", "-3", "1e3"; not "nan", "inf", "0x10", "1e999", "5abc"),
/// or nothing.
std::optional<double> finiteNumber(const std::string& text);

/// finiteNumber(text), else throws Error "rays: error: FLAG: expected a finite number, got 'TEXT'".
double flagNumber(const std::string& text, const char* flag);

/// CLI11 check for a floating-point option: the value must be a finite decimal number (CLI11
/// itself takes "nan" and "inf", which pass CLI::Range).
CLI::Validator finiteNumberCheck();

/// CLI11 check for an unsigned 64-bit option (--seed): decimal digits only, at most 2^64 − 1
/// (strtoull saturates a larger number to 2^64 − 1 without a word).
CLI::Validator unsigned64Check();

/// "R,G,B" with three finite numbers from 0 to 1; throws Error "rays: error: FLAG takes R,G,B ..."
/// naming the flag and the text.
Vec3 flagColour(const std::string& text, const char* flag);

}  // namespace rays::cli
