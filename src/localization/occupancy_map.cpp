#include "amigobot_tracking/localization/occupancy_map.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "amigobot_tracking/core/support/input_file.h"

namespace amigobot_tracking {
namespace localization {

void OccupancyMap::cellOf(double x, double y, int* cx, int* cy) const {
  *cx = static_cast<int>(std::floor((x - origin_x) / resolution));
  *cy = static_cast<int>(std::floor((y - origin_y) / resolution));
}

Eigen::Vector2d OccupancyMap::cellCenter(int cx, int cy) const {
  return {origin_x + (cx + 0.5) * resolution, origin_y + (cy + 0.5) * resolution};
}

OccupancyMap makeMap(double resolution, double origin_x, double origin_y, int width, int height, std::int8_t value) {
  OccupancyMap map;
  map.resolution = resolution;
  map.origin_x = origin_x;
  map.origin_y = origin_y;
  map.width = width;
  map.height = height;
  map.cells.assign(static_cast<std::size_t>(width) * height, value);
  return map;
}

namespace {

// The image's cap: 10^8 cells (a 500 m square at 5 cm) and the bytes of such a P2 file.
constexpr std::uintmax_t kMaxMapCells = 100000000;
constexpr std::uintmax_t kMaxImageBytes = 4 * kMaxMapCells;

[[noreturn]] void fail(const std::string& file, const std::string& what) { throw std::runtime_error(file + ": " + what); }

// "FILE:LINE: KEY: what" for a key of the map YAML.
[[noreturn]] void failAt(const std::string& file, const YAML::Node& node, const std::string& key,
                         const std::string& what) {
  const int line = node.IsDefined() ? node.Mark().line : -1;
  fail(file + (line >= 0 ? ":" + std::to_string(line + 1) : ""), key + ": " + what);
}

// The next header token of a PGM, skipping whitespace and # comments.
std::string pgmToken(std::istream& in) {
  std::string token;
  for (int c; (c = in.get()) != EOF;) {
    if (c == '#') {
      std::string comment;
      std::getline(in, comment);
      if (!token.empty()) return token;
    } else if (std::isspace(c)) {
      if (!token.empty()) return token;
    } else if (token.size() < 16) {  // a header number has at most 10 digits
      token += static_cast<char>(c);
    }
  }
  return token;
}

int pgmNumber(std::istream& in, const std::string& file, const char* what) {
  const std::string token = pgmToken(in);
  try {
    std::size_t used = 0;
    const int value = std::stoi(token, &used);
    if (used == token.size() && value > 0) return value;
  } catch (const std::exception&) {
  }
  fail(file, std::string("bad PGM header: ") + what + " '" + token + "'");
}

// The grey values of a PGM (P5 or P2, maxval <= 255), top row first, scaled to 0..255. The
// size is checked against the cap and the file's own length before anything is allocated.
std::vector<std::uint8_t> readPgm(const std::string& file, int* width, int* height) {
  const std::string problem = core::regularFileProblem(file, kMaxImageBytes);
  if (!problem.empty()) fail(file, "cannot read the map image: " + problem);
  std::ifstream in(file, std::ios::binary);
  if (!in) fail(file, "cannot read the map image");
  const std::string magic = pgmToken(in);
  if (magic != "P5" && magic != "P2") fail(file, "not a PGM image (magic '" + magic + "', expected P5 or P2)");
  *width = pgmNumber(in, file, "width");
  *height = pgmNumber(in, file, "height");
  const int maxval = pgmNumber(in, file, "maxval");
  if (maxval > 255) fail(file, "16-bit PGM (maxval " + std::to_string(maxval) + ") is not supported");
  const std::uintmax_t cells = static_cast<std::uintmax_t>(*width) * static_cast<std::uintmax_t>(*height);
  const std::string size = std::to_string(*width) + " x " + std::to_string(*height);
  if (cells > kMaxMapCells) fail(file, size + " pixels: more than the " + std::to_string(kMaxMapCells) + " accepted");
  // P5 holds one byte per pixel, P2 at least a digit and a separator per pixel but the last.
  const std::uintmax_t needed = magic == "P5" ? cells : 2 * cells - 1;
  const std::streamoff header = in.tellg();
  const std::uintmax_t left = std::filesystem::file_size(file) - static_cast<std::uintmax_t>(header < 0 ? 0 : header);
  if (header < 0 || left < needed) {
    fail(file, size + " pixels need at least " + std::to_string(needed) + " bytes of image data, the file has " +
                   std::to_string(header < 0 ? 0 : left));
  }
  std::vector<std::uint8_t> pixels(cells);
  const auto ends = [&](std::size_t i) {
    fail(file, "image data ends after " + std::to_string(i) + " of " + std::to_string(pixels.size()) + " pixels");
  };
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    long value = 0;
    if (magic == "P5") {
      const int c = in.get();
      if (c == EOF) ends(i);
      value = c;
    } else {
      const std::string token = pgmToken(in);
      if (token.empty()) ends(i);
      char* end = nullptr;
      value = std::strtol(token.c_str(), &end, 10);
      if (*end != '\0' || token[0] == '-' || token[0] == '+') value = -1;
    }
    if (value < 0 || value > maxval) {
      fail(file, "pixel " + std::to_string(i) + ": not a grey value in [0, " + std::to_string(maxval) + "]");
    }
    pixels[i] = static_cast<std::uint8_t>(value * 255 / maxval);
  }
  return pixels;
}

template <class T>
T required(const YAML::Node& root, const std::string& file, const char* key) {
  const YAML::Node node = root[key];
  if (!node) failAt(file, root, key, "missing");
  try {
    return node.as<T>();
  } catch (const YAML::Exception&) {
    failAt(file, node, key, node.IsScalar() ? "cannot read '" + node.Scalar() + "'" : "expected a value, got a list or mapping");
  }
}

std::string folderOf(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}

YAML::Node parseYaml(const std::string& yaml_path) {
  YAML::Node root;
  const std::string text = core::readInputFile(yaml_path);
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    fail(yaml_path + ":" + std::to_string(e.mark.line + 1), e.msg);
  }
  if (const auto big = core::yamlSizeProblem(root)) failAt(yaml_path, big->node, "(document)", big->reason);
  if (!root.IsMap()) fail(yaml_path, "not a map_server YAML (expected keys image, resolution, origin, ...)");
  for (const auto& entry : root) {
    static const std::vector<std::string> known = {"image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh", "mode"};
    if (!entry.first.IsScalar()) failAt(yaml_path, entry.first, "(key)", "a key must be a word, not a list or mapping");
    const std::string key = entry.first.Scalar();
    if (std::find(known.begin(), known.end(), key) == known.end()) failAt(yaml_path, entry.first, key, "unknown key");
  }
  return root;
}

}  // namespace

