#include "pov_options.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "rays/error.h"

namespace rays::cli {
namespace {

namespace fs = std::filesystem;

// What a key does. The first group is acted on; Quiet keys are checked and dropped (display,
// messages, bounding, quality: nothing Rays does depends on them); Warned keys are checked and,
// when their value asks for something Rays does not do, warned about once.
enum class Key {
    InputFileName, OutputFileName, Width, Height,
    Antialias, AntialiasThreshold, AntialiasDepth, SamplingMethod, Jitter, JitterAmount,
    LibraryPath, Declare,
    Clock, InitialFrame, FinalFrame, InitialClock, FinalClock, SubsetStartFrame, SubsetEndFrame, FrameStep, CyclicAnimation,
    StartRow, EndRow, StartColumn, EndColumn,
    OutputToFile, OutputFileType, OutputAlpha, BitsPerColor, Compression, WorkThreads, ContinueTrace,
    Quiet, Warned,
};

// How a value is checked.
enum class Kind { Bool, Int, Float, Text };

struct KeyInfo {
    const char* name;  ///< POV-Ray's spelling
    Key key;
    Kind kind;
    const char* unsupported = nullptr;  ///< Warned keys: what Rays does instead
};

// POV-Ray 3.7's INI keys (reference 3.2).
const KeyInfo kKeys[] = {
    {"Input_File_Name", Key::InputFileName, Kind::Text},
    {"Output_File_Name", Key::OutputFileName, Kind::Text},
    {"Width", Key::Width, Kind::Int},
    {"Height", Key::Height, Kind::Int},
    {"Antialias", Key::Antialias, Kind::Bool},
    {"Antialias_Threshold", Key::AntialiasThreshold, Kind::Float},
    {"Antialias_Depth", Key::AntialiasDepth, Kind::Int},
    {"Sampling_Method", Key::SamplingMethod, Kind::Int},
    {"Jitter", Key::Jitter, Kind::Bool},
    {"Jitter_Amount", Key::JitterAmount, Kind::Float},
    {"Library_Path", Key::LibraryPath, Kind::Text},
    {"Declare", Key::Declare, Kind::Text},
    {"Clock", Key::Clock, Kind::Float},
    {"Initial_Frame", Key::InitialFrame, Kind::Int},
    {"Final_Frame", Key::FinalFrame, Kind::Int},
    {"Initial_Clock", Key::InitialClock, Kind::Float},
    {"Final_Clock", Key::FinalClock, Kind::Float},
    {"Subset_Start_Frame", Key::SubsetStartFrame, Kind::Float},
    {"Subset_End_Frame", Key::SubsetEndFrame, Kind::Float},
    {"Frame_Step", Key::FrameStep, Kind::Int},
    {"Cyclic_Animation", Key::CyclicAnimation, Kind::Bool},
    {"Start_Row", Key::StartRow, Kind::Float},
    {"End_Row", Key::EndRow, Kind::Float},
    {"Start_Column", Key::StartColumn, Kind::Float},
    {"End_Column", Key::EndColumn, Kind::Float},
    {"Output_to_File", Key::OutputToFile, Kind::Bool},
    {"Output_File_Type", Key::OutputFileType, Kind::Text},
    {"Output_Alpha", Key::OutputAlpha, Kind::Bool},
    {"Bits_Per_Color", Key::BitsPerColor, Kind::Int},
    {"Compression", Key::Compression, Kind::Int},
    {"Work_Threads", Key::WorkThreads, Kind::Int},
    {"Continue_Trace", Key::ContinueTrace, Kind::Bool},
    // Accepted, not acted on.
    {"Display", Key::Quiet, Kind::Bool},
    {"Video_Mode", Key::Quiet, Kind::Text},
    {"Palette", Key::Quiet, Kind::Text},
    {"Display_Gamma", Key::Quiet, Kind::Text},
    {"Pause_When_Done", Key::Quiet, Kind::Bool},
    {"Verbose", Key::Quiet, Kind::Bool},
    {"Draw_Vistas", Key::Quiet, Kind::Bool},
    {"Preview_Start_Size", Key::Quiet, Kind::Int},
    {"Preview_End_Size", Key::Quiet, Kind::Int},
    {"Max_Image_Buffer_Memory", Key::Quiet, Kind::Int},
    {"Buffer_Output", Key::Quiet, Kind::Bool},
    {"Buffer_Size", Key::Quiet, Kind::Int},
    {"Test_Abort", Key::Quiet, Kind::Bool},
    {"Test_Abort_Count", Key::Quiet, Kind::Int},
    {"Odd_Field", Key::Quiet, Kind::Bool},
    {"Antialias_Gamma", Key::Quiet, Kind::Float},
    {"Quality", Key::Quiet, Kind::Int},
    {"Bounding", Key::Quiet, Kind::Bool},
    {"Bounding_Threshold", Key::Quiet, Kind::Int},
    {"Bounding_Method", Key::Quiet, Kind::Int},
    {"Light_Buffer", Key::Quiet, Kind::Bool},
    {"Vista_Buffer", Key::Quiet, Kind::Bool},
    {"Remove_Bounds", Key::Quiet, Kind::Bool},
    {"Split_Unions", Key::Quiet, Kind::Bool},
    {"BSP_MaxDepth", Key::Quiet, Kind::Int},
    {"BSP_BaseAccessCost", Key::Quiet, Kind::Float},
    {"BSP_ChildAccessCost", Key::Quiet, Kind::Float},
    {"BSP_IsectCost", Key::Quiet, Kind::Float},
    {"BSP_MissChance", Key::Quiet, Kind::Float},
    {"Render_Block_Size", Key::Quiet, Kind::Int},
    {"Render_Pattern", Key::Quiet, Kind::Int},
    {"Render_Block_Step", Key::Quiet, Kind::Int},
    {"High_Reproducibility", Key::Quiet, Kind::Bool},
    {"Radiosity_File_Name", Key::Quiet, Kind::Text},
    {"Radiosity_From_File", Key::Quiet, Kind::Bool},
    {"Radiosity_To_File", Key::Quiet, Kind::Bool},
    {"Radiosity_Vain_Pretrace", Key::Quiet, Kind::Bool},
    {"Debug_Console", Key::Quiet, Kind::Bool},
    {"Fatal_Console", Key::Quiet, Kind::Bool},
    {"Render_Console", Key::Quiet, Kind::Bool},
    {"Statistic_Console", Key::Quiet, Kind::Bool},
    {"Warning_Console", Key::Quiet, Kind::Bool},
    {"All_Console", Key::Quiet, Kind::Bool},
    {"Append_File", Key::Quiet, Kind::Bool},
    {"Warning_Level", Key::Quiet, Kind::Int},
    {"Pre_Scene_Return", Key::Quiet, Kind::Text},
    {"Pre_Frame_Return", Key::Quiet, Kind::Text},
    {"Post_Scene_Return", Key::Quiet, Kind::Text},
    {"Post_Frame_Return", Key::Quiet, Kind::Text},
    {"User_Abort_Return", Key::Quiet, Kind::Text},
    {"Fatal_Error_Return", Key::Quiet, Kind::Text},
    // Accepted with a warning when they ask for something.
    {"Field_Render", Key::Warned, Kind::Bool, "field rendering is not supported; whole frames are rendered"},
    {"Dither", Key::Warned, Kind::Bool, "dithering is not supported"},
    {"Dither_Method", Key::Warned, Kind::Text, "dithering is not supported"},
    {"File_Gamma", Key::Warned, Kind::Text, "the output gamma is not adjustable"},
    {"Include_Header", Key::Warned, Kind::Text, "an include header is not supported yet"},
    {"Version", Key::Warned, Kind::Float, "the initial language version is not settable yet"},
    {"Create_Ini", Key::Warned, Kind::Text, "no INI file is written"},
    {"Debug_File", Key::Warned, Kind::Text, "messages are not copied to files"},
    {"Fatal_File", Key::Warned, Kind::Text, "messages are not copied to files"},
    {"Render_File", Key::Warned, Kind::Text, "messages are not copied to files"},
    {"Statistic_File", Key::Warned, Kind::Text, "messages are not copied to files"},
    {"Warning_File", Key::Warned, Kind::Text, "messages are not copied to files"},
    {"All_File", Key::Warned, Kind::Text, "messages are not copied to files"},
    {"Pre_Scene_Command", Key::Warned, Kind::Text, "Rays runs no shell commands"},
    {"Pre_Frame_Command", Key::Warned, Kind::Text, "Rays runs no shell commands"},
    {"Post_Scene_Command", Key::Warned, Kind::Text, "Rays runs no shell commands"},
    {"Post_Frame_Command", Key::Warned, Kind::Text, "Rays runs no shell commands"},
    {"User_Abort_Command", Key::Warned, Kind::Text, "Rays runs no shell commands"},
    {"Fatal_Error_Command", Key::Warned, Kind::Text, "Rays runs no shell commands"},
};

// How a switch's text after its letters is used.
enum class Form {
    Value,   ///< +Xvalue or -Xvalue: the key gets the value (a value is required)
    Toggle,  ///< +X on, -X off (nothing may follow)
    OnValue, ///< +X on, -X off; a value after the letters goes to `second` (+A0.3, +J0.5, +FN16, +GAfile)
};

struct SwitchInfo {
    const char* letters;  ///< upper case
    const char* key;      ///< INI key set by the sign or the value
    Form form;
    const char* second = nullptr;  ///< OnValue: the key that gets the value
};

// POV-Ray 3.7's switches (reference 3.2); the longest matching letters win (+KFF before +KF).
const SwitchInfo kSwitches[] = {
    {"I", "Input_File_Name", Form::Value},
    {"O", "Output_File_Name", Form::Value},
    {"W", "Width", Form::Value},
    {"H", "Height", Form::Value},
    {"A", "Antialias", Form::OnValue, "Antialias_Threshold"},
    {"AM", "Sampling_Method", Form::Value},
    {"AG", "Antialias_Gamma", Form::Value},
    {"R", "Antialias_Depth", Form::Value},
    {"J", "Jitter", Form::OnValue, "Jitter_Amount"},
    {"L", "Library_Path", Form::Value},
    {"K", "Clock", Form::Value},
    {"KFI", "Initial_Frame", Form::Value},
    {"KFF", "Final_Frame", Form::Value},
    {"KI", "Initial_Clock", Form::Value},
    {"KF", "Final_Clock", Form::Value},
    {"KC", "Cyclic_Animation", Form::Toggle},
    {"SF", "Subset_Start_Frame", Form::Value},
    {"EF", "Subset_End_Frame", Form::Value},
    {"STP", "Frame_Step", Form::Value},
    {"SR", "Start_Row", Form::Value},
    {"ER", "End_Row", Form::Value},
    {"SC", "Start_Column", Form::Value},
    {"EC", "End_Column", Form::Value},
    {"F", "Output_to_File", Form::OnValue, "Output_File_Type"},
    {"UA", "Output_Alpha", Form::Toggle},
    {"UF", "Field_Render", Form::Toggle},
    {"UO", "Odd_Field", Form::Toggle},
    {"C", "Continue_Trace", Form::Toggle},
    {"D", "Display", Form::OnValue, "Video_Mode"},
    {"V", "Verbose", Form::Toggle},
    {"P", "Pause_When_Done", Form::Toggle},
    {"X", "Test_Abort", Form::OnValue, "Test_Abort_Count"},
    {"Q", "Quality", Form::Value},
    {"WT", "Work_Threads", Form::Value},
    {"WL", "Warning_Level", Form::Value},
    {"MB", "Bounding", Form::OnValue, "Bounding_Threshold"},
    {"MI", "Max_Image_Buffer_Memory", Form::Value},
    {"MV", "Version", Form::Value},
    {"BM", "Bounding_Method", Form::Value},
    {"BS", "Render_Block_Size", Form::Value},
    {"RP", "Render_Pattern", Form::Value},
    {"RS", "Render_Block_Step", Form::Value},
    {"UD", "Draw_Vistas", Form::Toggle},
    {"UL", "Light_Buffer", Form::Toggle},
    {"UV", "Vista_Buffer", Form::Toggle},
    {"UR", "Remove_Bounds", Form::Toggle},
    {"SU", "Split_Unions", Form::Toggle},
    {"SP", "Preview_Start_Size", Form::Value},
    {"EP", "Preview_End_Size", Form::Value},
    {"GA", "All_Console", Form::OnValue, "All_File"},
    {"GD", "Debug_Console", Form::OnValue, "Debug_File"},
    {"GF", "Fatal_Console", Form::OnValue, "Fatal_File"},
    {"GR", "Render_Console", Form::OnValue, "Render_File"},
    {"GS", "Statistic_Console", Form::OnValue, "Statistic_File"},
    {"GW", "Warning_Console", Form::OnValue, "Warning_File"},
    {"GP", "Append_File", Form::Toggle},
    {"GI", "Create_Ini", Form::Value},
    {"HI", "Include_Header", Form::Value},
    {"HR", "High_Reproducibility", Form::Toggle},
    {"TH", "Dither", Form::OnValue, "Dither_Method"},
    {"RF", "Radiosity_File_Name", Form::Value},
    {"RFI", "Radiosity_From_File", Form::Toggle},
    {"RFO", "Radiosity_To_File", Form::Toggle},
    {"RVP", "Radiosity_Vain_Pretrace", Form::Toggle},
};

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string trim(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t\r\n");
    if (a == std::string::npos) return {};
    const size_t b = s.find_last_not_of(" \t\r\n");
    return s.substr(a, b - a + 1);
}

bool endsWithNoCase(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && lower(s.substr(s.size() - suffix.size())) == suffix;
}

// A value wrapped in matching single or double quotes loses them (+I"my file.pov").
std::string unquote(const std::string& v) {
    if (v.size() >= 2 && (v.front() == '"' || v.front() == '\'') && v.back() == v.front()) return v.substr(1, v.size() - 2);
    return v;
}

const KeyInfo* findKey(const std::string& name) {
    const std::string l = lower(name);
    for (const KeyInfo& k : kKeys)
        if (lower(k.name) == l) return &k;
    return nullptr;
}

// The switch whose letters are the longest prefix of `body` (the switch without its sign).
const SwitchInfo* findSwitch(const std::string& body) {
    const SwitchInfo* best = nullptr;
    size_t bestLength = 0;
    for (const SwitchInfo& s : kSwitches) {
        const std::string letters = s.letters;
        if (letters.size() <= bestLength || body.size() < letters.size()) continue;
        bool match = true;
        for (size_t i = 0; i < letters.size(); ++i)
            if (std::toupper(static_cast<unsigned char>(body[i])) != letters[i]) match = false;
        if (match) {
            best = &s;
            bestLength = letters.size();
        }
    }
    return best;
}

bool hasExtension(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    const size_t dot = path.find_last_of('.');
    return dot != std::string::npos && (slash == std::string::npos || dot > slash + 1);
}

std::string folderOf(const std::string& path) {
    return fs::path(path).parent_path().string();
}

bool exists(const std::string& path) {
    std::error_code ec;
    return fs::exists(path, ec);
}

// A relative name from an INI file: as POV-Ray 3.7 does, relative to the current folder; when no
// such file exists there but one does next to the INI file, that one (so `rays dir/scene.ini`
// works from anywhere).
std::string besideIni(const std::string& name, const std::vector<std::string>& iniStack) {
    if (name.empty() || name[0] == '/' || iniStack.empty() || exists(name)) return name;
    const std::string folder = folderOf(iniStack.back());
    if (folder.empty()) return name;
    const std::string beside = folder + "/" + name;
    return exists(beside) ? beside : name;
}

bool isIdentifier(const std::string& s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    return std::all_of(s.begin(), s.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

bool parseDouble(const std::string& text, double& out) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtod(text.c_str(), &end);
    return *end == '\0' && errno == 0 && std::isfinite(out);
}

bool parseLong(const std::string& text, long& out) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtol(text.c_str(), &end, 10);
    return *end == '\0' && errno == 0;
}

// INI booleans (reference 3.2): true, yes, on, 1 and false, no, off, 0, any case.
bool parseBool(const std::string& text, bool& out) {
    const std::string l = lower(text);
    if (l == "on" || l == "true" || l == "yes" || l == "1") return out = true, true;
    if (l == "off" || l == "false" || l == "no" || l == "0") return out = false, true;
    return false;
}

// Splits an INI line of switches into words; quotes keep blanks inside a word, ';' outside quotes
// starts a comment.
std::vector<std::string> switchWords(const std::string& line) {
    std::vector<std::string> words;
    std::string word;
    char quote = 0;
    for (char c : line) {
        if (quote) {
            word += c;
            if (c == quote) quote = 0;
        } else if (c == '"' || c == '\'') {
            word += c;
            quote = c;
        } else if (c == ';') {
            break;
        } else if (c == ' ' || c == '\t') {
            if (!word.empty()) words.push_back(word);
            word.clear();
        } else {
            word += c;
        }
    }
    if (!word.empty()) words.push_back(word);
    return words;
}

// The line without its comment: ';' starts a comment unless inside quotes that open at the start
// of the text, after '=' or after a blank (an apostrophe inside a word opens nothing).
std::string withoutComment(const std::string& line) {
    char quote = 0;
    for (size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quote) {
            if (c == quote) quote = 0;
        } else if ((c == '"' || c == '\'') && (i == 0 || line[i - 1] == '=' || line[i - 1] == ' ' || line[i - 1] == '\t')) {
            quote = c;
        } else if (c == ';') {
            return line.substr(0, i);
        }
    }
    return line;
}

// "name[Section]" → name and section (empty when there is none).
void splitSection(const std::string& arg, std::string& name, std::string& section) {
    const size_t open = arg.find('[');
    if (!arg.empty() && arg.back() == ']' && open != std::string::npos) {
        name = trim(arg.substr(0, open));
        section = trim(arg.substr(open + 1, arg.size() - open - 2));
    } else {
        name = arg;
        section.clear();
    }
}

}  // namespace

