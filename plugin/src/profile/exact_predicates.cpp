// Exact orientation predicate.
//
// orient2d decides the sign of D = (b - a) x (c - a) in three stages, cheapest first:
//   1. sign shortcut: D = L - R with L = (a.r - c.r)(b.z - c.z) and R = (a.z - c.z)(b.r - c.r); the
//      signs of L and R follow exactly from coordinate comparisons, which settles every case where
//      they differ or vanish (e.g. axis-aligned configurations);
//   2. floating-point filter: the naive determinant, trusted when it exceeds a derived error bound;
//   3. exact evaluation: D expanded into six monomials x * y of input coordinates, each split
//      exactly into mantissa product and power of two, and summed with floating-point expansion
//      arithmetic (TwoSum, TwoProduct through std::fma, Grow-Expansion). Separating the exponents
//      keeps every step exact for all finite doubles: no product overflows or underflows, however
//      far apart the magnitudes of the coordinates are (1e300 next to denormals).
// Requires IEEE-754 binary64 with round-to-nearest; must not be compiled with -ffast-math.
#include "exact_predicates.h"

#include "util/rounding.h"

#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <utility>

namespace revolve::detail {
namespace {

// Unit roundoff of binary64: |fl(x op y) - x op y| <= kUnitRoundoff * |x op y| without underflow.

// Sign of x - y from a comparison, so it is exact even where the difference would overflow.
int signOfDifference(double x, double y) { return (x > y) - (x < y); }

// ---------------------------------------------------------------------------------------------
// Stage 2: floating-point filter.

// Error bound of the filter, relative to S = |L~| + |R~| (L~, R~ the computed L and R).
// Derivation: L~ and R~ each carry 3 roundings (two differences, one product), so |L~ - L| <=
// ((1 + u)^3 - 1) / (1 - u)^3 |L~| <= (3u + 13u^2)|L~| (u = unit roundoff), likewise R; the final
// subtraction adds u * S; 4u + 13u^2 plus the rounding of the bound's own product stays below 5u.
// (A compiler contracting a product and the subtraction into an fma only removes roundings.)
constexpr double kFilterBoundFactor = 5.0 * kUnitRoundoff;
// Below this S an underflowing product (absolute error up to 2^-1075) could exceed the slack of
// about u * S between 5u and 4u + 13u^2 in the bound; 2^-960 leaves a margin of 2^60.
constexpr double kFilterMinimumScale = 0x1p-960;

// Sign of D when the rounded determinant is certain; nothing when it is not (including when an
// intermediate overflowed, which turns S into inf or NaN).
std::optional<int> filteredSign(Point2 a, Point2 b, Point2 c) {
  const double left = (a.r - c.r) * (b.z - c.z);
  const double right = (a.z - c.z) * (b.r - c.r);
  const double determinant = left - right;
  const double scale = std::abs(left) + std::abs(right);
  if (!(scale <= std::numeric_limits<double>::max()) || scale < kFilterMinimumScale) {
    return std::nullopt;
  }
  const double errorBound = kFilterBoundFactor * scale;
  if (determinant > errorBound) return 1;
  if (determinant < -errorBound) return -1;
  return std::nullopt;
}

// ---------------------------------------------------------------------------------------------
// Stage 3: exact evaluation.

// a + b == sum + error exactly (Knuth's TwoSum: no ordering precondition on |a|, |b|; exact in
// binary floating point whenever nothing overflows, gradual underflow included).
void twoSum(double a, double b, double& sum, double& error) {
  sum = a + b;
  const double bPart = sum - a;
  const double aPart = sum - bPart;
  error = (a - aPart) + (b - bPart);
}

// An exact sum of doubles, kept as a non-overlapping expansion: components in increasing order of
// magnitude with zeros dropped, so the largest component outweighs all others together and alone
// gives the sign.
class Expansion {
 public:
  // Grow-Expansion: ripples `value` up through the components; each TwoSum keeps its rounding error
  // as a new, smaller component.
  void add(double value) {
    assert(count_ < kCapacity);
    std::size_t kept = 0;
    double carry = value;
    for (std::size_t i = 0; i < count_; ++i) {
      double error = 0.0;
      twoSum(carry, components_[i], carry, error);
      if (error != 0.0) components_[kept++] = error;
    }
    if (carry != 0.0) components_[kept++] = carry;
    count_ = kept;
  }

  int sign() const { return count_ == 0 ? 0 : signOf(components_[count_ - 1]); }

