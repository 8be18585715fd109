// make_city: a generated city to walk (docs/city.md): the point sets of a handful of models
// (three buildings of several heights with coloured facades and windows, a house, a tree, two
// cars, a street tile and a pavement tile) as binary PLY, and the scene file that places them on a
// grid of blocks and streets. scripts/make-city prepares the point sets into .oct models with
// octopoint-prepare; the scene names those. The same options give the same files.
//
// Scene units: one scene edge is 32 m. Every model's points span exactly 32 m, 16 m, 8 m or 4 m
// on their largest axis (the preparer fits its cube to that: octopoint-prepare's cube is the
// bounds' largest extent, centred on them), so its scale is a power of two, and its cube's centre
// is the centre of its bounds, which the scene places.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/numbers.h"
#include "cli/run_tool.h"

namespace {

constexpr const char* kUsage =
    R"(usage: make_city [--seed N] [--blocks N] [--spacing M] -o OUTDIR

Writes the point sets of a generated city's models (OUTDIR/NAME.ply, binary PLY in metres, y
down) and its scene file OUTDIR/city.json, which names OUTDIR/NAME.oct: prepare each with
octopoint-prepare (scripts/make-city does both).

  --seed N      another city of the same kind (default 1): which building on each lot, how it
                is turned, where the trees and cars stand
  --blocks N    N x N blocks of 2 x 2 lots of 32 m between streets 32 m wide, 1..40 (default 25:
                about 11,000 instances)
  --spacing M   the points' spacing on every surface, in centimetres, 1..100 (default 4: finer
                than a depth-9 voxel of a 32 m cube, 6.25 cm)
  -o OUTDIR     where to write (created if missing)
)";

constexpr double kSceneEdgeMetres = 32;

struct Colour {
  std::uint8_t r, g, b;
};

struct Point {
  float x, y, z;
  Colour colour;
};

class PointSet {
 public:
  explicit PointSet(double spacing) : spacing_(spacing) {}

  // A rectangle from `origin` along `u` and `v` (metres), coloured by `paint(s, t)` at (s, t)
  // metres along them.
  template <typename Paint>
  void rectangle(const double origin[3], const double u[3], const double v[3], Paint paint) {
    const double lu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    const double lv = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    const int nu = static_cast<int>(std::ceil(lu / spacing_)),
              nv = static_cast<int>(std::ceil(lv / spacing_));
    for (int i = 0; i <= nu; ++i) {
      for (int j = 0; j <= nv; ++j) {
        const double a = static_cast<double>(i) / nu, b = static_cast<double>(j) / nv;
        add(origin[0] + a * u[0] + b * v[0], origin[1] + a * u[1] + b * v[1],
            origin[2] + a * u[2] + b * v[2], paint(a * lu, b * lv));
      }
    }
  }

  // The four walls and the roof of a box standing on y = 0 (y down: the roof at y = -height),
  // x in [x0, x1], z in [z0, z1].
  template <typename Wall>
  void building(double x0, double x1, double z0, double z1, double height, Wall wall, Colour roof) {
    const double h = -height;
    const double corners[4][3] = {{x0, 0, z0}, {x1, 0, z0}, {x1, 0, z1}, {x0, 0, z1}};
    for (int k = 0; k < 4; ++k) {
      const double* a = corners[k];
      const double* b = corners[(k + 1) % 4];
      const double u[3] = {b[0] - a[0], 0, b[2] - a[2]};
      const double v[3] = {0, h, 0};
      rectangle(a, u, v, wall);
    }
    const double top[3] = {x0, h, z0}, u[3] = {x1 - x0, 0, 0}, v[3] = {0, 0, z1 - z0};
    rectangle(top, u, v, [roof](double, double) { return roof; });
  }

  // A sphere of radius r about (cx, cy, cz).
  void sphere(double cx, double cy, double cz, double r, Colour a, Colour b) {
    const int n = static_cast<int>(4 * M_PI * r * r / (spacing_ * spacing_));
    const double golden = M_PI * (3 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
      const double y = 1 - 2 * (i + 0.5) / n, radius = std::sqrt(1 - y * y), t = golden * i;
      add(cx + r * radius * std::cos(t), cy + r * y, cz + r * radius * std::sin(t),
          (i / 7) % 3 == 0 ? b : a);
    }
  }

  void add(double x, double y, double z, Colour colour) {
    points_.push_back(
        {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z), colour});
  }

  void write(const std::filesystem::path& path) const {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw octopoint::cli::Error(path.string() + ": cannot write");
    out << "ply\nformat binary_little_endian 1.0\ncomment octopoint make_city, metres, y down\n"
        << "element vertex " << points_.size()
        << "\nproperty float x\nproperty float y\nproperty float z\n"
        << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
    for (const Point& p : points_) {
      out.write(reinterpret_cast<const char*>(&p.x), 4);
      out.write(reinterpret_cast<const char*>(&p.y), 4);
      out.write(reinterpret_cast<const char*>(&p.z), 4);
      out.put(static_cast<char>(p.colour.r))
          .put(static_cast<char>(p.colour.g))
          .put(static_cast<char>(p.colour.b));
    }
    if (!out.flush()) throw octopoint::cli::Error(path.string() + ": cannot write");
  }

  std::size_t size() const { return points_.size(); }

 private:
  double spacing_;
  std::vector<Point> points_;
};