bool isPovSwitch(const std::string& arg) {
    return arg.size() >= 2 && (arg[0] == '+' || arg[0] == '-') && std::isalpha(static_cast<unsigned char>(arg[1]));
}

bool isPovSetting(const std::string& arg) {
    const size_t eq = arg.find('=');
    return eq != std::string::npos && isIdentifier(trim(arg.substr(0, eq)));
}

bool isIniArgument(const std::string& arg) {
    if (arg.empty() || arg[0] == '+' || arg[0] == '-' || isPovSetting(arg)) return false;
    return endsWithNoCase(arg, ".ini") || (arg.back() == ']' && arg.find('[') != std::string::npos);
}

bool isSceneArgument(const std::string& arg) {
    return !arg.empty() && arg[0] != '+' && arg[0] != '-' && !isPovSetting(arg) && endsWithNoCase(arg, ".pov");
}

PovOptionReader::PovOptionReader(PovOptions& options, Warn warn) : o_(options), warn_(std::move(warn)) {}

void PovOptionReader::bad(const Where& where, const std::string& message) const {
    if (!where.file.empty()) throw Error("rays: error: " + where.file + ":" + std::to_string(where.line) + ": " + message);
    throw Error("rays: error: " + where.text + ": " + message);
}

void PovOptionReader::warnOnce(const std::string& key, const std::string& message, const Where& where) {
    if (!warned_.insert(lower(key)).second || !warn_) return;
    if (!where.file.empty())
        warn_(where.file + ":" + std::to_string(where.line) + ": warning: " + message);
    else
        warn_("rays: warning: " + where.text + ": " + message);
}

