#include "tools/render_usage.h"

namespace octopoint {

const char* const kRenderUsage =
    R"(usage: octopoint-render [--model NAME | --file M.oct | --url URL [--bytes N]] )"
    R"([options] -o OUT.png
       octopoint-render --city SCENE.json [--cells CELLS] (--eye X,Y,Z | --path P.json
                        --frames N) -o OUT.png
       octopoint-render [--model NAME | --file M.oct] --info
       octopoint-render --list

Draws an octopoint model with the integer renderer and writes it as a PNG. With neither --model
nor --file nor --url it draws the default model embedded in this binary.

  --model NAME       an embedded model (see --list)
  --file M.oct       a model file written by octopoint-prepare (a regular file of at most 1 GiB);
                     it is validated before drawing. A chunked file (--chunked) is drawn at the
                     depth the view needs
  --url URL          a chunked model on an HTTP server with Range requests (octopoint-serve,
                     nginx, ...), http://HOST:PORT/NAME.oct: fetches what this view needs, coarse
                     first, then draws it (docs/streaming.md); with --perspective, --eye or
                     --path too (each frame of a path fetches what it needs, in turn)
  --bytes N          with --url: stop after N bytes and draw what they give (one connection, so
                     the same N bytes every time)
  --timeout S        with --url: draw what arrived after S seconds at most, 1..86400 (default 60)
  --point-budget N   a chunked model (--url, or --file of a chunked file): draw at most about N
                     points, 1..2^40 (default: no budget). When the view's visible chunks hold
                     more at the depth it needs, those largest on screen, then nearest, keep it
                     and the rest are drawn one depth coarser (docs/streaming.md, "Point budget").
                     In perspective (any model): the frame is drawn coarser where its voxels are
                     smallest on screen, the far parts first, until it draws at most N points
                     (docs/perspective.md, "Point budget")
  --yaw DEG          turn about the vertical axis, |DEG| <= 1e6 (default 0; the scan as its
                     sensor saw it)
  --pitch DEG        turn about the horizontal axis (default 0)
  --roll DEG         turn about the viewing axis (default 0)
  --zoom X           magnification, 1/65536..32767 (default 1: the model cube spans the shorter
                     side)
  --pan X,Y          move the picture X pixels right and Y down, each |.| <= 1e6 (default 0,0)
  --perspective      draw in perspective: the eye on the line of sight through the model's centre,
                     where the centre's depth is as large on screen as in the orthographic view
                     of the same zoom (so a narrow --fov converges to it); --fill, --style and
                     --sheet apply (docs/perspective.md). A chunked file is
                     the same frame as the one-file model of its depths; with --url the stream
                     follows the perspective view (nearest and largest on screen first, each
                     region only as fine as its distance asks) and each region is drawn at the
                     finest depth held there (with --bytes N: coarser where finer did not come)
  --eye X,Y,Z        draw in perspective from an eye at X,Y,Z in the scan's own units and axes
                     (the frame octopoint-prepare --crop takes; --info prints where the model's
                     cube lies in it); anywhere within 128 cube edges of the cube's centre, inside
                     the model too. --fill, --style and --sheet apply; needs a model
                     that records its cube's placement (prepared since format version 4)
  --look YAW,PITCH[,ROLL]
                     with --eye: where the eye looks, in degrees (default 0,0: the way the sensor
                     looked, +z of a y-down scan, -z of a y-up one): yaw turns it right, pitch
                     up, roll clockwise
  --path PATH.json   draw a camera path (docs/perspective.md, "Camera paths": key frames of eye
                     and look in the scan's units, interpolated smoothly; a file of at most
                     1 MiB, at most 1000 keys) to numbered PNGs: -o OUT.png (or -o OUT) writes
                     OUT_0000.png, OUT_0001.png, ... and, where OpenCV's Motion JPEG writer
                     works, the video OUT.avi (25 frames a second). Every frame's camera is
                     checked before anything is written; a path that fails leaves no file
  --frames N         with --path: the number of frames, 1..3600, evenly spaced in time from the
                     first key to the last; at most 2^30 pixels in all (N x W x H)
  --collide          with --path: walk the path's eye with collision (docs/perspective.md,
                     "Collision"): from frame to frame the eye's sphere stops short of the
                     model's occupied voxels (its finest depth) and slides along them, never
                     through a wall however thin; prints in how many frames something stopped it.
                     With --city: against every instance of the scene (docs/city.md,
                     "Collision"), R and H then in scene edges
  --eye-radius R     with --collide: the eye's radius in scan units (default 1/128 of the
                     cube's edge; 2^-24 to 1 cube edge)
  --eye-height H     with --collide: gravity: the eye stays H scan units above the ground under
                     it (what its foot, a sphere of the radius H - R below it, rests on within H),
                     and keeps its height where there is none; above R, at most one cube edge
  --fov DEG          with --perspective, --eye or --path: the vertical field of view, 10..120
                     (default 60, or the path's "fov")
  --city SCENE.json  draw a scene of many models (docs/city.md: models and instances of them,
                     each placed, turned about the vertical and scaled by a power of two; a
                     file of at most 64 MiB, 1..256 models sharing at most 255 colours, 1..2^20
                     instances) with --eye (in scene edges, the cube edge of a model at scale 0,
                     within 128 of the scene's origin) and --look, or --path and --frames (PNGs
                     only, no video); colour, each instance at the depth its distance asks for,
                     nearer instances hiding farther ones
  --cells CELLS      with --city: the scene's visibility cells (octopoint-pvs, docs/city.md):
                     only the instances the eye's cell sees are drawn (all of them when the eye
                     lies outside the cells' grid)
  --near D           with --perspective, --eye or --path: the near plane, D scan units before the
                     eye; nothing nearer is drawn (default half the voxel edge of the model's
                     finest depth: the ground at the eye's feet is drawn)
  --size WxH         framebuffer size in pixels, each side 1..8192 and at most 16777216 pixels
                     (4096x4096) in all (default 320x240)
  --depth N|auto     which of the model's depths to draw (default auto: depth by projected size,
                     below); N, 1..16, must be one the model stores. In perspective, auto draws
                     each part of the frame at the depth its own distance asks for (detail by
                     distance) and culls parts hidden behind nearer ones
  --variant NAME     decoder variant (default: the fastest this CPU runs, fixed_simd with AVX2,
                     else fixed_fast; see --list)
  --splats MODE      how a magnified voxel is drawn: box (default), a flat rectangle of its colour,
                     or smooth, blended with its neighbours by an integer kernel, with round
                     silhouettes (docs/splats.md), in every --style (the lit styles light the
                     blended normal; a chunked model or --url: what arrived, blended); smooth
                     needs fixed_fast or fixed_simd, a single view, no --fill or --perspective;
                     where voxels are at most a pixel both draw the same frame
  --fill, --no-fill  scanline hole filling after decoding, as the paper does (default --no-fill:
                     footprint splats leave no holes; docs/holefill.md)
  --style NAME       colour (default), shaded, lines, toon or outlined (docs/styles.md); all but
                     colour need a model with normals (octopoint-prepare --normals), so a
                     chunked model (a chunked file or --url) is drawn in colour only
  --light AZ,EL      where the light of shaded and toon comes from, in degrees relative to the
                     viewer: azimuth to the right (negative: left), elevation up, each within
                     +-90; 0,0 is at the viewer's eye (default -30,35)
  --headlight        add a weaker second light at the viewer's eye (no face is left black)
  --crease DEG       line styles: neighbouring normals further apart than this are a crease,
                     1..179 (default 60)
  --sheet N          a contact sheet instead: N yaw angles (1..36) in columns; rows: depth auto,
                     then each depth of the model unfilled and filled, in --style; then, for a
                     model with normals, depth auto in each other style; the whole sheet may
                     have at most 16777216 pixels. In perspective: --perspective turns the
                     orbit's yaw, --eye the look's yaw by a turn / N a column, --path takes N
                     evenly spaced frames of the path (instead of --frames); rows: depth by
                     distance, then each stored depth everywhere, filled and styled as asked
  -o, --output FILE  the PNG to write (written whole or not at all); if it exists it must be a
                     regular file (a device or FIFO is refused)
  --info             print what the model holds instead of drawing it: file, format version,
                     palette, normals, leaves and node bytes per depth, the cube's edge in metres,
                     and the line `cube X0,Y0,Z0 EDGE`: the cube's lowest corner and edge in the
                     scan's units and axes (the frame --crop and --eye take)
  --list             list the embedded models and the decoder variants
  -h, --help         show this help

Depth auto (docs/splats.md): a voxel of depth d has an edge of e = zoom * min(W, H) / 2^d
pixels on a WxH frame. Auto draws the coarsest stored depth with e <= 1 pixel, among the depths
the scan samples densely; if even the finest has e > 1 pixel, the finest. Where a leaf's projected
footprint (e times the rotation row's |r0|+|r1|+|r2|, up to 1.73 e when turned) is wider than a
pixel, fixed_fast and fixed_simd cover it with a footprint splat, z-tested per pixel (the paper's
variants set one pixel per leaf).

Numbers are parsed whole and range-checked. On any error prints one line on stderr and exits
with status 1, writing nothing.
)";

}  // namespace octopoint
