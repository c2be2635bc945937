#include "render_command.h"

#include <unistd.h>

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
#include "rays/io/obj_loader.h"
#include "rays/image/filter.h"
#include "rays/npr/feature_lines.h"
#include "rays/npr/stencil_pass.h"
#include "rays/render/renderer.h"
#include "interrupt.h"
#include "paths.h"
#include "render_budget.h"
#include "render_limits.h"

namespace rays::cli {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

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
    if (job.savePartial && img && scene && img->width > 0) {
        const std::string partial = partialImagePath(job.outputPath);
        try {
            checkOutputIsNotInput(partial, job.scenePath);
            checkOutputIsNotInput(partial, job.objPath);
            checkOutputIsNoTexture(partial, *scene);
            CriticalSection writing;
            writeImage(partial, toImage8(*img), job.jpegQuality);
            std::fprintf(stderr, "rays: warning: partial image saved to %s\n", partial.c_str());
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
    if (!isSupportedImageExtension(path))
        failFile(path, std::string("unsupported ") + what + " image format (use .png, .jpg, .jpeg, .ppm, .tga or .bmp)");
    checkOutputDirectory(path);
    checkOutputIsNotInput(path, job.scenePath);
    checkOutputIsNotInput(path, job.objPath);
}

// The streamed PNG's bytes; a failure is named after the file, as writeImage names it.
std::vector<uint8_t> finishPng(PngStream& png, const std::string& path) {
    try {
        return png.finish();
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
    if (o.width >= 0) e.width = o.width;
    if (o.creaseAngle >= 0) e.creaseAngle = o.creaseAngle;
    if (!o.color.empty()) {
        double c[3];
        char extra;
        if (std::sscanf(o.color.c_str(), "%lf,%lf,%lf%c", &c[0], &c[1], &c[2], &extra) != 3)
            throw Error("rays: error: --edge-color takes R,G,B (0..1), got '" + o.color + "'");
        e.color = {c[0], c[1], c[2]};
    }
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

Scene loadJobScene(const RenderJob& job) {
    ParseOptions opt;
    opt.rotation = job.rotation;
    opt.threads = job.settings.threads;
    opt.language = job.language;
    opt.language.imageWidth = job.settings.width;
    opt.language.imageHeight = job.settings.height;
    opt.checkInterrupt = [] { throwIfInterrupted(); };  // Ctrl-C stops a long parse
    Scene scene = loadScene(job.scenePath, opt);
    if (!job.objPath.empty()) appendObj(scene, job.objPath);
    return scene;
}

int runRender(const RenderJob& job) {
    InterruptScope interruptScope;  // Ctrl-C / SIGTERM stop the render cleanly (exit 130 / 143)
    const RenderSettings& s = job.settings;
    checkSettingsLimits(s);  // every form of the command line comes through here
    checkImageOutput(job.outputPath, "output", job);
    if (!job.edges.maskPath.empty()) checkImageOutput(job.edges.maskPath, "mask", job);

    auto t0 = Clock::now();
    std::optional<QuitAtOnce> loading(std::in_place);  // nothing written yet: a signal ends it at once
    const Scene scene = loadJobScene(job);
    if (s.cameraIndex < 0 || size_t(s.cameraIndex) >= scene.cameras.size())
        failFile(job.scenePath, "camera " + std::to_string(s.cameraIndex) + " does not exist (the scene has " +
                                    std::to_string(scene.cameras.size()) + ")");
    checkOutputIsNoTexture(job.outputPath, scene);
    if (!job.edges.maskPath.empty()) checkOutputIsNoTexture(job.edges.maskPath, scene);
    const double parseMs = msSince(t0);
    const EdgeSettings edges = resolveEdges(scene.edges, job.edges);
    BufferFeatures buffers;
    buffers.aaEdges = s.aaEdges && !edges.linesOnly;
    buffers.lines = edges.enabled() || edges.linesOnly;
    buffers.mask = !job.edges.maskPath.empty();
    buffers.post = !job.post.empty();
    checkRenderBudget(s.width, s.height, resolveView(scene, s).samples, buffers, sceneBytes(scene));
    stopIfInterrupted(job, &scene, nullptr);

    // The render records what each pixel centre saw for the lines when it can (centred samples);
    // the surface ids those records need are computed while the BVH is built.
    const bool reuse = edges.enabled() && !edges.linesOnly && renderRecordsAreCentred(scene, s);
    std::future<SurfaceIds> surfaceIds;
    if (reuse) surfaceIds = std::async(std::launch::async, [&scene] { return computeSurfaceIds(scene); });

    t0 = Clock::now();
    const Bvh bvh(scene.objects);
    const double buildMs = msSince(t0);
    loading.reset();
    stopIfInterrupted(job, &scene, nullptr);

    t0 = Clock::now();
    TraceStats stats;
    ProgressBar bar(!job.quiet && isatty(STDERR_FILENO));
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
    if (isPngPath(job.outputPath) && !buffers.lines && !buffers.post && !s.aaEdges) {
        png = std::make_unique<PngStream>(s.width, s.height);
        onRows = [&](const ImageF& rows, int y0, int y1, int) { png->rowsDone(rows, y0, y1); };
    }
    ImageF img = edges.linesOnly ? ImageF(s.width, s.height)
                                 : render(scene, bvh, s, stats, [&](double f) { bar(f); }, nullptr, onRecord, onRows);
    stopIfInterrupted(job, &scene, &img);
    if (!job.post.empty()) img = applyFilters(img, job.post, BorderMode::Clamp, s.threads);
    const double renderMs = msSince(t0);
    double linesMs = 0;
    LineCoverage lines;
    if (edges.enabled() || edges.linesOnly) {
        t0 = Clock::now();
        lines = stencil ? stencil->finish(stats) : drawFeatureLines(scene, bvh, s, edges, records.get(), stats);
        stopIfInterrupted(job, &scene, &img);
        compositeLines(img, lines, edges, s.threads);
        linesMs = msSince(t0);
    }

    t0 = Clock::now();
    {
        // A signal from here on waits until both files are complete: never a temporary left behind.
        CriticalSection writing;
        stopIfInterrupted(job, &scene, &img);
        if (!job.edges.maskPath.empty()) writeImage(job.edges.maskPath, coverageImage(lines), job.jpegQuality);
        if (png)
            writeFileAtomically(job.outputPath, finishPng(*png, job.outputPath));
        else
            writeImage(job.outputPath, toImage8(img), job.jpegQuality);
    }
    const double writeMs = msSince(t0);

    if (!job.quiet && job.summary) {
        const double mrays = renderMs > 0 ? stats.total() / (renderMs * 1000.0) : 0.0;
        const double mraysAll = (renderMs + linesMs) > 0 ? stats.total() / ((renderMs + linesMs) * 1000.0) : 0.0;
        if (edges.enabled())
            std::fprintf(stderr, "rays: wrote %s (%dx%d): parse %.1f ms, build %.1f ms, render %.1f ms, lines %.1f ms, write %.1f ms; %.2f Mrays/s\n",
                         job.outputPath.c_str(), s.width, s.height, parseMs, buildMs, renderMs, linesMs, writeMs, mraysAll);
        else
            std::fprintf(stderr, "rays: wrote %s (%dx%d): parse %.1f ms, build %.1f ms, render %.1f ms, write %.1f ms; %.2f Mrays/s\n",
                         job.outputPath.c_str(), s.width, s.height, parseMs, buildMs, renderMs, writeMs, mrays);
    }
    if (job.stats) {
        std::fprintf(stderr, "stats: objects %zu, lights %zu, BVH nodes %zu (depth %d), threads %d\n",
                     scene.objects.size(), scene.lights.size(), bvh.nodeCount(), bvh.depth(),
                     resolveThreads(s.threads));
        std::fprintf(stderr, "stats: rays %llu (primary %llu, secondary %llu, shadow %llu)\n",
                     (unsigned long long)stats.total(), (unsigned long long)stats.primaryRays,
                     (unsigned long long)stats.secondaryRays, (unsigned long long)stats.shadowRays);
    }
    return 0;
}

}  // namespace rays::cli
