// Enclosures of a skeleton's blend tree over a box and the box
// classification (skelconv/interval/enclosure.hpp). -frounding-math TU.
#include <algorithm>
#include <limits>
#include <vector>

#include "skelconv/interval/enclosure.hpp"
#include "../detail/infinity.hpp"

namespace skelconv::interval {
namespace {

/// [x]₊^t over x, t > 0 (increasing in x): exp(t log x) outward-rounded.
Interval positive_power(const Interval& x, double t) {
  const auto power = [t](double v) { return boost::numeric::exp(Interval(t) * boost::numeric::log(Interval(v))); };
  const double low = x.lower() > 0.0 ? (x.lower() == infinity ? infinity : power(x.lower()).lower()) : 0.0;
  const double high = x.upper() > 0.0 ? (x.upper() == infinity ? infinity : power(x.upper()).upper()) : 0.0;
  return Interval(low, high);
}

struct Walker {
  const Skeleton& skeleton;
  const Box& box;
  const EnclosureOptions& options;

  Interval child(Skeleton::NodeId id, std::size_t k) const {
    const auto [is_blend, index] = skeleton.child(id, k);
    return is_blend ? node(index) : enclose(skeleton.primitives()[index], box, options);
  }

  Interval node(Skeleton::NodeId id) const {
    const Blend& blend = skeleton.blend(id);
    std::vector<Interval> children;
    for (std::size_t k = 0; k < skeleton.child_count(id); ++k) children.push_back(child(id, k));
    // A child certainly +inf (the box is a point on an inverse skeleton)
    // makes every blend +inf (skeleton/blend.hpp's marker).
    for (const Interval& c : children)
      if (c.lower() == infinity) return Interval(infinity);
    switch (blend.kind) {
      case BlendKind::sum: return sum(blend, children);
      case BlendKind::union_max: return union_max(children);
      case BlendKind::super_elliptic: return super_elliptic(blend, children);
    }
    return Interval(-infinity, infinity);  // unreachable
  }

  static Interval sum(const Blend& blend, const std::vector<Interval>& children) {
    Interval total(0.0);
    for (std::size_t k = 0; k < children.size(); ++k) {
      // A child that may be +inf may make the sum the +inf marker.
      if (children[k].upper() == infinity) total = Interval(total.lower(), infinity);
      // A plain product, not safe_product: a child may be negative (a
      // negative weight below it), which safe_product's k ⊂ [0, +inf] does
      // not allow, and the weight is finite and non-zero, so no 0 · inf.
      total += Interval(blend.weight_of(k)) *
               Interval(children[k].lower(), std::min(children[k].upper(), std::numeric_limits<double>::max()));
    }
    return total;
  }

  static Interval union_max(const std::vector<Interval>& children) {
    double low = -infinity, high = -infinity;
    for (const Interval& c : children) {
      low = std::max(low, c.lower());
      high = std::max(high, c.upper());
    }
    return Interval(low, high);
  }

  /// c Σ [x_k]₊^t, x_k = 1 − V_k/(r_k a), V_k = c − f_k; a = 1 without the
  /// angle, a ∈ [min_angle_factor, 2] (cos θ ∈ [−1, 1]) with it.
  static Interval super_elliptic(const Blend& blend, const std::vector<Interval>& children) {
    const Interval a = blend.angle_weighted ? Interval(Blend::min_angle_factor, 2.0) : Interval(1.0);
    Interval total(0.0);
    bool may_be_infinite = false;
    for (std::size_t k = 0; k < children.size(); ++k) {
      may_be_infinite = may_be_infinite || children[k].upper() == infinity;
      const Interval f(children[k].lower(), std::min(children[k].upper(), std::numeric_limits<double>::max()));
      const Interval x = 1.0 - (blend.iso - f) / (blend.r_of(k) * a);
      total += blend.iso * positive_power(x, blend.t);
    }
    return may_be_infinite ? Interval(total.lower(), infinity) : total;
  }
};

}  // namespace

Interval enclose(const Skeleton& skeleton, const Box& box, const EnclosureOptions& options) {
  skeleton.validate();
  return Walker{skeleton, box, options}.node(Skeleton::root);
}

Classification classify(const Interval& enclosure, double iso) {
  if (enclosure.lower() > iso) return Classification::inside;
  if (enclosure.upper() < iso) return Classification::outside;
  return Classification::undetermined;
}

const char* classification_name(Classification classification) {
  switch (classification) {
    case Classification::inside: return "inside";
    case Classification::outside: return "outside";
    case Classification::undetermined: return "undetermined";
  }
  return "?";
}

}  // namespace skelconv::interval