OccupancyMap loadMap(const std::string& yaml_path) {
  const YAML::Node root = parseYaml(yaml_path);
  const std::string image = required<std::string>(root, yaml_path, "image");
  const double resolution = required<double>(root, yaml_path, "resolution");
  if (!(resolution > 0.0) || !std::isfinite(resolution)) failAt(yaml_path, root["resolution"], "resolution", "must be > 0 m");
  const std::vector<double> origin = required<std::vector<double>>(root, yaml_path, "origin");
  if (origin.size() != 3) failAt(yaml_path, root["origin"], "origin", "expected [x, y, yaw]");
  for (double v : origin)
    if (!std::isfinite(v)) failAt(yaml_path, root["origin"], "origin", "must be finite");
  if (std::abs(origin[2]) > 1e-9) failAt(yaml_path, root["origin"], "origin", "a rotated map (yaw != 0) is not supported");
  const int negate = required<int>(root, yaml_path, "negate");
  if (negate != 0 && negate != 1) failAt(yaml_path, root["negate"], "negate", "must be 0 or 1");
  const double occupied_thresh = required<double>(root, yaml_path, "occupied_thresh");
  const double free_thresh = required<double>(root, yaml_path, "free_thresh");
  if (!(occupied_thresh > 0.0 && occupied_thresh <= 1.0))
    failAt(yaml_path, root["occupied_thresh"], "occupied_thresh", "must be in (0, 1]");
  if (!(free_thresh >= 0.0 && free_thresh < occupied_thresh))
    failAt(yaml_path, root["free_thresh"], "free_thresh", "must be in [0, occupied_thresh)");
  const std::string mode = root["mode"] ? required<std::string>(root, yaml_path, "mode") : "trinary";
  if (mode != "trinary" && mode != "scale" && mode != "raw")
    failAt(yaml_path, root["mode"], "mode", "must be trinary, scale or raw, got '" + mode + "'");
  if (image.empty()) failAt(yaml_path, root["image"], "image", "empty (expected the PGM's path)");

  const std::string image_path = image[0] == '/' ? image : folderOf(yaml_path) + image;
  int width = 0, height = 0;
  const std::vector<std::uint8_t> pixels = readPgm(image_path, &width, &height);
  OccupancyMap map = makeMap(resolution, origin[0], origin[1], width, height);
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      const int pixel = pixels[static_cast<std::size_t>(row) * width + col];
      std::int8_t& cell = map.at(col, height - 1 - row);  // the image's top row is the map's last
      if (mode == "raw") {
        cell = static_cast<std::int8_t>(pixel > 100 ? OccupancyMap::kUnknown : pixel);
        continue;
      }
      const double occ = negate ? pixel / 255.0 : (255.0 - pixel) / 255.0;
      if (occ > occupied_thresh) cell = OccupancyMap::kOccupied;
      else if (occ < free_thresh) cell = OccupancyMap::kFree;
      else if (mode == "scale") cell = static_cast<std::int8_t>(std::lround(99.0 * (occ - free_thresh) / (occupied_thresh - free_thresh)));
      else cell = OccupancyMap::kUnknown;
    }
  }
  return map;
}

