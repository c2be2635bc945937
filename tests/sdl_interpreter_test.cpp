// The scene language on its own (no renderer): values, directives, macros, arrays, strings,
// includes and errors, checked through #debug output and error messages.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/sdl_run.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

using test::runSdl;

std::string dbg(const std::string& text) {
    const test::SdlRun r = runSdl(text);
    EXPECT_EQ(r.error, "") << text;
    return r.debug;
}

std::string err(const std::string& text) { return runSdl(text).error; }

TEST(SdlValues, FloatArithmeticAndPrecedence) {
    EXPECT_EQ(dbg("#declare A = 2*-3; #debug str(A,0,1)"), "-6.0");
    EXPECT_EQ(dbg("#declare A = -2*3+!0; #debug str(A,0,1)"), "-5.0");
    EXPECT_EQ(dbg("#declare A = (1 < 2) + (3 >= 4) + (2 = 2); #debug str(A,0,0)"), "2");
    EXPECT_EQ(dbg("#declare A = (1 ? 2 : 3) + 1; #debug str(A,0,0)"), "3");
    EXPECT_EQ(dbg("#declare A = (0 | 1) + (1 & 0); #debug str(A,0,0)"), "1");
    EXPECT_EQ(dbg("#debug str(mod(-7,3),0,1) #debug str(div(-7,2),0,1) #debug str(int(-2.5),0,1)"), "-1.0-3.0-2.0");
    EXPECT_EQ(dbg("#debug str(select(-1,1,2),0,0) #debug str(select(0,1,2,3),0,0) #debug str(max(1,5,3),0,0)"), "125");
}

TEST(SdlValues, VersionReadsPovRaysOwnUntilSet) {
    // Measured with POV-Ray 3.7.0: 3.70 without #version; +MV / Version= set the start.
    EXPECT_EQ(dbg("#debug str(version, 0, 2)"), "3.70");
    EXPECT_EQ(dbg("#version 3.5; #debug str(version, 0, 2)"), "3.50");
    sdl::LanguageOptions o;
    o.version = 3.1;
    EXPECT_EQ(runSdl("#debug str(version, 0, 2)", o).debug, "3.10");
}

TEST(SdlValues, VectorPromotion) {
    EXPECT_EQ(dbg("#declare V = <1,2> + <1,2,3>; #debug vstr(3,V,\",\",0,0)"), "2,4,3");
    EXPECT_EQ(dbg("#declare V = <1,2,3>*2 + 1; #debug vstr(3,V,\",\",0,0)"), "3,5,7");
    EXPECT_EQ(dbg("#declare V = 3*x - z; #debug vstr(3,V,\",\",0,0)"), "3,0,-1");
    EXPECT_EQ(dbg("#declare A = <1,2,3>.y + -x.x; #debug str(A,0,0)"), "1");
    EXPECT_EQ(dbg("#debug vstr(3, vrotate(x, y*90), \",\", 0, 3)"), "0.000,0.000,-1.000");
    EXPECT_EQ(dbg("#debug vstr(3, vaxis_rotate(x, y, 90), \",\", 0, 3)"), "0.000,0.000,-1.000");
    EXPECT_EQ(dbg("#debug vstr(3, vcross(x, y), \",\", 0, 0) #debug str(vdot(<1,2,3>,<4,5,6>),0,0)"), "0,0,132");
}

