// The ways a benchmark traces rays through Embree, each as a batch function for the timer: one ray
// at a time (rtcIntersect1), packets of eight or sixteen (rtcIntersect8, rtcIntersect16), rtcIntersect1 on all threads,
// and shadow rays (rtcOccluded1, rtcOccluded8). Every batch walks its ray set cyclically from where the previous batch
// stopped.
#pragma once

#include <revolve/embree_api.h>
#include <revolve/revolve.h>

#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace revolve::bench {

// Rays 8i .. 8i + 7 of `rays` as packet i (rays.size() must be a multiple of 8).
std::shared_ptr<const std::vector<RTCRayHit8>> packetsOf(const std::vector<Ray>& rays);

// Rays 16i .. 16i + 15 of `rays` as packet i (rays.size() must be a multiple of 16).
std::shared_ptr<const std::vector<RTCRayHit16>> packets16Of(const std::vector<Ray>& rays);

std::function<std::size_t()> singleRayBatch(RTCScene scene, const std::vector<Ray>& rays);
std::function<std::size_t()> packetBatch(RTCScene scene, std::shared_ptr<const std::vector<RTCRayHit8>> packets);
std::function<std::size_t()> packet16Batch(RTCScene scene, std::shared_ptr<const std::vector<RTCRayHit16>> packets);
std::function<std::size_t()> threadedBatch(RTCScene scene, const std::vector<Ray>& rays);
std::function<std::size_t()> occludedBatch(RTCScene scene, const std::vector<Ray>& rays);
std::function<std::size_t()> occludedPacketBatch(RTCScene scene,
                                                 std::shared_ptr<const std::vector<RTCRayHit8>> packets);

}  // namespace revolve::bench
