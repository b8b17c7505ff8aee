// A scene file's object table: many objects, each with a profile of its own, read from two CSV
// files rather than spelled out in JSON (README.md, "Scene format", "Object tables"). A million
// objects are gigabytes of text, so the files are read a block at a time and the profiles built in
// parallel a batch at a time: memory holds the scene being described, not the text describing it.
//
//   "object_tables": [{"profiles_csv": "vases-profiles.csv", "objects_csv": "vases-objects.csv",
//                      "material": "clay"}]
//
// profiles_csv: `object,r,z`, one point a line, each object's points together and in order
// (bottom to top, as a profile CSV's). objects_csv: one line an object,
// `object,spline,x,y,z,axis_x,axis_y,axis_z,degrees,scale`: its spline kind (as a profile's
// "spline": linear for a polyline), its translation, its rotation (axis and angle, as "rotate")
// and its uniform scale factor. Objects are numbered 0, 1, 2, ... in both files, in order; the
// header lines are optional. Optional keys "tolerance", "crease" and "reflectivity" apply to every
// object of the table as they do to a named profile or an object. The table's objects follow the
// scene's "objects" (and the tables before it): the first is geometry objects.size() at the time.
//
// Internal to platform/io: the scene file reader calls it.
#pragma once

#include "io/input_file.h"
#include "io/json_reader.h"
#include "io/scene_file.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace revolve::io {

// An object table's CSV files are read a block at a time up to 64 GiB each (a million 64-point
// profiles are about 3 GB of text), unless their texts are kept (FileTexts), then whole.
inline constexpr std::uint64_t kMaxObjectTableFileBytes = std::uint64_t{1} << 36;
// At most 2^24 (16.7 million) objects a table: a million take some 20 GB built (docs/performance.md),
// so more than this is no scene a machine holds.
inline constexpr std::size_t kMaxObjectTableObjects = std::size_t{1} << 24;
// At most 2^20 points a table's profile: a batch of profiles being built stays within memory.
inline constexpr std::size_t kMaxObjectTablePoints = std::size_t{1} << 20;

// The column headers, the files' formats in one place (the bench's writer uses them too).
inline constexpr const char* kObjectTableProfilesHeader = "object,r,z";
inline constexpr const char* kObjectTableObjectsHeader = "object,spline,x,y,z,axis_x,axis_y,axis_z,degrees,scale";

// Reads the table `json` at key path `path` (CSVs relative to `directory`, their texts kept in or
// taken from `csvs` unless it is null) and appends its profiles and objects to `scene`, whose
// materials are read. Throws SceneError naming the key path, and for a bad line the file, the line
// and the rule.
void readObjectTable(const json::Reader<SceneError>& in, const json::Json& json, const std::string& path,
                     const std::string& directory, FileTexts* csvs, SceneDescription& scene);

}  // namespace revolve::io
