// Expressions compiled per place (sdl/expr_code.h): what compiles, what the type check refuses,
// and that loops and macros that run compiled code read exactly what the text reader reads
// (values, rand() sequences, errors, macros whose text goes on in the caller).
#include <gtest/gtest.h>

#include "rays/sdl/expr_code.h"
#include "rays/sdl/lexer.h"
#include "support/sdl_run.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

using test::runSdl;

struct Compiled {
    bool ok = false;
    sdl::ExprCode code;
    sdl::SourceFile file;
};

// Compiles text as binary(minPrec, full) would read it at its first token.
Compiled compile(const std::string& text, int minPrec = 3, bool full = false) {
    Compiled c;
    sdl::Names names;
    sdl::lexFile(text, c.file, names);
    c.ok = sdl::compileExpression(c.file.tokens.data(), 0, minPrec, full, false, c.code);
    return c;
}

std::string dbg(const std::string& text) {
    const test::SdlRun r = runSdl(text);
    EXPECT_EQ(r.error, "") << text;
    return r.debug;
}

TEST(SdlCompiledExpressions, CompilesThePureArithmeticAndStopsWhereTheReaderStops) {
    Compiled c = compile("A * B + sin(A) ;");
    ASSERT_TRUE(c.ok);
    EXPECT_EQ(c.code.idents.size(), 3u);
    EXPECT_EQ(c.code.end, 8u);  // at ';'
    // Outside parentheses '>' closes a vector and comparisons end the expression.
    c = compile("A + 1 > 2");
    ASSERT_TRUE(c.ok);
    EXPECT_EQ(c.code.end, 3u);
    c = compile("A + 1 > 2 ;", 1, true);
    ASSERT_TRUE(c.ok);
    EXPECT_EQ(c.code.end, 5u);
    // A right operand read at precedence 4 stops before '+'.
    c = compile("A * B + C", 4);
    ASSERT_TRUE(c.ok);
    EXPECT_EQ(c.code.end, 3u);
    EXPECT_TRUE(compile("<1, 2, A>.y * (B < 2 ? 3 : 4) - vlength(<1, 1>) + max(1, 2, 3) + rand(R) ;").ok);
}

TEST(SdlCompiledExpressions, LeavesToTheReaderWhatItCannotCompile) {
    EXPECT_FALSE(compile("rgb 1").ok);             // colour keywords
    EXPECT_FALSE(compile("A + \"s\"").ok);          // strings
    EXPECT_FALSE(compile("A + seed(1)").ok);        // a function with a side effect on the scene
    EXPECT_FALSE(compile("A + (B #declare C = 1 )").ok);  // a directive inside
    EXPECT_FALSE(compile("<1, 2, 3, 4, 5, 6>").ok);  // the reader's error
    EXPECT_FALSE(compile("sin(1, 2)").ok);
    // After a directive or an identifier (a macro may go on with the expression) only one plain
    // operand may end the code: the reader carries it on there.
    EXPECT_FALSE(compile("A + B #end").ok);
    EXPECT_FALSE(compile("-A #end").ok);
    EXPECT_FALSE(compile("A + B M").ok);
    EXPECT_TRUE(compile("(A + B) #end").ok);
    EXPECT_TRUE(compile("sin(A) #end").ok);
}

TEST(SdlCompiledExpressions, TypeCheckRefusesWhatTheReaderWouldReportAndFindsScalarCode) {
    Compiled c = compile("A.y + B ;");
    ASSERT_TRUE(c.ok);
    const uint8_t floats[2] = {0, 0}, vector3[2] = {3, 0};
    EXPECT_FALSE(sdl::typeCheckExpression(c.code, floats));  // '.y' of a float
    EXPECT_TRUE(sdl::typeCheckExpression(c.code, vector3));
    EXPECT_FALSE(sdl::scalarExpression(c.code, vector3));  // a component needs vectors
    c = compile("(A ? B : C) ;");
    ASSERT_TRUE(c.ok);
    const uint8_t mixed[3] = {0, 0, 3}, same[3] = {0, 0, 0}, vectorTest[3] = {3, 0, 0};
    EXPECT_FALSE(sdl::typeCheckExpression(c.code, mixed));       // the type would depend on A's value
    EXPECT_FALSE(sdl::typeCheckExpression(c.code, vectorTest));  // a vector as a condition
    EXPECT_TRUE(sdl::typeCheckExpression(c.code, same));
    EXPECT_TRUE(sdl::scalarExpression(c.code, same));
}

TEST(SdlCompiledExpressions, LoopsReadTheSameValuesWhenIdentifiersChangeKind) {
    // The same place read with a float, then a vector, then a colour, then a macro in A.
    EXPECT_EQ(dbg("#macro M() 7 #end"
                  "#declare I = 0; #while (I < 4)"
                  "  #switch (I) #case (0) #declare A = 2; #break #case (1) #declare A = <1, 2, 3>; #break"
                  "  #case (2) #declare A = rgb <1, 0, 0>; #break #else #undef A #declare A = 5; #end"
                  "  #declare B = A * 2 + 1;"
                  "  #if (I = 1 | I = 2) #debug vstr(3, B, \",\", 0, 0) #else #debug str(B, 0, 0) #end #debug \";\""
                  "  #declare I = I + 1; #end"),
              "5;3,5,7;3,1,1;11;");
}

