// What a lidar return's fields and a beam's footprint cost, measured side by side on the same
// beams (revolve-lidar-bench's third part):
//   - "rays only": the sensor's beam rays traced in packets of 8 through EmbreeScene::nearest,
//     keeping the hit's distance only: the ranges-only floor, without intensity, time, point
//     placement or the scan's bookkeeping;
//   - "scan at rest": robot::Lidar's scan (ranges, points, intensity, each beam's time);
//   - "scan moving": the sensor spinning at 10 Hz on poses 0.1 s apart, every beam traced from
//     where the moving sensor is when it fires;
//   - "subrays 4" and "subrays 16": beams of 3 mrad divergence sampled by that many sub-rays
//     (traced as packets), every return reported (returns "all", 2 a beam).
// Each configuration is timed `repeats` times, interleaved within each repeat (whole passes over
// the poses for at least 0.25 s), on all threads; medians reported, with the cost per sub-ray.
#pragma once

#include "io/poses_file.h"
#include "io/sensor_file.h"
#include "scene/embree_scene.h"

#include <nlohmann/json.hpp>

#include <vector>

namespace revolve::bench {

nlohmann::ordered_json measureReturnCosts(const scene::EmbreeScene& scene, const io::SensorDescription& sensor,
                                          const std::vector<io::RobotPose>& poses, int repeats);

}  // namespace revolve::bench