// A facade: windows of w x w metres every `pitch` metres along and up, from 1 m above the ground.
auto facade(Colour wall, Colour window, double w, double pitch) {
  return [=](double s, double t) {
    const double a = std::fmod(s, pitch), b = std::fmod(t, pitch);
    const bool glass = t > 1 && a > (pitch - w) / 2 && a < (pitch + w) / 2 && b > (pitch - w) / 2 &&
                       b < (pitch + w) / 2;
    return glass ? window : wall;
  };
}

struct Model {
  std::string name;
  int scale;        // its cube edge is 2^scale scene edges
  double centre_y;  // its bounds' centre, metres (x and z are centred on 0)
};

// Each model's points, x and z centred on 0, standing on y = 0.
std::vector<Model> writeModels(const std::filesystem::path& folder, double spacing) {
  std::vector<Model> models;
  const auto save = [&](const PointSet& set, const std::string& name, int scale, double centre_y) {
    set.write(folder / (name + ".ply"));
    std::printf("%s.ply: %zu points\n", name.c_str(), set.size());
    models.push_back({name, scale, centre_y});
  };
  const Colour glass{46, 62, 92}, roof{96, 96, 100};
  {  // a tower 16 x 32 x 16 m: 32 m on its largest axis
    PointSet set(spacing);
    set.building(-8, 8, -8, 8, 32, facade({206, 186, 150}, glass, 1.6, 3), roof);
    save(set, "tower", 0, -16);
  }
  {  // a slab 32 x 20 x 12 m
    PointSet set(spacing);
    set.building(-16, 16, -6, 6, 20, facade({160, 76, 56}, glass, 1.8, 3.2), roof);
    save(set, "slab", 0, -10);
  }
  {  // a hall 32 x 10 x 32 m, wide windows
    PointSet set(spacing);
    set.building(-16, 16, -16, 16, 10, facade({188, 190, 196}, {70, 110, 130}, 3.5, 4.5),
                 {120, 124, 110});
    save(set, "hall", 0, -5);
  }
  {  // a house 16 x 9 x 12 m: 16 m, half a scene edge
    PointSet set(spacing);
    set.building(-8, 8, -6, 6, 9, facade({222, 200, 120}, glass, 1.2, 3), {150, 54, 40});
    save(set, "house", -1, -4.5);
  }
  {  // a tree 5 m wide, 8 m tall: a trunk and a crown
    PointSet set(spacing);
    for (double h = 0; h < 3.5; h += spacing) {
      for (int k = 0; k < 16; ++k) {
        const double a = k * M_PI / 8;
        set.add(0.25 * std::cos(a), -h, 0.25 * std::sin(a), {92, 64, 40});
      }
    }
    set.sphere(0, -5.5, 0, 2.5, {58, 120, 52}, {84, 146, 60});
    save(set, "tree", -2, -4);
  }
  const auto car = [&](const std::string& name, Colour body) {
    // 4 m long (x), 1.8 m wide, 1.5 m tall: a body and a cabin with windows
    PointSet set(spacing);
    set.building(
        -2, 2, -0.9, 0.9, 0.9, [body](double, double) { return body; }, body);
    set.building(
        -1.1, 1.0, -0.8, 0.8, 1.5,
        [body](double, double t) {
          return t > 0.95 && t < 1.4 ? Colour{40, 48, 60} : body;
        },
        body);
    save(set, name, -3, -0.75);
  };
  car("car_red", {180, 30, 36});
  car("car_blue", {40, 70, 160});
  {  // a street tile 32 x 32 m: asphalt, a dashed white line along x
    PointSet set(spacing);
    const double origin[3] = {-16, 0, -16}, u[3] = {32, 0, 0}, v[3] = {0, 0, 32};
    set.rectangle(origin, u, v, [](double s, double t) {
      const bool line = std::fabs(t - 16) < 0.12 && std::fmod(s, 6) < 3;
      const bool kerb = t < 0.5 || t > 31.5;
      return line ? Colour{236, 236, 230} : kerb ? Colour{150, 150, 150} : Colour{74, 76, 80};
    });
    save(set, "street", 0, 0);
  }
  {  // a pavement tile 32 x 32 m: light slabs with joints every 2 m
    PointSet set(spacing);
    const double origin[3] = {-16, 0, -16}, u[3] = {32, 0, 0}, v[3] = {0, 0, 32};
    set.rectangle(origin, u, v, [](double s, double t) {
      return std::fmod(s, 2) < 0.06 || std::fmod(t, 2) < 0.06 ? Colour{130, 128, 122}
                                                              : Colour{176, 172, 160};
    });
    save(set, "pavement", 0, 0);
  }
  return models;
}

