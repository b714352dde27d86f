// libFuzzer target: map_server's map files (localization/occupancy_map.h loadMap) on an
// arbitrary YAML and image: the input is the YAML, a line "#PGM", then the image, written
// to a scratch folder as map.yaml and image.pgm. Invariants: no crash or UB, no exception
// but std::runtime_error naming a file; an accepted map has width x height cells, each
// unknown or an occupancy in 0..100.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "amigobot_tracking/localization/occupancy_map.h"
#include "fuzz_support.h"

using namespace amigobot_tracking::localization;
using fuzz_support::check;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t split = input.find("\n#PGM\n");
  const std::string yaml = input.substr(0, split);
  const std::string image = split == std::string::npos ? "" : input.substr(split + 6);
  fuzz_support::writeScratch("image.pgm", image);
  const std::string path = fuzz_support::writeScratch("map.yaml", yaml);
  OccupancyMap map;
  try {
    map = loadMap(path);
  } catch (const std::runtime_error& e) {
    check(std::string(e.what()).find(": ") != std::string::npos);
    return 0;
  }
  check(map.width > 0 && map.height > 0);
  check(map.cells.size() == static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height));
  for (const std::int8_t cell : map.cells) check(cell == OccupancyMap::kUnknown || (cell >= 0 && cell <= 100));
  return 0;
}
