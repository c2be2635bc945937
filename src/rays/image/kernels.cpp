#include "rays/image/kernels.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "rays/error.h"
#include "rays/io/file_text.h"

namespace rays {
namespace {

[[noreturn]] void failSpec(const std::string& spec, const std::string& msg) {
    throw Error("rays: error: kernel '" + spec + "': " + msg);
}

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// A whole-string decimal number (no leading '+', no inf/nan, no hex); false otherwise.
bool parseNumber(const std::string& s, double& out) {
    if (s.empty() || s[0] == '+') return false;
    const char* end = s.data() + s.size();
    const auto [p, ec] = std::from_chars(s.data(), end, out, std::chars_format::general);
    return ec == std::errc() && p == end && std::isfinite(out);
}

// The N of box_blur_N, gaussian_blur_N, median_N: an odd positive integer up to maxSize.
int parseSize(const std::string& spec, const std::string& digits, int maxSize) {
    bool integer = !digits.empty();
    size_t start = digits.size() > 1 && digits[0] == '-' ? 1 : 0;
    for (size_t i = start; i < digits.size(); ++i)
        if (digits[i] < '0' || digits[i] > '9') integer = false;
    if (!integer || (start == 1 && digits.size() == 1))
        failSpec(spec, "the size must be an odd positive integer, got '" + digits + "'");
    if (start == 1) failSpec(spec, "the size must be odd and positive, got " + digits);
    // Strip leading zeros, then compare lengths to avoid overflow.
    size_t first = digits.find_first_not_of('0');
    const std::string sig = first == std::string::npos ? "0" : digits.substr(first);
    if (sig.size() > 9 || std::stol(sig) > maxSize)
        failSpec(spec, "the size must be at most " + std::to_string(maxSize) + ", got " + digits);
    const int n = std::stoi(sig);
    if (n <= 0 || n % 2 == 0) failSpec(spec, "the size must be odd and positive, got " + digits);
    return n;
}

KernelSpec fixed3x3(KernelKind kind, const std::string& text, std::vector<double> w, double divisor, bool absolute) {
    KernelSpec k;
    k.kind = kind;
    k.text = text;
    k.width = k.height = 3;
    for (double& v : w) v /= divisor;
    k.weights = std::move(w);
    k.absolute = absolute;
    return k;
}

}  // namespace

std::string validKernelNames() {
    return "box_blur_N, gaussian_blur_N, gaussian_blur_N:SIGMA, median_N (N odd and positive), "
           "edge_detect_1, edge_detect_2, sobel, sharpen, emboss, brighten_X, kernel:FILE";
}

std::vector<double> gaussianWeights(int n, double sigma) {
    std::vector<double> w(size_t(n > 0 ? n : 0));
    const int r = (n - 1) / 2;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        const double d = i - r;
        w[size_t(i)] = std::exp(-d * d / (2 * sigma * sigma));
        sum += w[size_t(i)];
    }
    for (double& v : w) v /= sum;
    return w;
}

bool isConvolution(const KernelSpec& k) {
    switch (k.kind) {
        case KernelKind::BoxBlur:
        case KernelKind::GaussianBlur:
        case KernelKind::EdgeDetect1:
        case KernelKind::EdgeDetect2:
        case KernelKind::Sharpen:
        case KernelKind::Emboss:
        case KernelKind::Custom: return true;
        case KernelKind::Brighten:
        case KernelKind::Sobel:
        case KernelKind::Median: return false;
    }
    return false;
}