void saveMap(const std::string& yaml_path, const OccupancyMap& map) {
  if (map.empty()) fail(yaml_path, "the map is empty (no scan has been inserted yet)");
  // The folder is created when missing (a recipe's ~/maps/lab.yaml on a fresh account).
  std::error_code created;
  const std::filesystem::path folder = std::filesystem::absolute(yaml_path, created).parent_path();
  if (!created) std::filesystem::create_directories(folder, created);
  if (created) fail(yaml_path, "cannot create the folder " + folder.string() + ": " + created.message());
  std::string stem = yaml_path;
  const std::size_t dot = stem.rfind('.');
  if (dot != std::string::npos && dot > stem.rfind('/') + 1) stem = stem.substr(0, dot);
  const std::string pgm_path = stem + ".pgm";
  {
    std::ofstream out(pgm_path, std::ios::binary);
    if (!out) fail(pgm_path, "cannot write the map image");
    out << "P5\n# CREATOR: amigobot_tracking localization " << map.resolution << " m/pix\n"
        << map.width << " " << map.height << "\n255\n";
    std::string row(static_cast<std::size_t>(map.width), '\0');
    for (int y = map.height - 1; y >= 0; --y) {
      for (int x = 0; x < map.width; ++x) {
        const int v = map.at(x, y);
        row[static_cast<std::size_t>(x)] = static_cast<char>(v < 0 ? 205 : v >= 65 ? 0 : v <= 19 ? 254 : 205);
      }
      out.write(row.data(), static_cast<std::streamsize>(row.size()));
    }
    if (!out) fail(pgm_path, "cannot write the map image");
  }
  std::ofstream out(yaml_path);
  if (!out) fail(yaml_path, "cannot write the map file");
  char origin[128];
  std::snprintf(origin, sizeof origin, "[%.6f, %.6f, 0.0]", map.origin_x, map.origin_y);
  out << "image: " << pgm_path.substr(pgm_path.rfind('/') + 1) << "\n"
      << "resolution: " << map.resolution << "\n"
      << "origin: " << origin << "\n"
      << "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\nmode: trinary\n";
  if (!out) fail(yaml_path, "cannot write the map file");
}

}  // namespace localization
}  // namespace amigobot_tracking
