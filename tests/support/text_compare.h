// Test support: token-by-token comparison of program text output with the course tolerance
// (numbers within max(0.002, 0.1 % of the expected value), integers ±1, other tokens equal).
// Header-only.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace rays::test {

/// One token of a text and the 1-based line it is on.
struct TextToken {
    std::string text;
    int line = 1;
};

/// True for characters that form a token of their own: { } ( ) [ ] , : ; =
inline bool isPunctToken(char c) {
    switch (c) {
        case '{': case '}': case '(': case ')': case '[': case ']':
        case ',': case ':': case ';': case '=':
            return true;
        default:
            return false;
    }
}

/// Splits text on whitespace; each punctuation character (isPunctToken) is a separate token.
inline std::vector<TextToken> tokenizeText(std::string_view text) {
    std::vector<TextToken> tokens;
    int line = 1;
    std::string cur;
    auto flush = [&] {
        if (!cur.empty()) tokens.push_back({cur, line});
        cur.clear();
    };
    for (char c : text) {
        if (c == '\n' || c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            flush();
            if (c == '\n') ++line;
        } else if (isPunctToken(c)) {
            flush();
            tokens.push_back({std::string(1, c), line});
        } else {
            cur.push_back(c);
        }
    }
    flush();
    return tokens;
}

/// True when s is a plain decimal number ([+-]digits[.digits][e[+-]digits], no nan/inf/hex);
/// then sets value, and isInteger when it has neither '.' nor an exponent.
inline bool parseNumber(std::string_view s, double& value, bool& isInteger) {
    size_t i = 0;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    size_t digits = 0;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i, ++digits;
    bool integer = true;
    if (i < s.size() && s[i] == '.') {
        integer = false;
        ++i;
        while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i, ++digits;
    }
    if (digits == 0) return false;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        integer = false;
        ++i;
        if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
        size_t expDigits = 0;
        while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i, ++expDigits;
        if (expDigits == 0) return false;
    }
    if (i != s.size()) return false;
    std::string_view body = s;
    if (!body.empty() && body[0] == '+') body.remove_prefix(1);  // from_chars rejects '+'
    double v = 0;
    const auto res = std::from_chars(body.data(), body.data() + body.size(), v);
    if (res.ec != std::errc() || res.ptr != body.data() + body.size()) return false;
    value = v;
    isInteger = integer;
    return true;
}

/// Largest |actual - expected| accepted for two numeric tokens (±1 when both are integers).
inline double numberTolerance(double expected, bool bothIntegers) {
    return bothIntegers ? 1.0 : std::max(0.002, 0.001 * std::fabs(expected));
}

/// True when the actual token matches the expected one: both numbers within tolerance, or equal.
inline bool tokensMatch(std::string_view expected, std::string_view actual) {
    double e = 0, a = 0;
    bool eInt = false, aInt = false;
    if (parseNumber(expected, e, eInt) && parseNumber(actual, a, aInt))
        return std::fabs(a - e) <= numberTolerance(e, eInt && aInt) + 1e-9;
    return expected == actual;
}

namespace detail {

inline std::string lineOf(std::string_view text, int line) {
    size_t start = 0;
    for (int l = 1; l < line; ++l) {
        const size_t nl = text.find('\n', start);
        if (nl == std::string_view::npos) return {};
        start = nl + 1;
    }
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string s(text.substr(start, end - start));
    if (!s.empty() && s.back() == '\r') s.pop_back();
    return s;
}

inline std::string quote(const std::string& s) { return "\"" + s + "\""; }

}  // namespace detail

/// Empty when `actual` matches `expected` token by token (tokensMatch); otherwise a description
/// of the first mismatch: token index, both tokens, their line numbers and both lines.
inline std::string compareText(std::string_view expected, std::string_view actual) {
    const auto exp = tokenizeText(expected);
    const auto act = tokenizeText(actual);
    const size_t n = std::min(exp.size(), act.size());
    for (size_t i = 0; i < n; ++i) {
        if (tokensMatch(exp[i].text, act[i].text)) continue;
        std::string msg = "first difference at token " + std::to_string(i + 1) + ": expected " +
                          detail::quote(exp[i].text) + " (line " + std::to_string(exp[i].line) +
                          "), got " + detail::quote(act[i].text) + " (line " +
                          std::to_string(act[i].line) + ")";
        double e = 0, a = 0;
        bool eInt = false, aInt = false;
        if (parseNumber(exp[i].text, e, eInt) && parseNumber(act[i].text, a, aInt)) {
            char buf[128];
            std::snprintf(buf, sizeof buf, "; numbers differ by %.6g, allowed %.6g", std::fabs(a - e),
                          numberTolerance(e, eInt && aInt));
            msg += buf;
        }
        msg += "\n  expected line " + std::to_string(exp[i].line) + ": " +
               detail::lineOf(expected, exp[i].line);
        msg += "\n  actual   line " + std::to_string(act[i].line) + ": " +
               detail::lineOf(actual, act[i].line);
        return msg;
    }
    if (exp.size() > act.size()) {
        const TextToken& t = exp[act.size()];
        return "actual output ends early: it has " + std::to_string(act.size()) +
               " tokens, expected " + std::to_string(exp.size()) + "; first missing token " +
               detail::quote(t.text) + " (expected line " + std::to_string(t.line) + ")" +
               "\n  expected line " + std::to_string(t.line) + ": " + detail::lineOf(expected, t.line);
    }
    if (act.size() > exp.size()) {
        const TextToken& t = act[exp.size()];
        return "actual output has extra text: it has " + std::to_string(act.size()) +
               " tokens, expected " + std::to_string(exp.size()) + "; first extra token " +
               detail::quote(t.text) + " (actual line " + std::to_string(t.line) + ")" +
               "\n  actual   line " + std::to_string(t.line) + ": " + detail::lineOf(actual, t.line);
    }
    return {};
}

/// The text with each line prefixed by its 1-based number ("  12| ..."), cut after maxLines lines.
inline std::string numberedText(std::string_view text, size_t maxLines = 200) {
    std::string out;
    size_t start = 0, line = 0;
    while (start < text.size()) {
        if (line == maxLines) {
            out += "   ...| (output cut after " + std::to_string(maxLines) + " lines)\n";
            break;
        }
        size_t end = text.find('\n', start);
        const bool last = end == std::string_view::npos;
        if (last) end = text.size();
        char num[32];
        std::snprintf(num, sizeof num, "%4zu| ", ++line);
        out += num;
        out.append(text.substr(start, end - start));
        out += '\n';
        start = end + 1;
    }
    if (text.empty()) out = "   (empty)\n";
    return out;
}

}  // namespace rays::test
