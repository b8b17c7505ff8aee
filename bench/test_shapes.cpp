#include "test_shapes.h"

namespace revolve::bench {

// Sizes are of the order of 1; each profile starts on the axis at the bottom heading outwards
// (+r) and is listed so that revolve's normals point out of the solid.

SmoothProfile sphereShape() { return SmoothProfile("sphere", {0.0, 0.0}, 0.0).arc(0.5, 180.0); }

SmoothProfile torusShape() {
  // Minor radius 0.15 about a circle of radius 0.35; starts at the bottom of the tube.
  return SmoothProfile("torus", {0.35, 0.0}, 0.0).arc(0.15, 360.0);
}

SmoothProfile vaseShape() {
  return SmoothProfile("vase", {0.0, 0.0}, 0.0)
      .line(0.16)
      .arc(0.04, 80.0)   // the foot's rounded edge
      .arc(0.60, 30.0)   // the belly, widening then turning inwards
      .arc(0.50, -50.0)  // the concave neck
      .arc(0.10, -30.0)  // the lip flaring out
      .corner(150.0)     // a sharp rim, then the flat top
      .lineToAxis();
}

SmoothProfile gobletShape() {
  return SmoothProfile("goblet", {0.0, 0.0}, 0.0)
      .line(0.24)
      .arc(0.012, 180.0)  // the foot's rim
      .line(0.12)
      .arc(0.08, -90.0)  // foot rising into the stem
      .line(0.14)
      .arc(0.03, -60.0)  // the knob
      .arc(0.03, 120.0)
      .arc(0.03, -60.0)
      .line(0.10)
      .arc(0.06, -75.0)   // the bowl's base
      .arc(0.28, 80.0)    // the bowl's side, closing in slightly at the rim
      .arc(0.006, 180.0)  // the thin rounded rim
      .arc(0.268, -80.0)  // the inside of the bowl, back down
      .arc(0.05, -15.0)
      .lineToAxis();
}

SmoothProfile bottleShape() {
  return SmoothProfile("bottle", {0.0, 0.0}, 0.0)
      .line(0.16)
      .arc(0.04, 90.0)  // the base's fillet
      .line(0.50)       // the body
      .arc(0.12, 60.0)  // the shoulder
      .line(0.08)
      .arc(0.05, -60.0)  // into the neck
      .line(0.20)
      .arc(0.012, -90.0)  // the lip: a rounded ring
      .line(0.012)
      .arc(0.012, 180.0)
      .lineToAxis();
}

std::vector<SmoothProfile> testShapes() {
  return {sphereShape(), torusShape(), vaseShape(), gobletShape(), bottleShape()};
}

}  // namespace revolve::bench
