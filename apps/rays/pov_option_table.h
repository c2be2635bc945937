// POV-Ray 3.7's option catalogue (reference 3.2 "Command-Line and INI-File Options"): every INI
// key with the kind of value it takes and what Rays does with it, and every switch with the key
// it sets. Used by PovOptionReader (pov_options.h).
#pragma once
#include <string>

namespace rays::cli::pov {

/// What a key does. The first group is acted on; Quiet keys are checked and dropped (display,
/// messages, bounding, quality: nothing Rays does depends on them); Warned keys are checked and,
/// when their value asks for something Rays does not do, warned about once.
enum class Key {
    InputFileName, OutputFileName, Width, Height,
    Antialias, AntialiasThreshold, AntialiasDepth, AntialiasGamma, SamplingMethod, Jitter, JitterAmount,
    LibraryPath, Declare, Version,
    Clock, InitialFrame, FinalFrame, InitialClock, FinalClock, SubsetStartFrame, SubsetEndFrame, FrameStep, CyclicAnimation,
    StartRow, EndRow, StartColumn, EndColumn,
    OutputToFile, OutputFileType, OutputAlpha, BitsPerColor, FileGamma, Compression, WorkThreads, ContinueTrace,
    IncludeHeader,
    Quiet, Warned,
};

/// How a value is checked.
enum class Kind { Bool, Int, Float, Text };

/// One INI key.
struct KeyInfo {
    const char* name;  ///< POV-Ray's spelling
    Key key;
    Kind kind;
    const char* unsupported = nullptr;  ///< Warned keys: what Rays does instead
};

/// How a switch's text after its letters is used.
enum class Form {
    Value,   ///< +Xvalue or -Xvalue: the key gets the value (a value is required)
    Toggle,  ///< +X on, -X off (nothing may follow)
    OnValue, ///< +X on, -X off; a value after the letters goes to `second` (+A0.3, +J0.5, +FN16, +GAfile)
};

/// One switch.
struct SwitchInfo {
    const char* letters;  ///< upper case
    const char* key;      ///< INI key set by the sign or the value
    Form form;
    const char* second = nullptr;  ///< OnValue: the key that gets the value
};

/// The key named `name` (any case), or nullptr.
const KeyInfo* findKey(const std::string& name);

/// The switch whose letters are the longest prefix of `body` (the switch without its sign, any
/// case), or nullptr.
const SwitchInfo* findSwitch(const std::string& body);

}  // namespace rays::cli::pov
