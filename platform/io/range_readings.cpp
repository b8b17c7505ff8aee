#include "io/range_readings.h"

#include <cinttypes>
#include <cmath>

namespace revolve::io {

RangeTableWriter::RangeTableWriter(OutputStream& out) : out_(out) { out_.print("%s\n", kRangeTableHeader); }

void RangeTableWriter::write(std::uint64_t firstPose, std::size_t sensors, std::span<const RangeReading> rows) {
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const RangeReading& row = rows[i];
    const std::uint64_t pose = firstPose + i / sensors;
    const std::size_t sensor = i % sensors;
    if (std::isinf(row.range)) {
      out_.print("%" PRIu64 ",%zu,inf,,,,\n", pose, sensor);
    } else {
      out_.print("%" PRIu64 ",%zu,%.17g,%.17g,%.17g,%.17g,%" PRId64 "\n", pose, sensor, row.range, row.point[0],
                 row.point[1], row.point[2], row.object);
    }
  }
}

}  // namespace revolve::io
