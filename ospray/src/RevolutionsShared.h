// The part of a "revolution" geometry OSPRay's ISPC code reads: OSPRay's Geometry first (its
// postIntersect and intersect pointers), then the host object the per-lane C++ helpers need.
#pragma once

#ifdef __cplusplus
#include "common/StructShared.h"  // ispc::int32 and the other names GeometryShared.h uses in C++
#endif
#include "geometry/GeometryShared.h"

#ifdef __cplusplus
namespace ispc {
#endif  // __cplusplus

struct Revolutions {
  Geometry super;
  // The C++ RevolutionSet (revolution_set.h): opaque here, passed back to the extern "C" helpers.
  void* host;

#ifdef __cplusplus
  Revolutions() : host(nullptr) {}
};
}  // namespace ispc
#else
};
#endif  // __cplusplus