TEST(SdlValues, ColoursFollowPovRaysPromotionRules) {
    // Values measured with POV-Ray 3.7.0.10.
    EXPECT_EQ(dbg("#declare C = color 0.3; #debug vstr(5,C,\",\",0,1)"), "0.3,0.3,0.3,0.3,0.3");
    EXPECT_EQ(dbg("#declare C = rgbt 0.5; #debug vstr(5,C,\",\",0,1)"), "0.5,0.5,0.5,0.0,0.5");
    EXPECT_EQ(dbg("#declare C = rgb <1,2,3> filter 0.5 red 7; #debug vstr(5,C,\",\",0,1)"), "7.0,2.0,3.0,0.5,0.0");
    EXPECT_EQ(dbg("#declare C = color red 0.5 + 0.25; #debug vstr(5,C,\",\",0,2)"), "0.75,0.00,0.00,0.00,0.00");
    EXPECT_EQ(dbg("#declare C = rgb 1; #declare D = C + 1; #debug vstr(5,D,\",\",0,0)"), "2,2,2,1,1");
    EXPECT_EQ(dbg("#declare C = rgb <1,2,3> + <1,1,1>; #debug vstr(5,C,\",\",0,0)"), "2,3,4,0,0");
    EXPECT_EQ(dbg("#declare C = rgb <0,1,0>; #declare G = C.gray + 0; #debug str(G,0,3)"), "0.589");
    EXPECT_EQ(dbg("#declare L = <1,2,3>; #declare M = color L; #debug vstr(5,M,\",\",0,0)"), "1,2,3,0,0");
}

TEST(SdlDirectives, ConditionalsAndTheirBranches) {
    EXPECT_EQ(dbg("#if (0) #debug \"a\" #elseif (1) #debug \"b\" #else #debug \"c\" #end"), "b");
    EXPECT_EQ(dbg("#if (1) #debug \"a\" #elseif (1) #debug \"b\" #else #debug \"c\" #end"), "a");
    EXPECT_EQ(dbg("#if (0) #if (1) #debug \"x\" #end #else #debug \"c\" #end"), "c");
    EXPECT_EQ(dbg("#ifdef (Q) #debug \"a\" #else #debug \"b\" #end #declare Q = 1; #ifdef (Q) #debug \"c\" #end"), "bc");
    EXPECT_EQ(dbg("#declare A = array[3] #declare A[1] = 5; #ifdef (A[0]) #debug \"0\" #end #ifdef (A[1]) #debug \"1\" #end"), "1");
    EXPECT_EQ(dbg("#ifndef (pi) #debug \"no\" #else #debug \"builtin\" #end"), "builtin");
}

TEST(SdlDirectives, SwitchFallsThroughAsPovRayDoes) {
    // POV-Ray 3.7.0.10 prints two three five else: once a clause runs, later clauses are not tested.
    const char* s =
        "#switch (2) #case (1) #debug \"one \" #case (2) #debug \"two \" #case (3) #debug \"three \" "
        "#case (5) #debug \"five \" #else #debug \"else\" #end";
    EXPECT_EQ(dbg(s), "two three five else");
    EXPECT_EQ(dbg("#switch (4) #range (1,3) #debug \"low\" #break #range (4,6) #debug \"mid\" #break #else #debug \"x\" #end"), "mid");
    EXPECT_EQ(dbg("#switch (9) #case (1) #debug \"one\" #break #else #debug \"other\" #end"), "other");
    EXPECT_EQ(dbg("#switch (9) #case (1) #debug \"one\" #end #debug \"after\""), "after");
}

TEST(SdlDirectives, LoopsAndBreak) {
    EXPECT_EQ(dbg("#declare I = 0; #while (I < 3) #debug str(I,0,0) #declare I = I + 1; #end"), "012");
    EXPECT_EQ(dbg("#for (I, 1, 3) #debug str(I,0,0) #end #debug str(I,0,0)"), "1234");
    EXPECT_EQ(dbg("#for (I, 3, 1, -1) #debug str(I,0,0) #end"), "321");
    EXPECT_EQ(dbg("#declare K = 5; #while (K > 0) #declare K = K - 1; #if (K = 2) #break #end #end #debug str(K,0,0)"), "2");
    EXPECT_EQ(dbg("#for (I, 1, 10) #if (I = 4) #break #end #debug str(I,0,0) #end"), "123");
    EXPECT_EQ(dbg("#for (I, 1, 2) #for (J, 1, 2) #debug concat(str(I,0,0), str(J,0,0), \" \") #end #end"), "11 12 21 22 ");
}

