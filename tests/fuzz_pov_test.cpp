// The POV-Ray scene fuzzer's harness (fuzz/entry_points.h, parseFuzzPov) and dictionary
// (fuzz/dict/pov.dict): the include folder it writes is found and usable, #fopen writes stay in its
// scratch scene folder and are removed after each input, its lowered limits apply, and the
// dictionary lists every keyword of the language. FuzzPovFindings: the behaviour of the fixes for
// its findings (docs/fuzzing.md) beyond the messages tests/regressions_test.cpp checks.
#include <gtest/gtest.h>
#include <pthread.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "../fuzz/entry_points.h"
#include "rays/error.h"
#include "rays/pov/load_pov.h"
#include "rays/pov/pov_host.h"
#include "support/files.h"
#include "support/process.h"

namespace fs = std::filesystem;

using rays::test::readFile;

namespace { namespace RAYS_TEST_UNIT {

/// The Error parseFuzzPov throws for text ("" when it parses), with text padded to an even size so
/// that strict mode (odd sizes) is off.
std::string povError(std::string text) {
    if (text.size() % 2) text += ' ';
    try {
        rays::fuzz::parseFuzzPov(text);
    } catch (const rays::Error& e) {
        return e.what();
    }
    return "";
}

TEST(FuzzPovHarness, IncludeFilesDefineColoursTexturesAndMacros) {
    EXPECT_EQ(povError("#include \"stdinc.inc\"\n"
                       "object { Row(2) }\n"
                       "sphere { 0, Square(2) texture { Checks } }\n"
                       "Ball(<0, 1, 0>, Fact(3), Plain)\n"
                       "#declare A = 1; #declare B = 2; Swap(A, B)\n"
                       "#if (A != 2 | B != 1) #error \"Swap\" #end\n"
                       "box { 0, 1 pigment { Marble } } sphere { 0, 1 material { Glass } }"),
              "");
    // stdinc.inc includes the other two: their identifiers come from the harness's folder.
    EXPECT_NE(povError("#include \"colors.inc\" #declare X = Yellow + Square(1);").find("undeclared identifier 'Square'"),
              std::string::npos);
    EXPECT_EQ(povError("#include \"macros.inc\" #declare X = Fact(4); #if (X != 24) #error \"Fact\" #end"), "");
}

TEST(FuzzPovHarness, IncludeFolderIsTheInstalledOneAndNothingElseIsSearched) {
    const fs::path inc = rays::fuzz::povIncludeDir();
    EXPECT_TRUE(fs::is_regular_file(inc / "colors.inc"));
    EXPECT_TRUE(fs::is_regular_file(inc / "macros.inc"));
    EXPECT_TRUE(fs::is_regular_file(inc / "stdinc.inc"));
    // POV-Ray's own include files are not reached even when they are installed.
    EXPECT_NE(povError("#include \"textures.inc\"").find("cannot find include file \"textures.inc\""), std::string::npos);
}

TEST(FuzzPovHarness, WrittenFilesStayInTheScratchSceneFolderAndAreRemoved) {
    const fs::path scene = rays::fuzz::povSceneDir();
    EXPECT_EQ(povError("#fopen F \"w.txt\" write #write (F, \"\\\"hi\\\"\") #fclose F\n"
                       "#fopen G \"w.txt\" read #read (G, S) #if (strcmp(S, \"hi\") != 0) #error \"read back\" #end"),
              "");
    EXPECT_TRUE(fs::is_empty(scene)) << "files written by one input must not reach the next";
    EXPECT_NE(povError("#fopen F \"../w.txt\" write").find("may only write files in the scene's folder"), std::string::npos);
    EXPECT_NE(povError("#fopen F \"/tmp/w.txt\" write").find("may only write files in the scene's folder"), std::string::npos);
    EXPECT_FALSE(fs::exists(scene.parent_path() / "w.txt"));
}

TEST(FuzzPovHarness, LimitsAreLoweredToKeepInputsShort) {
    EXPECT_NE(povError("#while (1) #end").find("loops ran more than 20000 iterations"), std::string::npos);
    EXPECT_NE(povError("#macro R() R() #end R()").find("macro calls nested deeper than 1000"), std::string::npos);
}

TEST(FuzzPovHarness, StrictModeOnOddSizesOnly) {
    const std::string text = "sphere { 0,1 pigment { tiling 26} }";  // the Penrose tilings are not rendered yet
    ASSERT_EQ(text.size() % 2, 1u);
    EXPECT_NO_THROW(rays::fuzz::parseFuzzPov(text + " "));
    EXPECT_THROW(rays::fuzz::parseFuzzPov(text), rays::Error);
    // The fuzz entry point swallows the Error.
    rays::fuzz::fuzzPov(reinterpret_cast<const uint8_t*>(text.data()), text.size());
}

TEST(FuzzPovDictionary, ListsEveryKeywordAndDirective) {
    const std::string def = readFile(fs::path(RAYS_SOURCE_DIR) / "src/rays/sdl/keywords.def");
    const std::string dict = readFile(fs::path(RAYS_SOURCE_DIR) / "fuzz/dict/pov.dict");
    ASSERT_FALSE(def.empty());
    ASSERT_FALSE(dict.empty());
    std::set<std::string> entries;
    const std::regex entry(R"re(^\w+="([^"\\]*)"$)re");
    std::istringstream lines(dict);
    for (std::string line; std::getline(lines, line);) {
        std::smatch m;
        if (std::regex_match(line, m, entry)) entries.insert(m[1]);
    }
    const std::regex keyword(R"(^XR?\((\w+)\))");
    std::istringstream defs(def);
    int keywords = 0;
    for (std::string line; std::getline(defs, line);) {
        std::smatch m;
        if (!std::regex_search(line, m, keyword)) continue;
        ++keywords;
        EXPECT_TRUE(entries.count(m[1].str() + " ")) << m[1] << " is missing from fuzz/dict/pov.dict";
    }
    EXPECT_GT(keywords, 400);
    for (const char* d : {"#include ", "#declare ", "#local ", "#macro ", "#switch ", "#fopen ", "#write "})
        EXPECT_TRUE(entries.count(d)) << d;
}

TEST(FuzzPovFindings, BuilderClampsCountsAsFloatsBeforeConverting) {
    const rays::Scene scene = rays::fuzz::parseFuzzPov(
        "camera { aperture 1 blur_samples 1e300 }\n"
        "light_source { 0, 1 area_light x, y, 1e300, -1e300 adaptive 1e300 }\n"
        "global_settings { max_trace_level 1e300 }\n");
    ASSERT_EQ(scene.cameras.size(), 1u);
    EXPECT_EQ(scene.cameras[0].blurSamples, 65536);
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].n1, 1024);
    EXPECT_EQ(scene.lights[0].n2, 1);
    EXPECT_EQ(scene.lights[0].adaptive, 1000);
    EXPECT_EQ(scene.pov.maxTraceLevel, 256);
}

TEST(FuzzPovFindings, FunctionLoopsShareTheParsesLoopLimit) {
    const std::string sum = "#declare F = function(n) { sum(i, 1, n, i) };\n";
    EXPECT_EQ(povError(sum + "#if (F(100) != 5050) #error \"sum\" #end"), "");
    // 20000 in all: 15000 #while iterations leave 5000 for sum's repetitions.
    const std::string loop = "#declare I = 0; #while (I < 15000) #declare I = I + 1; #end\n";
    EXPECT_EQ(povError(sum + loop + "#declare A = F(4999);"), "");
    EXPECT_NE(povError(sum + loop + "#declare A = F(5001);").find("loops ran more than 20000 iterations (sum, prod"),
              std::string::npos);
    // Calls of other functions count too: each level calls the one below twice (2^41 calls).
    EXPECT_NE(povError("#declare H = function { x + 1 }\n#for (I, 0, 40) #declare H = function { H(x, y, z) + H(y, x, z) } #end\n"
                       "#declare A = H(1, 2, 3);")
                  .find("loops ran more than 20000 iterations (sum, prod or calls"),
              std::string::npos);
    EXPECT_EQ(povError("#declare H = function { x + 1 }\n#for (I, 0, 5) #declare H = function { H(x, y, z) + H(y, x, z) } #end\n"
                       "#if (H(1, 2, 3) != 160) #error \"calls\" #end"),
              "");
    // A loop whose counter stops growing (1e300 + 1 = 1e300) ends too.
    EXPECT_NE(povError("#declare G = function { prod(i, 1e300, 1e301, 1) };\n#declare A = G(0, 0, 0);").find("loops ran more"),
              std::string::npos);
}

/// The Error pov::parsePovText throws for text with the given limits ("" when it parses); files
/// are written in folder.
std::string povErrorWith(const std::string& text, const rays::sdl::Limits& limits, const std::string& folder = ".") {
    rays::ParseOptions opt;
    opt.warn = [](const std::string&) {};
    opt.language.installedIncludeDir.clear();
    try {
        rays::pov::parsePovText(text, "scene.pov", folder, opt, limits);
    } catch (const rays::Error& e) {
        return e.what();
    }
    return "";
}

TEST(FuzzPovFindings, DirectivesAndMacroArgumentsCountAsNesting) {
    rays::sdl::Limits limits;
    limits.nesting = 50;
    auto errorOf = [&](const std::string& text) { return povErrorWith(text, limits); };
    auto nest = [](const std::string& open, const std::string& core, const std::string& close, int n) {
        std::string s;
        for (int i = 0; i < n; ++i) s += open;
        s += core;
        for (int i = 0; i < n; ++i) s += close;
        return s;
    };
    const std::string tooDeep = "nesting deeper than 50 levels";
    EXPECT_NE(errorOf("#macro M(A) A #end #declare B = " + nest("M(", "1", ")", 60) + ";").find(tooDeep), std::string::npos);
    EXPECT_NE(errorOf(nest("#debug ", "\"x\"", "", 60)).find(tooDeep), std::string::npos);
    EXPECT_NE(errorOf("#declare V = " + nest("<", "1", ">", 60) + ";").find(tooDeep), std::string::npos);
    EXPECT_NE(errorOf("#declare C = " + nest("rgb ", "1", "", 60) + ";").find(tooDeep), std::string::npos);
    EXPECT_NE(errorOf("#declare S = " + nest("concat(", "\"a\"", ")", 60) + ";").find(tooDeep), std::string::npos);
    EXPECT_NE(errorOf("sphere { 0, 1 pigment { " + nest("pigment_pattern { ", "checker", " }", 60) + " } }").find(tooDeep),
              std::string::npos);
    // Shallow nests of each kind still parse.
    EXPECT_EQ(errorOf("#macro M(A) A #end #declare B = " + nest("M(", "1", ")", 10) + ";"), "");
    EXPECT_EQ(errorOf("#declare S = " + nest("concat(", "\"a\"", ")", 10) + ";"), "");
}

// fuzz/run.sh's pov target timed out on advanced/wallstucco.pov (a 500 × 500 height_field of a
// noisy pigment function, 250,000 samples: 11–14 s under the sanitizers): a height field's samples
// count against the scene's object limit, as a mesh's triangles do, and a function's resolution
// past what is left is refused before the function runs.
TEST(FuzzPovFindings, HeightFieldSamplesCountAsObjects) {
    rays::sdl::Limits limits;
    limits.sceneObjects = 1000;
    const std::string hf = "height_field { function 30, 30 { x * z } }\n";  // 900 samples
    EXPECT_EQ(povErrorWith(hf, limits), "");
    EXPECT_EQ(povErrorWith("height_field { function 40, 30 { x * z } }", limits),
              "scene.pov:1:1: error: height_field's function of 40 x 30 samples goes past the scene's object limit "
              "(999 left; each sample counts, as a mesh's triangles do)");  // the field itself counted one
    EXPECT_NE(povErrorWith(hf + "sphere { 0, 1 } " + hf, limits).find("goes past the scene's object limit (97 left"),
              std::string::npos);
}

TEST(FuzzPovFindings, ArrayElementsMadeAreCountedNewAndCopied) {
    rays::sdl::Limits limits;
    limits.arrayElements = 100;
    // A new array counts once (a declaration takes it as it is), a copy again: 50 + 50 for B's copy.
    EXPECT_EQ(povErrorWith("#declare A = array[50]; #declare B = A;", limits), "");
    EXPECT_EQ(povErrorWith("#declare A = array[60]; #declare B = A;", limits),
              "scene.pov:1:34: error: more than 100 array elements and spline points made (new and copied) in this parse (runaway loop?)");
    // Nested arrays count their elements too; a macro's by-reference argument is a copy.
    EXPECT_NE(povErrorWith("#declare A = array[3] { array[40], array[40], array[40] };", limits).find("more than 100 array elements"),
              std::string::npos);
    EXPECT_NE(povErrorWith("#macro M(P) #end #declare A = array[40]; M(A) M(A)", limits).find("more than 100 array elements"),
              std::string::npos);
    // The default allows any single array the size limits allow (up to 2^27 elements, copied once).
    EXPECT_EQ(rays::sdl::Limits{}.arrayElements, uint64_t(1) << 28);
}

TEST(FuzzPovFindings, SplinePointsAreCountedNewAndCopied) {
    rays::sdl::Limits limits;
    limits.arrayElements = 10;
    // Three points (the second t = 0 replaces the first), then 3 + 1 copied and new, then 4 + 1.
    const std::string s = "#declare S = spline { linear_spline 0, 0, 1, 1, 0, 2, 2, 3 }\n"
                          "#if (S(0).x != 2) #error \"replaced\" #end\n"
                          "#declare T = spline { S 5, 5 }\n";
    EXPECT_EQ(povErrorWith(s, limits), "");
    EXPECT_EQ(povErrorWith(s + "#declare U = spline { T 6, 6 }", limits),
              "scene.pov:4:14: error: more than 10 array elements and spline points made (new and copied) in this parse "
              "(runaway loop?)");
    // A NaN time sorts last instead of breaking the sort's ordering.
    EXPECT_EQ(povErrorWith("#declare S = spline { linear_spline sqrt(-1), 7, 0, 0, 1, 1 }\n"
                           "#if (S(0.5).x != 0.5) #error \"nan\" #end",
                           {}),
              "");
}

TEST(FuzzPovFindings, StringBytesAndWrittenBytesAreCounted) {
    rays::sdl::Limits limits;
    limits.stringBytes = 10;
    EXPECT_EQ(povErrorWith("#declare S = concat(\"abcde\", \"fghij\");", limits), "");
    EXPECT_NE(povErrorWith("#declare S = concat(\"abcde\", \"fghij\"); #declare T = str(1, 0, 0);", limits)
                  .find("more than 10 bytes of strings made by string functions"),
              std::string::npos);
    // concat checks its length as it grows, not once all arguments are joined.
    std::string longArgs = "#declare S = \"ab\"; #for (I, 1, 23) #declare S = concat(S, S); #end #declare T = concat(S";
    for (int i = 0; i < 100; ++i) longArgs += ", S";
    EXPECT_NE(povError(longArgs + ");").find("concat made a string longer than 16 MiB"), std::string::npos);

    rays::test::TempDir dir;
    rays::sdl::Limits w;
    w.writeBytes = 8;
    EXPECT_EQ(povErrorWith("#fopen F \"a.txt\" write #write (F, \"1234\", uint16le <1, 2>)", w, dir.path().string()), "");
    EXPECT_NE(povErrorWith("#fopen F \"a.txt\" write #write (F, \"1234\", uint16le <1, 2>, 5)", w, dir.path().string())
                  .find("more than 8 bytes written by #write"),
              std::string::npos);
}

TEST(FuzzPovFindings, SceneBuilderCountsObjectsCopiesAndTriangles) {
    rays::sdl::Limits limits;
    limits.sceneObjects = 3;
    EXPECT_EQ(povErrorWith("union { sphere { 0, 1 } sphere { x, 1 } }", limits), "");
    // The second copy is refused: a union and its two spheres count three.
    EXPECT_EQ(povErrorWith("#declare O = union { sphere { 0, 1 } sphere { x, 1 } } object { O } object { O }", limits),
              "scene.pov:1:69: error: the scene makes more than 3 objects (each copy of a declared object counts, and each "
              "mesh triangle)");
    EXPECT_NE(povErrorWith("mesh { triangle { 0, x, y } triangle { 0, y, z } triangle { 0, z, x } }", limits).find("more than 3 objects"),
              std::string::npos);
}

TEST(FuzzPovFindings, ItemsUsedAgainCountTheirWholeTree) {
    rays::sdl::Limits limits;
    limits.itemCopies = 20;
    // O is a union and two spheres: 3 items per use.
    const std::string o = "#declare O = union { sphere { 0, 1 } sphere { x, 1 } }\n";
    std::string uses;
    for (int i = 0; i < 6; ++i) uses += "object { O }\n";
    EXPECT_EQ(povErrorWith(o + uses, limits), "");
    EXPECT_EQ(povErrorWith(o + uses + "object { O }", limits),
              "scene.pov:8:1: error: more than 20 items used again through identifiers (each use counts the item's whole "
              "tree) in this parse (runaway loop?)");
    // Items written out are not uses: a union of 30 spheres counts nothing.
    std::string written = "union {";
    for (int i = 0; i < 30; ++i) written += " sphere { 0, 1 }";
    EXPECT_EQ(povErrorWith(written + " }", limits), "");
    // A doubling chain of transforms, finishes or cameras stops after a few levels.
    EXPECT_NE(povErrorWith("#declare F = finish { ambient 0.1 }\n#for (I, 0, 40) #declare F = finish { F F } #end", limits)
                  .find("items used again"),
              std::string::npos);
}

TEST(FuzzPovFindings, DeclaredItemsNestAtMost4000Deep) {
    auto chain = [](int n) {  // n levels: a sphere in n - 1 objects
        return "#declare O = sphere { 0, 1 }\n#for (I, 2, " + std::to_string(n) + ") #declare O = object { O } #end\n";
    };
    EXPECT_EQ(povErrorWith(chain(4000), {}), "");
    EXPECT_EQ(povErrorWith(chain(4001), {}),
              "scene.pov:2:32: error: items nested deeper than 4000 levels (a declared item used in itself again and again?)");
}

TEST(FuzzPovFindings, DefaultsAreAppendedAndSharedNotCopied) {
    rays::pov::ParsedScene parsed;
    rays::pov::PovHost host(parsed);
    rays::sdl::LanguageOptions lang;
    lang.installedIncludeDir.clear();
    rays::sdl::Interpreter in(lang, host, rays::sdl::Diagnostics{});
    in.runText("sphere { 0, 1 } #for (I, 1, 3) #default { finish { ambient I / 10 } } sphere { 0, 1 } #end", "scene.pov");
    ASSERT_EQ(parsed.items.size(), 4u);
    EXPECT_EQ(parsed.items[0].defaults, nullptr);
    for (size_t i = 1; i < 4; ++i) {
        EXPECT_EQ(parsed.items[i].defaults, parsed.items[3].defaults) << i;
        EXPECT_EQ(parsed.items[i].defaultsCount, i);
    }
    // Each object gets the defaults in force where it was written.
    const rays::Scene scene = rays::fuzz::parseFuzzPov(
        "#default { finish { ambient 0.5 } } sphere { 0, 1 } #default { finish { ambient 0.25 diffuse 0.5 } } "
        "sphere { 0, 1 } sphere { 0, 1 finish { ambient 0.125 } } #default { pigment { rgb 1 } } sphere { 0, 1 }   ");
    ASSERT_EQ(scene.objects.size(), 4u);
    EXPECT_EQ(scene.objects[0].material.ambient, 0.5);
    EXPECT_EQ(scene.objects[1].material.ambient, 0.25);
    EXPECT_EQ(scene.objects[2].material.ambient, 0.125);
    EXPECT_EQ(scene.objects[3].material.ambient, 0.25);
}

// Parses text on a thread with a stack of stackBytes; returns the Error's message ("" when none).
std::string parseOnSmallStack(const std::string& text, size_t stackBytes) {
    struct Job {
        std::string text, error;
    } job{text, ""};
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setstacksize(&attr, stackBytes);
    pthread_t thread;
    const int rc = pthread_create(
        &thread, &attr,
        [](void* p) -> void* {
            Job& j = *static_cast<Job*>(p);
            try {
                rays::ParseOptions opt;
                opt.warn = [](const std::string&) {};
                opt.language.installedIncludeDir.clear();
                rays::pov::parsePovText(j.text, "scene.pov", ".", opt);
            } catch (const rays::Error& e) {
                j.error = e.what();
            }
            return nullptr;
        },
        &job);
    pthread_attr_destroy(&attr);
    if (rc != 0) return "pthread_create failed";
    pthread_join(thread, nullptr);
    return job.error;
}

TEST(FuzzPovFindings, NestingWithinTheCountLimitStopsBeforeTheStackRunsOut) {
    // 3990 parentheses are within the 4000 levels allowed; on a 1 MiB stack (about 1.6 KiB a level
    // in a release build) they would overflow it.
    std::string text = "#declare A = " + std::string(3990, '(') + "1" + std::string(3990, ')') + ";";
    const std::string e = parseOnSmallStack(text, size_t(1) << 20);
    EXPECT_NE(e.find("scene.pov:1:"), std::string::npos) << e;
    EXPECT_NE(e.find(": error: nesting too deep for the parser's stack ("), std::string::npos) << e;
    EXPECT_EQ(parseOnSmallStack("#declare A = ((((1))));", size_t(1) << 20), "");
}

}}  // namespace RAYS_TEST_UNIT, namespace
