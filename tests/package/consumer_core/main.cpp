// revolve's core without Embree: a capped cylinder (radius 1, height 2) asked for a ray's hit, a
// point's distance and a robot's clearance, all closed forms.
#include <revolve/core.h>

#if defined(RTC_VERSION_MAJOR)
#error "revolve/core.h must not include Embree's header"
#endif

#include <cmath>
#include <cstdio>
#include <vector>

int main() {
  const std::vector<revolve::Point2> points{{0, 0}, {1, 0}, {1, 2}, {0, 2}};
  const revolve::Shape shape{revolve::Profile(points)};
  int failures = 0;

  // Along -x at height 1 from x = 5: the side at x = 1, t = 4, segment 1, outward normal +x.
  const std::optional<revolve::Hit> hit = revolve::intersect(shape, {{5, 0, 1}, {-1, 0, 0}});
  const bool hitOk = hit && hit->t == 4.0f && hit->segment == 1 && hit->normal.x == 1.0f;
  std::printf("%s: intersect gives t = 4 on the side\n", hitOk ? "ok  " : "FAIL");
  failures += !hitOk;

  // (3, 0, 1) lies 2 from the side; (0, 0, 3) lies 1 above the top.
  const float side = revolve::closestPoint(shape, {3, 0, 1}).distance;
  const float top = revolve::closestPoint(shape, {0, 0, 3}).distance;
  const bool distanceOk = std::abs(side - 2.0f) < 1e-6f && std::abs(top - 1.0f) < 1e-6f;
  std::printf("%s: closestPoint gives 2 beside and 1 above\n", distanceOk ? "ok  " : "FAIL");
  failures += !distanceOk;

  // A robot of radius 0.5 whose axis stands 3 from the cylinder's: 3 - 0.5 - 1 = 1.5 apart.
  const revolve::CylinderClearance clearance = revolve::cylinderClearance(shape, {3.0, 0.5, 0.0, 1.8});
  const bool clearanceOk = std::abs(clearance.clearance - 1.5) < 1e-12;
  std::printf("%s: cylinderClearance gives 1.5\n", clearanceOk ? "ok  " : "FAIL");
  failures += !clearanceOk;

  std::printf("consumer_core: %d failure(s)\n", failures);
  return failures == 0 ? 0 : 1;
}