TEST(SdlMacros, ParametersLocalsAndReturnedValues) {
    EXPECT_EQ(dbg("#macro Add(A, B) (A + B) #end #declare S = Add(2, 3) * 2; #debug str(S,0,0)"), "10");
    EXPECT_EQ(dbg("#macro F(N) #if (N <= 1) 1 #else N * F(N - 1) #end #end #debug str(F(5),0,0)"), "120");
    EXPECT_EQ(dbg("#macro M() #local T = 1; #end M() #ifdef (T) #debug \"leak\" #else #debug \"gone\" #end"), "gone");
    EXPECT_EQ(dbg("#macro M() #declare G = 7; #end M() #debug str(G,0,0)"), "7");
    EXPECT_EQ(dbg("#declare X = 1; #macro M() #local X = 2; #debug str(X,0,0) #end M() #debug str(X,0,0)"), "21");
}

// POV-Ray 3.7 reads shapes3.inc, whose Rounded_Tube ends its parameter list with a comma, whose
// Half_Hollowed_Rounded_Cylinder2 leaves a comma out, and whose #warning texts run across lines.
TEST(SdlMacros, ParameterListsAsLenientAsPovRays) {
    EXPECT_EQ(dbg("#macro M(A, B,) str(A + B, 0, 0) #end\n#debug M(1, 2)"), "3");
    EXPECT_EQ(dbg("#macro M(A, B C, D) str(A + B + C + D, 0, 0) #end\n#debug M(1, 2, 3, 4)"), "10");
    // ... and a call may end its arguments with a comma (the shapes3.inc templates do).
    EXPECT_EQ(dbg("#macro M(A, B) str(A + B, 0, 0) #end\n#debug M(1, 2,)"), "3");
    EXPECT_EQ(err("#macro M(A, B) #end\nM(1, 2, 3)"), "scene.pov:2:9: error: macro M takes 2 parameters, more were given");
    EXPECT_EQ(err("#macro M(A, , B) #end"),
              "scene.pov:1:13: error: expected an identifier for the macro parameter, found ','");
}

// #undef of a macro names it without calling it (ior.inc ends so).
TEST(SdlMacros, UndefOfAMacroDoesNotCallIt) {
    EXPECT_EQ(dbg("#macro M(A) A #end\n#undef M\n#ifdef (M) #debug \"kept\" #else #debug \"gone\" #end"), "gone");
}

// POV-Ray 3.7 (measured) reads '#' before a keyword that is no directive as the keyword alone, and
// an unknown word after '#' stays an error.
TEST(SdlDirectives, AHashBeforeAKeywordThatIsNoDirectiveIsDropped) {
    EXPECT_EQ(dbg("#declare A = #union { sphere { 0, 1 } }\n#debug \"ok\""), "ok");
    EXPECT_EQ(err("#declare Foo = 1;\n#Foo"), "scene.pov:2:1: error: unknown directive '#Foo'");
}

// In a function whose parameters do not name them, x, y, z, u and v read as 0 (POV-Ray 3.7,
// measured: function(a, b) { x + 10*y + 100*z } gives 0 at (2, 3); function(u, v) { x + 10*y +
// 100*z } gives 32, x and y being u and v).
TEST(SdlFunctions, CoordinatesThatAreNoParameterReadAsZero) {
    EXPECT_EQ(dbg("#declare G = function(a, b) { x + 10*y + 100*z }\n#debug str(G(2, 3), 0, 0)"), "0");
    EXPECT_EQ(dbg("#declare G = function(u, v) { x + 10*y + 100*z }\n#debug str(G(2, 3), 0, 0)"), "32");
    EXPECT_EQ(dbg("#declare K = function(u) { v + 10 }\n#debug str(K(2), 0, 0)"), "10");
}

// `spline { A[i] }` copies a spline out of an array of splines (meshmaker.inc's MSM does so).
TEST(SdlValues, ASplineCopiedFromAnArrayOfSplines) {
    EXPECT_EQ(dbg("#declare S = spline { linear_spline 0, <0,0,0> 1, <2,4,6> }\n"
                  "#declare A = array[2] { S, S }\n#declare T = spline { A[1] }\n"
                  "#debug vstr(3, T(0.5), \",\", 0, 0)"),
              "1,2,3");
}

