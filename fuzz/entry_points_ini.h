// The INI files' fuzzing entry point: POV-Ray INI files as the program reads them
// (apps/rays/pov_options.h, code of the program rather than the library, hence its own header).
// Shared by fuzz/fuzz_ini.cpp and tests/regressions_test.cpp, like entry_points.h.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

#include "../apps/rays/pov_options.h"
#include "entry_points.h"

namespace rays::fuzz {

/// True when an INI input names a special file (/dev/stdin, /proc/self/fd/0, a FIFO in /sys …): an
/// INI file may name any file as a nested INI file, and reading a terminal or a pipe would wait
/// for input, which is not a finding.
inline bool namesSpecialFiles(std::string_view text) {
    for (const std::string_view word : {"dev", "proc", "sys"})
        if (text.find(word) != std::string_view::npos) return true;
    return false;
}

/// INI files: the bytes go to ini/in.ini (nested INI files it names are looked for beside it: only
/// itself is there) and PovOptionReader::readIniFile reads it, with no section, [Sec] or [anim]
/// by the input's size. Warnings are discarded.
inline void fuzzIni(const uint8_t* data, size_t size) {
    const std::string_view text = asText(data, size);
    if (namesSpecialFiles(text)) return;
    const std::string path = scratchSubdir("ini") + "/in.ini";
    writeScratchFile(path, text);
    cli::PovOptions options;
    cli::PovOptionReader reader(options, [](const std::string&) {});
    static const char* const kSections[] = {"", "Sec", "anim"};
    try {
        reader.readIniFile(path, kSections[size % 3]);
    } catch (const Error&) {
    }
}

}  // namespace rays::fuzz
