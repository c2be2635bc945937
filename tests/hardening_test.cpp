// Hardening II beyond the catalogue rows (tests/errors_hardening_test.cpp): permissions of replaced
// outputs, the outputs of one run committed together (OutputFiles), write errors on stdout, the
// message rules of rays::Error (escaped, bounded), source text forms (byte-order mark, CR-only
// lines), unusable transforms and the shared checks of command-line numbers.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../apps/rays/flag_values.cpp"
#include "rays/error.h"
#include "rays/image/kernels.h"
#include "rays/io/file_text.h"
#include "rays/io/obj_loader.h"
#include "rays/io/output_files.h"
#include "rays/math/transform.h"
#include "support/files.h"
#include "support/process.h"

namespace fs = std::filesystem;
using rays::test::readFile;
using rays::test::runProcess;
using rays::test::TempDir;
using rays::test::writeFile;

namespace { namespace RAYS_TEST_UNIT {

const std::string kScene =
    "camera { location <0,0,14> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }\n"
    "light_source { <10,10,10> color rgb <1,1,1> }\n"
    "sphere { <0,0,0>, 2 pigment { color rgb <1,0,0> } finish { ambient 0.2 diffuse 0.6 } }\n";

rays::test::ProcessResult rays_(const TempDir& dir, const std::vector<std::string>& args) {
    return runProcess(RAYS_BINARY, args, dir.path().string(), std::chrono::seconds(60));
}

unsigned modeOf(const fs::path& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 ? unsigned(st.st_mode & 07777) : 0u;
}

// ---- class 5: outputs ----

TEST(HardeningOutputs, ReplacedFilesKeepTheirPermissions) {
    TempDir dir;
    writeFile(dir.path() / "scene.pov", kScene);
    ASSERT_TRUE(rays_(dir, {"render", "scene.pov", "16", "12", "-o", "in.png", "-q"}).ok());
    for (const char* name : {"out.png", "mask.png", "filtered.png", "diff.png"}) {
        writeFile(dir.path() / name, "old");
        fs::permissions(dir.path() / name, fs::perms(0600));
    }
    auto r = rays_(dir, {"render", "scene.pov", "16", "12", "-o", "out.png", "-q", "--edges", "all", "--edge-mask", "mask.png"});
    ASSERT_TRUE(r.ok()) << r.err;
    r = rays_(dir, {"filter", "in.png", "filtered.png", "box_blur_3", "-q"});
    ASSERT_TRUE(r.ok()) << r.err;
    r = rays_(dir, {"compare", "in.png", "out.png", "--diff", "diff.png"});
    ASSERT_TRUE(r.ok()) << r.err;
    for (const char* name : {"out.png", "mask.png", "filtered.png", "diff.png"}) {
        EXPECT_NE(readFile(dir.path() / name), "old") << name << " not replaced";
        EXPECT_EQ(modeOf(dir.path() / name), 0600u) << name;
    }
}

TEST(HardeningOutputs, OutputFilesReplaceNothingUntilCommitted) {
    TempDir dir;
    const fs::path a = dir.path() / "a.bin", b = dir.path() / "b.bin";
    writeFile(a, "old a");
    writeFile(b, "old b");
    {
        rays::OutputFiles files;
        files.stage(a.string(), {'n', 'e', 'w'});
        EXPECT_THROW(files.stage((dir.path() / "nodir" / "c.bin").string(), {'x'}), rays::Error);
        // Destroyed without commit (an error later in the run): nothing replaced, nothing left.
    }
    EXPECT_EQ(readFile(a), "old a");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}), 2);
    {
        rays::OutputFiles files;
        files.stage(a.string(), {'n', 'e', 'w'});
        files.stage(b.string(), {'B'});
        EXPECT_EQ(readFile(a), "old a");  // staged is not yet replaced
        files.commit();
    }
    EXPECT_EQ(readFile(a), "new");
    EXPECT_EQ(readFile(b), "B");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}), 2);
}

TEST(HardeningOutputs, ARenameFailingMidwayLeavesEveryOutputAsItWas) {
    // The third destination is a folder that is not empty: its rename fails after the first two
    // files were renamed over theirs. Before, those two stayed replaced.
    TempDir dir;
    const fs::path a = dir.path() / "a.bin", fresh = dir.path() / "new.bin", folder = dir.path() / "c.bin";
    writeFile(a, "old a");
    fs::create_directory(folder);
    writeFile(folder / "inside", "x");
    rays::OutputFiles files;
    files.stage(a.string(), {'n', 'e', 'w'});
    files.stage(fresh.string(), {'N'});
    files.stage(folder.string(), {'C'});
    try {
        files.commit();
        FAIL() << "commit over a folder succeeded";
    } catch (const rays::Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind(folder.string() + ": error: cannot replace file: ", 0), 0u) << e.what();
    }
    EXPECT_EQ(readFile(a), "old a");
    EXPECT_FALSE(fs::exists(fresh));
    // Nothing else left: no temporary, no backup.
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir.path())) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"a.bin", "c.bin"}));
    // And a commit that succeeds leaves no backup behind either.
    rays::OutputFiles again;
    again.stage(a.string(), {'2'});
    again.commit();
    EXPECT_EQ(readFile(a), "2");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}), 2);
}