TEST(SdlStrings, AStringMaySpanLines) {
    EXPECT_EQ(dbg("#declare S = \"one\ntwo\";\n#debug str(strlen(S), 0, 0)"), "7");
    // The lines it spans count for the positions after it.
    EXPECT_EQ(err("#declare S = \"a\nb\";\n#declare T = U;"), "scene.pov:3:14: error: undeclared identifier 'U'");
    EXPECT_EQ(err("#declare S = \"open\n\n"), "scene.pov:1:14: error: unterminated string");
}

TEST(SdlMacros, LoneIdentifiersArePassedByReference) {
    EXPECT_EQ(dbg("#macro Set(R) #declare R = 5; #end #declare V = 0; Set(V) #debug str(V,0,0)"), "5");
    EXPECT_EQ(dbg("#macro Set(R) #declare R = 5; #end #declare V = 0; Set(V+0) #debug str(V,0,0)"), "0");
    EXPECT_NE(err("#macro Set(R) #declare R = 5; #end Set(NewVar)").find("undeclared identifier 'NewVar'"), std::string::npos);
}

TEST(SdlMacros, OptionalParametersAndArgumentCounts) {
    EXPECT_EQ(dbg("#macro M(A, optional B) #ifdef (B) #debug \"B\" #else #debug \"-\" #end #end M(1,) M(1,2) M(1)"), "-B-");
    EXPECT_NE(err("#macro M(A, B) #end M(1)").find("macro M takes 2 parameters; 'B' was not given"), std::string::npos);
    EXPECT_NE(err("#macro M(A) #end M(1, 2)").find("more were given"), std::string::npos);
}

TEST(SdlArrays, InitialisersCopiesAndDimensions) {
    EXPECT_EQ(dbg("#declare A = array[3] {1, 2, 3}; #declare B = A; #declare B[0] = 7; #debug str(A[0],0,0)"), "1");
    EXPECT_EQ(dbg("#declare G = array[2][3] {{1,2,3},{4,5,6}}; #debug str(G[1][2],0,0) #debug str(dimension_size(G,2),0,0) #debug str(dimensions(G),0,0)"),
              "632");
    EXPECT_EQ(dbg("#declare S = array[2] {\"a\", \"b\"}; #debug concat(S[1], S[0])"), "ba");
    EXPECT_NE(err("#declare A = array[2] {1, 2, 3};").find("more elements"), std::string::npos);
    EXPECT_NE(err("#declare A = array[2]; #declare B = A[1] + 1;").find("before it was given a value"), std::string::npos);
    EXPECT_NE(err("#declare A = array[2]; #declare B = A[2];").find("out of range 0..1"), std::string::npos);
}

TEST(SdlArrays, ArraysOfArraysAndFreshArraysKeepPovRaysCopyRules) {
    // Values measured with POV-Ray 3.7.0: an array in an initialiser is copied, G[0][0] indexes
    // the inner array, and each call of a macro returning its local array gives a new array.
    EXPECT_EQ(dbg("#declare A = array[2] {1, 2}; #declare G = array[1] {A}; #declare G[0][0] = 9;"
                  "#debug concat(str(A[0],0,0), str(G[0][0],0,0))"),
              "19");
    EXPECT_EQ(dbg("#macro M() #local L = array[2] {5, 6}; L #end #declare X = M(); #declare X[0] = 7;"
                  "#declare Y = M(); #debug concat(str(X[0],0,0), str(Y[0],0,0))"),
              "75");
    EXPECT_EQ(dbg("#declare A = array[2] {1, 2}; #declare B = array[1]; #declare B[0] = A; #declare B[0][1] = 8;"
                  "#debug concat(str(A[1],0,0), str(B[0][1],0,0)) #if (defined(B[0][1])) #debug \"d\" #end"),
              "28d");
    // An element of an inner array starts the expression after it (POV-Ray 3.7.0: 3, 7, 11, 5,7,9).
    const std::string g = "#declare G = array[2] { array[2] {1, 2}, array[2] {3, 4} };"
                          "#declare H = array[1] { array[2] {<1,2,3>, <4,5,6>} };";
    EXPECT_EQ(dbg(g + "#declare A = G[0][1] + 1; #declare B = G[1][0] * 2 + G[0][0]; #declare C = H[0][1].y * 2 + 1;"
                      "#declare D = H[0][0] + H[0][1]; #debug concat(str(A,0,0), str(B,0,0), str(C,0,0), vstr(3,D,\",\",0,0))"),
              "37115,7,9");
    EXPECT_NE(err("#declare A = array[2] {1, 2}; #declare G = array[1] {A}; #declare G[0][2] = 1;").find("out of range 0..1"),
              std::string::npos);
}

