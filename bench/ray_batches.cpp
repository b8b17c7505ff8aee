#include "ray_batches.h"

#include "embree/embree_rays.h"

#include <tbb/parallel_for.h>

#include <stdexcept>
#include <string>

namespace revolve::bench {
namespace {

constexpr std::size_t kBatchRays = 1024;           // per batch on one thread: 20 us to 10 ms of work
constexpr std::size_t kThreadedBatchRays = 16384;  // enough work to spread over the threads

}  // namespace

namespace {

template <class Packet, std::size_t kWidth>
std::shared_ptr<const std::vector<Packet>> packetsOfWidth(const std::vector<Ray>& rays) {
  if (rays.size() % kWidth != 0)
    throw std::invalid_argument("packetsOf: the ray count must be a multiple of " + std::to_string(kWidth));
  auto packets = std::make_shared<std::vector<Packet>>(rays.size() / kWidth);
  for (std::size_t p = 0; p < packets->size(); ++p) {
    Packet& packet = (*packets)[p];
    for (std::size_t i = 0; i < kWidth; ++i) {
      const Ray& ray = rays[kWidth * p + i];
      packet.ray.org_x[i] = ray.origin.x;
      packet.ray.org_y[i] = ray.origin.y;
      packet.ray.org_z[i] = ray.origin.z;
      packet.ray.dir_x[i] = ray.direction.x;
      packet.ray.dir_y[i] = ray.direction.y;
      packet.ray.dir_z[i] = ray.direction.z;
      packet.ray.tnear[i] = ray.tnear;
      packet.ray.tfar[i] = ray.tfar;
      packet.ray.time[i] = 0.0f;
      packet.ray.mask[i] = ~0u;
      packet.ray.id[i] = 0;
      packet.ray.flags[i] = 0;
      packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    }
  }
  return packets;
}

}  // namespace

std::shared_ptr<const std::vector<RTCRayHit8>> packetsOf(const std::vector<Ray>& rays) {
  return packetsOfWidth<RTCRayHit8, 8>(rays);
}

std::shared_ptr<const std::vector<RTCRayHit16>> packets16Of(const std::vector<Ray>& rays) {
  return packetsOfWidth<RTCRayHit16, 16>(rays);
}

std::function<std::size_t()> singleRayBatch(RTCScene scene, const std::vector<Ray>& rays) {
  return [scene, &rays, cursor = std::size_t{0}]() mutable {
    embree::RayQuery query;
    for (std::size_t i = 0; i < kBatchRays; ++i) {
      RTCRayHit rayHit = app::embreeRayHit(rays[cursor]);
      query.intersect(scene, rayHit);
      if (++cursor == rays.size()) cursor = 0;
    }
    return kBatchRays;
  };
}

std::function<std::size_t()> packetBatch(RTCScene scene, std::shared_ptr<const std::vector<RTCRayHit8>> packets) {
  return [scene, packets, cursor = std::size_t{0}]() mutable {
    embree::RayQuery query;
    alignas(32) const int valid[8] = {-1, -1, -1, -1, -1, -1, -1, -1};
    for (std::size_t i = 0; i < kBatchRays / 8; ++i) {
      RTCRayHit8 packet = (*packets)[cursor];
      query.intersect(valid, scene, packet);
      if (++cursor == packets->size()) cursor = 0;
    }
    return kBatchRays;
  };
}

std::function<std::size_t()> packet16Batch(RTCScene scene, std::shared_ptr<const std::vector<RTCRayHit16>> packets) {
  return [scene, packets, cursor = std::size_t{0}]() mutable {
    embree::RayQuery query;
    alignas(64) const int valid[16] = {-1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1};
    for (std::size_t i = 0; i < kBatchRays / 16; ++i) {
      alignas(64) RTCRayHit16 packet = (*packets)[cursor];
      query.intersect(valid, scene, packet);
      if (++cursor == packets->size()) cursor = 0;
    }
    return kBatchRays;
  };
}

std::function<std::size_t()> threadedBatch(RTCScene scene, const std::vector<Ray>& rays) {
  return [scene, &rays, cursor = std::size_t{0}]() mutable {
    const std::size_t start = cursor;
    tbb::parallel_for(std::size_t{0}, kThreadedBatchRays, [&](std::size_t i) {
      embree::RayQuery query;
      RTCRayHit rayHit = app::embreeRayHit(rays[(start + i) % rays.size()]);
      query.intersect(scene, rayHit);
    });
    cursor = (start + kThreadedBatchRays) % rays.size();
    return kThreadedBatchRays;
  };
}

std::function<std::size_t()> occludedBatch(RTCScene scene, const std::vector<Ray>& rays) {
  return [scene, &rays, cursor = std::size_t{0}]() mutable {
    embree::RayQuery query;
    for (std::size_t i = 0; i < kBatchRays; ++i) {
      RTCRay ray = app::embreeRayHit(rays[cursor]).ray;
      query.occluded(scene, ray);
      if (++cursor == rays.size()) cursor = 0;
    }
    return kBatchRays;
  };
}

std::function<std::size_t()> occludedPacketBatch(RTCScene scene,
                                                 std::shared_ptr<const std::vector<RTCRayHit8>> packets) {
  return [scene, packets, cursor = std::size_t{0}]() mutable {
    embree::RayQuery query;
    alignas(32) const int valid[8] = {-1, -1, -1, -1, -1, -1, -1, -1};
    for (std::size_t i = 0; i < kBatchRays / 8; ++i) {
      RTCRay8 packet = (*packets)[cursor].ray;
      query.occluded(valid, scene, packet);
      if (++cursor == packets->size()) cursor = 0;
    }
    return kBatchRays;
  };
}

}  // namespace revolve::bench
