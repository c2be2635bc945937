#include "render_command.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <future>
#include <memory>
#include <optional>
#include <iostream>

#include "rays/accel/bvh.h"
#include "rays/error.h"
#include "rays/image/image.h"
#include "rays/io/image_io.h"
#include "rays/io/png_stream.h"
#include "rays/io/mesh_from_obj.h"
#include "rays/io/output_files.h"
#include "rays/io/obj_loader.h"
#include "rays/image/filter.h"
#include "rays/npr/feature_lines.h"
#include "rays/npr/edge_types.h"
#include "rays/npr/stencil_pass.h"
#include "rays/render/renderer.h"
#include "flag_values.h"
#include "interrupt.h"
#include "paths.h"
#include "render_budget.h"
#include "hdr_output.h"
#ifdef RAYS_WITH_MPI
#include "mpi/mpi_render.h"
#include "mpi/mpi_session.h"
#include "mpi/mpi_summary.h"
#endif
#include "render_limits.h"

namespace rays::cli {
namespace {

using Clock = std::chrono::steady_clock;

// This process's place among the ranks of an MPI run (0 of 1 without MPI: apps/rays/mpi).
#ifdef RAYS_WITH_MPI
int worldRank() { return mpi::rank(); }
int worldSize() { return mpi::size(); }
#else
constexpr int worldRank() { return 0; }
constexpr int worldSize() { return 1; }
#endif

double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

#ifdef RAYS_WITH_MPI
// The MPI line after a shared still: the slowest rank's parse and build, rank 0's render (which
// includes receiving the bands) and write, each rank's rays per second and the load balance.
void printShareSummary(const mpi::ShareFigures& share, double renderMs, double writeMs) {
    mpi::JobPhases phases;
    for (const mpi::RankFigures& r : share.ranks) phases.parseBuild = std::max(phases.parseBuild, r.parseBuild);
    phases.render = renderMs / 1000;
    phases.gather = share.gatherSeconds;
    phases.write = writeMs / 1000;
    std::fprintf(stderr, "%s\n", mpi::summaryLine(share.ranks, phases, mpi::hostCount()).c_str());
}
#endif

// An OBJ given on the command line becomes one mesh object with a default material: the MTL's
// first diffuse colour (else grey 0.8), ambient 0.2, diffuse 0.7, specular 0.2, roughness 0.3.
void appendObj(Scene& scene, const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) failFile(path, "cannot open OBJ file");
    const ObjMesh obj = loadObj(path);
    if (obj.faces.empty()) failFile(path, "OBJ file has no faces (is it an OBJ file?)");
    Object o;
    o.material.color = obj.materials.empty() ? Vec3{0.8, 0.8, 0.8} : obj.materials[0].diffuse;
    o.material.ambient = 0.2;
    o.material.diffuse = 0.7;
    o.material.specular = 0.2;
    o.material.roughness = 0.3;
    std::unique_ptr<Mesh> mesh = meshFromObj(obj);
    o.type = ShapeType::Mesh;
    o.mesh = mesh.get();
    scene.meshes.push_back(std::move(mesh));
    prepareObject(o, Transform{});
    scene.objects.push_back(o);
}

// Refuses to overwrite an image the scene reads (image_map, normal_map, bump_map).
void checkOutputIsNoTexture(const std::string& output, const Scene& scene) {
    for (const Texture& t : scene.textures) checkOutputIsNotInput(output, t.path);
}

// After a signal (Ctrl-C): optionally saves what was rendered so far as OUTPUT.partial.png, then
// throws Interrupted; the output itself is never written.
void stopIfInterrupted(const RenderJob& job, const Scene* scene, const ImageF* img) {
    if (!interrupted()) return;
    if (job.savePartial && job.outputToFile && img && scene && img->width > 0) {
        const std::string partial = partialImagePath(job.outputPath);
        try {
            checkOutputIsNotInput(partial, job.scenePath);
            checkOutputIsNotInput(partial, job.objPath);
            checkOutputIsNoTexture(partial, *scene);
            CriticalSection writing;
            writeImage(partial, toImage8(*img), job.jpegQuality);
            std::fprintf(stderr, "rays: warning: partial image saved to %s\n", printableMessage(partial).c_str());
        } catch (const Error& e) {
            std::fprintf(stderr, "rays: warning: partial image not saved: %s\n", e.what());
        }
    }
    throwIfInterrupted();
}

// Fails before rendering when the image could not be written where asked.
void checkOutputDirectory(const std::string& output) {
    std::error_code ec;
    const std::filesystem::path parent = std::filesystem::absolute(output, ec).parent_path();
    if (!std::filesystem::is_directory(parent, ec))
        failFile(output, "cannot write the image: directory '" + parent.string() + "' does not exist");
    if (access(parent.c_str(), W_OK) != 0)
        failFile(output, "cannot write the image: directory '" + parent.string() + "' is not writable");
    if (std::filesystem::is_directory(output, ec)) failFile(output, "is a directory");
}

// An image the render will write (what: "output" or "mask"): a known format, in a folder that
// exists, and not one of the job's input files.
void checkImageOutput(const std::string& path, const char* what, const RenderJob& job) {
    const bool hdr = std::string(what) == "output" && isHdrOutput(path);
    if (!isSupportedImageExtension(path) && !hdr)
        failFile(path, std::string("unsupported ") + what + " image format (use .png, .jpg, .jpeg, .ppm, .tga, .bmp" +
                           (std::string(what) == "output" ? ", .exr or .pfm)" : ")"));
    if (isExrPath(path) && !exrAvailable())
        failFile(path, "cannot write EXR: this Rays was built without OpenEXR (install libopenexr-dev and rebuild)");
    checkOutputDirectory(path);
    checkOutputIsNotInput(path, job.scenePath);
    checkOutputIsNotInput(path, job.objPath);
    for (const KernelSpec& k : job.post) checkOutputIsNotInput(path, k.file);
}

// The streamed PNG's bytes; a failure is named after the file, as writeImage names it.
std::vector<uint8_t> finishPng(PngStream& png, const std::string& path) {
    try {
        return png.finish();
    } catch (const Error& e) {
        throw Error(path + ": " + e.what());
    }
}

// The image as a PNG of 16 bits per channel; a failure is named after the file.
std::vector<uint8_t> png16Bytes(const ImageF& img, const std::string& path) {
    try {
        return encodePng16(img);
    } catch (const Error& e) {
        throw Error(path + ": " + e.what());
    }
}

class ProgressBar {
public:
    explicit ProgressBar(bool enabled) : enabled_(enabled), start_(Clock::now()) {}
    void operator()(double fraction) {
        if (!enabled_) return;
        const int width = 30;
        const int filled = int(fraction * width + 0.5);
        const double elapsed = msSince(start_) / 1000.0;
        char eta[32] = "";
        if (fraction > 0.02 && fraction < 1.0)
            std::snprintf(eta, sizeof eta, " ETA %.1f s", elapsed * (1.0 - fraction) / fraction);
        std::fprintf(stderr, "\rrendering [%-*s] %3d%%%s   ", width, std::string(size_t(filled), '#').c_str(),
                     int(fraction * 100 + 0.5), eta);
        if (fraction >= 1.0) std::fprintf(stderr, "\r%*s\r", width + 40, "");
        std::fflush(stderr);
    }

private:
    bool enabled_;
    Clock::time_point start_;
};

}  // namespace