TEST(SdlStrings, FunctionsAndComparisons) {
    EXPECT_EQ(dbg("#debug concat(\"a\", str(12.345, 0, 1), chr(66), substr(\"ABCDEF\", 2, 3))"), "a12.3BBCD");
    EXPECT_EQ(dbg("#debug str(strlen(\"hello\"),0,0) #debug strupr(\"aB\") #debug strlwr(\"aB\")"), "5ABab");
    EXPECT_EQ(dbg("#declare S = \"abc\"; #if (S = \"abc\") #debug \"eq\" #end #if (S < \"abd\") #debug \"lt\" #end"), "eqlt");
    EXPECT_EQ(dbg("#debug str(val(\"1e3\"),0,0) #debug str(asc(\"A\"),0,0) #debug str(strcmp(\"a\",\"b\"),0,0)"), "100065-1");
}

TEST(SdlRandom, SeedAndRandFollowPovRaysSequence) {
    // POV-Ray 3.7: rand(seed(0)) first gives 12345 / (2^32 - 1).
    EXPECT_EQ(dbg("#declare S = seed(0); #debug str(rand(S), 0, 15)"), "0.000002874294297");
    EXPECT_EQ(dbg("#declare S = seed(0); #declare T = seed(5); #debug str(S,0,0) #debug str(T,0,0)"), "01");
}

TEST(SdlSplines, LinearSplineInterpolatesAndClamps) {
    const char* s = "#declare P = spline { linear_spline 0, <0,0,0>, 1, <2,4,6> } ";
    EXPECT_EQ(dbg(std::string(s) + "#debug vstr(3, P(0.5), \",\", 0, 1)"), "1.0,2.0,3.0");
    EXPECT_EQ(dbg(std::string(s) + "#debug vstr(3, P(2), \",\", 0, 1)"), "2.0,4.0,6.0");
}

TEST(SdlFunctions, BodiesCompileAndEvaluateWhileParsing) {
    EXPECT_EQ(dbg("#declare F = function { x*x + y*y + z*z - 1 } #debug str(F(1, 2, 3), 0, 1)"), "13.0");
    EXPECT_EQ(dbg("#declare G = function(a, b) { select(a - b, -1, 1) } #debug str(G(1, 2), 0, 0)"), "-1");
    EXPECT_EQ(dbg("#declare K = 3; #declare H = function(u) { u * K + pi * 0 } #declare K = 100; #debug str(H(2), 0, 0)"),
              "6");  // identifiers of floats are constants of the body, read when it is defined
    EXPECT_EQ(dbg("#declare F = function(n) { prod(i, 1, n, i) } #debug str(F(5), 0, 0)"), "120");
    EXPECT_EQ(dbg("#declare A = function { x + 1 } #declare B = function { A(x, y, z) * 2 } #debug str(B(1, 0, 0), 0, 0)"), "4");
    // A macro in a body runs once, when the function is defined.
    EXPECT_EQ(dbg("#macro Two() 2 #end #declare F = function { x * Two() } #debug str(F(8, 0, 0), 0, 0)"), "16");
    EXPECT_EQ(dbg("#declare S = function { spline { linear_spline 0, <0,0,0>, 1, <2,4,6> } } #debug str(S(0.5).y, 0, 1)"), "2.0");
    // An array element is a constant operand; the rest of the expression stays the body's
    // (values from POV-Ray 3.7.0).
    EXPECT_EQ(dbg("#declare A = array[2] {7, 8}; #declare G = function { A[1] * x + 1 } #debug str(G(2, 0, 0), 0, 0)"), "17");
    // A sum's variable is seen from its `to` expression on, holding `from` there.
    EXPECT_EQ(dbg("#declare S = function { sum(i, 1, 3, sum(i, 1, i, i)) } #debug str(S(0, 0, 0), 0, 0)"), "3");
    EXPECT_EQ(dbg("#declare T = function { sum(j, 1, 4, j) } #debug str(T(0, 0, 0), 0, 0)"), "10");
    EXPECT_NE(err("#declare F = function { x + Nope }").find("undeclared identifier 'Nope' in a function body"), std::string::npos);
    EXPECT_NE(err("#declare F = function { x } #declare G = F(1, 2);").find("takes 3 arguments, 2 given"), std::string::npos);
}

