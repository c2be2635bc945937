// rays: command-line entry point. Four forms:
//   rays render|raycast|sceneinfo|pixelray|firsthit|pixelcolor|printrays SCENE ... (course form,
//        plus modern options and POV-Ray switches on render),
//   rays WIDTH HEIGHT INPUT.pov OUTPUT.png SHADING RAYS_PER_PIXEL DEPTH [MODEL.obj] (positional form),
//   rays +Iscene.pov +W640 +H480 ... | rays scene.ini ... (POV-Ray's form: pov_forms.h).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "rays/accel/bvh.h"
#include "rays/error.h"
#include "rays/render/course_commands.h"
#include "animation.h"
#include "arg_text.h"
#include "compare_command.h"
#include "filter_command.h"
#include "flag_values.h"
#include "frame_plan.h"
#include "heap_setup.h"
#include "stdout_check.h"
#include "interrupt.h"
#include "pov_forms.h"
#include "pov_options.h"
#include "pov_settings.h"
#include "rays/image/filter.h"
#include "render_command.h"
#include "render_limits.h"
#include "render_options.h"
#include "scene_library.h"
#ifdef RAYS_WITH_MPI
#include "mpi/mpi_frames.h"
#include "mpi/mpi_session.h"
#endif

using namespace rays;

namespace {

int toInt(const std::string& s, const char* what) {
    if (!cli::isDigits(s) || s.size() > 9) throw Error(std::string("rays: error: ") + what + " must be a non-negative integer, got '" + s + "'");
    return std::stoi(s);
}

// Positional form of the original C++ system.
int runPositional(const std::vector<std::string>& a) {
    if (a.size() < 7 || a.size() > 8)
        throw Error("rays: error: positional form is: rays WIDTH HEIGHT INPUT.pov OUTPUT.png SHADING_MODEL RAYS_PER_PIXEL RECURSION_DEPTH [MODEL.obj]");
    cli::RenderJob job;
    job.settings.width = toInt(a[0], "WIDTH");
    job.settings.height = toInt(a[1], "HEIGHT");
    job.scenePath = a[2];
    job.outputPath = a[3];
    const int model = toInt(a[4], "SHADING_MODEL");
    if (model > 5)
        throw Error("rays: error: SHADING_MODEL must be 0 (Blinn-Phong), 1 (Cook-Torrance), 2 (Oren-Nayar), 3 (Lambert), "
                    "4 (flat) or 5 (normals); got " + a[4]);
    job.settings.shading = ShadingModel(model);
    job.settings.spp = toInt(a[5], "RAYS_PER_PIXEL");
    if (job.settings.spp < 1) throw Error("rays: error: RAYS_PER_PIXEL must be at least 1");
    if (job.settings.spp > 1) job.settings.aa = AaMode::Stratified;
    job.settings.maxDepth = toInt(a[6], "RECURSION_DEPTH");
    if (a.size() == 8) job.objPath = a[7];
    return cli::runRender(job);
}

int run(int argc, char** argv) {
    if (argc > 1 && std::string(argv[1]) == "filter")
        return cli::runFilterCommand(std::vector<std::string>(argv + 2, argv + argc));
    if (argc > 1 && std::string(argv[1]) == "compare")
        return cli::runCompareCommand(std::vector<std::string>(argv + 2, argv + argc));
    std::vector<std::string> args = cli::normaliseCourseFlags(argc, argv);
    if (!args.empty() && cli::isDigits(args[0])) return runPositional(args);
    static const std::vector<std::string> kCommands = {"render", "raycast", "sceneinfo", "pixelray", "firsthit", "pixelcolor", "printrays", "scenes", "assets", "filter", "compare"};
    const bool povForm = cli::isPovForm(args, kCommands);
    if (!povForm && !args.empty() && args[0][0] != '-' &&
        std::none_of(kCommands.begin(), kCommands.end(), [&](const std::string& c) { return args[0] == c; }))
        throw Error("rays: error: unknown command '" + args[0] +
                    "' (commands: render, raycast, sceneinfo, pixelray, firsthit, pixelcolor, printrays, scenes, assets, filter, compare; "
                    "or the positional form WIDTH HEIGHT INPUT OUTPUT SHADING RAYS_PER_PIXEL DEPTH [OBJ])");

    CLI::App app{"Rays: a fast ray tracer for POV-Ray-style scenes with feature lines", "rays"};
    app.set_version_flag("--version", std::string("rays ") + RAYS_VERSION);
    app.require_subcommand(1);
    app.footer("Positional form: rays WIDTH HEIGHT INPUT.pov OUTPUT.png SHADING_MODEL RAYS_PER_PIXEL RECURSION_DEPTH [MODEL.obj]\n"
               "POV-Ray's form: rays +Iscene.pov +W640 +H480 +A0.3 [+Oout.png] [file.ini[Section]] [KEY=VALUE] (see rays render --help)\n"
               "Course flags may be written with one dash: -altbrdf -fresnel -beers -ss=N -sds.\n"
               "Image tools (see their --help): rays filter INPUT OUTPUT KERNEL...; rays compare A B [--diff DIFF]\n");

    std::string scene;
    int width = -1, height = -1, px = 0, py = 0;  // -1: not given
    cli::CourseFlags flags;
    cli::ModernOptions modern;
    cli::RenderJob job;
    std::string obj, libraryScene;
    bool povrayRotate = false;

    // render
    CLI::App* render = app.add_subcommand("render", "render a scene to an image (default output.png)");
    cli::SharedOptions shared;
    std::vector<std::string> povArgs, libraries;
    std::string dialect;
    bool strict = false, resume = false;
    shared.pov = render->add_option("--pov", povArgs, "")  // POV-Ray arguments, marked by markPovArguments
                     ->allow_extra_args(false)
                     ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
                     ->group("");
    shared.scene = render->add_option("scene", scene, "scene file (.pov); or --scene");
    shared.width = render->add_option("width", width, "image width in pixels (or -W)");
    shared.height = render->add_option("height", height, "image height in pixels (or -H)");
    cli::addCourseFlags(render, flags);
    shared.output = render->add_option("-o,--output", job.outputPath, "output image: .png .jpg .ppm .tga .bmp, or .exr .pfm (linear float) (default output.png)");
    shared.widthFlag = render->add_option("-W,--width", width, "image width in pixels");
    shared.heightFlag = render->add_option("-H,--height", height, "image height in pixels");
    cli::addModernOptions(render, modern, job.settings);
    shared.libraryScene = render->add_option("--scene", libraryScene, "render a shipped scene by number or name (see `rays scenes`)");
    shared.library = render->add_option("--library", libraries, "folder searched for #include files, after the scene's (repeatable; POV-Ray: +LPATH)")
                         ->allow_extra_args(false);
    render->add_option("--dialect", dialect, "scene language: auto (default) | course | povray")
        ->check(CLI::IsMember({"auto", "course", "povray"}));
    render->add_flag("--strict", strict, "a POV-Ray feature parsed but not rendered yet is an error, not a warning");
    shared.resume = render->add_flag("--resume", resume, "skip frames (or the image) already written (POV-Ray: +C)");
    std::string post;
    render->add_option("--post", post, "filter kernels applied to the rendered image, e.g. gaussian_blur_3,sharpen (see rays filter)");
    render->add_option("--edges", job.edges.types, "feature lines: silhouette,occlusion,intersection,crease,material,shadow,reflection | all | none");
    render->add_option("--edge-method", job.edges.method, "stencil (default) | image");
    render->add_option("--edge-width", job.edges.width, "line width in pixels, 0.5 to 8 (default 1.5)");
    render->add_option("--edge-color", job.edges.color, "line colour R,G,B in 0..1 (default 0,0,0)");
    render->add_option("--crease-angle", job.edges.creaseAngle, "crease threshold in degrees (default 30)");
    render->add_flag("--lines-only", job.edges.linesOnly, "lines on white, no shading");
    render->add_option("--edge-mask", job.edges.maskPath, "also write the line coverage as a greyscale image");
    // EXR / PFM output and AOVs (docs/aov.md)
    render->add_option("--aov", job.aovs, "extra outputs: depth,normal,albedo,objectid,materialid,coverage,edgetype | all (EXR channels, else OUTPUT.NAME.pfm)");
    render->add_flag("--exr-half", job.exrHalf, "EXR colour channels as 16-bit half floats (default 32-bit float)");
    render->add_option("--obj", obj, "add an OBJ mesh to the scene with a default material");
    shared.jpegQuality = render->add_option("--jpeg-quality", job.jpegQuality, "JPEG quality 1-100 (default 90)")->check(CLI::Range(1, 100));
    render->add_flag("--povray-rotate", povrayRotate, "apply rotate x, then y, then z as POV-Ray does (course: z first)");
    render->add_flag("-q,--quiet", job.quiet, "no progress bar or summary on stderr");
    render->add_flag("--stats", job.stats, "print counters (rays by kind, BVH size) on stderr");
    render->add_flag("--save-partial", job.savePartial, "on Ctrl-C, save what was rendered as OUTPUT.partial.png");
    for (const char* name : {"--spp", "--aa", "--ss"}) shared.antialias.push_back(render->get_option(name));
    shared.threads = render->get_option("--threads");
    render->footer(
        "POV-Ray switches and INI files (docs/cli.md), mixed with the options above in any order (a later one wins):\n"
        "  +Iscene.pov +Oout.png +W640 +H480 +A[0.3] -A +AM2 +R3 +J[0.5] -J +L/path +K0.5 +KFI1 +KFF30 +KI0 +KF1 +KC\n"
        "  +SF/+EF (frame subset) +STP2 +SR/+ER/+SC/+EC (a part; the rest black) +C (resume) +WT2 +FN +FJ +FP +FT +FB\n"
        "  +FN16 (16-bit PNG) -F (no image file) File_Gamma=1.8 +HIheader.inc\n"
        "  accepted and not acted on: +D -D +V +P +Q9 +GA etc. +MB +UA (warns)\n"
        "  KEY=VALUE (Width=640, Declare=NAME=1, Work_Threads=2), file.ini or file.ini[Section]\n"
        "In `rays render` a POV-Ray switch starts with '+', or '-' and an upper-case letter (-D, -A); -W and -H are the same\n"
        "in both. -o wins over +O when it comes later and is used exactly as written.\n"
        "Animation: +KFF N renders frames 1..N as OUTPUT01.png ...; --resume (+C) skips frames already written.");

    // raycast
    CLI::App* raycast = app.add_subcommand("raycast", "render flat object colours (course part 1) to output.png");
    raycast->add_option("scene", scene, "scene file")->required();
    raycast->add_option("width", width, "image width")->required();
    raycast->add_option("height", height, "image height")->required();
    raycast->add_option("-o,--output", job.outputPath, "output image (default output.png)");
    raycast->add_flag("-q,--quiet", job.quiet, "no progress or summary");

    // scenes
    CLI::App* scenes = app.add_subcommand("scenes", "list the shipped scenes (render one with render --scene N)");

    // assets
    std::string assetDir;
    CLI::App* assets = app.add_subcommand("assets", "write the procedural textures the demo scenes use (checker, bricks, brick normal and height maps)");
    assets->add_option("dir", assetDir, "output folder (must exist)")->required();

    // filter and compare run before this parser (runFilterCommand, runCompareCommand); listed here
    // so that `rays --help` names them.
    app.add_subcommand("filter", "apply image convolution filters: rays filter IN.png OUT.png KERNEL... (see rays filter --help)");
    app.add_subcommand("compare", "compare two images (SSIM, PSNR): rays compare A.png B.png (see rays compare --help)");

    // sceneinfo
    CLI::App* sceneinfo = app.add_subcommand("sceneinfo", "print the camera, lights and objects of a scene");
    sceneinfo->add_option("scene", scene, "scene file")->required();

    // pixel commands
    auto pixelCommand = [&](const char* name, const char* help, bool withFlags) {
        CLI::App* c = app.add_subcommand(name, help);
        c->add_option("scene", scene, "scene file")->required();
        c->add_option("width", width, "image width")->required();
        c->add_option("height", height, "image height")->required();
        c->add_option("x", px, "pixel column (0 = left)")->required();
        c->add_option("y", py, "pixel row (0 = bottom)")->required();
        if (withFlags) cli::addCourseFlags(c, flags);
        return c;
    };
    CLI::App* pixelray = pixelCommand("pixelray", "print the primary ray of a pixel", false);
    CLI::App* firsthit = pixelCommand("firsthit", "print the first hit of a pixel's ray", false);
    CLI::App* pixelcolor = pixelCommand("pixelcolor", "print the shaded colour of a pixel", true);
    CLI::App* printrays = pixelCommand("printrays", "print the whole ray tree of a pixel", true);

    if (povForm) {
        args = cli::markPovArguments(args, *render, true);
        args.insert(args.begin(), "render");
    } else if (!args.empty() && args[0] == "render") {
        const std::vector<std::string> rest = cli::markPovArguments({args.begin() + 1, args.end()}, *render, false);
        args.resize(1);
        args.insert(args.end(), rest.begin(), rest.end());
    }
    try {
        std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them reversed
        app.parse(reversed);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
        // One line with the usual prefix, like every other error (CLI11 adds a second line).
        throw Error(std::string("rays: error: ") + e.what() + " (see rays --help)");
    }

    if (assets->parsed()) return cli::writeAssets(assetDir);
    if (scenes->parsed()) {
        std::printf("Scenes in %s (render one: rays render --scene N):\n", cli::sceneDirectory().c_str());
        for (const cli::LibraryScene& ls : cli::listScenes(cli::sceneDirectory()))
            std::printf("%3d  %-20s %s\n", ls.number, ls.name.c_str(), ls.description.c_str());
        return 0;
    }
    if (!post.empty()) job.post = parseKernelList(splitKernelList(post));  // bad kernels fail before rendering
    job.scenePath = scene;
    RenderSettings& s = job.settings;
    job.rotation = povrayRotate ? RotationOrder::Povray : RotationOrder::Course;
    job.objPath = obj;

    if (render->parsed()) {
        // POV-Ray's options and render's own ones for the same settings, in command-line order.
        cli::PovOptions pov;
        cli::PovOptionReader reader(pov, [](const std::string& line) { std::cerr << printableMessage(line) << '\n'; });
        cli::readInOrder(*render, shared, reader);
        if (shared.width->count() > 0 && pov.height == -1)
            throw Error("rays: error: width " + shared.width->results().front() + " without a height: give both "
                        "(rays render SCENE WIDTH HEIGHT)");  // `rays render s.pov 320` rendered 320x480
        if (pov.inputFile.empty())
            throw Error(povForm ? "rays: error: no scene: give +Iscene.pov, a .pov file or Input_File_Name in an INI file"
                                : "rays: error: no scene: give a scene file or --scene N");
        if (pov.antialias.given) modern.aaEdges = false;  // the POV-Ray threshold decides edge-guided sampling
        cli::applyOptions(flags, modern, s);
        cli::applyPovOptions(pov, povForm, job);
        job.language.dialect = dialect == "course" ? sdl::Dialect::Course
                               : dialect == "povray" ? sdl::Dialect::Povray
                                                     : sdl::Dialect::Auto;
        job.language.strict = strict;
        const cli::FramePlan plan = cli::planFrames(pov.animation);
#ifdef RAYS_WITH_MPI
        if (cli::mpi::rank() > 0) job.quiet = true;  // rank 0 reports for all ranks
        // At least a frame per rank: whole frames to the ranks; fewer: each frame shared like a still.
        if (plan.animated && cli::mpi::size() > 1 && plan.frames.size() >= size_t(cli::mpi::size()))
            return cli::mpi::runFramesOnRanks(job, plan, pov.continueTrace, cli::runRender);
#endif
        return cli::runFrames(job, plan, pov.continueTrace, cli::runRender);
    }
    cli::applyOptions(flags, modern, s);
    if (raycast->parsed()) {
        s.width = width == -1 ? 640 : width;
        s.height = height == -1 ? 480 : height;
        s.shading = ShadingModel::Flat;
        return cli::runRender(job);
    }

    // The scene is loaded as render loads it, with the command's image size (image_width and
    // image_height; sceneinfo has none and sees render's default).
    if (sceneinfo->parsed()) {
        printSceneInfo(std::cout, cli::loadJobScene(job));
        return 0;
    }
    s.width = width;
    s.height = height;
    cli::checkSettingsLimits(s);
    if (px < 0 || px >= width || py < 0 || py >= height)
        throw Error("rays: error: pixel [" + std::to_string(px) + ", " + std::to_string(py) + "] is outside the " +
                    std::to_string(width) + "x" + std::to_string(height) + " image");
    const Scene sc = cli::loadJobScene(job);
    if (pixelray->parsed()) {
        printPixelRay(std::cout, sc, s, px, py);
        return 0;
    }
    const Bvh bvh(sc.objects);
    if (firsthit->parsed()) printFirstHit(std::cout, sc, bvh, s, px, py);
    else if (pixelcolor->parsed()) printPixelColor(std::cout, sc, bvh, s, px, py);
    else if (printrays->parsed()) printRays(std::cout, sc, bvh, s, px, py);
    return 0;
}

// After a command that wrote to stdout (sceneinfo, the pixel commands, compare's figures, --help):
// everything written must have arrived. Returns the exit status.
int checkStdout(int status) {
    cli::flushStdout();
    return status;
}

// run() with its errors reported as exit statuses.
int runMain(int argc, char** argv) {
    try {
        return checkStdout(run(argc, argv));
    } catch (const cli::Interrupted& e) {
        if (!cli::interruptMessagesMuted()) std::cerr << "rays: interrupted; no image written\n";
        return e.exitStatus();
    } catch (const std::bad_alloc&) {
        std::cerr << "rays: error: out of memory\n";
        return 1;
    } catch (const Error& e) {
        std::cerr << e.what() << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "rays: internal error: " << printableMessage(e.what()) << '\n';
        return 1;
    }
}

}  // namespace

int main(int argc, char** argv) {
    cli::prepareHeap();
#ifdef RAYS_WITH_MPI
    cli::mpi::start(&argc, &argv);  // only under mpirun / mpiexec / srun (apps/rays/mpi)
    return cli::mpi::finish(runMain(argc, argv));
#else
    return runMain(argc, argv);
#endif
}
