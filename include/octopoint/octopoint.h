#pragma once
// octopoint/octopoint.h: the manual, and the one header an app includes.
//
// octopoint draws real 3D range scans, turned into compact octrees, with integer arithmetic only:
// no FPU, no GPU, no allocation while drawing. A scan becomes a model with the octopoint-prepare
// tool (const arrays compiled into the app, or a `.oct` file); the app validates the model once
// and draws it from any camera, frame after frame.
//
//   find_package(octopoint REQUIRED)
//   target_link_libraries(app PRIVATE octopoint::renderer octopoint::models)
//   #include "octopoint/octopoint.h"
//
// Libraries: octopoint::fixedpoint (fixed-point numbers, angles, rotations), octopoint::renderer
// (models, camera, frames, decoders, styles, bands, chunked and progressive models),
// octopoint::models (the default model compiled in), octopoint::interactive (two render threads
// behind one view) and octopoint::net (HTTP streaming, cpp-httplib). Every type and function lives
// in namespace octopoint. This header includes the core headers; three are separate includes, as
// they bring threads or sockets: octopoint/progressive.h (no threads, but the largest API),
// octopoint/interactive.h (std::thread) and octopoint/http.h (octopoint::net, cpp-httplib).
//
// Conventions: errors are returned, never thrown, and every function that returns an error, a
// status or an optional result is [[nodiscard]]. Each error enum has describe(error), a short
// stable English line. Fixed-point formats are written Q(integer bits).(fraction bits): Q17.15 is a
// signed 32-bit value with 15 fraction bits. Nothing that draws allocates; what allocates says so.
//
// ---------------------------------------------------------------------------------------------
// Example 1: one call from an embedded model to RGB pixels (examples/draw_rgb.cpp)
//
//   ModelIssue issue;
//   const EmbeddedModel& embedded = *models::defaultModel();  // const arrays in the library
//   const std::optional<ModelView> model = ModelView::fromEmbedded(embedded, &issue);
//   if (!model) return fail(describe(issue.error));          // validated once, trusted after
//   Camera camera;                                           // 320x240, frontal, zoom 1
//   camera.yaw = Angle::fromDegrees(30);
//   camera.zoom = *zoomRatio(3, 2);                          // 1.5x
//   std::vector<std::uint8_t> rgb(camera.width * camera.height * 3);
//   RgbRenderer renderer;                                    // owns the frame
//   const DrawError error = renderer.draw(*model, camera, rgb, {.fill_holes = true});
//   if (error != DrawError::kNone) return fail(describe(error));
//
// Example 2: bands to an RGB565 panel on a microcontroller, no heap (examples/bands_rgb565.cpp)
//
//   alignas(4) std::uint32_t band_a[16 * 240], band_b[16 * 240];  // two 16-row bands
//   std::array<SubtreeSize, 512> index_storage;
//   void flush(void*, std::int32_t y0, std::int32_t rows, std::span<const std::uint8_t> rgb565) {
//     panelWrite(y0, rows, rgb565);          // rows * 240 RGB565 halfwords, CPU byte order
//   }
//   ...
//   const LevelView& level = model->finestLevel();
//   FrameSetup setup;
//   if (buildFrameSetup(camera, level.depth, kDefaultFractionBits, &setup) != CameraError::kNone)
//     return;                                // camera.width = 240, camera.height = 320
//   BandConfig config;                       // fixed_fast, no hole filling
//   config.band_rows = 16;
//   const Rgb565Palette palette = makeRgb565Palette(*model, config.background);
//   const BandIndex index =
//       buildBandIndex(level, deepestIndexLevel(level, index_storage.size()), index_storage);
//   const BandError error = renderBands(level, setup, config, index, palette,
//                                       {band_a, band_b, {}}, {nullptr, flush, nullptr});
//
// Example 3: a model streamed over HTTP (examples/stream_http.cpp; #include "octopoint/http.h")
//
//   std::string why;
//   const std::optional<net::HttpUrl> url = net::parseHttpUrl(argv[1], &why);
//   if (!url) return fail(why);
//   net::ModelStream stream(*url, net::StreamOptions{});
//   stream.setView(camera);                  // fetch what this view shows, coarse before fine
//   stream.start();
//   const net::StreamStatus status = stream.waitUntilSettled(std::chrono::seconds(30));
//   if (!status.head_known) return fail(status.error);
//   ProgressiveFrame snapshot;               // per drawing thread
//   const ProgressiveModel* model = stream.snapshot(snapshot);  // under the stream's lock
//   Framebuffer frame(camera.width, camera.height);
//   frame.clear();
//   if (!model->draw(snapshot, camera, defaultVariant(), frame)) return fail("camera refused");
//   if (!resolveToRgb(frame, model->baseModel(), Rgb{236, 236, 240}, rgb)) return fail("rgb");
//
// An app draws every frame while the stream runs (the snapshot and draw as above, each frame):
// coarse at first, the file's own picture once the view's chunks have arrived.
// ---------------------------------------------------------------------------------------------
//
// octopoint/fixed.h: numbers (octopoint::fixedpoint; constexpr, no floating point)
//   Fixed<F>                 signed fixed point, value = raw / 2^F, int32 storage, F in 1..30;
//                            Q15 = Fixed<15> (Q17.15), Q16 = Fixed<16> (Q16.16). No conversion
//                            from or to arithmetic types: fromInt, fromRatio, fromRaw; floorToInt,
//                            roundToInt, raw. Every rounding is to nearest, ties toward +infinity.
//   Fixed::fromInt(v), fromRatio(n, d), convert<G>(), checkedAdd/Sub/Mul/Div(a, b)
//                            optional: nullopt when the result does not fit (or d is 0). The
//                            operators + - * assert that it fits: for proven-safe hot paths.
//   mulShiftRound(a, b, s), divShiftRound(n, d, s)
//                            exact round(a * b / 2^s), round(n * 2^s / d) in int64; nullopt on
//                            overflow. roundShiftRight(v, s), mulWideUnsigned(a, b): helpers.
//   Angle                    1/65536 turn, wraps like the circle: fromDegrees, fromMilliDegrees,
//                            fromTurns16, turns16(), + and -.
//   Rotation                 3x3 matrix in Q1.30. rotationFromYawPitchRoll(yaw, pitch, roll)
//                            (yaw first, roll last; each entry within 3.5 units of 2^-30),
//                            identityRotation(), multiplyRotations(lhs, rhs).
//
// octopoint/model.h: models
//   ModelView::fromEmbedded(model, &issue), ModelView::fromBytes(bytes, &issue)
//                            validate a model compiled in (EmbeddedModel, the arrays the preparer
//                            generates) or a whole `.oct` file (version 1 or 2); optional, nullopt
//                            with the ModelIssue (error, byte offset, depth) when anything is
//                            wrong. The view never copies the bytes: they must outlive it. It
//                            builds a small skip index per level on the heap (none on bare metal).
//   ModelView                levelCount(), level(i), levelOfDepth(d) (nullptr when absent),
//                            finestLevel(); paletteCount(), paletteColour(i); hasNormals(),
//                            normalCount(), normal(i) (NormalQ14, Q1.14); colourIsSynthetic();
//                            cubeEdgePicometres(); formatVersion().
//   LevelView                one depth's stream: depth, nodes (child masks, depth first), leaves
//                            (a palette index each), normals (empty or one index each), skip.
//   ModelError, ModelIssue, describe(ModelError)
//   validateLevelStream(level, palette_count, normal_count), plausibleLevelSize(d, nodes, leaves)
//                            what validation runs per level, for tools and tests.
//   format::                 the `.oct` layout's constants (kMagic, kMaxDepth 16, kMaxLevels 8,
//                            kPaletteEntries 256, v1::, v2:: offsets); docs/format.md.
//   SkipIndex, SubtreeEnd, skipIndexLevel, skipIndexEntries, buildSkipIndex
//                            the per-level index ModelView builds; needed only by hand-made views.
//
// octopoint/models.h: the models compiled into octopoint::models
//   models::defaultModel()   the default scan (a tabletop, 62,502 voxels at depth 8).
//   models::findModel(name)  nullptr when there is none; models::embeddedModels(): all of them.
//
// octopoint/camera.h: the camera
//   Camera                   yaw, pitch, roll (Angle); zoom (Q16.16, > 0; 1: the cube spans the
//                            shorter side); pan_x_px, pan_y_px; width, height (1..8192 pixels).
//                            Orthographic; x right, y down, z away from the viewer.
//   buildFrameSetup(camera, depth, fraction_bits, &setup)
//                            the per-frame vectors the decoders add (FrameSetup), at a stored
//                            depth, with positions in Q(32-F).F pixels (kDefaultFractionBits: 15).
//                            Returns CameraError: kNone, or why the camera is refused (size, zoom,
//                            fraction bits, depth, or a coordinate that could overflow 32 bits).
//                            An optional fifth argument, the sample reach (Q4 voxel footprints,
//                            kOneSampleReach 16 .. kMaxSampleReach 128), widens the splat for a
//                            level sampled more coarsely than its voxels (docs/splats.md).
//   leafFootprint(camera, depth, fraction_bits)
//                            the splat a leaf covers (SplatFootprint); nullopt for a refused
//                            camera.
//   voxelEdgeOnScreen(setup) a voxel's edge in Q(32-F).F pixels. splatFootprint(): the footprint
//                            from the last level's offsets. kMaxRenderDepth: 16 unless a build says
//                            less (OCTOPOINT_MAX_RENDER_DEPTH).
//
// octopoint/framebuffer.h: frames
//   Framebuffer(width, height), Framebuffer(setup)
//                            owns width * height 32-bit words (depth key and palette index per
//                            pixel), allocated once, all kEmpty. A bad size gives a 0 x 0 frame
//                            every draw refuses.
//   FrameView(pixels, width, height)
//                            the same over memory the caller owns (a band buffer): no allocation.
//   clear(payload)           empties what was drawn (PixelPayload::kColourNormal for lit styles).
//   pixels(), pixelAt(x, y), covered(x, y), colourIndexAt, depthKeyAt, normalIndexAt, drawnRect()
//   resolveToRgb(frame, model, background, rgb)
//                            palette to RGB888; rgb holds >= width * height * 3 bytes, else false
//                            and nothing written.
//   makeRgb565Palette(model, background), packedToRgb565(words, count, palette, out)
//                            pixel words to RGB565 halfwords (out: 2 * count bytes, may alias the
//                            words); toRgb565(Rgb). fillWords(words, count, value).
//
// octopoint/render.h: drawing
//   renderLevel(variant, level, setup, frame, abort = nullptr)
//                            draws one level into the frame (not cleared: several models may
//                            share it). false, nothing drawn, when the arguments do not fit
//                            (checkRender says why: RenderError), or when *abort became true
//                            (then the frame is incomplete). Never allocates.
//   Variant                  the decoders, all integer but float_*: defaultVariant() is the fastest
//                            this CPU runs (fixed_simd with AVX2, else fixed_fast). allVariants(),
//                            variantFromName(name) (optional), drawsSplats, drawsNormals,
//                            isFixedPoint, simdDecoderAvailable; renderFixedFast(...) and the other
//                            per-variant functions, which refuse what renderLevel refuses.
//   checkFrameSetup(setup), checkRender(level, setup, frame)
//                            RenderError: kNone, or what renderLevel would refuse.
//   HoleFiller(width).fill(frame, bridgeDepthLimit(setup))
//                            fills one- and two-pixel gaps between covered pixels
//                            (docs/holefill.md); HoleFillCounts (per gap type; refused when the
//                            width differs).
//                            fillHoleRows(window, rows, limit, history) does a band's rows with the
//                            caller's holeFillHistoryWords(width) words. countEnclosedEmptyPixels:
//                            for measuring. A perspective frame: fill(frame, PerspectiveBridge),
//                            the limit at each pair's depth (docs/perspective.md).
//   kAbortCheckLevel         the tree level at which decoders poll the abort flag.
//
// octopoint/rgb_renderer.h: the common case in one call (Example 1)
//   RgbRenderer::draw(model, camera, rgb, options)
//                            DrawError: kNone; kBadCamera (cameraError() says why); kNoSuchDepth
//                            (options.depth not stored, or no depth suits the camera); kRgbTooSmall
//                            (rgb below width * height * 3 bytes); kRefused (renderError()). On an
//                            error rgb is untouched. Allocates its frame on the first draw and when
//                            the camera's size changes, never otherwise.
//   DrawOptions              depth (0: depth auto, the coarsest densely sampled depth whose voxel
//                            edge is at most a pixel; docs/splats.md), variant, fill_holes,
//                            background.
//   frame(), drawnDepth()    what the last draw drew.
//   zoomRatio(n, d)          n / d as a Q16.16 zoom; nullopt outside [1/65536, 32767].
//
// octopoint/styles.h: how a frame becomes a picture (docs/styles.md)
//   Style                    colour, shaded, lines, toon, outlined; allStyles(), styleFromName
//                            (optional), styleName, nextStyle, styleNeedsNormals.
//   FrameStyler(model)       setOptions(StyleOptions: style, light, crease angle, background):
//                            StyleError kNeedsNormals when the model has none (options kept).
//                            payload(): what to clear frames with. Per frame: beginFrame(setup)
//                            (a perspective frame: beginPerspectiveFrame(rotation, focal_q16)),
//                            then resolve(frame, rgb) or resolveRows(frame, first, end, rgb):
//                            StyleError kFrameWithoutNormals or kFrameSizeMismatch, else kNone.
//                            No allocation (tables of about 12 KiB are members).
//   Light, ShadingTable, CreaseTable, SurfaceSlopes, EdgeRule, classifyPixel, forEachStyledPixel,
//   StylePass and the *Rows functions
//                            the styler's parts, for band renderers that style rows themselves.
//
// octopoint/smooth.h: smooth close-ups, blended splats in integers (docs/splats.md)
//   SplatMode                box (flat footprints, the default), smooth; allSplatModes(),
//                            splatModeFromName (optional), splatModeName.
//   SmoothSplats(width, height)
//                            16 bytes a pixel, allocated once. blend(level, setup, frame, palette)
//                            over a box frame (kColour) drawn by fixed_fast or fixed_simd, then
//                            resolveToRgb(frame, palette, background, rgb). Never allocates.
//   SmoothSplats(width, height, model)
//                            28 bytes a pixel where the model has normals: a kColourNormal frame
//                            also blends them; styler.resolve(frame, rgb, smooth.pixelBlend())
//                            lights the blended normals in any style.
//   renderSmoothBands(level, setup, config, index, palette565, colours, buffers, smooth, sink)
//                            (octopoint/bands.h) renderBands with each band blended: the whole
//                            frame's blend bit for bit, no margin rows, 16 bytes a band pixel.
//   renderSmooth(variant, level, setup, frame, smooth, palette)
//                            renderLevel, then blend. paletteOf(model): the 256 colours.
//
// octopoint/scene.h: scenes of many models (docs/city.md)
//   InstanceTransform        at (Q.24 scene edges), turn about the vertical, scale 2^-8..2^8: where
//                            an instance of a model stands. SceneInstance: a model index and one.
//   checkTransform(transform), describe(SceneError)
//                            the limits (kMaxSceneModels, kMaxSceneInstances, kMaxSceneCoordinate)
//                            a scene's renderer checks; octopoint-render --city draws scene files.
//
// octopoint/bands.h: a frame in bands of a few rows, for RAM smaller than a frame (Example 2)
//   renderBands(level, setup, config, index, palette, buffers, sink)
//                            draws the frame top to bottom into the caller's band buffers and calls
//                            sink.flush(user, y0, rows, rgb565) per band; with sink.wait, a flush
//                            may finish later (DMA). The bands equal the whole frame bit for bit.
//                            BandError: kUnsupportedVariant (float_*), kBadBandRows,
//                            kBufferTooSmall, kOverflow, kNoSink, kRefused. Never allocates.
//   BandConfig               variant (fixed_fast), band_rows (24), fill, background.
//   bandBufferWords(width, config)
//                            words per band buffer: (band_rows + 2 * bandMarginRows) * width. With
//                            fill, BandBuffers::fill_history needs holeFillHistoryWords(width).
//   buildBandIndex(level, index_level, storage), deepestIndexLevel(level, capacity)
//                            the optional index (4 bytes per node of one tree level) that lets a
//                            band walk only the subtrees it meets; level 0: none.
//                            indexLevelAllowed, countNodesPerLevel: its rules.
//   bandFrameSetup(frame_setup, y0, rows, &band), supportsBands(variant)
//
// octopoint/progressive.h (separate include; it includes octopoint/chunked.h, the format):
// chunked models, refined while bytes arrive
//   ProgressiveModel::fromHead(bytes, &issue), progressiveModelFromPrefix(bytes, &issue)
//                            a model from a version-3 file's head (chunkedHeadBytes says how many
//                            bytes), or from any prefix of the file; nullopt with ChunkedIssue.
//   accept(item, bytes), acceptBytes(offset, bytes, &issue)
//                            hand it a record table or chunk (FetchItem), or a piece of the file
//                            read front to back; a damaged one is refused (ChunkedIssue) and may
//                            come again, kMaxChunkAttempts times in all.
//   fetchPriority(camera, include_invisible, out, &total)
//                            what to fetch next for this view, most urgent first; no allocation.
//   draw(camera, variant, frame, &stats, abort, coarser_levels), snapshot(frame) + draw(frame, ...)
//                            a complete picture at every moment (coarser where data is missing);
//                            false for a refused camera or an abort. The snapshot form draws
//                            without the feeder's lock. setPointBudget caps the points drawn.
//   wantedDepth(camera), viewComplete(camera), chunkState, chunksIn, heldBytes, baseModel()
//   looksChunked, parseChunkedHead, parseRecordTable, validateChunk, refineRegion,
//   forEachSubregion, chunked::
//                            the format's readers and constants, for tools (docs/format.md).
//
// octopoint/interactive.h (separate include; octopoint::interactive, std::thread)
//   DualResolutionRenderer(model, clock, config)
//                            two threads behind one view: a coarse frame while the view moves, the
//                            fine one (depth auto) once it rests, aborted by the next move. Feed it
//                            ViewEvents with handle(event) (key press and release, tick, zoom,
//                            resize, ...); the display calls acquireLatest(&info) (nullptr before
//                            the first frame); status(), waitUntil(predicate, timeout) (false on
//                            timeout). Also from two levels, or from a ViewDrawFunction (a
//                            streamed model). Clock: SteadyClock, or ManualClock with a
//                            ScriptedTimeline (an EventSource) for tests. frameChecksum(frame).
//
// octopoint/http.h (separate include; octopoint::net, links cpp-httplib): Example 3
//   net::parseHttpUrl(text, &error)
//                            http://HOST[:PORT]/PATH; nullopt with the reason.
//   net::ModelStream(url, options)
//                            fetches a chunked model's byte ranges for the view (setView) on
//                            `connections` threads, with retries and back-off, and feeds a
//                            ProgressiveModel: start(), stop(), status() and
//                            waitUntilSettled(timeout) (StreamStatus: head_known, failed and error,
//                            view_complete, bytes), snapshot(frame) (the model to draw, nullptr
//                            until the head arrived), withModel(use), onAccepted(callback).
//   net::RangeClient(url, timeouts).fetch(offset, size, sink, cancel)
//                            one byte range, trusting nothing the server says: FetchResult with a
//                            FetchStatus (kOk, kConnectionFailed, kHttpStatus, kBadResponse,
//                            kTooLong, kTooShort, kTooSlow, kCancelled).

#include "octopoint/bands.h"
#include "octopoint/camera.h"
#include "octopoint/fixed.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/models.h"
#include "octopoint/render.h"
#include "octopoint/rgb_renderer.h"
#include "octopoint/scene.h"
#include "octopoint/smooth.h"
#include "octopoint/styles.h"