TEST(SdlItems, DeclaredObjectIsBoundBeforeTheNextDirective) {
    const test::SdlRun r = runSdl("#declare O = sphere { 0, 1 }\n#declare P = object { O }\nobject { P }");
    ASSERT_EQ(r.error, "");
    ASSERT_EQ(r.items.size(), 1u);
    EXPECT_EQ(r.items[0]->kind, sdl::Kw::object);
}

TEST(SdlErrors, NameTheFileLineAndColumn) {
    EXPECT_EQ(err("#declare A = 1;\n#declare B = C + 1;"), "scene.pov:2:14: error: undeclared identifier 'C'");
    EXPECT_EQ(err("#declare A = 1\nsphere { 0, 1 }"),
              "scene.pov:1:14: error: the declaration of 'A' must end with ';' (float, vector and colour declarations need one since POV-Ray 3.5)");
    EXPECT_EQ(err("#if (1)\n#debug \"x\""), "scene.pov:1:1: error: this directive is never closed by #end (end of file reached)");
    EXPECT_EQ(err("#error \"stop here\\n\""), "scene.pov:1:1: error: #error: stop here");
    EXPECT_EQ(err("#end"), "scene.pov:1:1: error: #end without a matching #if, #while, #for, #switch or #macro");
}

TEST(SdlErrors, MacroCallsAppearInTheMessage) {
    EXPECT_EQ(err("#macro M()\n  #declare A = Nope;\n#end\nM()"),
              "scene.pov:2:16: error: undeclared identifier 'Nope' (in macro M called at scene.pov:4:1)");
}

TEST(SdlErrors, RunawayLoopsAndRecursionStop) {
    sdl::Limits limits;
    limits.loopIterations = 10000;
    limits.macroDepth = 500;
    EXPECT_EQ(runSdl("#while (1) #end", {}, ".", limits).error,
              "scene.pov:1:1: error: loops ran more than 10000 iterations (runaway #while?)");
    EXPECT_NE(runSdl("#macro R() R() #end R()", {}, ".", limits).error.find("macro calls nested deeper than 500"), std::string::npos);
}

TEST(SdlErrors, AnInterruptStopsALongParse) {
    // The host's check (Ctrl-C in the CLI) runs every 65536 tokens; here it stops the 3rd time.
    test::GenericHost host;
    sdl::Diagnostics d;
    int checks = 0;
    struct Stop {};
    d.checkInterrupt = [&] {
        if (++checks == 3) throw Stop{};
    };
    sdl::LanguageOptions o;
    o.installedIncludeDir.clear();
    sdl::Interpreter in(o, host, d);
    EXPECT_THROW(in.runText("#while (1) #declare A = 1; #end", "scene.pov"), Stop);
    EXPECT_EQ(checks, 3);
}

class SdlFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() / ("rays_sdl_" + std::to_string(::getpid()) + "_" +
                                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }
    std::filesystem::path dir_;
};

