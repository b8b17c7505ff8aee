// The MIBIT paper's comparisons (Baciu, Jia & Lam 2001): the searches it measures MIBIT against
// (Wang's intersection with every segment in turn, Kajiya's strip tree), its bounding-shell kinds,
// and the switches of its table (MR subdivisions, no monotone split, no range search, the binary
// tree instead of the wide one). An application needs none of these: a Shape built without them
// uses the fastest search measured here. revolve-bench, the paper's table and the tests use them.
// No Embree needed; Embree's own primitives for comparison are in revolve/embree_baselines.h.
#pragma once

#include <revolve/core.h>

#include <cstdint>
#include <optional>
#include <string_view>

namespace revolve {

enum class Method {
  mibit,   // the MIBIT tree: monotone intervals, uniform refinement, bounding shells, range search
  linear,  // Wang's intersection with every segment in turn (the paper's linear baseline)
  kajiya,  // Kajiya's strip tree (Ballard strips, conic-vs-strip tests)
};

enum class ShellKind {
  cylinder,  // CY: annular cylinder shells r in [rmin, rmax], z in [zmin, zmax]
  cone,      // TC: truncated-cone shells, a band parallel to the node's chord
  hybrid,    // HY: per node the cheaper-to-test fit, by the paper's area / interval / factor-4 rule
};

// "mibit", "linear", "kajiya" and "cylinder", "cone", "hybrid" (the names the tools' --method,
// --geometry and --shell take), and back; nothing for an unknown name.
[[nodiscard]] const char* methodName(Method method) noexcept;
[[nodiscard]] std::optional<Method> methodNamed(std::string_view name) noexcept;
[[nodiscard]] const char* shellKindName(ShellKind shell) noexcept;
[[nodiscard]] std::optional<ShellKind> shellKindNamed(std::string_view name) noexcept;

struct BuildOptions {
  Method method = Method::mibit;
  // Cylinders by default: measured fastest here (README, Performance), their test needs no square
  // root; the paper's hybrid and cone shells remain for its comparisons.
  ShellKind shell = ShellKind::cylinder;
  // MR refinement: leaves per monotone interval, each an equal share of its segments, searched by
  // Wang's intersection in turn. 0 refines down to one segment a leaf.
  std::uint32_t subdivisions = 0;
  bool monotoneSplit = true;  // false: refine the whole profile as one interval (paper's "no split")
  bool rangeSearch = true;    // false: intersect every node's shell (paper's "no range search")
  // Lay the tree out for SIMD: leaves of up to 32 segments of a monotone interval whose segment
  // shells are tested several at once, under nodes of up to 64 children (docs/design.md). Used
  // with the defaults above (cylinder shells, monotone split, range search, subdivisions 0); false,
  // or any other option, keeps the paper's binary tree. Both give the same hits bit for bit.
  bool wideNodes = true;
};

}  // namespace revolve