KernelSpec parseKernelSpec(const std::string& spec) {
    if (spec == "edge_detect_1")
        return fixed3x3(KernelKind::EdgeDetect1, spec, {0, -1, 0, -1, 4, -1, 0, -1, 0}, 4, true);
    if (spec == "edge_detect_2")
        return fixed3x3(KernelKind::EdgeDetect2, spec, {-1, -1, -1, -1, 8, -1, -1, -1, -1}, 8, true);
    if (spec == "sharpen") return fixed3x3(KernelKind::Sharpen, spec, {0, -1, 0, -1, 5, -1, 0, -1, 0}, 1, false);
    if (spec == "emboss") return fixed3x3(KernelKind::Emboss, spec, {-2, -1, 0, -1, 1, 1, 0, 1, 2}, 1, false);
    if (spec == "sobel") {
        KernelSpec k;
        k.kind = KernelKind::Sobel;
        k.text = spec;
        k.width = k.height = 3;
        return k;
    }
    if (startsWith(spec, "box_blur_")) {
        KernelSpec k;
        k.kind = KernelKind::BoxBlur;
        k.text = spec;
        const int n = parseSize(spec, spec.substr(9), kMaxKernelSize);
        k.width = k.height = n;
        k.weights.assign(size_t(n) * size_t(n), 1.0 / (double(n) * double(n)));
        return k;
    }
    if (startsWith(spec, "gaussian_blur_")) {
        KernelSpec k;
        k.kind = KernelKind::GaussianBlur;
        k.text = spec;
        const std::string rest = spec.substr(14);
        const size_t colon = rest.find(':');
        const int n = parseSize(spec, rest.substr(0, colon), kMaxKernelSize);
        k.width = k.height = n;
        k.sigma = n / 6.0;
        if (colon != std::string::npos) {
            const std::string s = rest.substr(colon + 1);
            if (!parseNumber(s, k.sigma) || k.sigma <= 0)
                failSpec(spec, "sigma must be a positive number, got '" + s + "'");
        }
        const std::vector<double> g = gaussianWeights(n, k.sigma);
        k.weights.resize(size_t(n) * size_t(n));
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) k.weights[size_t(y) * size_t(n) + size_t(x)] = g[size_t(y)] * g[size_t(x)];
        return k;
    }
    if (startsWith(spec, "median_")) {
        KernelSpec k;
        k.kind = KernelKind::Median;
        k.text = spec;
        const int n = parseSize(spec, spec.substr(7), kMaxMedianSize);
        k.width = k.height = n;
        return k;
    }
    if (startsWith(spec, "brighten_")) {
        KernelSpec k;
        k.kind = KernelKind::Brighten;
        k.text = spec;
        const std::string s = spec.substr(9);
        if (!parseNumber(s, k.factor) || k.factor < 0)
            failSpec(spec, "the factor must be a non-negative number, got '" + s + "'");
        return k;
    }
    if (startsWith(spec, "kernel:")) {
        const std::string path = spec.substr(7);
        if (path.empty()) failSpec(spec, "missing file name (kernel:FILE)");
        KernelSpec k = loadKernelFile(path);
        k.text = spec;
        return k;
    }
    throw Error("rays: error: unknown kernel '" + spec + "' (valid: " + validKernelNames() + ")");
}

std::vector<KernelSpec> parseKernelList(const std::vector<std::string>& specs) {
    std::vector<KernelSpec> out;
    out.reserve(specs.size());
    for (const std::string& s : specs) out.push_back(parseKernelSpec(s));
    return out;
}