// ---- class 8: streams ----

TEST(HardeningStreams, WriteErrorsOnStdoutFailTheCommand) {
    TempDir dir;
    writeFile(dir.path() / "scene.pov", kScene);
    ASSERT_TRUE(rays_(dir, {"render", "scene.pov", "16", "12", "-o", "a.png", "-q"}).ok());
    const std::string bin = RAYS_BINARY;
    for (const std::string& args : {std::string("sceneinfo scene.pov"), std::string("pixelray scene.pov 16 12 3 4"),
                                    std::string("printrays scene.pov 16 12 3 4"), std::string("compare a.png a.png"),
                                    std::string("scenes"), std::string("--help")}) {
        const auto r = runProcess("/bin/sh", {"-c", "exec '" + bin + "' " + args + " > /dev/full"}, dir.path().string(),
                                  std::chrono::seconds(60));
        EXPECT_EQ(r.exitCode, 2) << args << ": " << r.err;
        EXPECT_EQ(r.err, "rays: error: cannot write to standard output: No space left on device\n") << args;
        // The same command with a working stdout succeeds: the failure is the write's.
        const auto ok = runProcess("/bin/sh", {"-c", "exec '" + bin + "' " + args + " > /dev/null"}, dir.path().string(),
                                   std::chrono::seconds(60));
        EXPECT_EQ(ok.exitCode, 0) << args << ": " << ok.err;
    }
}

TEST(HardeningStreams, SourceTextSkipsTheByteOrderMarkAndEndsLinesAtLoneCarriageReturns) {
    std::string text = "\xEF\xBB\xBF" "a\rb\r\nc\r";
    const size_t skip = rays::makeSourceText(text.data(), text.size());
    EXPECT_EQ(text.substr(skip), "a\nb\r\nc\n");
    TempDir dir;
    writeFile(dir.path() / "t.txt", "\xEF\xBB\xBFx\ry");
    const rays::FileText raw((dir.path() / "t.txt").string());
    EXPECT_EQ(raw.text(), "\xEF\xBB\xBFx\ry");
    const rays::FileText source((dir.path() / "t.txt").string(), rays::TextForm::Source);
    EXPECT_EQ(source.text(), "x\ny");
}

TEST(HardeningStreams, KernelFilesAreReadAsSourceText) {
    const rays::KernelSpec k = rays::parseKernelText("\xEF\xBB\xBF" "0 0 0\r0 1 0\r0 0 0\r", "k.txt");
    EXPECT_EQ(k.width, 3);
    EXPECT_EQ(k.height, 3);
    try {
        rays::parseKernelText("0 0 0\r0 1\r", "k.txt");
        ADD_FAILURE() << "a ragged kernel was taken";
    } catch (const rays::Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("k.txt:2:1: error: ragged kernel", 0), 0u) << e.what();
    }
}

TEST(HardeningStreams, ObjAndMtlFilesMayStartWithAByteOrderMark) {
    TempDir dir;
    writeFile(dir.path() / "m.obj", "\xEF\xBB\xBFmtllib m.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    writeFile(dir.path() / "m.mtl", "\xEF\xBB\xBFnewmtl red\r\nKd 1 0 0\r\n");
    const rays::ObjMesh obj = rays::loadObj((dir.path() / "m.obj").string());
    ASSERT_EQ(obj.materials.size(), 1u);
    EXPECT_EQ(obj.materials[0].name, "red");
    EXPECT_EQ(obj.materials[0].diffuse.x, 1.0);
    EXPECT_EQ(obj.faces.size(), 1u);
}

// ---- class 6: messages ----

TEST(HardeningMessages, ErrorsEscapeControlBytesAndKeepUtf8) {
    EXPECT_EQ(rays::printableMessage("a\x1b[2Jb\x07\x7f"), "a\\x1b[2Jb\\x07\\x7f");
    EXPECT_EQ(rays::printableMessage("line\nnext\ttab\rret"), "line\\nnext\\ttab\\rret");
    EXPECT_EQ(rays::printableMessage("caf\xC3\xA9 \xE2\x82\xAC"), "caf\xC3\xA9 \xE2\x82\xAC");  // UTF-8 kept
    EXPECT_EQ(rays::printableMessage("\xC2\x9B" "1m"), "\\xc2\\x9b1m");                        // C1 control (CSI)
    EXPECT_EQ(rays::printableMessage("\xff\xC3"), "\\xff\\xc3");                               // not UTF-8
    EXPECT_EQ(rays::printableMessage("'\\x89'"), "'\\x89'");  // an escape already made stays as it is
    EXPECT_EQ(rays::printableMessage("a\nb\tc\x1b", true), "a\nb\tc\\x1b");
    EXPECT_EQ(std::string(rays::Error("x\x1b").what()), "x\\x1b");
}

TEST(HardeningMessages, LongMessagesKeepTheirStartAndEnd) {
    const std::string msg = "scene.pov:2:1: error: unknown keyword '" + std::string(3'000'000, 'a') + "' (in macro M)";
    const std::string shown = rays::Error(msg).what();
    EXPECT_LE(shown.size(), rays::kMaxMessageBytes);
    EXPECT_EQ(shown.rfind("scene.pov:2:1: error: unknown keyword 'aaa", 0), 0u);
    EXPECT_EQ(shown.substr(shown.size() - 14), "' (in macro M)");
    EXPECT_NE(shown.find(" bytes left out] ... "), std::string::npos);
    std::string mixed;
    for (int i = 0; i < 1000; ++i) mixed += "\xC3\xA9";  // é: a cut never splits one
    const std::string cut = rays::printableMessage(mixed);
    EXPECT_EQ(rays::printableMessage(cut), cut);
}

TEST(HardeningMessages, FileNamesInProgressLinesAreEscaped) {
    TempDir dir;
    writeFile(dir.path() / "scene.pov", kScene);
    const std::string name = "\x1b[2Jx.png";
    auto r = rays_(dir, {"render", "scene.pov", "16", "12", "-o", name});
    ASSERT_TRUE(r.ok()) << r.err;
    EXPECT_EQ(r.err.rfind("rays: wrote \\x1b[2Jx.png (16x12)", 0), 0u) << r.err;
    r = rays_(dir, {"filter", name, "f.png", "box_blur_3"});
    ASSERT_TRUE(r.ok()) << r.err;
    r = rays_(dir, {"filter", "f.png", name, "box_blur_3"});
    ASSERT_TRUE(r.ok()) << r.err;
    EXPECT_EQ(r.err.rfind("rays: wrote \\x1b[2Jx.png (16x12", 0), 0u) << r.err;
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos);
}

