// Small text rules shared by the command-line readers.
#pragma once
#include <algorithm>
#include <cctype>
#include <string>

namespace rays::cli {

/// s in lower case (ASCII).
inline std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

/// True for a non-empty run of decimal digits and nothing else ("640"; not "-1", "+3" or "1e3").
inline bool isDigits(const std::string& s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace rays::cli
