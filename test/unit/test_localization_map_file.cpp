// map_server's map files (YAML + PGM): a round trip keeps every cell, a file written by hand
// the way map_saver writes it reads with the right rows and thresholds, and each bad file is
// refused naming the file and the key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "amigobot_tracking/localization/occupancy_map.h"
#include "temp_dir.h"

using namespace amigobot_tracking::localization;

namespace {

class MapFiles : public TempDirTest {
 protected:
  // The error loadMap throws for the YAML text (with a valid 2x2 image beside it).
  std::string errorOf(const std::string& yaml) {
    write("ok.pgm", std::string("P5\n2 2\n255\n") + char(0) + char(254) + char(205) + char(0));
    const std::string path = write("bad.yaml", yaml);
    try {
      loadMap(path);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "no error";
  }
};

const char kGoodYaml[] = "image: ok.pgm\nresolution: 0.1\norigin: [-1.0, 2.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";

}  // namespace

TEST_F(MapFiles, RoundTripKeepsCellsResolutionAndOrigin) {
  OccupancyMap map = makeMap(0.05, -2.5, 1.25, 7, 5, OccupancyMap::kFree);
  map.at(0, 0) = OccupancyMap::kOccupied;
  map.at(6, 4) = OccupancyMap::kOccupied;
  map.at(3, 2) = OccupancyMap::kUnknown;
  map.at(1, 4) = OccupancyMap::kUnknown;
  const std::string yaml = dir_ + "/room.yaml";
  saveMap(yaml, map);
  std::ifstream pgm(dir_ + "/room.pgm");
  EXPECT_TRUE(pgm.good()) << "the image is written beside the YAML, named like it";
  const OccupancyMap back = loadMap(yaml);
  EXPECT_DOUBLE_EQ(back.resolution, 0.05);
  EXPECT_NEAR(back.origin_x, -2.5, 1e-6);
  EXPECT_NEAR(back.origin_y, 1.25, 1e-6);
  ASSERT_EQ(back.width, 7);
  ASSERT_EQ(back.height, 5);
  EXPECT_EQ(back.cells, map.cells);
}

TEST_F(MapFiles, ReadsMapServerImagesBottomRowFirstWithTheThresholds) {
  // Top row: occupied (0), free (254); bottom row: unknown (205), occupied (0).
  write("ok.pgm", std::string("P5\n# a comment\n2 2\n255\n") + char(0) + char(254) + char(205) + char(0));
  const OccupancyMap map = loadMap(write("map.yaml", kGoodYaml));
  EXPECT_EQ(map.at(0, 1), OccupancyMap::kOccupied);
  EXPECT_EQ(map.at(1, 1), OccupancyMap::kFree);
  EXPECT_EQ(map.at(0, 0), OccupancyMap::kUnknown);
  EXPECT_EQ(map.at(1, 0), OccupancyMap::kOccupied);
  EXPECT_DOUBLE_EQ(map.origin_x, -1.0);
  // The same picture as ASCII (P2), negated: white is occupied.
  write("neg.pgm", "P2\n2 2\n255\n255 0\n50 255\n");
  std::string yaml = kGoodYaml;
  yaml.replace(yaml.find("ok.pgm"), 6, "neg.pgm");
  yaml.replace(yaml.find("negate: 0"), 9, "negate: 1");
  const OccupancyMap negated = loadMap(write("neg.yaml", yaml));
  EXPECT_EQ(negated.at(0, 1), OccupancyMap::kOccupied);
  EXPECT_EQ(negated.at(1, 1), OccupancyMap::kFree);
  EXPECT_EQ(negated.at(0, 0), OccupancyMap::kUnknown);  // 50/255 = 0.196: between the thresholds
}

TEST_F(MapFiles, BadFilesNameTheFileAndTheKey) {
  EXPECT_NE(errorOf("image: ok.pgm\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.2\n")
                .find("bad.yaml:1: resolution: missing"),
            std::string::npos);
  std::string yaml = kGoodYaml;
  EXPECT_NE(errorOf(yaml + "colour: red\n").find("bad.yaml:7: colour: unknown key"), std::string::npos);
  EXPECT_NE(errorOf(std::string(kGoodYaml).replace(std::string(kGoodYaml).find("[-1.0, 2.0, 0.0]"), 16, "[1, 2]"))
                .find("bad.yaml:3: origin: expected [x, y, yaw]"),
            std::string::npos);
  EXPECT_NE(errorOf(std::string(kGoodYaml).replace(std::string(kGoodYaml).find("0.1"), 3, "-0.1")).find("bad.yaml:2: resolution:"),
            std::string::npos);
  EXPECT_NE(errorOf(std::string(kGoodYaml).replace(std::string(kGoodYaml).find("0.196"), 5, "0.9")).find("bad.yaml:6: free_thresh:"),
            std::string::npos);
  EXPECT_NE(errorOf(std::string(kGoodYaml) + "mode: fancy\n").find("bad.yaml:7: mode:"), std::string::npos);
  EXPECT_NE(errorOf("resolution: [oops\n").find("bad.yaml:2:"), std::string::npos);
  EXPECT_NE(errorOf(std::string(kGoodYaml).replace(0, 13, "image: none.pgm")).find("none.pgm: cannot read the map image: does not exist"),
            std::string::npos);
  write("text.pgm", "P6\n2 2\n255\n");
  EXPECT_NE(errorOf(std::string(kGoodYaml).replace(0, 13, "image: text.pgm")).find("text.pgm: not a PGM image"), std::string::npos);
  write("short.pgm", std::string("P5\n2 2\n255\n") + char(0));
  EXPECT_NE(errorOf(std::string(kGoodYaml).replace(0, 13, "image: short.pgm")).find("short.pgm: 2 x 2 pixels need at least 4 bytes of image data, the file has 1"),
            std::string::npos);
  try {
    loadMap(dir_ + "/absent.yaml");
    ADD_FAILURE() << "an absent file must throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("absent.yaml: does not exist"), std::string::npos) << e.what();
  }
}

TEST_F(MapFiles, SavingAnEmptyMapOrIntoAnUncreatableFolderNamesTheFile) {
  EXPECT_THROW(saveMap(dir_ + "/empty.yaml", OccupancyMap()), std::runtime_error);
  // A missing folder is created (a mapping drive must not end in "cannot write the map image").
  saveMap(dir_ + "/new/folder/map.yaml", makeMap(0.1, 0, 0, 2, 2));
  EXPECT_TRUE(std::ifstream(dir_ + "/new/folder/map.pgm").good());
  // A folder that cannot be made (a regular file in its path) is named.
  std::ofstream(dir_ + "/a_file") << "not a folder\n";
  try {
    saveMap(dir_ + "/a_file/maps/map.yaml", makeMap(0.1, 0, 0, 2, 2));
    ADD_FAILURE() << "an unwritable path must throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("a_file"), std::string::npos) << e.what();
  }
}
