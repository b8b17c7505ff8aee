#include "robot/robot_argument.h"

#include "io/csv_fields.h"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace revolve::robot {

RobotDimensions parseRobotArgument(std::string_view text) {
  const std::vector<std::string_view> fields = io::csv::splitFields(text);
  if (fields.size() != 3) {
    throw std::runtime_error("--robot " + io::csv::quote(text) +
                             ": expected RADIUS,ZMIN,ZMAX (3 comma-separated numbers), found " +
                             std::to_string(fields.size()));
  }
  const char* names[3] = {"RADIUS", "ZMIN", "ZMAX"};
  double values[3];
  for (int i = 0; i < 3; ++i) {
    const std::optional<double> value = io::csv::parseNumber<double>(fields[i]);
    if (!value || !std::isfinite(*value)) {
      throw std::runtime_error("--robot: " + std::string(names[i]) + " = " + io::csv::quote(fields[i]) +
                               " is not a finite number");
    }
    values[i] = *value;
  }
  if (!(values[0] > 0)) throw std::runtime_error("--robot: RADIUS = " + io::csv::quote(fields[0]) + " is not positive");
  if (!(values[1] < values[2])) {
    throw std::runtime_error("--robot: ZMAX = " + io::csv::quote(fields[2]) +
                             " is not above ZMIN = " + io::csv::quote(fields[1]));
  }
  return {values[0], values[1], values[2]};
}

}  // namespace revolve::robot