TEST(HardeningMessages, AHugeIdentifierGivesABoundedLine) {
    TempDir dir;
    for (const std::string& header : {std::string(), std::string("#version 3.7;\n")}) {
        writeFile(dir.path() / "scene.pov", header + std::string(3'000'000, 'q') + " { }\n");
        const auto r = rays_(dir, {"render", "scene.pov", "16", "12", "-o", "out.png", "-q"});
        EXPECT_EQ(r.exitCode, 2) << header;
        EXPECT_LE(r.err.size(), rays::kMaxMessageBytes + 1) << header;
        EXPECT_NE(r.err.find("bytes left out"), std::string::npos) << r.err.substr(0, 200);
        EXPECT_EQ(r.err.rfind("scene.pov:", 0), 0u) << r.err.substr(0, 200);
    }
}

// ---- class 7: silent acceptance ----

TEST(HardeningTransforms, OverflowAndUnderflowAreNotUsable) {
    using rays::Transform;
    using rays::Vec3;
    EXPECT_TRUE(Transform::scale(Vec3(1e300, 1, 1)).isUsable());
    EXPECT_FALSE((Transform::scale(Vec3(1e300, 1e300, 1e300)) * Transform::scale(Vec3(1e300, 1e300, 1e300))).isUsable());
    EXPECT_FALSE((Transform::scale(Vec3(1e-200, 1, 1)) * Transform::scale(Vec3(1e-200, 1, 1))).isUsable());
    EXPECT_FALSE(Transform::scale(Vec3(1e200, 1e200, 1e-200)).isUsable());  // finite, inverse overflows
    EXPECT_TRUE(Transform::translate(Vec3(1e308, 0, 0)).isUsable());
    EXPECT_FALSE((Transform::translate(Vec3(1e308, 0, 0)) * Transform::translate(Vec3(1e308, 0, 0))).isUsable());
}

TEST(HardeningFlags, NumbersMustBeFiniteAndWhole) {
    using rays::cli::finiteNumber;
    EXPECT_EQ(finiteNumber("0.5"), 0.5);
    EXPECT_EQ(finiteNumber("-3"), -3.0);
    EXPECT_EQ(finiteNumber("+2"), 2.0);
    EXPECT_EQ(finiteNumber("1e3"), 1000.0);
    for (const char* bad : {"", "nan", "NaN", "inf", "-inf", "1e999", "0x10", "5abc", " 1", "1 ", "++1", "+-1"})
        EXPECT_FALSE(finiteNumber(bad)) << bad;
    EXPECT_THROW(rays::cli::flagColour("0.5,0.5", "--edge-color"), rays::Error);
    EXPECT_THROW(rays::cli::flagColour("0,0,0,0", "--edge-color"), rays::Error);
    EXPECT_THROW(rays::cli::flagColour("0,0,1.5", "--edge-color"), rays::Error);
    const rays::Vec3 c = rays::cli::flagColour("0,0.25,1", "--edge-color");
    EXPECT_EQ(c.y, 0.25);
    EXPECT_EQ(c.z, 1.0);
    std::string v = "18446744073709551615";
    EXPECT_EQ(rays::cli::unsigned64Check()(v), "");
    for (std::string bad : {"18446744073709551616", "-1", "1e3", "", "99999999999999999999999"})
        EXPECT_NE(rays::cli::unsigned64Check()(bad), "") << bad;
}

}}  // namespace RAYS_TEST_UNIT, namespace