std::vector<std::string> splitKernelList(const std::string& commaSeparated) {
    std::vector<std::string> out;
    size_t start = 0;
    for (;;) {
        const size_t comma = commaSeparated.find(',', start);
        const std::string item = commaSeparated.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (item.empty())
            throw Error("rays: error: empty kernel in list '" + commaSeparated + "' (use KERNEL[,KERNEL...])");
        out.push_back(item);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

KernelSpec parseKernelText(const std::string& text, const std::string& file) {
    KernelSpec k;
    k.kind = KernelKind::Custom;
    k.text = "kernel:" + file;
    k.file = file;
    double divisor = 1;
    int divisorLine = 0;
    bool absolute = false;
    int cols = 0, firstRowLine = 0, lastRowLine = 0, rows = 0;
    std::vector<double> values;

    std::string source = text;  // as scene files: a byte-order mark skipped, lone CRs end lines
    source.erase(0, makeSourceText(source.data(), source.size()));
    std::istringstream in(source);
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const size_t hash = line.find('#');
        if (hash != std::string::npos) line.resize(hash);
        // Tokens with their 1-based columns.
        std::vector<std::pair<std::string, int>> tokens;
        for (size_t i = 0; i < line.size();) {
            if (line[i] == ' ' || line[i] == '\t') {
                ++i;
                continue;
            }
            const size_t j = line.find_first_of(" \t", i);
            const size_t end = j == std::string::npos ? line.size() : j;
            tokens.emplace_back(line.substr(i, end - i), int(i) + 1);
            i = end;
        }
        if (tokens.empty()) continue;
        const SourceLoc at{file, lineNo, tokens[0].second};
        if (tokens[0].first == "divisor") {
            if (divisorLine) fail(at, "'divisor' given twice (first on line " + std::to_string(divisorLine) + ")");
            if (tokens.size() != 2) fail(at, "expected 'divisor D' with one number D");
            const SourceLoc numAt{file, lineNo, tokens[1].second};
            if (!parseNumber(tokens[1].first, divisor)) fail(numAt, "expected a number, got '" + tokens[1].first + "'");
            if (divisor == 0) fail(numAt, "the divisor must not be zero");
            divisorLine = lineNo;
            continue;
        }
        if (tokens[0].first == "absolute") {
            if (tokens.size() != 1) fail({file, lineNo, tokens[1].second}, "unexpected '" + tokens[1].first + "' after 'absolute'");
            absolute = true;
            continue;
        }
        for (const auto& [word, col] : tokens) {
            double v = 0;
            if (!parseNumber(word, v))
                fail({file, lineNo, col}, "expected a number, 'divisor D' or 'absolute', got '" + word + "'");
            values.push_back(v);
        }
        if (rows == 0) {
            cols = int(tokens.size());
            firstRowLine = lineNo;
            if (cols % 2 == 0)
                fail(at, "kernel rows have " + std::to_string(cols) + " values; the width must be odd");
            if (cols > kMaxKernelSize)
                fail(at, "kernel rows have " + std::to_string(cols) + " values; at most " +
                             std::to_string(kMaxKernelSize) + " allowed");
        } else if (int(tokens.size()) != cols) {
            fail(at, "ragged kernel: this row has " + std::to_string(tokens.size()) + " values but the first row (line " +
                         std::to_string(firstRowLine) + ") has " + std::to_string(cols));
        }
        ++rows;
        lastRowLine = lineNo;
        if (rows > kMaxKernelSize)
            fail(at, "kernel has more than " + std::to_string(kMaxKernelSize) + " rows");
    }
    if (rows == 0) failFile(file, "kernel file has no rows of numbers");
    if (rows % 2 == 0)
        fail({file, lastRowLine, 1}, "kernel has " + std::to_string(rows) + " rows; the number of rows must be odd");
    for (double& v : values) v /= divisor;
    k.width = cols;
    k.height = rows;
    k.weights = std::move(values);
    k.absolute = absolute;
    return k;
}

KernelSpec loadKernelFile(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) failFile(path, "cannot read kernel file: is a directory");
    const FileText text(path, TextForm::Bytes, kMaxKernelFileBytes);
    if (text.status() == FileText::Status::CannotOpen)
        failFile(path, std::string("cannot read kernel file: ") + std::strerror(errno));
    if (text.status() == FileText::Status::CannotRead) failFile(path, "cannot read kernel file");
    if (text.status() == FileText::Status::TooLarge)
        failFile(path, "kernel file is larger than " + FileText::describe(kMaxKernelFileBytes));
    return parseKernelText(std::string(text.text()), path);
}

}  // namespace rays
