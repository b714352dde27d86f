// world_map: draws a world file into a map_server map (YAML + PGM), the "surveyed" map of
// an emulated room: a cell is occupied when a wall, a disk or a polygon reaches into it,
// free otherwise (cells outside the room stay free: no beam ends there). The end-to-end
// tests localise on such maps. With --compare it judges a map (e.g. one `make map` built by
// SLAM) against the world instead: how many of its occupied cells lie on the world's
// surfaces (precision), and how much of those surfaces it shows (coverage).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <string>

#include <CLI/CLI.hpp>

#include "amigobot_tracking/localization/occupancy_map.h"
#include "amigobot_tracking/world/geometry.h"
#include "amigobot_tracking/world/world.h"

using namespace amigobot_tracking;
using localization::OccupancyMap;

namespace {

// Bounding box of every shape and the start pose, grown by `margin` [m].
void bounds(const world::World& w, double margin, Eigen::Vector2d* lo, Eigen::Vector2d* hi) {
  const double inf = std::numeric_limits<double>::infinity();
  *lo = Eigen::Vector2d(inf, inf);
  *hi = -*lo;
  auto add = [&](const Eigen::Vector2d& p, double r) {
    *lo = lo->cwiseMin(p - Eigen::Vector2d(r, r));
    *hi = hi->cwiseMax(p + Eigen::Vector2d(r, r));
  };
  for (const core::Disk& d : w.obstacles) add(d.center, d.radius);
  for (const world::Segment& s : world::surfaceSegments(w)) {
    add(s.from, 0.0);
    add(s.to, 0.0);
  }
  if (w.initial_pose) add(w.initial_pose->position(), 0.0);
  *lo -= Eigen::Vector2d(margin, margin);
  *hi += Eigen::Vector2d(margin, margin);
}

OccupancyMap draw(const world::World& w, double resolution, double margin) {
  Eigen::Vector2d lo, hi;
  bounds(w, margin, &lo, &hi);
  const int width = static_cast<int>(std::ceil((hi.x() - lo.x()) / resolution));
  const int height = static_cast<int>(std::ceil((hi.y() - lo.y()) / resolution));
  OccupancyMap map = localization::makeMap(resolution, lo.x(), lo.y(), width, height, OccupancyMap::kFree);
  // A cell is hit when a shape comes within half a cell of its centre (its inscribed disk);
  // the slack keeps a wall that runs exactly along a cell border (x = 4.5 at 0.05 m) in both
  // neighbours instead of in neither by rounding.
  const double reach = 0.5 * resolution * (1.0 + 1e-6);
  for (int cy = 0; cy < height; ++cy)
    for (int cx = 0; cx < width; ++cx)
      if (world::clearance(w, map.cellCenter(cx, cy), reach) <= 0.0) map.at(cx, cy) = OccupancyMap::kOccupied;
  return map;
}

bool occupiedNear(const OccupancyMap& map, const Eigen::Vector2d& p, double radius) {
  int cx, cy;
  map.cellOf(p.x(), p.y(), &cx, &cy);
  const int k = static_cast<int>(std::ceil(radius / map.resolution));
  for (int dy = -k; dy <= k; ++dy)
    for (int dx = -k; dx <= k; ++dx)
      if (map.contains(cx + dx, cy + dy) && map.occupied(cx + dx, cy + dy) &&
          (map.cellCenter(cx + dx, cy + dy) - p).norm() <= radius + 1e-9)
        return true;
  return false;
}

// Exit 0 when at least `min_precision` of the map's occupied cells lie within `tolerance`
// of a world surface, 3 otherwise (walls where the world has none: a broken map).
int compare(const world::World& w, const std::string& map_path, double tolerance, double min_precision) {
  const OccupancyMap map = localization::loadMap(map_path);
  size_t occupied = 0, on_surface = 0;
  for (int cy = 0; cy < map.height; ++cy)
    for (int cx = 0; cx < map.width; ++cx)
      if (map.occupied(cx, cy)) {
        ++occupied;
        // On a surface, or inside a solid (a table's filled outline): either agrees with the world.
        if (world::clearance(w, map.cellCenter(cx, cy), 0.0) <= tolerance) ++on_surface;
      }
  // Coverage: the world's surface cells, drawn on the same grid, that the map shows nearby.
  const double half_diagonal = 0.5 * std::sqrt(2.0) * map.resolution;
  size_t surface = 0, shown = 0;
  for (int cy = 0; cy < map.height; ++cy)
    for (int cx = 0; cx < map.width; ++cx) {
      const Eigen::Vector2d c = map.cellCenter(cx, cy);
      if (std::fabs(world::clearance(w, c, 0.0)) > half_diagonal) continue;
      ++surface;
      if (occupiedNear(map, c, tolerance)) ++shown;
    }
  const double precision = occupied ? static_cast<double>(on_surface) / occupied : 0.0;
  const double coverage = surface ? static_cast<double>(shown) / surface : 0.0;
  std::printf("world_map: %s against the world: %zu occupied cells, %.1f %% within %.2f m of a surface "
              "(or inside a solid: precision); %.1f %% of the world's %zu surface cells shown (coverage; unseen faces count against)\n",
              map_path.c_str(), occupied, 100.0 * precision, tolerance, 100.0 * coverage, surface);
  if (precision < min_precision) {
    std::fprintf(stderr, "world_map: %s: precision %.3f below %.3f\n", map_path.c_str(), precision, min_precision);
    return 3;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string world_path, out, compared;
  double resolution = 0.05, margin = 0.5, tolerance = 0.1, min_precision = 0.9;
  CLI::App app("Draws a world file (world/world.h) into a map_server map (YAML + PGM beside it): occupied where "
               "a wall, disk or polygon reaches into a cell, free elsewhere. --compare judges a map against the "
               "world instead.",
               "world_map");
  app.add_option("--world", world_path, "world YAML")->required();
  auto* out_opt = app.add_option("--out", out, "map YAML to write (the PGM is written beside it)");
  auto* cmp_opt = app.add_option("--compare", compared, "map YAML to judge against the world");
  out_opt->excludes(cmp_opt);
  app.add_option("--resolution", resolution, "[m] cell side (--out)")->capture_default_str()->check(CLI::Range(0.005, 1.0));
  app.add_option("--margin", margin, "[m] free border around the world's shapes (--out)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 10.0));
  app.add_option("--tolerance", tolerance, "[m] a cell this close to a surface is on it (--compare)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--min-precision", min_precision, "[-] exit 3 below this precision (--compare)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  app.footer("Exit 0: written / the map agrees; 3: --compare found a precision below --min-precision; "
             "2: bad arguments or unreadable input.");
  try {
    app.parse(argc, argv);
    if (out.empty() && compared.empty()) throw CLI::RequiredError("--out or --compare");
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    const world::World w = world::loadWorld(world_path);
    if (w.empty()) throw std::runtime_error(world_path + ": the world has no shape to draw");
    if (!compared.empty()) return compare(w, compared, tolerance, min_precision);
    const OccupancyMap map = draw(w, resolution, margin);
    localization::saveMap(out, map);
    std::cout << "world_map: " << map.width << " x " << map.height << " cells of " << resolution << " m from ("
              << map.origin_x << ", " << map.origin_y << ") -> " << out << "\n";
  } catch (const std::exception& e) {
    std::cerr << "world_map: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