// Metres to the scene's Q.24 scene edges.
std::int64_t units(double metres) { return std::llround(metres / kSceneEdgeMetres * 16777216.0); }

int run(int argc, char** argv) {
  octopoint::cli::ArgumentReader args(argc, argv);
  std::uint32_t seed = 1;
  int blocks = 25;
  double spacing = 0.04;
  std::string output;
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (args.is("--seed")) {
      seed = static_cast<std::uint32_t>(
          octopoint::cli::parseInt(args.name(), args.value(), 0, 1'000'000'000));
    } else if (args.is("--blocks")) {
      blocks = octopoint::cli::parseInt(args.name(), args.value(), 1, 40);
    } else if (args.is("--spacing")) {
      spacing = octopoint::cli::parseInt(args.name(), args.value(), 1, 100) / 100.0;
    } else if (args.is("-o")) {
      output = args.value();
    } else {
      args.refuseUnknown();
    }
  }
  if (output.empty()) throw octopoint::cli::Error("no output given: use -o OUTDIR");
  const std::filesystem::path folder(output);
  std::filesystem::create_directories(folder);
  const std::vector<Model> models = writeModels(folder, spacing);
  enum { kTower, kSlab, kHall, kHouse, kTree, kCarRed, kCarBlue, kStreet, kPavement };

  // The grid: cells of 32 m; every third row and column of cells is a street, the rest lots.
  const int cells = 3 * blocks + 1;
  const double half = cells * kSceneEdgeMetres / 2;
  std::mt19937 random(seed);
  const auto roll = [&](int n) {
    return static_cast<int>(random() % static_cast<std::uint32_t>(n));
  };
  std::string instances;
  std::size_t count = 0;
  const auto place = [&](int model, double x, double z, int quarter_turns, int turn16 = -1) {
    const Model& m = models[static_cast<std::size_t>(model)];
    const int turn = turn16 >= 0 ? turn16 : (quarter_turns & 3) * 16384;
    char line[160];
    std::snprintf(line, sizeof line, "%s\n  [%d, %lld, %lld, %lld, %d, %d]", count == 0 ? "" : ",",
                  model, static_cast<long long>(units(x)),
                  static_cast<long long>(units(m.centre_y)), static_cast<long long>(units(z)), turn,
                  m.scale);
    instances += line;
    ++count;
  };
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < cells; ++j) {
      const double x = (i + 0.5) * kSceneEdgeMetres - half, z = (j + 0.5) * kSceneEdgeMetres - half;
      const bool street_x = i % 3 == 0, street_z = j % 3 == 0;
      if (street_x || street_z) {
        // The dashed line runs along the street: along z where the street column runs along z.
        place(kStreet, x, z, street_x && !street_z ? 1 : 0);
        if (street_x && street_z) continue;      // a crossing: no trees or cars
        const double across = street_x ? 1 : 0;  // 1: the street runs along z
        if (roll(2) == 0) {                      // a tree at the kerb
          const double side = roll(2) ? 14.5 : -14.5, along = roll(20) - 10.0;
          place(kTree, x + (across ? side : along), z + (across ? along : side), 0, roll(65536));
        }
        for (int c = roll(3); c > 0; --c) {  // cars in their lanes
          const double lane = roll(2) ? 5.0 : -5.0, along = roll(28) - 14.0;
          place(roll(2) ? kCarRed : kCarBlue, x + (across ? lane : along),
                z + (across ? along : lane), (across ? 1 : 0) + (lane > 0 ? 2 : 0));
        }
      } else {
        place(kPavement, x, z, 0);
        const int kind = roll(10);
        if (kind < 3) {
          place(kTower, x, z, roll(4));
        } else if (kind < 6) {
          place(kSlab, x, z, roll(4));
        } else if (kind < 8) {
          place(kHall, x, z, roll(4));
        } else {  // four houses
          for (int q = 0; q < 4; ++q)
            place(kHouse, x + (q & 1 ? 8 : -8), z + (q & 2 ? 8 : -8), roll(4));
        }
      }
    }
  }
  std::string scene = "{\"models\": [";
  for (std::size_t m = 0; m < models.size(); ++m)
    scene += (m ? ", \"" : "\"") + models[m].name + ".oct\"";
  scene += "],\n \"instances\": [" + instances + "]}\n";
  std::ofstream out(folder / "city.json", std::ios::trunc);
  if (!out || !(out << scene) || !out.flush())
    throw octopoint::cli::Error((folder / "city.json").string() + ": cannot write");
  std::printf("city.json: %d x %d blocks, %zu instances of %zu models, %.0f m across\n", blocks,
              blocks, count, models.size(), cells * kSceneEdgeMetres);
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return octopoint::cli::runTool("make_city", argc, argv, run); }