EdgeSettings resolveEdges(const EdgeSettings& fromScene, const EdgeOptions& o) {
    EdgeSettings e = fromScene;
    if (!o.types.empty()) e.types = parseEdgeTypes(o.types);
    if (!o.method.empty()) {
        if (o.method == "stencil") e.method = EdgeMethod::Stencil;
        else if (o.method == "image") e.method = EdgeMethod::Image;
        else throw Error("rays: error: unknown edge method '" + o.method + "' (use stencil or image)");
    }
    if (!o.width.empty()) e.width = flagNumber(o.width, "--edge-width");
    if (!o.creaseAngle.empty()) e.creaseAngle = flagNumber(o.creaseAngle, "--crease-angle");
    if (!o.color.empty()) e.color = flagColour(o.color, "--edge-color");
    if (o.linesOnly) e.linesOnly = true;
    // Lines-only without any edge type asked for (an explicit --edges none stays empty): draw the
    // outline, folds, intersections and creases.
    if (e.linesOnly && e.types == 0 && o.types.empty())
        e.types = kEdgeSilhouette | kEdgeOcclusion | kEdgeCrease | kEdgeIntersection;
    validateEdgeSettings(e);
    if (!o.maskPath.empty() && !e.enabled())
        throw Error("rays: error: --edge-mask needs edge lines (--edges LIST or an edges { } block)");
    return e;
}

void checkImageSize(int width, int height) {
    constexpr int kMaxSide = 65536;
    if (width <= 0 || height <= 0)
        throw Error("rays: error: image size must be positive, got " + std::to_string(width) + "x" +
                    std::to_string(height));
    if (width > kMaxSide || height > kMaxSide || double(width) * height > 268435456.0)
        throw Error("rays: error: image size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is too large (at most 65536 per side and 268435456 pixels)");
}