void PovOptionReader::readArgument(const std::string& arg) {
    const Where where{"", 0, arg};
    if (isPovSwitch(arg)) return readSwitch(arg, where);
    if (isPovSetting(arg)) {
        const size_t eq = arg.find('=');
        return set(trim(arg.substr(0, eq)), unquote(trim(arg.substr(eq + 1))), where);
    }
    if (isSceneArgument(arg)) {
        o_.inputFile = resolveScene(arg, where);
        o_.sceneFromOptions = true;
        return;
    }
    std::string name, section;
    splitSection(arg, name, section);
    readIniFile(name, section, "on the command line");
}

void PovOptionReader::readSwitch(const std::string& sw, const Where& where) {
    const bool plus = sw[0] == '+';
    const std::string body = sw.substr(1);
    const SwitchInfo* s = findSwitch(body);
    if (!s) return warnOnce(sw, "unknown option '" + sw + "'", where);
    const std::string rest = unquote(body.substr(std::string(s->letters).size()));
    switch (s->form) {
        case Form::Value:
            if (rest.empty()) bad(where, std::string("'") + sw[0] + s->letters + "' needs a value (" + s->key + ")");
            return set(s->key, rest, where);
        case Form::Toggle:
            if (!rest.empty()) return warnOnce(sw, "unknown option '" + sw + "'", where);
            return set(s->key, plus ? "on" : "off", where);
        case Form::OnValue:
            // The sign first, then the value: +J0 sets jitter on, then its amount 0 turns it off.
            set(s->key, plus ? "on" : "off", where);
            if (!rest.empty()) set(s->second, rest, where);
            return;
    }
}