TEST(SdlCompiledExpressions, MacroTextGoesOnInTheCallersExpression) {
    // POV-Ray's macros are text: `F(a, b) * 2` with a body `A + B` multiplies only B (POV-Ray
    // 3.7 prints 234 for the first loop).
    EXPECT_EQ(dbg("#macro F(A, B) A + B #end"
                  "#declare I = 0; #while (I < 3) #declare R = F(I, 1) * 2; #debug str(R, 0, 0) #declare I = I + 1; #end"),
              "234");
    EXPECT_EQ(dbg("#macro G(A) (A * 3) #end"
                  "#declare I = 0; #while (I < 3) #declare R = G(I) * 2 + 1; #debug str(R, 0, 0) #declare I = I + 1; #end"),
              "1713");
    // A component after the macro's end applies to its value.
    EXPECT_EQ(dbg("#macro V(A) <A, 2 * A, 3> #end"
                  "#declare I = 1; #while (I < 3) #declare R = V(I).y + 0; #debug str(R, 0, 0) #declare I = I + 1; #end"),
              "24");
}

TEST(SdlCompiledExpressions, ArrayElementsAreReadAsTheReaderReadsThem) {
    Compiled c = compile("A[I][J + 1] * 2 ;");
    ASSERT_TRUE(c.ok);
    EXPECT_TRUE(c.code.hasElement);
    ASSERT_EQ(c.code.indexCount.size(), 3u);  // I, J, then the element of A
    EXPECT_EQ(c.code.indexCount[2], 2u);
    // A run that meets an unset element leaves it to the reader: not with rand()'s stream moved.
    EXPECT_FALSE(compile("A[I] + rand(R) ;").ok);
    // Vectors of several sizes in one array, and an array of two dimensions.
    EXPECT_EQ(dbg("#declare A = array[3] {<1, 2>, <1, 2, 3>, <4, 5, 6>}"
                  "#declare I = 0; #while (I < 3) #declare B = A[I] * 2 + 1; #debug vstr(3, B, \",\", 0, 0)"
                  "  #debug \";\" #declare I = I + 1; #end"
                  "#declare G = array[2][2] {{1, 2}, {3, 4}}"
                  "#declare I = 0; #while (I < 4) #declare B = G[div(I, 2)][mod(I, 2)] * 10; #debug str(B, 0, 0)"
                  "  #debug \";\" #declare I = I + 1; #end"),
              "3,5,0;3,5,7;9,11,13;10;20;30;40;");
    // The reader's errors where a run meets an unset element or an index out of range.
    EXPECT_EQ(runSdl("#declare A = array[4] #declare A[0] = 1; #declare A[1] = 2; #declare A[3] = 4;\n"
                     "#declare I = 0; #while (I < 4) #declare B = A[I] * 2 + 1; #declare I = I + 1; #end").error,
              "scene.pov:2:50: error: array element is used before it was given a value");
    EXPECT_EQ(runSdl("#declare A = array[3] {1, 2, 3}\n"
                     "#declare I = 0; #while (I < 4) #declare B = A[I] * 2 + 1; #declare I = I + 1; #end").error,
              "scene.pov:2:46: error: array index 3 is out of range 0..2");
}

TEST(SdlCompiledExpressions, RandSequencesAndErrorsAreTheReaders) {
    // The same stream read through compiled code in a loop and through the reader once each.
    const std::string loop = dbg(
        "#declare S = seed(7); #declare I = 0;"
        "#while (I < 5) #declare V = rand(S) * 10 + I; #debug str(V, 0, 6) #debug \",\" #declare I = I + 1; #end");
    const std::string once = dbg(
        "#declare S = seed(7);"
        "#debug str(rand(S) * 10 + 0, 0, 6) #debug \",\" #debug str(rand(S) * 10 + 1, 0, 6) #debug \",\""
        "#debug str(rand(S) * 10 + 2, 0, 6) #debug \",\" #debug str(rand(S) * 10 + 3, 0, 6) #debug \",\""
        "#debug str(rand(S) * 10 + 4, 0, 6) #debug \",\"");
    EXPECT_EQ(loop, once);
    // An illegal stream found on the third run names rand's place.
    EXPECT_EQ(runSdl("#declare S = seed(1); #declare I = 0;\n"
                     "#while (I < 5) #if (I = 2) #declare S = 9; #end\n"
                     "  #declare V = 1 + rand(S) * 2; #declare I = I + 1; #end").error,
              "scene.pov:3:20: error: Illegal random number generator.");
    EXPECT_EQ(runSdl("#declare I = 0; #declare P = x;\n"
                     "#while (I < 3) #if (I = 2) #declare P = 0 * x; #end\n"
                     "  #declare V = 2 * vnormalize(P); #declare I = I + 1; #end").error,
              "scene.pov:3:20: error: vnormalize of a zero vector");
}

TEST(SdlCompiledExpressions, DeprecatedIdentifiersStillWarnInLoops) {
    const test::SdlRun r = runSdl(
        "#declare deprecated \"old A\" A = 1; #declare I = 0;"
        "#while (I < 3) #declare B = A + I; #declare I = I + 1; #end");
    EXPECT_EQ(r.error, "");
    EXPECT_EQ(r.warnings.size(), 3u);
}

}}  // namespace RAYS_TEST_UNIT
}  // namespace rays
