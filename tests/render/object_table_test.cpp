// The scene file's object tables (io/object_table.h): a table's objects read back as written, after
// the listed objects; the same scene from kept texts as from the files; and every bad line refused
// with one SceneError naming the key, the file, the line and the rule.
#include "../io/scratch_directory.h"
#include "io/scene_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace revolve {
namespace {

using ::testing::HasSubstr;
using testing::WorkingDirectory;

const std::string kTableScene = R"({
  "camera": {"from": [0, -3, 1], "to": [0, 0, 0.5], "up": [0, 0, 1], "fov": 40},
  "profiles": {"ball": {"points": [[0, 0], [0.5, 0.2], [0.5, 0.8], [0, 1]]}},
  "materials": {"white": {"type": "diffuse", "color": [0.8, 0.8, 0.8]}, "clay": {"type": "diffuse", "color": [0.7, 0.5, 0.4]}},
  "objects": [{"profile": "ball", "material": "white"}],
  "object_tables": [{"profiles_csv": "p.csv", "objects_csv": "o.csv", "material": "clay", "reflectivity": 0.5}]
})";

// Three objects: a polyline, a Catmull-Rom spline and a polyline, the header lines given.
const std::string kProfiles =
    "object,r,z\n"
    "0,0,0\n0,0.3,0\n0,0.3,1\n0,0,1\n"
    "1,0,0\n1,0.25,0.25\n1,0.4,0.5\n1,0.2,0.75\n1,0,1\n"
    "2,0,0\n2,0.125,0\n2,0.125,2.5\n2,0,2.5\n";
const std::string kObjects =
    "object,spline,x,y,z,axis_x,axis_y,axis_z,degrees,scale\n"
    "0,linear,1,2,3,0,0,1,0,1\n"
    "1,catmull-rom,-4.5,0.25,0,1,0,0,90,0.5\n"
    "2,linear,7,8,9,0,0,2,30,2\n";