TEST_F(SdlFiles, IncludeFilesSeeAndSetGlobalsAndKeepTheirLocals) {
    write("a.inc", "#local L = 1; #declare G = 2; #macro Twice(X) (2*X) #end");
    const test::SdlRun r = runSdl("#include \"a.inc\" #debug str(Twice(G),0,0) #ifdef (L) #debug \"L\" #end", {}, dir_.string());
    EXPECT_EQ(r.error, "");
    EXPECT_EQ(r.debug, "4");
}

TEST_F(SdlFiles, IncludeChainAppearsInErrors) {
    write("a.inc", "#include \"b.inc\"");
    write("b.inc", "#declare X = Missing;");
    EXPECT_EQ(runSdl("\n#include \"a.inc\"", {}, dir_.string()).error,
              "b.inc:1:14: error: undeclared identifier 'Missing' (in b.inc included from a.inc:1:1; in a.inc included from scene.pov:2:1)");
}

TEST_F(SdlFiles, LibraryPathsAreSearchedAndCyclesStop) {
    std::filesystem::create_directories(dir_ / "lib");
    std::ofstream(dir_ / "lib" / "l.inc") << "#declare FromLib = 3;";
    sdl::LanguageOptions o;
    o.libraryPaths.push_back((dir_ / "lib").string());
    EXPECT_EQ(runSdl("#include \"l.inc\" #debug str(FromLib,0,0)", o, dir_.string()).debug, "3");
    write("self.inc", "#include \"self.inc\"");
    EXPECT_NE(runSdl("#include \"self.inc\"", {}, dir_.string()).error.find("include files nested deeper than 64"), std::string::npos);
    EXPECT_NE(runSdl("#include \"nope.inc\"", {}, dir_.string()).error.find("cannot find include file \"nope.inc\""), std::string::npos);
}

TEST_F(SdlFiles, AnIncludeHeaderIsReadBeforeTheScene) {
    // Include_Header / +HI: as if `#include` stood before the scene's first line.
    write("head.inc", "#declare FromHead = 7; #declare Later = 1;");
    sdl::LanguageOptions o;
    o.includeHeader = "head.inc";
    EXPECT_EQ(runSdl("#declare Later = 2; #debug str(FromHead + Later, 0, 0)", o, dir_.string()).debug, "9");
    write("bad.inc", "#declare X = Missing;");
    o.includeHeader = "bad.inc";
    EXPECT_EQ(runSdl("\n#debug \"x\"", o, dir_.string()).error,
              "bad.inc:1:14: error: undeclared identifier 'Missing' (in bad.inc included from scene.pov:1:1)");
    o.includeHeader = "nope.inc";
    EXPECT_EQ(runSdl("#debug \"x\"", o, dir_.string()).error,
              "rays: error: Include_Header: cannot find \"nope.inc\" (searched the scene's folder, the library paths)");
}

TEST_F(SdlFiles, WriteThenReadBack) {
    const std::string s =
        "#fopen F \"data.txt\" write #write (F, 1.5, \",\", <1,2,3>, \",\\\"hi\\\"\") #fclose F "
        "#fopen G \"data.txt\" read #read (G, A, B, C) #debug concat(str(A,0,1), vstr(3,B,\";\",0,0), C) "
        "#read (G, D) #ifdef (G) #debug \"open\" #else #debug \" closed\" #end";
    const test::SdlRun r = runSdl(s, {}, dir_.string());
    EXPECT_EQ(r.error, "");
    EXPECT_EQ(r.debug, "1.51;2;3hi closed");
    EXPECT_NE(runSdl("#fopen F \"../x.txt\" write", {}, dir_.string()).error.find("scene's folder"), std::string::npos);
}

TEST(SdlOptions, ClockImageSizeAndDeclares) {
    sdl::LanguageOptions o;
    o.animation.clock = 0.25;
    o.animation.frameNumber = 3;
    o.imageWidth = 320;
    EXPECT_EQ(runSdl("#debug concat(str(clock,0,2), \" \", str(frame_number,0,0), \" \", str(image_width,0,0))", o).debug,
              "0.25 3 320");
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
