// The landmark override file: parsing, errors that name the file, frames
// and units.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "measure/landmarks/landmarks.h"
#include "scanners/core/errors.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

using testing::TempDir;

std::filesystem::path Write(const TempDir& dir, const std::string& name, const std::string& text) {
  const std::filesystem::path file = dir / name;
  std::ofstream(file) << text;
  return file;
}

// Expects InputError whose message contains the file's name and `what`.
void ExpectInputError(const std::filesystem::path& file, const std::string& what) {
  try {
    ReadLandmarkOverrides(file);
    FAIL() << "no error for " << file;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(file.filename().string()), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  }
}

TEST(LandmarkOverrides, ReadsBodyFrameFile) {
  TempDir dir;
  const auto file = Write(dir, "o.json",
                          R"({"frame": "body", "units": "mm",
                              "landmarks": {"shoulder_right": [180, 5, 1450.5],
                                            "crown": [0, 10, 1750]}})");
  const LandmarkOverrides overrides = ReadLandmarkOverrides(file);
  EXPECT_EQ(overrides.frame, "body");
  EXPECT_EQ(overrides.units, "mm");
  ASSERT_EQ(overrides.points.size(), 2u);
  EXPECT_DOUBLE_EQ(overrides.points.at("shoulder_right").z(), 1450.5);
}

TEST(LandmarkOverrides, DefaultsToScanFrameInMillimetres) {
  TempDir dir;
  const auto file = Write(dir, "o.json", R"({"landmarks": {"crotch": [1, 2, 3]}})");
  const LandmarkOverrides overrides = ReadLandmarkOverrides(file);
  EXPECT_EQ(overrides.frame, "scan");
  EXPECT_EQ(overrides.units, "mm");
}

TEST(LandmarkOverrides, ErrorsNameTheFile) {
  TempDir dir;
  ExpectInputError(Write(dir, "broken.json", "{\"landmarks\": {"), "broken.json");
  ExpectInputError(Write(dir, "array.json", "[1, 2]"), "not a JSON object");
  ExpectInputError(Write(dir, "none.json", "{\"frame\": \"body\"}"), "landmarks");
  ExpectInputError(Write(dir, "name.json", R"({"landmarks": {"shoulder_middle": [0, 0, 0]}})"),
                   "shoulder_middle");
  ExpectInputError(Write(dir, "short.json", R"({"landmarks": {"crown": [0, 0]}})"), "crown");
  ExpectInputError(Write(dir, "text.json", R"({"landmarks": {"crown": ["a", 0, 0]}})"), "crown");
  ExpectInputError(Write(dir, "frame.json", R"({"frame": "world", "landmarks": {}})"), "world");
  ExpectInputError(Write(dir, "units.json", R"({"units": "inch", "landmarks": {}})"), "inch");
  EXPECT_THROW(ReadLandmarkOverrides(dir / "absent.json"), InputError);
}

TEST(LandmarkOverrides, AcceptsAScanSimTruthDocument) {
  // The virtual scanner's truth file says "frame": "scanner".
  TempDir dir;
  const auto file = Write(dir, "truth.json",
                          R"({"format": "bespoke-measurements", "units": "mm", "frame": "scanner",
                              "landmarks": {"crown": [1, 2, 3]},
                              "landmarks_body": {"crown": [0, 0, 1700]}, "file_unit": "m"})");
  const LandmarkOverrides overrides = ReadLandmarkOverrides(file);
  EXPECT_EQ(overrides.frame, "scan");
  EXPECT_EQ(overrides.points.size(), 1u);
}

TEST(LandmarkOverrides, ApplyMapsScanFrameAndUnitsToBodyMillimetres) {
  LandmarkSet set;
  set.points["crown"].position_mm = Eigen::Vector3d(0, 0, 1700);
  set.points["crown"].confidence = 0.3;
  set.missing["wrist_left"] = "arm not found";
  LandmarkOverrides overrides;
  overrides.frame = "scan";
  overrides.units = "m";
  overrides.points["crown"] = Eigen::Vector3d(0.01, 0.02, 1.75);
  overrides.points["wrist_left"] = Eigen::Vector3d(-0.5, 0.0, 1.0);
  Eigen::Isometry3d body_from_scan = Eigen::Isometry3d::Identity();
  body_from_scan.translate(Eigen::Vector3d(100, 0, 0));
  body_from_scan.rotate(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  ApplyLandmarkOverrides(overrides, body_from_scan, &set);
  // Rotated 90 deg about z: (10, 20, 1750) -> (-20, 10, 1750), then +100 in x.
  EXPECT_NEAR((set.At("crown").position_mm - Eigen::Vector3d(80, 10, 1750)).norm(), 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(set.At("crown").confidence, 1.0);
  EXPECT_EQ(set.At("crown").flags, std::vector<std::string>{"override"});
  EXPECT_TRUE(set.Has("wrist_left"));
  EXPECT_EQ(set.missing.count("wrist_left"), 0u);
  EXPECT_NEAR((set.At("wrist_left").position_mm - Eigen::Vector3d(100, -500, 1000)).norm(), 0.0,
              1e-9);
}

TEST(LandmarkOverrides, ApplyIgnoresTheTransformInBodyFrame) {
  LandmarkSet set;
  LandmarkOverrides overrides;
  overrides.frame = "body";
  overrides.units = "cm";
  overrides.points["knee_right"] = Eigen::Vector3d(10, 1, 50);
  Eigen::Isometry3d body_from_scan = Eigen::Isometry3d::Identity();
  body_from_scan.translate(Eigen::Vector3d(100, 0, 0));
  ApplyLandmarkOverrides(overrides, body_from_scan, &set);
  EXPECT_NEAR((set.At("knee_right").position_mm - Eigen::Vector3d(100, 10, 500)).norm(), 0.0, 1e-9);
}

TEST(LandmarkSet, AtNamesTheLandmarkAndReason) {
  LandmarkSet set;
  set.missing["elbow_left"] = "left arm touches the torso";
  try {
    set.At("elbow_left");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("touches the torso"), std::string::npos);
  }
  EXPECT_THROW(set.At("crown"), InputError);
}

TEST(LandmarkOptions, CheckRejectsBadValues) {
  LandmarkOptions options;
  EXPECT_NO_THROW(options.Check());
  options.slice_step_mm = 0;
  EXPECT_THROW(options.Check(), InputError);
  options = LandmarkOptions();
  options.only = {"nose_tip"};
  EXPECT_THROW(options.Check(), InputError);
}

}  // namespace
}  // namespace bespoke