std::string PovOptionReader::resolveScene(const std::string& name, const Where& where) const {
    if (name == "-") bad(where, "reading the scene from standard input (+I-) is not supported");
    std::string path = hasExtension(name) ? name : name + ".pov";  // ".pov is assumed" (reference 3.2.5.2)
    return where.file.empty() ? path : besideIni(path, iniStack_);
}

void PovOptionReader::set(const std::string& keyName, const std::string& value, const Where& where) {
    const KeyInfo* info = findKey(keyName);
    if (!info) return warnOnce(keyName, "unknown option '" + keyName + "'", where);
    const std::string name = info->name;
    bool flag = false;
    long integer = 0;
    double number = 0;
    switch (info->kind) {
        case Kind::Bool:
            if (!parseBool(value, flag))
                bad(where, name + " must be on or off (true/false, yes/no, 1/0), got '" + value + "'");
            break;
        case Kind::Int:
            if (!parseLong(value, integer))
                bad(where, name + (info->key == Key::Width || info->key == Key::Height || info->key == Key::FrameStep
                                       ? " must be a positive integer"
                                       : " must be a whole number") +
                               ", got '" + value + "'");
            break;
        case Kind::Float:
            if (!parseDouble(value, number)) bad(where, name + " must be a number, got '" + value + "'");
            break;
        case Kind::Text:
            if (value.empty()) bad(where, name + " needs a value");
            break;
    }
    auto atLeast = [&](long lo, const std::string& rule) {
        if (integer < lo) bad(where, name + " must be " + rule + ", got '" + value + "'");
    };
    auto inRange = [&](long lo, long hi) {
        if (integer < lo || integer > hi)
            bad(where, name + " must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got '" + value + "'");
    };
    // Start_Row … End_Column and the subset frames: a fraction below 1, else a whole number.
    auto bound = [&](const char* unit) {
        if (number < 0 || (number >= 1 && number != std::floor(number)))
            bad(where, name + " must be a fraction below 1 or a " + unit + " number, got '" + value + "'");
    };
    AnimationOptions& a = o_.animation;
    PovAntialias& aa = o_.antialias;
    switch (info->key) {
        case Key::InputFileName:
            o_.inputFile = resolveScene(value, where);
            o_.sceneFromOptions = true;
            break;
        case Key::OutputFileName:
            if (value == "-") bad(where, "writing the image to standard output (-) is not supported");
            o_.outputFile = value;
            o_.outputExact = false;
            break;
        case Key::Width:
            atLeast(1, "a positive integer");
            o_.width = int(std::min(integer, 1L << 30));
            break;
        case Key::Height:
            atLeast(1, "a positive integer");
            o_.height = int(std::min(integer, 1L << 30));
            break;
        case Key::Antialias: aa.on = flag, aa.given = true; break;
        case Key::AntialiasThreshold:
            if (number < 0) bad(where, name + " must be 0 or more, got '" + value + "'");
            aa.threshold = number, aa.given = true;
            break;
        case Key::AntialiasDepth: inRange(1, 9), aa.depth = int(integer), aa.given = true; break;
        case Key::SamplingMethod: inRange(1, 2), aa.method = int(integer), aa.given = true; break;
        case Key::Jitter: aa.jitter = flag, aa.given = true; break;
        case Key::JitterAmount:
            aa.jitterAmount = number, aa.given = true;
            if (number <= 0) aa.jitter = false;  // "If n.n <= 0 aa-jitter is set off"
            break;
        case Key::LibraryPath: addLibraryPath(value); break;
        case Key::Declare: {
            const size_t eq = value.find('=');
            const std::string id = eq == std::string::npos ? value : trim(value.substr(0, eq));
            const std::string v = eq == std::string::npos ? std::string() : trim(value.substr(eq + 1));
            double ignored = 0;
            const bool isString = v.size() >= 2 && v.front() == '"' && v.back() == '"';
            if (!isIdentifier(id) || !(isString || parseDouble(v, ignored)))
                bad(where, "Declare needs NAME=VALUE with VALUE a number or a string in double quotes, got '" + value + "'");
            auto same = std::find_if(o_.declares.begin(), o_.declares.end(), [&](const sdl::Declare& d) { return d.name == id; });
            if (same != o_.declares.end()) same->value = v;
            else o_.declares.push_back({id, v});
            break;
        }
        case Key::Clock: a.clock = number, a.clockGiven = true; break;
        case Key::InitialFrame: atLeast(0, "a whole number, 0 or more"), a.initialFrame = int(std::min(integer, 1L << 30)); break;
        case Key::FinalFrame: atLeast(-1, "a whole number, -1 or more"), a.finalFrame = int(std::min(integer, 1L << 30)); break;
        case Key::InitialClock: a.initialClock = number; break;
        case Key::FinalClock: a.finalClock = number; break;
        case Key::SubsetStartFrame: bound("frame"), a.subsetStart = {true, std::min(number, 1e9)}; break;
        case Key::SubsetEndFrame: bound("frame"), a.subsetEnd = {true, std::min(number, 1e9)}; break;
        case Key::FrameStep: atLeast(1, "a positive integer"), a.frameStep = int(std::min(integer, 1L << 30)); break;
        case Key::CyclicAnimation: a.cyclic = flag; break;
        case Key::StartRow: bound("row"), o_.startRow = {true, number}; break;
        case Key::EndRow: bound("row"), o_.endRow = {true, number}; break;
        case Key::StartColumn: bound("column"), o_.startColumn = {true, number}; break;
        case Key::EndColumn: bound("column"), o_.endColumn = {true, number}; break;
        case Key::OutputToFile:
            if (!flag) warnOnce(name, "Output_to_File=off is not supported: Rays always writes the image", where);
            break;
        case Key::OutputFileType: {
            const char type = char(std::toupper(static_cast<unsigned char>(value[0])));
            const std::string depth = value.substr(1);
            if (type == 'E' || type == 'H')
                bad(where, std::string(type == 'E' ? "OpenEXR" : "Radiance HDR") +
                               " output is not supported (Output_File_Type N, J, P, T, C, B or S)");
            if (std::string("NPTCJBS").find(type) == std::string::npos)
                bad(where, "unknown Output_File_Type '" + value + "' (use N PNG, J JPEG, P PPM, T or C Targa, B BMP, S system)");
            o_.fileType = type;
            if (!depth.empty()) set("Bits_Per_Color", depth, where);
            break;
        }
        case Key::OutputAlpha:
            if (flag) warnOnce(name, "Output_Alpha is not supported: the image has no alpha channel", where);
            break;
        case Key::BitsPerColor:
            inRange(1, 16);
            if (integer > 8) warnOnce(name, "only 8 bits per colour are written, not " + value, where);
            break;
        case Key::Compression:
            // POV-Ray: 0 or 1 mean its default quality 85; values outside 0..100 are clipped.
            o_.jpegQuality = integer <= 1 ? 85 : int(std::min(integer, 100L));
            break;
        case Key::WorkThreads: inRange(0, 1024), o_.threads = int(integer); break;
        case Key::ContinueTrace: o_.continueTrace = flag; break;
        case Key::Quiet: break;
        case Key::Warned: {
            // Asking for nothing (off, false, 0) needs no warning.
            bool off = false;
            if (info->kind == Kind::Bool ? !flag : (parseBool(value, off) && !off)) break;
            if (info->name == std::string("File_Gamma") && lower(value) == "srgb") break;
            warnOnce(name, name + " is not acted on: " + info->unsupported, where);
            break;
        }
    }
}