 private:
  static constexpr std::size_t kCapacity = 12;  // 6 monomials x (high, low); one more each add
  std::array<double, kCapacity> components_{};
  std::size_t count_ = 0;
};

// A monomial +-x*y of the determinant, exactly (high + low) * 2^exponent with |high + low| < 1.
struct Monomial {
  double high;
  double low;
  int exponent;
};

// Up to six nonzero monomials.
class MonomialList {
 public:
  // Appends sign * x * y unless it is zero. frexp's mantissas lie in [0.5, 1) and are multiples of
  // 2^-53, so their product and its fma remainder never overflow or underflow.
  void addProduct(double x, double y, int sign) {
    if (x == 0.0 || y == 0.0) return;
    int xExponent = 0;
    int yExponent = 0;
    const double xMantissa = std::frexp(x, &xExponent);
    const double yMantissa = std::frexp(y, &yExponent);
    const double high = xMantissa * yMantissa;
    const double low = std::fma(xMantissa, yMantissa, -high);  // TwoProduct
    assert(count_ < terms_.size());
    terms_[count_++] = Monomial{sign * high, sign * low, xExponent + yExponent};
  }

  std::span<Monomial> terms() { return {terms_.data(), count_}; }

 private:
  std::array<Monomial, 6> terms_{};
  std::size_t count_ = 0;
};

// Exponent gap that separates clusters of monomials. A cluster's sum is a multiple of
// 2^(k - 106), k its lowest exponent (each monomial is a multiple of 2^(exponent - 106)); the at
// most 5 monomials below a gap of 128 add up to less than 5 * 2^(k - 128) < 2^(k - 106), so they
// cannot change the sign of a nonzero cluster sum.
constexpr int kClusterGap = 128;

// Exact sign of the sum of one cluster. Exponents in a cluster span at most 5 * 127 bits, so
// rescaling by 2^-(top exponent) keeps every component a multiple of 2^(-635 - 106), far above
// the smallest denormal, and below 6 in magnitude: ldexp and the expansion stay exact.
int signOfCluster(std::span<const Monomial> cluster) {
  const int topExponent = cluster.front().exponent;
  Expansion sum;
  for (const Monomial& term : cluster) {
    sum.add(std::ldexp(term.high, term.exponent - topExponent));
    sum.add(std::ldexp(term.low, term.exponent - topExponent));
  }
  return sum.sign();
}

// Exact sign of a sum of monomials with arbitrary exponents: the highest cluster decides unless it
// cancels to exactly zero, then the next one, and so on.
int signOfMonomialSum(std::span<Monomial> terms) {
  // Insertion sort by decreasing exponent: at most six terms.
  for (std::size_t i = 1; i < terms.size(); ++i) {
    for (std::size_t j = i; j > 0 && terms[j - 1].exponent < terms[j].exponent; --j) {
      std::swap(terms[j - 1], terms[j]);
    }
  }
  std::size_t begin = 0;
  while (begin < terms.size()) {
    std::size_t end = begin + 1;
    while (end < terms.size() && terms[end - 1].exponent - terms[end].exponent < kClusterGap) {
      ++end;
    }
    if (const int sign = signOfCluster(terms.subspan(begin, end - begin)); sign != 0) return sign;
    begin = end;
  }
  return 0;
}

// D = a.r*b.z - a.r*c.z + b.r*c.z - b.r*a.z + c.r*a.z - c.r*b.z, evaluated exactly. Expanding the
// differences avoids their rounding and overflow; the a.r*a.z-type terms cancel symbolically.
int exactSign(Point2 a, Point2 b, Point2 c) {
  MonomialList monomials;
  monomials.addProduct(a.r, b.z, +1);
  monomials.addProduct(a.r, c.z, -1);
  monomials.addProduct(b.r, c.z, +1);
  monomials.addProduct(b.r, a.z, -1);
  monomials.addProduct(c.r, a.z, +1);
  monomials.addProduct(c.r, b.z, -1);
  return signOfMonomialSum(monomials.terms());
}

}  // namespace

int orient2d(Point2 a, Point2 b, Point2 c) {
  const int signLeft = signOfDifference(a.r, c.r) * signOfDifference(b.z, c.z);
  const int signRight = signOfDifference(a.z, c.z) * signOfDifference(b.r, c.r);
  if (signLeft != signRight || signLeft == 0) {
    return (signLeft > signRight) - (signLeft < signRight);
  }
  if (const std::optional<int> sign = filteredSign(a, b, c)) return *sign;
  return exactSign(a, b, c);
}

}  // namespace revolve::detail
