// The benchmark's test shapes: smooth profiles with known geometry, from the simplest surface of
// revolution to the awkward ones (non-monotone, thin walls, a loop off the axis).
#pragma once

#include "smooth_profile.h"

#include <vector>

namespace revolve::bench {

SmoothProfile sphereShape();  // one arc, both ends on the axis
SmoothProfile torusShape();   // a full circle off the axis: a closed loop
SmoothProfile vaseShape();    // foot, a bulging belly, a concave neck and a flared lip
SmoothProfile gobletShape();  // foot, knobbed stem, bowl with a thin rounded rim: not monotone in z
SmoothProfile bottleShape();  // base fillet, straight body, shoulder, neck and lip

std::vector<SmoothProfile> testShapes();

}  // namespace revolve::bench
