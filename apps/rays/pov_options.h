// POV-Ray 3.7's command-line switches and INI files (reference 3.2 "Command-Line and INI-File
// Options", tutorial 2.2.8 "Setting POV-Ray Options"), read into PovOptions: a plain record of
// what was asked. Settings apply in the order they are read: a later one wins, library paths and
// declarations accumulate. Options Rays does not act on are accepted (some with a warning), unknown
// ones are warned about once, malformed values are errors naming the file and line.
#pragma once
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "frame_plan.h"
#include "rays/sdl/options.h"

namespace rays::cli {

namespace pov {
struct KeyInfo;  // pov_option_table.h
}

/// POV-Ray's anti-aliasing options (reference 3.2.8.7).
struct PovAntialias {
    bool given = false;        ///< set by a POV-Ray option after any of render's own --spp, --aa, -ss
    bool on = false;           ///< Antialias, +A / -A
    double threshold = 0.3;    ///< Antialias_Threshold, +An.n
    int depth = 3;             ///< Antialias_Depth, +Rn (1 to 9)
    double gamma = 2.5;        ///< Antialias_Gamma, +AGn.n: colours are compared as linear^(1/gamma)
    int method = 1;            ///< Sampling_Method, +AMn (1 adaptive, 2 adaptive recursive)
    bool jitter = true;        ///< Jitter, +J / -J
    double jitterAmount = 1;   ///< Jitter_Amount, +Jn.n (0 or less turns jitter off)
};

struct PovOptions {
    std::string inputFile;     ///< Input_File_Name, +I or a .pov argument (".pov" added when it has no extension)
    std::string outputFile;    ///< Output_File_Name, +O or render's -o; empty: not given
    bool outputExact = false;  ///< outputFile came from render's -o: used as written
    /// Output_to_File, +F / -F: off renders without writing the image (a later -o turns it on).
    bool outputToFile = true;
    int bitsPerColor = 8;      ///< Bits_Per_Color, +FN16: above 8, a PNG is written with 16 bits per channel
    double fileGamma = 0;      ///< File_Gamma: 0 sRGB (the default), else a power-law gamma
    std::string includeHeader; ///< Include_Header, +HI: read before the scene (empty: none)
    int width = -1, height = -1;  ///< Width, Height, +W, +H (and render's W H, -W, -H); -1: not given
    PovAntialias antialias;
    AnimationOptions animation;
    PovBound startRow, endRow, startColumn, endColumn;  ///< Start_Row … End_Column, +SR +ER +SC +EC
    char fileType = 0;         ///< Output_File_Type, +Fx: 'N' 'P' 'T' 'C' 'J' 'B' 'S'; 0: not given (PNG)
    int jpegQuality = 0;       ///< Compression (0 or 1 mean POV-Ray's 85) or --jpeg-quality; 0: not given
    std::vector<std::string> libraryPaths;  ///< Library_Path, +L, render's --library: in order, each once
    std::vector<sdl::Declare> declares;     ///< Declare=NAME=VALUE, in order
    double version = 0;        ///< Version=, +MV: the initial #version; 0: not given
    int threads = -1;          ///< Work_Threads, +WT (0: all cores); -1: not given
    bool continueTrace = false;  ///< Continue_Trace, +C (and render's --resume): keep frames already written
};

/// Reads POV-Ray options into a PovOptions, one argument, setting or INI file at a time.
class PovOptionReader {
public:
    using Warn = std::function<void(const std::string&)>;
    /// warn receives each warning line ("scene.ini:3: warning: unknown option 'Foo'").
    PovOptionReader(PovOptions& options, Warn warn);

    /// One command-line argument: a +/- switch, KEY=VALUE, a scene (NAME.pov) or an INI file
    /// (NAME, NAME.ini, NAME[Section]; ".ini" is added when NAME has no extension), read in place.
    void readArgument(const std::string& arg);
    /// Reads an INI file in place: its unlabelled top part, then (when section is not empty) the
    /// parts labelled [section] (labels compare without case). `from` names where it was asked for.
    void readIniFile(const std::string& path, const std::string& section, const std::string& from = "");

    /// Render's own options that POV-Ray options also set, applied in command-line order.
    void setOutputExact(const std::string& path);           ///< -o PATH
    void setWidth(int width);                               ///< render's W or -W
    void setHeight(int height);                             ///< render's H or -H
    void setScene(const std::string& path);                 ///< render's SCENE or --scene
    void setThreads(int threads);                           ///< --threads
    void addLibraryPath(const std::string& path);           ///< --library
    void setResume(bool on);                                ///< --resume
    void setJpegQuality(int quality);                       ///< --jpeg-quality
    void renderChoseAntialias();                            ///< --spp, --aa or -ss: Rays' own AA wins until a later POV-Ray AA option

    /// Where a setting was read, for messages.
    struct Where {
        std::string file;  ///< INI file; empty: the command line
        int line = 0;
        std::string text;  ///< the switch or setting as written (for command-line messages)
    };

private:
    struct Value;
    void readSwitch(const std::string& sw, const Where& where);
    void set(const std::string& key, const std::string& value, const Where& where);
    /// KEY=VALUE (text holds an '='): set with the trimmed key and the trimmed, unquoted value.
    void setKeyValue(const std::string& text, const Where& where);
    static Value readValue(const pov::KeyInfo& info, const std::string& text, const Where& where);
    bool setAnimation(const Value& v);
    bool setAntialias(const Value& v);
    bool setOutput(const Value& v);
    void setFileType(const Value& v);
    void setFileGamma(const Value& v);
    void setDeclare(const Value& v);
    void setOther(const Value& v);
    void readIniText(const std::string& text, const std::string& path, const std::string& section);
    void warnOnce(const std::string& key, const std::string& message, const Where& where);
    std::string resolveScene(const std::string& name, const Where& where) const;

    PovOptions& o_;
    Warn warn_;
    std::set<std::string> warned_;        ///< keys already warned about
    std::vector<std::string> iniStack_;   ///< INI files being read (for nesting and relative names)
    size_t iniFilesRead_ = 0;             ///< INI files read so far (each reading counts)
    size_t iniBytesRead_ = 0;             ///< and their bytes
};

/// The options of these arguments read in order (a convenience for tests and simple callers).
PovOptions readPovArguments(const std::vector<std::string>& args, PovOptionReader::Warn warn);

/// True for an argument written as a POV-Ray switch: '+' or '-' and a letter ("+W640", "-D").
bool isPovSwitch(const std::string& arg);
/// True for KEY=VALUE with KEY an identifier ("Width=640", "Declare=N=1").
bool isPovSetting(const std::string& arg);
/// True for an INI file argument: NAME.ini, or anything ending in [Section] (no leading '-' or '+').
bool isIniArgument(const std::string& arg);
/// True for a scene argument: NAME.pov (any case).
bool isSceneArgument(const std::string& arg);

}  // namespace rays::cli
