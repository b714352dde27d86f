// An occupancy grid as map_server and nav_msgs/OccupancyGrid hold it: row-major from the
// lower-left cell at `origin`, values -1 (unknown) or 0..100 (occupancy per cent), and the
// map files of map_server (YAML + PGM, trinary mode): read with the YAML's thresholds,
// written as map_saver writes them (254 free, 0 occupied, 205 unknown).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace amigobot_tracking {
namespace localization {

struct OccupancyMap {
  double resolution = 0.05;               // [m] cell side
  double origin_x = 0.0, origin_y = 0.0;  // [m] map-frame position of cell (0, 0)'s lower-left corner
  int width = 0, height = 0;              // cells
  std::vector<std::int8_t> cells;         // width * height, row 0 at the bottom

  static constexpr std::int8_t kUnknown = -1;
  static constexpr std::int8_t kFree = 0;
  static constexpr std::int8_t kOccupied = 100;

  bool empty() const { return cells.empty(); }
  bool contains(int cx, int cy) const { return cx >= 0 && cy >= 0 && cx < width && cy < height; }
  std::int8_t at(int cx, int cy) const { return cells[static_cast<std::size_t>(cy) * width + cx]; }
  std::int8_t& at(int cx, int cy) { return cells[static_cast<std::size_t>(cy) * width + cx]; }
  // Cell of a map-frame point (may be outside the map).
  void cellOf(double x, double y, int* cx, int* cy) const;
  Eigen::Vector2d cellCenter(int cx, int cy) const;
  bool occupied(int cx, int cy, int threshold = 65) const { return at(cx, cy) >= threshold; }
};

// A map of `width` x `height` cells, every one `value`.
OccupancyMap makeMap(double resolution, double origin_x, double origin_y, int width, int height,
                     std::int8_t value = OccupancyMap::kUnknown);

// Reads a map_server YAML (image, resolution, origin, negate, occupied_thresh, free_thresh,
// optional mode: trinary) and its PGM (P5 or P2, relative to the YAML's folder). Throws
// std::runtime_error "FILE: KEY: what is wrong" (or "FILE: what is wrong" for the image).
OccupancyMap loadMap(const std::string& yaml_path);

// Writes yaml_path and, beside it, the PGM named like it (map.yaml -> map.pgm), creating the
// folder when missing. Throws std::runtime_error naming the file that cannot be written.
void saveMap(const std::string& yaml_path, const OccupancyMap& map);

}  // namespace localization
}  // namespace amigobot_tracking
