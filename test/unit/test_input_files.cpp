// Hostile input files for every loader (core/support/input_file.h): special files, sizes that would
// allocate gigabytes, alias bombs, overflowing pixels and keys that are not words are each
// refused with an error naming the file (and the line and key where there is one), quickly
// and without a crash.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "amigobot_tracking/aria/robot_params.h"
#include "amigobot_tracking/core/support/input_file.h"
#include "amigobot_tracking/localization/occupancy_map.h"
#include "amigobot_tracking/sim/scenario.h"
#include "amigobot_tracking/world/world.h"
#include "temp_dir.h"

using namespace amigobot_tracking;

namespace {

class InputFiles : public TempDirTest {
 protected:
  // The error of loadMap for a map YAML whose image is `image` (a path or a file written here).
  std::string mapError(const std::string& image) {
    const std::string yaml = write("map.yaml", "image: " + image +
                                                   "\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\n"
                                                   "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
    return errorOf([&] { localization::loadMap(yaml); });
  }
  template <class F>
  static std::string errorOf(F&& load) {
    try {
      load();
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "no error";
  }
};

// A document whose aliases expand to 10^levels entries: a few hundred bytes.
std::string aliasBomb(const std::string& leaf, int levels) {
  std::string text = "a0: &a0 " + leaf + "\n";
  for (int i = 1; i <= levels; ++i) {
    const std::string p = "*a" + std::to_string(i - 1);
    text += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [" + p;
    for (int k = 1; k < 10; ++k) text += ", " + p;
    text += "]\n";
  }
  return text;
}

}  // namespace

TEST_F(InputFiles, OnlyRegularFilesUpToTheCapAreRead) {
  EXPECT_EQ(core::regularFileProblem(write("ok.yaml", "{}"), 10), "");
  EXPECT_EQ(core::regularFileProblem("/dev/zero", 1u << 30), "is not a regular file (a device, FIFO or socket)");
  EXPECT_EQ(core::regularFileProblem(dir_, 1u << 30), "is a directory, not a file");
  EXPECT_EQ(core::regularFileProblem(dir_ + "/absent", 1u << 30), "does not exist");
  const std::string fifo = dir_ + "/fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(core::regularFileProblem(fifo, 1u << 30), "is not a regular file (a device, FIFO or socket)");
  const std::string big = write("big.yaml", std::string(2000001, ' '));
  EXPECT_EQ(core::regularFileProblem(big, 1000000), "is 2.0 MB, more than the 1.0 MB accepted");
  EXPECT_EQ(errorOf([&] { core::readInputFile(big, 1000000); }), big + ": is 2.0 MB, more than the 1.0 MB accepted");
}

TEST_F(InputFiles, MapImageMustBeARegularFile) {
  EXPECT_EQ(mapError("/dev/zero"), "/dev/zero: cannot read the map image: is not a regular file (a device, FIFO or socket)");
  EXPECT_EQ(mapError(dir_), dir_ + ": cannot read the map image: is a directory, not a file");
  const std::string fifo = dir_ + "/image.pgm";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(mapError("image.pgm").find("image.pgm: cannot read the map image: is not a regular file"), std::string::npos);
}

TEST_F(InputFiles, AHugePgmHeaderIsRefusedBeforeAllocating) {
  // 60000 x 60000 once allocated 14 GB (as int) before reading a pixel.
  const auto start = std::chrono::steady_clock::now();
  write("huge.pgm", "P5\n60000 60000\n255\n" + std::string(100, '\0'));
  EXPECT_EQ(mapError("huge.pgm"), dir_ + "/huge.pgm: 60000 x 60000 pixels: more than the 100000000 accepted");
  write("wide.pgm", "P5\n9000 9000\n255\n" + std::string(100, '\0'));
  EXPECT_EQ(mapError("wide.pgm"),
            dir_ + "/wide.pgm: 9000 x 9000 pixels need at least 81000000 bytes of image data, the file has 100");
  write("ascii.pgm", "P2\n3 1\n255\n0 0\n");
  EXPECT_NE(mapError("ascii.pgm").find("need at least 5 bytes"), std::string::npos);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
}

TEST_F(InputFiles, PgmPixelsOutsideZeroToMaxvalAreRefused) {
  // 2147483647 * 255 overflowed an int (undefined behaviour) on the way to the grey value.
  write("max.pgm", "P2\n2 1\n255\n2147483647 0\n");
  EXPECT_EQ(mapError("max.pgm"), dir_ + "/max.pgm: pixel 0: not a grey value in [0, 255]");
  write("neg.pgm", "P2\n2 1\n100\n0 -5\n");
  EXPECT_EQ(mapError("neg.pgm"), dir_ + "/neg.pgm: pixel 1: not a grey value in [0, 100]");
  write("over.pgm", "P2\n2 1\n100\n0 101\n");
  EXPECT_EQ(mapError("over.pgm"), dir_ + "/over.pgm: pixel 1: not a grey value in [0, 100]");
  write("word.pgm", "P2\n2 1\n100\n0 x1\n");
  EXPECT_EQ(mapError("word.pgm"), dir_ + "/word.pgm: pixel 1: not a grey value in [0, 100]");
  write("fine.pgm", "P2\n2 1\n100\n0 100\n");
  EXPECT_EQ(mapError("fine.pgm"), "no error");
}

TEST_F(InputFiles, KeysThatAreNotWordsNameFileLineAndKey) {
  // yaml-cpp's "bad conversion" escaped from every loader, naming no file.
  const std::string map = write("map.yaml", "image: a.pgm\n[x, y]: 1\n");
  EXPECT_EQ(errorOf([&] { localization::loadMap(map); }), map + ":2: (key): a key must be a word, not a list or mapping");
  const std::string world = write("world.yaml", "obstacles:\n  - {center: [0, 0], radius: 1, {a: 1}: 2}\n");
  EXPECT_EQ(errorOf([&] { world::loadWorld(world); }),
            world + ":2: obstacles[0].(key): a key must be a word, not a list or mapping");
  EXPECT_EQ(errorOf([&] { sim::parseScenario("robot: {radius: 0.2}\n[1]: 2\n", "bad.yaml"); }),
            "bad.yaml:2: (key): a key must be a word, got a list");
  const std::string robot = write("robot.yaml", "model: amigo\n? [a]\n: 1\n");
  EXPECT_EQ(errorOf([&] { aria::loadRobotParams(robot); }), robot + ":2: a key must be a word, not a list or mapping");
}

TEST_F(InputFiles, AliasBombsAreRefusedWithoutBuildingThem) {
  // 10^7 walls behind 600 bytes; the loader walking the aliases built them (~1 GB).
  const auto start = std::chrono::steady_clock::now();
  const std::string bomb = aliasBomb("{from: [0, 0], to: [1, 0]}", 7);
  const std::string world = write("world.yaml", bomb + "walls: *a7\n");
  ASSERT_LT(bomb.size(), 1000u);
  const std::string error = errorOf([&] { world::loadWorld(world); });
  EXPECT_EQ(error.rfind(world + ":", 0), 0u) << error;
  EXPECT_NE(error.find("more than 1000000 YAML nodes once aliases are expanded"), std::string::npos) << error;
  const std::string scenario = errorOf([&] { sim::parseScenario(aliasBomb("1", 7), "bomb.yaml"); });
  EXPECT_NE(scenario.find("bomb.yaml:"), std::string::npos) << scenario;
  EXPECT_NE(scenario.find("more than 1000000 YAML nodes"), std::string::npos) << scenario;
  const std::string map = write("bomb_map.yaml", aliasBomb("1", 7));
  EXPECT_NE(errorOf([&] { localization::loadMap(map); }).find("more than 1000000 YAML nodes"), std::string::npos);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

TEST_F(InputFiles, EveryLoaderRefusesSpecialFilesNamingThem) {
  const std::string not_regular = ": is not a regular file (a device, FIFO or socket)";
  EXPECT_EQ(errorOf([] { world::loadWorld("/dev/zero"); }), "/dev/zero" + not_regular);
  EXPECT_EQ(errorOf([] { localization::loadMap("/dev/zero"); }), "/dev/zero" + not_regular);
  EXPECT_EQ(errorOf([] { aria::loadRobotParams("/dev/zero"); }), "/dev/zero" + not_regular);
  EXPECT_EQ(errorOf([] { sim::loadScenario("/dev/zero"); }), "/dev/zero" + not_regular + " (the scenario file)");
  EXPECT_EQ(errorOf([&] { world::loadWorld(dir_); }), dir_ + ": is a directory, not a file");
}