void PovOptionReader::readIniFile(const std::string& path, const std::string& section, const std::string& from) {
    std::string name = hasExtension(path) ? path : path + ".ini";  // ".ini is assumed" (tutorial 2.2.8.2)
    name = besideIni(name, iniStack_);
    const std::string origin = from.empty() ? std::string() : " (named " + from + ")";
    if (iniStack_.size() >= 10)
        throw Error("rays: error: " + name + ": INI files nested more than 10 deep" + origin);
    std::ifstream in(name, std::ios::binary);
    std::error_code ec;
    if (!in || fs::is_directory(name, ec)) throw Error("rays: error: cannot open INI file '" + name + "'" + origin);
    std::ostringstream text;
    text << in.rdbuf();
    iniStack_.push_back(name);
    readIniText(text.str(), name, section);
    iniStack_.pop_back();
}

void PovOptionReader::readIniText(const std::string& text, const std::string& path, const std::string& section) {
    // POV-Ray 3.7 (observed) reads the unlabelled top part, then the parts labelled [section]; its
    // manual says a named section replaces the top part, but the program reads both.
    bool reading = true, found = false;
    std::istringstream lines(text);
    int lineNo = 0;
    for (std::string raw; std::getline(lines, raw);) {
        ++lineNo;
        const Where where{path, lineNo, ""};
        const std::string line = trim(withoutComment(raw));
        if (line.empty()) continue;
        if (line[0] == '[') {
            const size_t close = line.find(']');
            if (close == std::string::npos) bad(where, "section label without ']': '" + line + "'");
            reading = !section.empty() && lower(trim(line.substr(1, close - 1))) == lower(section);
            found = found || reading;
            continue;
        }
        if (!reading) continue;
        if (line[0] == '+' || line[0] == '-') {
            for (const std::string& word : switchWords(line)) {
                const Where at{path, lineNo, word};
                if (isPovSwitch(word)) readSwitch(word, at);
                else warnOnce(word, "unknown option '" + word + "'", at);
            }
        } else if (line.find('=') != std::string::npos) {
            const size_t eq = line.find('=');
            set(trim(line.substr(0, eq)), unquote(trim(line.substr(eq + 1))), where);
        } else {
            std::string name, sub;
            splitSection(line, name, sub);
            readIniFile(unquote(name), sub, path + ":" + std::to_string(lineNo));
        }
    }
    if (!section.empty() && !found && warn_)
        warn_(path + ": warning: no section [" + section + "]; only the top part was read");
}

