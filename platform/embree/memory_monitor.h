// Embree's own allocations on a device, as its memory monitor reports them: now and at the peak.
#pragma once

#include <revolve/embree_api.h>

#include <sys/types.h>

#include <atomic>
#include <cstdint>

namespace revolve::app {

struct EmbreeMemory {
  std::atomic<std::int64_t> current{0}, peak{0};
};

// Has `device` report every allocation and release to `memory` (which must outlive the device),
// from any of its threads; nothing is refused.
inline void monitorMemory(RTCDevice device, EmbreeMemory* memory) {
  rtcSetDeviceMemoryMonitorFunction(
      device,
      [](void* user, ssize_t bytes, bool) {
        auto* counter = static_cast<EmbreeMemory*>(user);
        const std::int64_t now = counter->current.fetch_add(bytes) + bytes;
        std::int64_t peak = counter->peak.load();
        while (now > peak && !counter->peak.compare_exchange_weak(peak, now)) {}
        return true;
      },
      memory);
}

}  // namespace revolve::app
