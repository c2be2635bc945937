// POV-Ray switches and INI files (apps/rays/pov_options.cpp) and what they make of a render job
// (apps/rays/pov_settings.cpp), tested in-process: every switch and key, booleans, sections,
// nested INI files, relative scene names, ordering, warnings (once, with file and line) and errors
// (file and line), anti-aliasing mapping, output names and the whole-image check.
//
// rays_tests links rays_core only (the app's sources are not a library), so these sources are
// compiled into this test directly.
#include "../apps/rays/pov_option_table.cpp"
#include "../apps/rays/pov_options.cpp"
#include "../apps/rays/pov_settings.cpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <array>
#include <string>
#include <vector>

#include "rays/error.h"
#include "support/files.h"
#include "support/process.h"

namespace fs = std::filesystem;
using rays::Error;
using rays::cli::PovOptionReader;
using rays::cli::PovOptions;
using rays::test::TempDir;
using rays::test::writeFile;

namespace { namespace RAYS_TEST_UNIT {

/// Reads args in order; collects the warnings.
struct Read {
    PovOptions o;
    std::vector<std::string> warnings;
};
Read readArgs(const std::vector<std::string>& args) {
    Read r;
    r.o = rays::cli::readPovArguments(args, [&](const std::string& w) { r.warnings.push_back(w); });
    return r;
}

/// The message of the Error that reading args throws ("" when none is thrown).
std::string errorOf(const std::vector<std::string>& args) {
    try {
        readArgs(args);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

/// Changes the working directory for one test and restores it.
class InDirectory {
public:
    explicit InDirectory(const fs::path& dir) : previous_(fs::current_path()) { fs::current_path(dir); }
    ~InDirectory() { fs::current_path(previous_); }

private:
    fs::path previous_;
};

// ---- switches --------------------------------------------------------------------------------

TEST(PovOptionsSwitch, SizeWithEitherSignAndAnyCase) {
    EXPECT_EQ(readArgs({"+W640", "+H480"}).o.width, 640);
    EXPECT_EQ(readArgs({"+W640", "+H480"}).o.height, 480);
    EXPECT_EQ(readArgs({"-W320"}).o.width, 320);  // values: either sign
    EXPECT_EQ(readArgs({"+h100"}).o.height, 100);  // any case
    EXPECT_EQ(readArgs({}).o.width, -1);  // not given
}

TEST(PovOptionsSwitch, AntialiasSwitches) {
    auto aa = [](std::vector<std::string> args) { return readArgs(args).o.antialias; };
    EXPECT_FALSE(aa({}).given);
    EXPECT_TRUE(aa({"+A"}).given);
    EXPECT_TRUE(aa({"+A"}).on);
    EXPECT_DOUBLE_EQ(aa({"+A"}).threshold, 0.3);
    EXPECT_TRUE(aa({"+A0.1"}).on);
    EXPECT_DOUBLE_EQ(aa({"+A0.1"}).threshold, 0.1);
    EXPECT_FALSE(aa({"+A", "-A"}).on);
    EXPECT_FALSE(aa({"-A0.2"}).on);
    EXPECT_DOUBLE_EQ(aa({"-A0.2"}).threshold, 0.2);  // off, threshold kept for later
    EXPECT_DOUBLE_EQ(aa({"-A0.2", "+A"}).threshold, 0.2);  // "+A: threshold 0.3 or previous amount"
    EXPECT_EQ(aa({"+AM2"}).method, 2);
    EXPECT_EQ(aa({"+R4"}).depth, 4);
    EXPECT_TRUE(aa({}).jitter);
    EXPECT_FALSE(aa({"-J"}).jitter);
    EXPECT_TRUE(aa({"-J", "+J"}).jitter);
    EXPECT_DOUBLE_EQ(aa({"+J0.5"}).jitterAmount, 0.5);
    EXPECT_FALSE(aa({"+J0"}).jitter);  // "If n.n <= 0 aa-jitter is set off"
    EXPECT_DOUBLE_EQ(aa({}).gamma, 2.5);  // Antialias_Gamma's default (POV-Ray 3.7's change log)
    EXPECT_DOUBLE_EQ(aa({"+AG2.2"}).gamma, 2.2);
    EXPECT_FALSE(aa({"+AG2.2"}).given);  // the gamma alone does not choose the sampling
    EXPECT_DOUBLE_EQ(aa({"Antialias_Gamma=1.8"}).gamma, 1.8);
}

TEST(PovOptionsSwitch, FilesAndLibraryPaths) {
    EXPECT_EQ(readArgs({"+Iscene.pov"}).o.inputFile, "scene.pov");
    EXPECT_EQ(readArgs({"+Iscene"}).o.inputFile, "scene.pov");  // ".pov is assumed"
    EXPECT_EQ(readArgs({"+I\"my file.pov\""}).o.inputFile, "my file.pov");
    EXPECT_EQ(readArgs({"+I'file\"s.pov'"}).o.inputFile, "file\"s.pov");
    EXPECT_EQ(readArgs({"scene.pov"}).o.inputFile, "scene.pov");  // a .pov argument is the scene
    EXPECT_EQ(readArgs({"+Oout.png"}).o.outputFile, "out.png");
    EXPECT_FALSE(readArgs({"+Oout.png"}).o.outputExact);
    // In order; a trailing '/' dropped; the same path counted once (reference 3.2.5.4).
    EXPECT_EQ(readArgs({"+L/a", "+L/b/", "+L/a", "Library_Path=rel"}).o.libraryPaths,
              (std::vector<std::string>{"/a", "/b", "rel"}));
}

TEST(PovOptionsSwitch, AnimationSwitches) {
    const PovOptions o = readArgs({"+K0.5", "+KFI2", "+KFF30", "+KI0.25", "+KF2", "+KC", "+SF3", "+EF0.5", "+STP2"}).o;
    EXPECT_TRUE(o.animation.clockGiven);
    EXPECT_DOUBLE_EQ(o.animation.clock, 0.5);
    EXPECT_EQ(o.animation.initialFrame, 2);
    EXPECT_EQ(o.animation.finalFrame, 30);
    EXPECT_DOUBLE_EQ(o.animation.initialClock, 0.25);
    EXPECT_DOUBLE_EQ(o.animation.finalClock, 2);
    EXPECT_TRUE(o.animation.cyclic);
    EXPECT_TRUE(o.animation.subsetStart.given);
    EXPECT_DOUBLE_EQ(o.animation.subsetStart.value, 3);
    EXPECT_DOUBLE_EQ(o.animation.subsetEnd.value, 0.5);
    EXPECT_EQ(o.animation.frameStep, 2);
    EXPECT_FALSE(readArgs({"+KC", "-KC"}).o.animation.cyclic);
    EXPECT_FALSE(readArgs({}).o.animation.clockGiven);
    EXPECT_EQ(readArgs({}).o.animation.finalFrame, -1);
}

TEST(PovOptionsSwitch, RegionSwitches) {
    const PovOptions o = readArgs({"+SR0.25", "+ER100", "+SC1", "+EC0.75"}).o;
    EXPECT_TRUE(o.startRow.given);
    EXPECT_DOUBLE_EQ(o.startRow.value, 0.25);
    EXPECT_DOUBLE_EQ(o.endRow.value, 100);
    EXPECT_DOUBLE_EQ(o.startColumn.value, 1);
    EXPECT_DOUBLE_EQ(o.endColumn.value, 0.75);
    EXPECT_NE(errorOf({"+SR2.5"}).find("Start_Row must be a fraction below 1 or a row number, got '2.5'"), std::string::npos);
}

TEST(PovOptionsSwitch, OutputTypeThreadsResumeAndDeclare) {
    EXPECT_EQ(readArgs({"+FN"}).o.fileType, 'N');
    EXPECT_EQ(readArgs({"+FJ"}).o.fileType, 'J');
    EXPECT_EQ(readArgs({"+Fp"}).o.fileType, 'P');
    EXPECT_EQ(readArgs({"+FT"}).o.fileType, 'T');
    EXPECT_EQ(readArgs({"Output_File_Type=C"}).o.fileType, 'C');
    EXPECT_EQ(readArgs({"+FB"}).o.fileType, 'B');
    EXPECT_EQ(readArgs({"+FS"}).o.fileType, 'S');
    EXPECT_NE(errorOf({"+FE"}).find("OpenEXR output is not supported"), std::string::npos);
    EXPECT_NE(errorOf({"+FX"}).find("unknown Output_File_Type 'X'"), std::string::npos);
    EXPECT_EQ(readArgs({"+WT3"}).o.threads, 3);
    EXPECT_EQ(readArgs({"Work_Threads=2"}).o.threads, 2);
    EXPECT_EQ(readArgs({}).o.threads, -1);
    EXPECT_TRUE(readArgs({"+C"}).o.continueTrace);
    EXPECT_FALSE(readArgs({"+C", "-C"}).o.continueTrace);
    EXPECT_EQ(readArgs({"Compression=50"}).o.jpegQuality, 50);
    EXPECT_EQ(readArgs({"Compression=1"}).o.jpegQuality, 85);  // POV-Ray's default quality
    const PovOptions d = readArgs({"Declare=Rad=0", "Declare=Name=\"str\"", "Declare=Rad=1e-3"}).o;
    ASSERT_EQ(d.declares.size(), 2u);
    EXPECT_EQ(d.declares[0].name, "Rad");
    EXPECT_EQ(d.declares[0].value, "1e-3");  // the later declaration of a name wins
    EXPECT_EQ(d.declares[1].value, "\"str\"");
    // Version= and +MV set the initial #version; POV-Ray reads numbers below 1 as 1.0.
    EXPECT_EQ(readArgs({}).o.version, 0.0);
    EXPECT_EQ(readArgs({"+MV3.5"}).o.version, 3.5);
    EXPECT_EQ(readArgs({"Version=0.5"}).o.version, 1.0);
    EXPECT_TRUE(readArgs({"Version=3.1"}).warnings.empty());
    EXPECT_NE(errorOf({"+MVabc"}).find("Version must be a number"), std::string::npos);
}

TEST(PovOptionsSwitch, HarmlessOptionsAreAcceptedSilently) {
    const Read r = readArgs({"+D", "-D", "+D0T", "+V", "-V", "+P", "-P", "+Q9", "+GA", "-GA", "+GD", "+GW", "+MB25",
                             "-MB", "+X", "+X100", "+UD", "+UL", "+UV", "+UR", "+SU", "+BM2", "+BS32", "+RP3", "+RS2",
                             "+WL5", "+MI128", "+SP16", "+EP2", "+HR", "+AG2.5", "-UA", "-UF", "+GP", "Verbose=on",
                             "Display=off", "Quality=11", "Pause_When_Done=no", "Bounding_Threshold=3"});
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    EXPECT_FALSE(r.o.antialias.on);
}

TEST(PovOptionsSwitch, OptionsThatChangeTheOutputWarnOnce) {
    const Read r = readArgs({"+UA", "+UA", "+FN16", "-F", "+GAall.log", "Post_Frame_Command=zip %o", "+UF", "Create_Ini=x.ini",
                             "File_Gamma=sRGB", "Bits_Per_Color=8"});
    ASSERT_EQ(r.warnings.size(), 5u);
    EXPECT_EQ(r.warnings[0], "rays: warning: +UA: Output_Alpha is not supported: the image has no alpha channel");
    EXPECT_NE(r.warnings[1].find("All_File is not acted on: messages are not copied to files"), std::string::npos);
    EXPECT_NE(r.warnings[2].find("Post_Frame_Command is not acted on: Rays runs no shell commands"), std::string::npos);
    EXPECT_NE(r.warnings[3].find("Field_Render"), std::string::npos);
    EXPECT_NE(r.warnings[4].find("Create_Ini is not acted on: no INI file is written"), std::string::npos);
    EXPECT_FALSE(r.o.outputToFile);  // -F: rendered, not written (tests/cli_pov_test.cpp)
    EXPECT_EQ(r.o.bitsPerColor, 8);  // Bits_Per_Color=8 came last; +FN16 had said 16
}

TEST(PovOptionsSwitch, UnknownSwitchesAndKeysWarnOnceEach) {
    const Read r = readArgs({"+Zap", "Foo=1", "+Zap", "foo=2", "+W10"});
    EXPECT_EQ(r.warnings, (std::vector<std::string>{"rays: warning: +Zap: unknown option '+Zap'",
                                                     "rays: warning: Foo=1: unknown option 'Foo'"}));
    EXPECT_EQ(r.o.width, 10);
}

TEST(PovOptionsSetting, FileGammaIsSrgbOrAPositiveNumber) {
    EXPECT_EQ(readArgs({}).o.fileGamma, 0);
    EXPECT_EQ(readArgs({"File_Gamma=1.8"}).o.fileGamma, 1.8);
    EXPECT_EQ(readArgs({"File_Gamma=1.8", "File_Gamma=srgb"}).o.fileGamma, 0);
    EXPECT_TRUE(readArgs({"File_Gamma=2.2"}).warnings.empty());
    EXPECT_NE(errorOf({"File_Gamma=0"}).find("File_Gamma must be sRGB or a positive number, got '0'"), std::string::npos);
    EXPECT_NE(errorOf({"File_Gamma=fast"}).find("File_Gamma=fast"), std::string::npos);
}

TEST(PovOptionsSwitch, MalformedValuesAreErrorsNamingTheSwitch) {
    EXPECT_EQ(errorOf({"+Wabc"}), "rays: error: +Wabc: Width must be a positive integer, got 'abc'");
    EXPECT_EQ(errorOf({"+W0"}), "rays: error: +W0: Width must be a positive integer, got '0'");
    EXPECT_EQ(errorOf({"+W12.5"}), "rays: error: +W12.5: Width must be a positive integer, got '12.5'");
    EXPECT_EQ(errorOf({"+W"}), "rays: error: +W: '+W' needs a value (Width)");
    EXPECT_EQ(errorOf({"+R10"}), "rays: error: +R10: Antialias_Depth must be a whole number from 1 to 9, got '10'");
    EXPECT_EQ(errorOf({"+AM3"}), "rays: error: +AM3: Sampling_Method must be a whole number from 1 to 2, got '3'");
    EXPECT_EQ(errorOf({"+Ax"}), "rays: error: +Ax: Antialias_Threshold must be a number, got 'x'");
    EXPECT_EQ(errorOf({"+AG0"}), "rays: error: +AG0: Antialias_Gamma must be more than 0, got '0'");
    EXPECT_EQ(errorOf({"+KFFx"}), "rays: error: +KFFx: Final_Frame must be a whole number, got 'x'");
    EXPECT_EQ(errorOf({"+KFI-2"}), "rays: error: +KFI-2: Initial_Frame must be a whole number, 0 or more, got '-2'");
    EXPECT_EQ(errorOf({"+STP0"}), "rays: error: +STP0: Frame_Step must be a positive integer, got '0'");
    EXPECT_EQ(errorOf({"+Kabc"}), "rays: error: +Kabc: Clock must be a number, got 'abc'");
    EXPECT_EQ(errorOf({"Antialias=maybe"}),
              "rays: error: Antialias=maybe: Antialias must be on or off (true/false, yes/no, 1/0), got 'maybe'");
    EXPECT_EQ(errorOf({"Declare=1x=3"}),
              "rays: error: Declare=1x=3: Declare needs NAME=VALUE with VALUE a number or a string in double quotes, got '1x=3'");
    EXPECT_NE(errorOf({"Declare=X=abc"}).find("Declare needs NAME=VALUE"), std::string::npos);
    EXPECT_NE(errorOf({"+I-"}).find("standard input"), std::string::npos);
    EXPECT_NE(errorOf({"+O-"}).find("standard output"), std::string::npos);
    EXPECT_NE(errorOf({"+WT2000"}).find("Work_Threads must be a whole number from 0 to 1024"), std::string::npos);
}

// ---- KEY=VALUE and booleans -----------------------------------------------------------------

TEST(PovOptionsSetting, EveryActedOnKey) {
    const PovOptions o = readArgs({"Input_File_Name=a.pov", "Output_File_Name=b.png", "Width=64", "Height=48",
                                   "Antialias=on", "Antialias_Threshold=0.2", "Antialias_Depth=2", "Sampling_Method=2",
                                   "Jitter=off", "Jitter_Amount=0.5", "Library_Path=/inc", "Declare=D=2", "Clock=0.3",
                                   "Initial_Frame=0", "Final_Frame=9", "Initial_Clock=1", "Final_Clock=3",
                                   "Subset_Start_Frame=2", "Subset_End_Frame=8", "Frame_Step=3", "Cyclic_Animation=yes",
                                   "Start_Row=1", "End_Row=0.999", "Start_Column=0", "End_Column=64",
                                   "Output_File_Type=J", "Work_Threads=4", "Continue_Trace=true"})
                             .o;
    EXPECT_EQ(o.inputFile, "a.pov");
    EXPECT_EQ(o.outputFile, "b.png");
    EXPECT_EQ(o.width, 64);
    EXPECT_EQ(o.height, 48);
    EXPECT_TRUE(o.antialias.on);
    EXPECT_DOUBLE_EQ(o.antialias.threshold, 0.2);
    EXPECT_EQ(o.antialias.depth, 2);
    EXPECT_EQ(o.antialias.method, 2);
    EXPECT_FALSE(o.antialias.jitter);
    EXPECT_DOUBLE_EQ(o.antialias.jitterAmount, 0.5);
    EXPECT_EQ(o.libraryPaths, std::vector<std::string>{"/inc"});
    ASSERT_EQ(o.declares.size(), 1u);
    EXPECT_EQ(o.declares[0].value, "2");
    EXPECT_DOUBLE_EQ(o.animation.clock, 0.3);
    EXPECT_EQ(o.animation.initialFrame, 0);
    EXPECT_EQ(o.animation.finalFrame, 9);
    EXPECT_DOUBLE_EQ(o.animation.initialClock, 1);
    EXPECT_DOUBLE_EQ(o.animation.finalClock, 3);
    EXPECT_DOUBLE_EQ(o.animation.subsetStart.value, 2);
    EXPECT_DOUBLE_EQ(o.animation.subsetEnd.value, 8);
    EXPECT_EQ(o.animation.frameStep, 3);
    EXPECT_TRUE(o.animation.cyclic);
    EXPECT_DOUBLE_EQ(o.startRow.value, 1);
    EXPECT_DOUBLE_EQ(o.endRow.value, 0.999);
    EXPECT_TRUE(o.startColumn.given);
    EXPECT_DOUBLE_EQ(o.endColumn.value, 64);
    EXPECT_EQ(o.fileType, 'J');
    EXPECT_EQ(o.threads, 4);
    EXPECT_TRUE(o.continueTrace);
}

TEST(PovOptionsSetting, KeysIgnoreCaseAndBooleansTakeEverySpelling) {
    EXPECT_EQ(readArgs({"WIDTH=20"}).o.width, 20);
    EXPECT_EQ(readArgs({"width = 21"}).o.width, 21);
    for (const char* on : {"on", "ON", "true", "True", "yes", "YES", "1"})
        EXPECT_TRUE(readArgs({std::string("Antialias=") + on}).o.antialias.on) << on;
    for (const char* off : {"off", "Off", "false", "FALSE", "no", "No", "0"})
        EXPECT_FALSE(readArgs({"+A", std::string("antialias=") + off}).o.antialias.on) << off;
}

TEST(PovOptionsSetting, LaterSettingsWinAndOrderIsKept) {
    EXPECT_EQ(readArgs({"+W10", "Width=20", "+W30"}).o.width, 30);
    EXPECT_EQ(readArgs({"Width=20", "+W10"}).o.width, 10);
    EXPECT_EQ(readArgs({"+Ia.pov", "b.pov"}).o.inputFile, "b.pov");
}

// ---- INI files --------------------------------------------------------------------------------

TEST(PovOptionsIni, CommentsSwitchLinesAndSettings) {
    TempDir dir;
    const fs::path ini = dir.path() / "opts.ini";
    writeFile(ini,
              "; a comment line\n"
              "\n"
              "Width = 80   ; a trailing comment\n"
              "  +H60 +A0.2 +KFF3 ; switches, several on a line\n"
              "Output_File_Name=\"semi;colon.png\" ; quotes keep ';'\n"
              "Post_Scene_Command=echo it's done ; an apostrophe opens nothing\n");
    const Read r = readArgs({ini.string()});
    EXPECT_EQ(r.o.width, 80);
    EXPECT_EQ(r.o.height, 60);
    EXPECT_TRUE(r.o.antialias.on);
    EXPECT_DOUBLE_EQ(r.o.antialias.threshold, 0.2);
    EXPECT_EQ(r.o.animation.finalFrame, 3);
    EXPECT_EQ(r.o.outputFile, "semi;colon.png");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0], ini.string() + ":6: warning: Post_Scene_Command is not acted on: Rays runs no shell commands");
}

TEST(PovOptionsIni, SettingsOnASwitchLineAndEmptyValues) {
    // animations/splinefollow.ini: `+kf0.1666 +kff20 +kc declare=fp=0`; benchmark.ini: `All_File=`.
    TempDir dir;
    const fs::path ini = dir.path() / "anim.ini";
    writeFile(ini, "+kff20 +kc declare=fp=0\nOutput_File_Name=\nAll_File=\n");
    const Read r = readArgs({ini.string()});
    EXPECT_EQ(r.o.animation.finalFrame, 20);
    EXPECT_TRUE(r.o.animation.cyclic);
    ASSERT_EQ(r.o.declares.size(), 1u);
    EXPECT_EQ(r.o.declares[0].name, "fp");
    EXPECT_EQ(r.o.declares[0].value, "0");
    EXPECT_EQ(r.o.outputFile, "");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
}

TEST(PovOptionsIni, TheExtensionIsAssumedAndTheIniIsReadInPlace) {
    TempDir dir;
    writeFile(dir.path() / "res.ini", "Width=100\nHeight=50\n");
    const std::string res = (dir.path() / "res").string();
    // "povray myopts +V other": in order, so options before the INI file lose and after it win.
    const Read r = readArgs({"+W10", "+H10", res, "+H20"});
    EXPECT_EQ(r.o.width, 100);
    EXPECT_EQ(r.o.height, 20);
}

// The RES.INI example of the manual (tutorial 2.2.8.2).
const char* kResIni =
    "; RES.INI\n"
    "+W120 +H100  ; This section has no label.\n"
    "[Low]\n"
    "+W80 +H60\n"
    "[Med]\n"
    "+W320 +H200\n"
    "[High]\n"
    "+W640 +H480  ; Labels are not case sensitive.\n"
    "[Really High]\n"
    "+W800 +H600  ; Labels may contain blanks\n"
    "+KFF2\n";

TEST(PovOptionsIni, OnlyTheTopPartWithoutASection) {
    TempDir dir;
    writeFile(dir.path() / "res.ini", kResIni);
    const PovOptions o = readArgs({(dir.path() / "res.ini").string()}).o;
    EXPECT_EQ(o.width, 120);
    EXPECT_EQ(o.height, 100);
    EXPECT_EQ(o.animation.finalFrame, -1);
}

TEST(PovOptionsIni, ANamedSectionAfterTheTopPart) {
    TempDir dir;
    writeFile(dir.path() / "res.ini", "Antialias=on\n" + std::string(kResIni));
    const std::string res = (dir.path() / "res").string();
    const PovOptions med = readArgs({res + "[Med]"}).o;
    EXPECT_EQ(med.width, 320);
    EXPECT_EQ(med.height, 200);
    EXPECT_TRUE(med.antialias.on);  // POV-Ray 3.7 reads the top part too
    EXPECT_EQ(readArgs({res + ".ini[high]"}).o.width, 640);
    const PovOptions really = readArgs({res + "[Really High]"}).o;
    EXPECT_EQ(really.width, 800);
    EXPECT_EQ(really.animation.finalFrame, 2);  // up to the next label or the end
}

TEST(PovOptionsIni, AMissingSectionWarnsAndKeepsTheTopPart) {
    TempDir dir;
    writeFile(dir.path() / "res.ini", kResIni);
    const std::string path = (dir.path() / "res.ini").string();
    const Read r = readArgs({path + "[Huge]"});
    EXPECT_EQ(r.o.width, 120);
    EXPECT_EQ(r.warnings, std::vector<std::string>{path + ": warning: no section [Huge]; only the top part was read"});
}

TEST(PovOptionsIni, NestedIniFilesWithSections) {
    TempDir dir;
    writeFile(dir.path() / "res.ini", kResIni);
    writeFile(dir.path() / "main.ini", "Width=1\nres[Low]  ; a nested INI file with a section\nHeight=7\n");
    const PovOptions o = readArgs({(dir.path() / "main.ini").string()}).o;
    EXPECT_EQ(o.width, 80);  // read in place: res.ini's settings replace Width=1
    EXPECT_EQ(o.height, 7);
}

TEST(PovOptionsIni, NestingDeeperThanTenIsAnError) {
    TempDir dir;
    writeFile(dir.path() / "loop.ini", "loop\n");  // includes itself (next to it, found from the INI's folder)
    const std::string message = errorOf({(dir.path() / "loop.ini").string()});
    EXPECT_NE(message.find("INI files nested more than 10 deep"), std::string::npos) << message;
}

TEST(PovOptionsIni, FilesNamingOthersManyTimesStopAtAThousandReads) {
    // Nesting stops at 10 levels, but each level may name the next many times: 40 lines naming
    // b.ini, whose 40 lines name c.ini, is 1 + 40 + 1600 reads (40^9 with ten such files). Before,
    // every one was read.
    TempDir dir;
    std::string a, b;
    for (int i = 0; i < 40; ++i) a += "b\n", b += "c\n";
    writeFile(dir.path() / "a.ini", a);
    writeFile(dir.path() / "b.ini", b);
    writeFile(dir.path() / "c.ini", "Width=3\n");
    const std::string bPath = (dir.path() / "b.ini").string();
    EXPECT_EQ(errorOf({(dir.path() / "a.ini").string()}),
              "rays: error: reading INI file '" + (dir.path() / "c.ini").string() +
                  "' makes more than 1000 INI files or 64 MiB of INI text read in all (do INI files name each other "
                  "over and over?) (named " + bPath + ":15)");
}

TEST(PovOptionsIni, AMissingIniFileIsAnErrorNamingWhereItWasAsked) {
    TempDir dir;
    EXPECT_EQ(errorOf({(dir.path() / "none").string()}),
              "rays: error: cannot open INI file '" + (dir.path() / "none.ini").string() + "' (named on the command line)");
    writeFile(dir.path() / "a.ini", "Width=2\nmissing\n");
    const std::string a = (dir.path() / "a.ini").string();
    EXPECT_EQ(errorOf({a}), "rays: error: cannot open INI file 'missing.ini' (named " + a + ":2)");
}

TEST(PovOptionsIni, ErrorsAndWarningsNameTheFileAndLine) {
    TempDir dir;
    InDirectory cd(dir.path());
    writeFile("scene.ini", "; settings\nInput_File_Name=scene.pov\nFoo=1\nWidth=abc\n");
    EXPECT_EQ(errorOf({"scene.ini"}), "rays: error: scene.ini:4: Width must be a positive integer, got 'abc'");
    writeFile("warn.ini", "Foo=1\n+Zap\nfoo=2\n[Sec]\nBar=3\n");
    const Read r = readArgs({"warn.ini"});
    EXPECT_EQ(r.warnings, (std::vector<std::string>{"warn.ini:1: warning: unknown option 'Foo'",
                                                     "warn.ini:2: warning: unknown option '+Zap'"}));
    writeFile("label.ini", "[Open\n");
    EXPECT_EQ(errorOf({"label.ini"}), "rays: error: label.ini:1: section label without ']': '[Open'");
    writeFile("sw.ini", "+W10 +Hx\n");
    EXPECT_EQ(errorOf({"sw.ini"}), "rays: error: sw.ini:1: Height must be a positive integer, got 'x'");
}

TEST(PovOptionsIni, RelativeSceneNamesFromTheCurrentFolderThenTheIniFolder) {
    TempDir dir;
    InDirectory cd(dir.path());
    fs::create_directory("sub");
    writeFile("sub/scene.pov", "");
    writeFile("sub/here.ini", "Input_File_Name=scene.pov\n");
    // Not in the current folder: the one next to the INI file.
    EXPECT_EQ(readArgs({"sub/here.ini"}).o.inputFile, "sub/scene.pov");
    // In the current folder (POV-Ray 3.7 reads names relative to it): that one.
    writeFile("scene.pov", "");
    EXPECT_EQ(readArgs({"sub/here.ini"}).o.inputFile, "scene.pov");
    // On the command line names are never moved.
    EXPECT_EQ(readArgs({"+Inone.pov"}).o.inputFile, "none.pov");
    // A nested INI file is found the same way.
    writeFile("sub/outer.ini", "inner\n");
    writeFile("sub/inner.ini", "Width=33\n");
    EXPECT_EQ(readArgs({"sub/outer.ini"}).o.width, 33);
}

// ---- render's own options in order --------------------------------------------------------------

TEST(PovOptionsOrder, RenderOptionsAndPovOptionsLaterWins) {
    PovOptions o;
    PovOptionReader reader(o, nullptr);
    reader.readArgument("+Oa.png");
    reader.setOutputExact("b.jpg");
    EXPECT_EQ(o.outputFile, "b.jpg");
    EXPECT_TRUE(o.outputExact);
    reader.readArgument("Output_File_Name=c");
    EXPECT_EQ(o.outputFile, "c");
    EXPECT_FALSE(o.outputExact);
    reader.readArgument("+A");
    EXPECT_TRUE(o.antialias.given);
    reader.renderChoseAntialias();  // --spp after +A: Rays' own sampling
    EXPECT_FALSE(o.antialias.given);
    reader.setWidth(5);
    reader.readArgument("+W6");
    EXPECT_EQ(o.width, 6);
    reader.addLibraryPath("/x");
    reader.readArgument("+L/y");
    reader.addLibraryPath("/x/");
    EXPECT_EQ(o.libraryPaths, (std::vector<std::string>{"/x", "/y"}));
}

// ---- what the options make of a render ------------------------------------------------------------

TEST(PovSettings, AntialiasMapsToTheNearestRaysSampling) {
    using rays::AaMode;
    using rays::cli::mapPovAntialias;
    rays::cli::PovAntialias aa;
    EXPECT_EQ(mapPovAntialias(aa).spp, 1);  // off
    aa.on = true;
    rays::cli::AaChoice c = mapPovAntialias(aa);  // +A: threshold 0.3, depth 3, method 1, jitter
    EXPECT_EQ(c.spp, 9);
    EXPECT_EQ(c.mode, AaMode::Stratified);
    EXPECT_TRUE(c.edges);
    EXPECT_DOUBLE_EQ(c.threshold, 0.3);  // POV-Ray's colour rule, with its threshold and gamma
    EXPECT_DOUBLE_EQ(c.gamma, 2.5);
    aa.method = 2;
    EXPECT_EQ(mapPovAntialias(aa).spp, 16);
    aa.method = 1;
    aa.depth = 1;
    EXPECT_EQ(mapPovAntialias(aa).spp, 4);  // at least 2×2
    aa.depth = 3;
    aa.jitter = false;
    EXPECT_EQ(mapPovAntialias(aa).mode, AaMode::Grid);
    aa.threshold = 0;
    EXPECT_FALSE(mapPovAntialias(aa).edges);  // every pixel supersampled
    EXPECT_EQ(mapPovAntialias(aa).spp, 9);
    aa.threshold = 3;
    EXPECT_EQ(mapPovAntialias(aa).spp, 1);  // "threshold 3.0: no anti-aliasing"
}

TEST(PovSettings, OutputNamesFollowPovRay) {
    using rays::cli::povOutputPath;
    PovOptions o;
    o.inputFile = "scenes/ball.pov";
    EXPECT_EQ(povOutputPath(o, true), "ball.png");  // the scene's name, in the current folder
    EXPECT_EQ(povOutputPath(o, false), "output.png");  // rays render keeps its default
    o.fileType = 'J';
    EXPECT_EQ(povOutputPath(o, true), "ball.jpg");
    EXPECT_EQ(povOutputPath(o, false), "output.jpg");
    o.outputFile = "out";
    EXPECT_EQ(povOutputPath(o, true), "out.jpg");
    o.outputFile = "out.jpeg";
    EXPECT_EQ(povOutputPath(o, true), "out.jpeg");
    o.fileType = 'T';
    o.outputFile = "out.png";
    EXPECT_EQ(povOutputPath(o, true), "out.png.tga");  // as POV-Ray: the type's extension is added
    o.fileType = 0;
    EXPECT_EQ(povOutputPath(o, true), "out.png");
    o.outputFile = "out.JPG";
    EXPECT_EQ(povOutputPath(o, true), "out.JPG");  // a format Rays writes: kept
    o.outputFile = "out.dat";
    EXPECT_EQ(povOutputPath(o, true), "out.dat.png");
    o.outputFile = "images/";
    EXPECT_EQ(povOutputPath(o, true), "images/ball.png");  // a folder gets the scene's name
    o.outputFile = "x.weird";
    o.outputExact = true;
    EXPECT_EQ(povOutputPath(o, true), "x.weird");  // render's -o: as written
}

TEST(PovSettings, APartOfTheImageIsRoundedAsPovRayRoundsIt) {
    // Measured with POV-Ray 3.7 at 32×24 (0-based rows and columns it rendered).
    auto region = [](const std::vector<std::string>& args) {
        rays::RenderSettings s;
        s.width = 32;
        s.height = 24;
        rays::cli::setImageRegion(readArgs(args).o, s);
        return std::array<int, 4>{s.regionX0, s.regionX1, s.regionY0, s.regionY1};
    };
    EXPECT_EQ(region({"+SR0.5"}), (std::array<int, 4>{0, 31, 12, 23}));
    EXPECT_EQ(region({"+SC0.25", "+EC0.5", "+SR5", "+ER10"}), (std::array<int, 4>{8, 15, 4, 9}));
    EXPECT_EQ(region({"+SR0.3", "+ER0.7"}), (std::array<int, 4>{0, 31, 7, 15}));
    EXPECT_EQ(region({"+SC0.1", "+EC0.9"}), (std::array<int, 4>{3, 27, 0, 23}));
    // The whole image, however written, is no region.
    EXPECT_EQ(region({"+SR1", "+ER1"}), (std::array<int, 4>{0, -1, 0, -1}));
    EXPECT_EQ(region({"+SR0", "+ER24", "+SC1", "+EC1"}), (std::array<int, 4>{0, -1, 0, -1}));
    EXPECT_EQ(region({"+EC0.999", "+ER0.99"}), (std::array<int, 4>{0, 30, 0, 22}));  // POV-Ray's too
    EXPECT_EQ(region({}), (std::array<int, 4>{0, -1, 0, -1}));
    try {
        region({"+SR0.9", "+ER0.5"});
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("is empty: rows 22-12 and columns 1-32 of 32x24"), std::string::npos) << e.what();
    }
}

TEST(PovSettings, ApplyFillsTheJob) {
    PovOptions o = readArgs({"+Iball.pov", "+W64", "+H48", "+A", "+WT2", "+L/inc", "Declare=D=1", "Compression=70"}).o;
    rays::cli::RenderJob job;
    rays::cli::applyPovOptions(o, true, job);
    EXPECT_EQ(job.scenePath, "ball.pov");
    EXPECT_EQ(job.outputPath, "ball.png");
    EXPECT_EQ(job.settings.width, 64);
    EXPECT_EQ(job.settings.height, 48);
    EXPECT_EQ(job.settings.spp, 9);
    EXPECT_TRUE(job.settings.aaEdges);
    EXPECT_EQ(job.settings.threads, 2);
    EXPECT_EQ(job.jpegQuality, 70);
    EXPECT_EQ(job.language.libraryPaths, std::vector<std::string>{"/inc"});
    ASSERT_EQ(job.language.declares.size(), 1u);
    EXPECT_EQ(job.language.declares[0].name, "D");

    rays::cli::RenderJob plain;
    plain.settings.spp = 4;  // render's own --spp
    rays::cli::applyPovOptions(readArgs({"+Ix.pov"}).o, false, plain);
    EXPECT_EQ(plain.settings.width, 640);
    EXPECT_EQ(plain.settings.height, 480);
    EXPECT_EQ(plain.settings.spp, 4);  // no POV-Ray AA option: untouched
    EXPECT_EQ(plain.outputPath, "output.png");
}

}}  // namespace RAYS_TEST_UNIT, namespace