// The SceneError reading the table scene with these CSVs (and scene text) gives, or "" if none.
std::string errorOf(const std::string& profiles, const std::string& objects, const std::string& scene = kTableScene) {
  const testing::ScratchDirectory dir;
  dir.write("scene.json", scene);
  dir.write("p.csv", profiles);
  dir.write("o.csv", objects);
  const WorkingDirectory inside(dir.path());
  try {
    io::readScene("scene.json");
  } catch (const io::SceneError& error) {
    EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << "one line";
    return error.what();
  }
  ADD_FAILURE() << "no error";
  return "";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(ObjectTableTest, ObjectsReadBackAsWrittenAfterTheListedOnes) {
  const testing::ScratchDirectory dir;
  dir.write("scene.json", kTableScene);
  dir.write("p.csv", kProfiles);
  dir.write("o.csv", kObjects);
  const WorkingDirectory inside(dir.path());
  const io::SceneDescription scene = io::readScene("scene.json");
  ASSERT_EQ(scene.objects.size(), 4u);  // the listed ball, then the table's three
  ASSERT_EQ(scene.profiles.size(), 4u);
  EXPECT_EQ(scene.objects[0].profile, 0u);
  const std::vector<std::vector<Point2>> points{{{0, 0}, {0.3, 0}, {0.3, 1}, {0, 1}},
                                                {{0, 0}, {0.25, 0.25}, {0.4, 0.5}, {0.2, 0.75}, {0, 1}},
                                                {{0, 0}, {0.125, 0}, {0.125, 2.5}, {0, 2.5}}};
  for (std::size_t k = 0; k < 3; ++k) {
    const io::SceneObject& object = scene.objects[1 + k];
    EXPECT_EQ(object.profile, 1 + k);
    EXPECT_EQ(object.material, 1u);  // "clay"
    EXPECT_EQ(object.reflectivity, 0.5);
    const io::SceneProfile& profile = scene.profiles[object.profile];
    const std::span<const Point2> read = k == 1 ? profile.spline->points() : profile.profile->points();
    ASSERT_EQ(read.size(), points[k].size()) << k;
    for (std::size_t i = 0; i < read.size(); ++i) {
      EXPECT_EQ(read[i].r, points[k][i].r) << k << " " << i;
      EXPECT_EQ(read[i].z, points[k][i].z) << k << " " << i;
    }
    EXPECT_EQ(profile.spline.has_value(), k == 1);
  }
  const app::Transform& second = scene.objects[2].transform;
  EXPECT_EQ(second.translate, (app::Vec3d{-4.5, 0.25, 0}));
  EXPECT_EQ(second.rotateAxis, (app::Vec3d{1, 0, 0}));
  EXPECT_EQ(second.rotateDegrees, 90);
  EXPECT_EQ(second.scale, (app::Vec3d{0.5, 0.5, 0.5}));
  const app::Transform& third = scene.objects[3].transform;
  EXPECT_EQ(third.rotateAxis, (app::Vec3d{0, 0, 1}));  // (0, 0, 2) made unit, as "rotate" does
  EXPECT_EQ(third.rotateDegrees, 30);
  EXPECT_EQ(third.scale, (app::Vec3d{2, 2, 2}));
}

// The texts kept while reading rebuild the same scene without opening a file (as Python's pickles do).
TEST(ObjectTableTest, KeptTextsRebuildTheSameScene) {
  const testing::ScratchDirectory dir;
  dir.write("scene.json", kTableScene);
  dir.write("p.csv", kProfiles);
  dir.write("o.csv", kObjects + "\n");  // a trailing blank line is no object
  const WorkingDirectory inside(dir.path());
  std::string text;
  io::FileTexts texts;
  const io::SceneDescription fromFiles = io::readScene("scene.json", text, texts);
  EXPECT_EQ(texts.texts.size(), 2u);
  texts.readFiles = false;
  const io::SceneDescription fromTexts = io::parseScene(text, "elsewhere.json", "", texts);
  ASSERT_EQ(fromTexts.objects.size(), fromFiles.objects.size());
  for (std::size_t i = 0; i < fromFiles.objects.size(); ++i) {
    EXPECT_EQ(fromTexts.objects[i].transform.translate, fromFiles.objects[i].transform.translate);
    const auto a = fromFiles.profiles[i].polyline().points(), b = fromTexts.profiles[i].polyline().points();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_TRUE(a[k].r == b[k].r && a[k].z == b[k].z);
  }
}

TEST(ObjectTableTest, HeaderLinesAreOptional) {
  const testing::ScratchDirectory dir;
  dir.write("scene.json", kTableScene);
  dir.write("p.csv", kProfiles.substr(kProfiles.find('\n') + 1));
  dir.write("o.csv", kObjects.substr(kObjects.find('\n') + 1));
  const WorkingDirectory inside(dir.path());
  EXPECT_EQ(io::readScene("scene.json").objects.size(), 4u);
}

TEST(ObjectTableTest, UnknownAndMissingKeysAreRefused) {
  EXPECT_THAT(errorOf(kProfiles, kObjects, replaced(kTableScene, R"("reflectivity": 0.5)", R"("colour": 0.5)")),
              HasSubstr("scene.json: object_tables[0].colour: unknown key; expected one of: profiles_csv, "
                        "objects_csv, material, reflectivity, tolerance, crease"));
  EXPECT_THAT(errorOf(kProfiles, kObjects, replaced(kTableScene, R"("material": "clay", )", "")),
              HasSubstr(R"(scene.json: object_tables[0]: missing key "material")"));
  EXPECT_THAT(errorOf(kProfiles, kObjects, replaced(kTableScene, R"("material": "clay")", R"("material": "clai")")),
              HasSubstr(R"(object_tables[0].material: no material named "clai")"));
  EXPECT_THAT(errorOf(kProfiles, kObjects, replaced(kTableScene, R"("o.csv")", R"("missing.csv")")),
              HasSubstr("object_tables[0].objects_csv: missing.csv: cannot open"));
}

TEST(ObjectTableTest, EmptyFilesAreRefused) {
  EXPECT_THAT(errorOf("", kObjects), HasSubstr("object_tables[0].profiles_csv: p.csv: no profile points"));
  EXPECT_THAT(errorOf("object,r,z\n\n", kObjects), HasSubstr("p.csv: no profile points"));
  EXPECT_THAT(errorOf(kProfiles, ""), HasSubstr("object_tables[0].objects_csv: o.csv: no objects"));
}

TEST(ObjectTableTest, WrongColumnsAreRefusedByLine) {
  EXPECT_THAT(errorOf(replaced(kProfiles, "0,0.3,1\n", "0,0.3,1,7\n"), kObjects),
              HasSubstr("object_tables[0].profiles_csv: p.csv:4: expected 3 comma-separated values (object,r,z), "
                        "found 4"));
  EXPECT_THAT(errorOf(kProfiles, replaced(kObjects, "0,0,1,0,1\n", "0,0,1,0\n")),
              HasSubstr("o.csv:2: expected 10 comma-separated values"));
  EXPECT_THAT(errorOf(replaced(kProfiles, "object,r,z", "id,r,z"), kObjects),
              HasSubstr(R"(p.csv:1: header "id,r,z" is not the expected "object,r,z")"));
  EXPECT_THAT(errorOf(kProfiles, replaced(kObjects, "0,linear,1,2,3", "0,linear,1,2,3," + std::string(5000, ' '))),
              HasSubstr("o.csv:2: the line is more than 4096 bytes long"));
}

TEST(ObjectTableTest, BadValuesAreNamedByFileLineAndRule) {
  EXPECT_THAT(errorOf(replaced(kProfiles, "1,0.4,0.5", "1,nan,0.5"), kObjects),
              HasSubstr(R"(p.csv:8: r = "nan" is not finite)"));
  EXPECT_THAT(errorOf(replaced(kProfiles, "1,0.4,0.5", "1,0.4,half"), kObjects),
              HasSubstr(R"(p.csv:8: z = "half" is not a number)"));
  EXPECT_THAT(errorOf(kProfiles, replaced(kObjects, "-4.5,0.25", "inf,0.25")),
              HasSubstr(R"(o.csv:3: x = "inf" is not finite)"));
  EXPECT_THAT(errorOf(kProfiles, replaced(kObjects, "7,8,9", "7,8,2e12")),
              HasSubstr(R"(o.csv:4: z = "2e12" is beyond the coordinate limit)"));
  EXPECT_THAT(errorOf(kProfiles, replaced(kObjects, "catmull-rom", "cubic")),
              HasSubstr(R"(o.csv:3: spline = "cubic" is not a spline kind; expected one of)"));
  EXPECT_THAT(errorOf(kProfiles, replaced(kObjects, "0,0,2,30,2", "0,0,0,30,2")),
              HasSubstr("o.csv:4: the rotation axis (axis_x, axis_y, axis_z) is zero"));
  EXPECT_THAT(errorOf(kProfiles, replaced(kObjects, "1,0,0,90,0.5", "1,0,0,90,0")), HasSubstr("o.csv:3: scale: "));
  // The profile's own rule (the Profile constructor's), at the point's line.
  EXPECT_THAT(errorOf(replaced(kProfiles, "2,0.125,2.5", "2,-0.125,2.5"), kObjects),
              HasSubstr("object_tables[0].profiles_csv: p.csv:13: "));
}

TEST(ObjectTableTest, IdsOutOfOrderOrMissingAreRefused) {
  // Object 1's points broken by object 0's again.
  EXPECT_THAT(errorOf(replaced(kProfiles, "1,0.4,0.5\n", "0,0.4,0.5\n"), kObjects),
              HasSubstr("p.csv:8: object 0 follows object 1: objects are numbered 0, 1, 2, ... in order"));
  // Object 1 missing from the profiles.
  std::string noOne = kProfiles;
  for (std::size_t at; (at = noOne.find("\n1,")) != std::string::npos;)
    noOne.erase(at + 1, noOne.find('\n', at + 1) - at);
  EXPECT_THAT(errorOf(noOne, kObjects), HasSubstr("p.csv:6: object 2 follows object 0"));
  EXPECT_THAT(errorOf(replaced(kProfiles, "object,r,z\n0,", "object,r,z\n1,"), kObjects),
              HasSubstr("p.csv:2: the first object is 1"));
  EXPECT_THAT(errorOf(kProfiles, replaced(kObjects, "1,catmull-rom", "2,catmull-rom")),
              HasSubstr("o.csv:3: object 2 where object 1 comes next"));
  EXPECT_THAT(errorOf(kProfiles, replaced(kObjects, "1,catmull-rom", "x,catmull-rom")),
              HasSubstr(R"(o.csv:3: object = "x" is not a whole number >= 0)"));
  EXPECT_THAT(errorOf(kProfiles, replaced(kObjects, "1,catmull-rom", "-1,catmull-rom")),
              HasSubstr(R"(o.csv:3: object = "-1" is not a whole number >= 0)"));
  // The two files disagree on the count.
  EXPECT_THAT(errorOf(kProfiles, kObjects + "3,linear,0,0,0,0,0,1,0,1\n"),
              HasSubstr("o.csv:5: object 3 has no profile: p.csv ends with object 2"));
  EXPECT_THAT(errorOf(kProfiles + "3,0,0\n3,1,0\n3,0,1\n", kObjects),
              HasSubstr("p.csv:15: object 3 has no line in o.csv, which ends with object 2"));
}

// An earlier object's error is the one reported, though later lines are read (and built) in batches.
TEST(ObjectTableTest, TheFirstFailingObjectIsReported) {
  const std::string profiles = replaced(kProfiles, "0,0.3,1", "0,-0.3,1");  // object 0: r < 0
  const std::string objects = replaced(kObjects, "2,linear", "2,cubic");    // object 2: a bad line
  EXPECT_THAT(errorOf(profiles, objects), HasSubstr("p.csv:4: "));
}

// Tables longer than a build batch (4,096 objects: io/object_table.cpp's kBatchObjects): 8,197 objects cross two batch
// boundaries and read back in order, each as the formula that wrote it says; a bad object in the second batch is named
// by its line, and of two bad objects in different batches the earlier one.
TEST(ObjectTableTest, TablesCrossingBuildBatchesReadBackInOrder) {
  constexpr std::size_t kCount = 2 * 4096 + 5;
  const auto radius = [](std::size_t i) { return 0.125 + double(i) * 0x1p-20; };  // exact in decimal text
  const auto tables = [&](std::size_t badObject, std::size_t secondBad) {
    std::string profiles = "object,r,z\n", objects = "object,spline,x,y,z,axis_x,axis_y,axis_z,degrees,scale\n";
    char line[160];
    for (std::size_t i = 0; i < kCount; ++i) {
      const double r = i == badObject || i == secondBad ? -radius(i) : radius(i);
      std::snprintf(line, sizeof line, "%zu,0,0\n%zu,%.17g,0\n%zu,%.17g,1\n%zu,0,1\n", i, i, r, i, r, i);
      profiles += line;
      std::snprintf(line, sizeof line, "%zu,linear,%zu,0,0,0,0,1,0,1\n", i, i);
      objects += line;
    }
    return std::pair{profiles, objects};
  };
  constexpr std::size_t kNone = kCount;
  {
    const auto [profiles, objects] = tables(kNone, kNone);
    const testing::ScratchDirectory dir;
    dir.write("scene.json", kTableScene);
    dir.write("p.csv", profiles);
    dir.write("o.csv", objects);
    const WorkingDirectory inside(dir.path());
    const io::SceneDescription scene = io::readScene("scene.json");
    ASSERT_EQ(scene.objects.size(), 1 + kCount);
    for (std::size_t i = 0; i < kCount; ++i) {
      const io::SceneObject& object = scene.objects[1 + i];
      ASSERT_EQ(object.transform.translate, (app::Vec3d{double(i), 0, 0})) << i;
      const std::span<const Point2> points = scene.profiles[object.profile].profile->points();
      ASSERT_EQ(points.size(), 4u) << i;
      ASSERT_EQ(points[1].r, radius(i)) << i;
      ASSERT_EQ(points[2].z, 1.0) << i;
    }
  }
  // Object k's profile lines are 2 + 4 k to 5 + 4 k: its second point, line 3 + 4 k, has r < 0.
  const auto [profiles, objects] = tables(4100, kNone);
  EXPECT_THAT(errorOf(profiles, objects), HasSubstr("p.csv:" + std::to_string(3 + 4 * 4100) + ": "));
  const auto [profiles2, objects2] = tables(4100, 8195);
  EXPECT_THAT(errorOf(profiles2, objects2), HasSubstr("p.csv:" + std::to_string(3 + 4 * 4100) + ": "));
}

}  // namespace
}  // namespace revolve
