// Sizes checked before allocating: a job whose memory grows with an input's numbers (an image's
// pixels, a mesh's triangles, a benchmark's rays) is refused in one line naming what was too
// large, instead of failing in the middle with std::bad_alloc or being killed by the kernel.
#pragma once

#include <cstdio>
#include <stdexcept>
#include <string>

#include <unistd.h>

namespace revolve::app {

// A tessellated mesh in Embree: its vertex and index buffers (about 18 bytes a triangle) and the
// BVH Embree builds over it (about 100 more at its peak, measured with its memory monitor),
// rounded up.
inline constexpr double kMeshBytesPerTriangle = 128;

// The machine's physical memory in bytes (0 when the system does not say).
inline double physicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? double(pages) * double(pageSize) : 0.0;
}

// Throws std::runtime_error "`what` needs about N GB, more than this machine's M GB of memory"
// when `bytes` exceed the physical memory.
inline void requireMemory(double bytes, const std::string& what) {
  const double available = physicalMemoryBytes();
  if (available > 0 && bytes > available) {
    char text[96];
    std::snprintf(text, sizeof text, " needs about %.3g GB, more than this machine's %.3g GB of memory", bytes * 1e-9,
                  available * 1e-9);
    throw std::runtime_error(what + text);
  }
}

}  // namespace revolve::app
