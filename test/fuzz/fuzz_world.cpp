// libFuzzer target: the world file reader (world/world.h parseWorld) on arbitrary YAML.
// Invariants: no crash or UB, no other exception than std::runtime_error naming the file;
// an accepted world is valid (validateWorld) and reads back from its own worldYaml.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "amigobot_tracking/world/world.h"
#include "fuzz_support.h"

using namespace amigobot_tracking::world;
using fuzz_support::check;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  World world;
  try {
    world = parseWorld(text, "fuzz.yaml");
  } catch (const std::runtime_error& e) {
    check(std::string(e.what()).rfind("fuzz.yaml:", 0) == 0);
    return 0;
  }
  check(validateWorld(world).empty());
  const World again = parseWorld(worldYaml(world), "again.yaml");
  check(again.obstacles.size() == world.obstacles.size() && again.walls.size() == world.walls.size() &&
        again.polygons.size() == world.polygons.size() && again.people.size() == world.people.size());
  return 0;
}