Scene loadJobScene(const RenderJob& job, const std::vector<std::string>& outputs) {
    ParseOptions opt;
    opt.rotation = job.rotation;
    opt.threads = job.settings.threads;
    opt.language = job.language;
    opt.language.outputFiles = outputs;
    opt.language.imageWidth = job.settings.width;
    opt.language.imageHeight = job.settings.height;
    opt.checkInterrupt = [] { throwIfInterrupted(); };  // Ctrl-C stops a long parse
    Scene scene = loadScene(job.scenePath, opt);
    if (!job.objPath.empty()) appendObj(scene, job.objPath);
    return scene;
}

// The AOVs in the order they are written.
constexpr AovBit kAovOrder[] = {kAovDepth, kAovNormal, kAovAlbedo, kAovObjectId, kAovMaterialId, kAovCoverage, kAovEdgeType};

int runRender(const RenderJob& job) {
    InterruptScope interruptScope;  // Ctrl-C / SIGTERM stop the render cleanly (exit 130 / 143)
    // HDR outputs (.exr, .pfm) take the linear float image (docs/aov.md).
    const bool hdrOutput = isHdrOutput(job.outputPath);
    RenderSettings s = job.settings;
    s.linearOutput = hdrOutput;
    checkImageSize(s.width, s.height);
    checkSettingsLimits(s);  // every form of the command line comes through here
    // Under MPI only rank 0 writes files (the others may run where its folders do not exist),
    // unless this process renders the job alone (a frame handed out whole).
    const int ranks = job.alone ? 1 : worldSize();
    const bool writer = job.alone || worldRank() == 0;
    const unsigned aovKinds = parseAovList(job.aovs);
    const bool aovFiles = job.outputToFile && aovKinds != 0 && !isExrPath(job.outputPath);  // one PFM per AOV
    const bool image = writer && job.outputToFile;  // Output_to_File=off: no image file
    const bool png16 = job.bitsPerColor > 8 && isPngPath(job.outputPath);
    if (image && job.bitsPerColor > 8 && !png16 && !hdrOutput && !job.quiet)
        std::fprintf(stderr, "rays: warning: %d bits per colour are written for PNG images only: %s has 8\n",
                     job.bitsPerColor, printableMessage(job.outputPath).c_str());
    if (writer) {
        if (image) checkImageOutput(job.outputPath, "output", job);
        if (aovFiles)
            for (AovBit bit : kAovOrder)
                if (aovKinds & bit) {
                    checkOutputIsNotInput(aovFilePath(job.outputPath, bit), job.scenePath);
                    checkOutputIsNotInput(aovFilePath(job.outputPath, bit), job.objPath);
                }
        if (!job.edges.maskPath.empty()) checkImageOutput(job.edges.maskPath, "mask", job);
        std::vector<NamedOutput> outputs = {{image ? job.outputPath : std::string(), "output image"},
                                            {job.edges.maskPath, "edge mask"},
                                            {image && job.savePartial ? partialImagePath(job.outputPath) : std::string(), "partial image"}};
        if (aovFiles)
            for (AovBit bit : kAovOrder)
                if (aovKinds & bit) outputs.push_back({aovFilePath(job.outputPath, bit), "AOV file"});
        checkOutputsDiffer(outputs);
    }

    auto t0 = Clock::now();
    std::optional<QuitAtOnce> loading(std::in_place);  // nothing written yet: a signal ends it at once
    const Scene scene = loadJobScene(job, {image ? job.outputPath : std::string(), job.edges.maskPath});
    if (s.cameraIndex < 0 || size_t(s.cameraIndex) >= scene.cameras.size())
        failFile(job.scenePath, "camera " + std::to_string(s.cameraIndex) + " does not exist (the scene has " +
                                    std::to_string(scene.cameras.size()) + ")");
    if (image) checkOutputIsNoTexture(job.outputPath, scene);
    if (!job.edges.maskPath.empty()) checkOutputIsNoTexture(job.edges.maskPath, scene);
    const double parseMs = msSince(t0);
    const EdgeSettings edges = resolveEdges(scene.edges, job.edges);
    BufferFeatures buffers;
    buffers.aaEdges = s.aaEdges && !edges.linesOnly;
    buffers.aaColours = s.aaThreshold >= 0;
    buffers.lines = edges.enabled() || edges.linesOnly;
    buffers.mask = !job.edges.maskPath.empty();
    buffers.post = !job.post.empty();
    checkRenderBudget(s.width, s.height, resolveView(scene, s).samples, buffers, sceneBytes(scene));
    stopIfInterrupted(job, &scene, nullptr);
    // Ranks share single-pass renders only; edge-guided AA and lines-only renders (no render) run
    // on rank 0 alone for now, the other ranks stop here.
    const bool distributed = ranks > 1 && !s.aaEdges && !edges.linesOnly && s.wholeImage();
    if (ranks > 1 && !distributed) {
        if (!writer) return 0;
        if (!job.quiet)
            std::fprintf(stderr, "rays: mpi: %s renders on rank 0 alone\n",
                         s.aaEdges ? "edge-guided AA" : (edges.linesOnly ? "--lines-only" : "a part of the image"));
    }

    // The render records what each pixel centre saw for the lines when it can (centred samples);
    // the surface ids those records need are computed while the BVH is built.
    // Under MPI the records stay with the ranks that rendered the pixels: the lines trace their own.
    const bool reuse = !distributed && edges.enabled() && !edges.linesOnly && renderRecordsAreCentred(scene, s);
    std::future<SurfaceIds> surfaceIds;
    if (reuse) surfaceIds = std::async(std::launch::async, [&scene] { return computeSurfaceIds(scene); });

    t0 = Clock::now();
    const Bvh bvh(scene.objects);
    const double buildMs = msSince(t0);
    loading.reset();
    stopIfInterrupted(job, &scene, nullptr);

    t0 = Clock::now();
    TraceStats stats;
    ProgressBar bar(writer && !job.quiet && isatty(STDERR_FILENO));
    std::unique_ptr<LineRecords> records;
    std::unique_ptr<StencilPass> stencil;
    RecordFn onRecord;
    RowsFn onRows;
    if (reuse) {
        records = std::make_unique<LineRecords>(surfaceIds.get(), s.width, s.height);
        onRecord = [&](int x, int y, const PathInfo& info) { records->store(x, y, info); };
        if (edges.method == EdgeMethod::Stencil) {
            // Stencil lines drawn by the render's threads, band by band, as rows finish.
            stencil = std::make_unique<StencilPass>(scene, bvh, s, edges, *records);
            onRows = [&](const ImageF&, int y0, int y1, int worker) { stencil->rowsDone(y0, y1, worker); };
        }
    }
    // A PNG of the render as it stands is compressed by the render's threads as rows finish.
    std::unique_ptr<PngStream> png;
    // Under MPI rank 0 compresses each band as it lands, its own or another rank's.
    if (isPngPath(job.outputPath) && !png16 && !buffers.lines && !buffers.post && !s.aaEdges && image) {
        png = std::make_unique<PngStream>(s.width, s.height);
        onRows = [&](const ImageF& rows, int y0, int y1, int) { png->rowsDone(rows, y0, y1); };
    }
    ImageF img;
#ifdef RAYS_WITH_MPI
    mpi::ShareFigures share;
    if (distributed) {
        img = mpi::renderDistributed(scene, bvh, s, (parseMs + buildMs) / 1000, stats, [&](double f) { bar(f); }, onRows,
                                     share);
        if (!writer) return 0;  // rank 0 alone filters, draws the lines and writes
    }
#endif
    if (!distributed)
        img = edges.linesOnly ? ImageF(s.width, s.height)
                              : render(scene, bvh, s, stats, [&](double f) { bar(f); }, nullptr, onRecord, onRows);
    stopIfInterrupted(job, &scene, &img);
    if (!job.post.empty()) {
        // The filters do not look at the flag and write nothing: a signal ends the process at once
        // (a --save-partial image is not written then).
        QuitAtOnce filtering;
        img = applyFilters(img, job.post, BorderMode::Clamp, s.threads);
    }
    const double renderMs = msSince(t0);
    double linesMs = 0;
    LineCoverage lines;
    if (edges.enabled() || edges.linesOnly) {
        t0 = Clock::now();
        // The edgetype AOV reads the centre records afterwards: probed here when the render did
        // not record them (drawFeatureLines then uses them instead of probing its own).
        if ((aovKinds & kAovEdgeType) && !records && edges.enabled()) {
            records = std::make_unique<LineRecords>(scene, s.width, s.height);
            probeLineRecords(scene, bvh, s, edges, *records, stats);
        }
        lines = stencil ? stencil->finish(stats) : drawFeatureLines(scene, bvh, s, edges, records.get(), stats);
        stopIfInterrupted(job, &scene, &img);
        compositeLines(img, lines, edges, s.threads);
        linesMs = msSince(t0);
    }
    // A part of the image (Start_Row …): lines and filters do not reach beyond it either.
    if (!s.wholeImage())
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x)
                if (!s.inRegion(x, y)) img.at(x, y) = Vec3{};

    // The AOVs: one pixel-centre ray per pixel (aov.h).
    AovBuffers aov = aovKinds ? computeAovs(scene, bvh, s, aovKinds) : AovBuffers{};
    if ((aovKinds & kAovEdgeType) && records && !lines.coverage.empty()) aov.edgeType = lineEdgeTypes(*records, lines, edges);
    const LineCoverage* lineCoverage = lines.coverage.empty() ? nullptr : &lines;

    t0 = Clock::now();
    {
        // A signal from here on waits until both files are complete: never a temporary left behind.
        // Both are written in full before either replaces an old file: a failure changes neither.
        CriticalSection writing;
        stopIfInterrupted(job, &scene, &img);
        OutputFiles files;
        if (!image) {
            // Output_to_File=off: no image file
        } else if (png) {
            files.stage(job.outputPath, finishPng(*png, job.outputPath));
        } else if (png16) {
            files.stage(job.outputPath, png16Bytes(img, job.outputPath));
        } else if (isExrPath(job.outputPath)) {
            files.stage(job.outputPath, encodeHdrImage(job.outputPath, exrImage(img, job.exrHalf, aov, lineCoverage, aovKinds)));
        } else if (hdrOutput) {
            files.stage(job.outputPath, encodeHdrImage(job.outputPath, colourImage(img, false)));
        } else {
            files.stage(job.outputPath, encodeImageFile(job.outputPath, toImage8(img), job.jpegQuality));
        }
        if (!job.edges.maskPath.empty())
            files.stage(job.edges.maskPath, encodeImageFile(job.edges.maskPath, coverageImage(lines), job.jpegQuality));
        if (aovFiles)
            for (AovBit bit : kAovOrder)
                if (aovKinds & bit) {
                    const std::string path = aovFilePath(job.outputPath, bit);
                    files.stage(path, encodeHdrImage(path, aovImage(aov, lineCoverage, bit)));
                }
        files.commit();
    }
    const double writeMs = msSince(t0);
    if (job.figures) *job.figures = RenderFigures{parseMs + buildMs, renderMs + linesMs, writeMs, double(stats.total())};

    if (!job.quiet && job.summary) {
        const double mrays = renderMs > 0 ? stats.total() / (renderMs * 1000.0) : 0.0;
        const double mraysAll = (renderMs + linesMs) > 0 ? stats.total() / ((renderMs + linesMs) * 1000.0) : 0.0;
        const std::string what = image ? "wrote " + printableMessage(job.outputPath) : std::string("rendered, no image written (Output_to_File=off)");
        if (edges.enabled())
            std::fprintf(stderr, "rays: %s (%dx%d): parse %.1f ms, build %.1f ms, render %.1f ms, lines %.1f ms, write %.1f ms; %.2f Mrays/s\n",
                         what.c_str(), s.width, s.height, parseMs, buildMs, renderMs, linesMs, writeMs, mraysAll);
        else
            std::fprintf(stderr, "rays: %s (%dx%d): parse %.1f ms, build %.1f ms, render %.1f ms, write %.1f ms; %.2f Mrays/s\n",
                         what.c_str(), s.width, s.height, parseMs, buildMs, renderMs, writeMs, mrays);
    }
#ifdef RAYS_WITH_MPI
    if (distributed && !job.quiet) printShareSummary(share, renderMs + linesMs, writeMs);
#endif
    if (job.stats) {
        std::fprintf(stderr, "stats: objects %zu, lights %zu, BVH nodes %zu (depth %d), threads %d\n",
                     scene.objects.size(), scene.lights.size(), bvh.nodeCount(), bvh.depth(),
                     resolveThreads(s.threads));
        std::fprintf(stderr, "stats: scene about %.1f MB in memory (objects, their BVH share, meshes, textures)\n",
                     double(sceneBytes(scene)) / 1e6);
        std::fprintf(stderr, "stats: rays %llu (primary %llu, secondary %llu, shadow %llu)\n",
                     (unsigned long long)stats.total(), (unsigned long long)stats.primaryRays,
                     (unsigned long long)stats.secondaryRays, (unsigned long long)stats.shadowRays);
    }
    return 0;
}

}  // namespace rays::cli