void PovOptionReader::setOutputExact(const std::string& path) {
    o_.outputFile = path;
    o_.outputExact = true;
}

void PovOptionReader::setWidth(int width) { o_.width = width; }
void PovOptionReader::setHeight(int height) { o_.height = height; }

void PovOptionReader::setScene(const std::string& path) {
    o_.inputFile = path;
    o_.sceneFromOptions = true;
}

void PovOptionReader::setThreads(int threads) { o_.threads = threads; }

void PovOptionReader::addLibraryPath(const std::string& path) {
    std::string p = path;
    while (p.size() > 1 && p.back() == '/') p.pop_back();  // "no final path separator"
    // "If you specify the exact same path twice it is only counted once" (reference 3.2.5.4).
    if (std::find(o_.libraryPaths.begin(), o_.libraryPaths.end(), p) == o_.libraryPaths.end()) o_.libraryPaths.push_back(p);
}

void PovOptionReader::setResume(bool on) { o_.continueTrace = on; }

void PovOptionReader::setJpegQuality(int quality) { o_.jpegQuality = quality; }

void PovOptionReader::renderChoseAntialias() { o_.antialias.given = false; }

PovOptions readPovArguments(const std::vector<std::string>& args, PovOptionReader::Warn warn) {
    PovOptions o;
    PovOptionReader reader(o, std::move(warn));
    for (const std::string& a : args) reader.readArgument(a);
    return o;
}

}  // namespace rays::cli
