// Implementation of skelconv/skeleton/skeleton.hpp.
#include "skelconv/skeleton/skeleton.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>

#include <boost/container/small_vector.hpp>
#include <fmt/format.h>

#include "skeleton_index.hpp"
#include "../detail/input_checks.hpp"
#include "skelconv/field/support_box.hpp"
#include "../detail/infinity.hpp"

namespace skelconv {
namespace {

ScalarSample<double> to_scalar(const FieldSample& s) { return {s.value, to_array(s.gradient)}; }
FieldSample from_scalar(const ScalarSample<double>& s) { return {s.value, to_vec3(s.gradient)}; }

/// Children of a union or super-elliptic node held on the stack during an
/// evaluation (more are allocated): no allocation per point for the blends
/// a file usually has.
constexpr std::size_t small_blend_children = 16;

/// What an evaluation of `primitive` at P produces: f (∇f = 0 in the
/// sample), ∇f (f = 0) or both, as `need` (a Skeleton::Need) asks. Always
/// inlined: it is the whole of a leaf's dispatch, once per primitive and point.
template <class P, class Need>
[[gnu::always_inline]] inline FieldSample sample_of(const P& primitive, const Vec3& p, Need need) {
  switch (need) {
    case Need::value: return {primitive.value(p), Vec3::Zero()};
    case Need::gradient: return {0.0, primitive.gradient(p)};
    case Need::both: break;
  }
  return primitive.value_and_gradient(p);
}

/// +inf with gradient (+inf, +inf, +inf): an inverse primitive on its own
/// skeleton somewhere below (blend.hpp, "Markers").
bool is_marker(const FieldSample& s) { return s.value == infinity || s.gradient.x() == infinity; }

/// Adds the samples of the primitives primitives[index_of(0)], …,
/// primitives[index_of(count − 1)], all of type P, to `total`, left to right,
/// and notes a marker among them: one loop with P's own evaluation, no
/// choice between blend node and primitive or between types per primitive.
/// A primitive's error is rethrown at its location, as evaluate_leaf does.
template <class P, class Need, class IndexOf>
void add_primitives_of_one_type(const std::vector<Primitive>& primitives, const std::vector<std::string>& locations,
                                std::size_t count, IndexOf index_of, const Vec3& p, Need need, FieldSample& total,
                                bool& marker) {
  std::size_t k = 0;  // the primitive being evaluated
  try {
    for (std::size_t position = 0; position < count; ++position) {
      k = index_of(position);
      const FieldSample term = sample_of(*std::get_if<P>(&primitives[k]), p, need);
      marker = marker || is_marker(term);
      total.value += term.value;
      if (need != Need::value) total.gradient += term.gradient;  // else every term's gradient is 0
    }
  } catch (const InputError& error) {
    throw error.inside(locations[k]);
  } catch (const EvaluationError& error) {
    throw error.inside(locations[k]);
  }
}

/// Segments whose rules are chosen before any is evaluated (a chunk on the
/// stack): evaluated grouped by node count, each group's loops and calls
/// alike from one segment to the next, which the processor predicts.
constexpr std::size_t far_rule_chunk = 64;

/// Whether a primitive's field is never negative: a SCALIS segment or
/// triangle (a kernel ≥ 0 integrated with positive radii), a point of
/// positive weight. The others may carry a negative weight coefficient.
bool never_negative(const Primitive& primitive) {
  if (std::holds_alternative<ScalisSegment>(primitive) || std::holds_alternative<ScalisTriangle>(primitive)) return true;
  if (const PointPrimitive* point = std::get_if<PointPrimitive>(&primitive)) return point->weight() > 0.0;
  return false;
}

/// The far rule of a classical or SCALIS segment that has one, else nullptr.
const FarSegmentRule* far_rule_of(const Primitive& primitive) {
  if (const Segment* segment = std::get_if<Segment>(&primitive)) return segment->far_rule();
  if (const ScalisSegment* segment = std::get_if<ScalisSegment>(&primitive)) return segment->far_rule();
  return nullptr;
}

/// The exact sample of a primitive that has a far rule (far_rule_of).
template <class Need>
FieldSample exact_sample_of_ruled(const Primitive& primitive, const Vec3& p, Need need) {
  if (const Segment* segment = std::get_if<Segment>(&primitive)) return sample_of(*segment, p, need);
  return sample_of(*std::get_if<ScalisSegment>(&primitive), p, need);
}

/// The sum of a list of segments that all have a far rule (far_rule_of:
/// classical and SCALIS Cauchy, mixed or not), in the tolerance mode
/// (docs/field.md, "Tolerance"): f̲, the sum of the segments' lower bounds,
/// is at most f, so granting each of the `count` segments an error of
/// `tolerance` f̲ / count keeps the whole sum within `tolerance` f (and each
/// component of ∇f within `tolerance` f times the mean over the segments of
/// their bound m g of |∇f|/f, far_segment_rule.hpp). A segment whose rule
/// would need more nodes than the longest takes the exact path. Within a
/// chunk the terms are added by node count (the exact ones first), then
/// in order: the same additions on every machine. `Degree` and `Scalis`:
/// those of every rule when the list is of one kind and degree (the
/// rules' loops then unrolled, and each n-node sum looked up once per
/// group), else 0 and −1 (read per rule); the same operations either way.
template <int Degree, int Scalis, class Need>
void add_segments_within(const std::vector<Primitive>& primitives, const std::vector<std::string>& locations,
                         const std::vector<FarSegmentRule>& rules, const Vec3& p, Need need, double tolerance,
                         const std::uint8_t* chosen, FieldSample& total) {
  constexpr bool uniform = Degree > 0 && Scalis >= 0;
  const std::size_t count = rules.size();
  const bool gradient = need != Need::value;
  // Q at the ends of every segment, read by the choice of rules, and the
  // lower bound (none where the rules are `chosen` already).
  boost::container::small_vector<FarSegmentRule::EndSquares, far_rule_chunk> ends(chosen ? 0 : count);
  double lower = 0;
  for (std::size_t k = 0; k < ends.size(); ++k) {
    ends[k] = rules[k].end_squares(p);
    lower += rules[k].template lower_bound<Degree>(rules[k].mean_square(p));
  }
  const double budget = tolerance * lower / double(count);
  constexpr std::size_t groups = FarSegmentRule::max_nodes / 2 + 1;  // 0 (exact), 2, 4, …, max_nodes nodes
  std::size_t position = 0;  // the segment being evaluated
  const auto add = [&](const FieldSample& term) {
    if (need != Need::gradient) total.value += term.value;  // else the value is not asked for
    if (gradient) total.gradient += term.gradient;
  };
  try {
    for (std::size_t first = 0; first < count; first += far_rule_chunk) {
      const std::size_t size = std::min(far_rule_chunk, count - first);
      std::array<std::uint8_t, far_rule_chunk> nodes;
      std::array<std::uint8_t, far_rule_chunk> order;  // positions − first, grouped by node count
      std::array<std::size_t, groups + 1> start{};
      for (std::size_t k = 0; k < size; ++k) {
        if (chosen) {
          nodes[k] = chosen[first + k];
        } else {
          nodes[k] = std::uint8_t(
              budget > 0.0 ? rules[first + k].template nodes<Degree, Scalis>(ends[first + k], budget) : 0);
        }
        ++start[nodes[k] / 2 + 1];
      }
      for (std::size_t g = 1; g <= groups; ++g) start[g] += start[g - 1];
      for (std::size_t k = 0; k < size; ++k) order[start[nodes[k] / 2]++] = std::uint8_t(k);
      FarSegmentRule::NodeRule rule;  // of its n nodes (lists of one kind and degree: looked up once)
      static const std::array<std::array<FarSegmentRule::NodeRule, groups>, 2> uniform_rules = [] {
        std::array<std::array<FarSegmentRule::NodeRule, groups>, 2> made{};
        if constexpr (uniform) {
          const int longest = Scalis == 1 ? FarSegmentRule::max_scalis_nodes : FarSegmentRule::max_classical_nodes;
          for (int n = 2; n <= longest; n += 2) {
            for (int gradient : {0, 1}) {
              made[std::size_t(gradient)][std::size_t(n / 2)] = FarSegmentRule::node_rule(Scalis == 1, Degree, n, gradient);
            }
          }
        }
        return made;
      }();
      for (std::size_t j = 0; j < size; ++j) {
        position = first + order[j];
        FieldSample term;
        const int n = nodes[order[j]];
        bool done = false;
        if (n != 0) {
          if constexpr (uniform) {
            rule = uniform_rules[gradient][std::size_t(n / 2)];
          } else {
            rule = rules[position].node_rule(n, gradient);
          }
          done = rules[position].evaluate_with(rule, p, gradient, term);
        }
        if (!done) term = exact_sample_of_ruled(primitives[position], p, need);
        add(term);
      }
    }
  } catch (const InputError& error) {
    throw error.inside(locations[position]);
  } catch (const EvaluationError& error) {
    throw error.inside(locations[position]);
  }
}

/// add_segments_within by the batch of the same rules (FarRuleBatch: their
/// constants side by side, two segments at a time): the same rules, terms
/// and additions, hence the same sum, bit for bit.
template <class Need>
void add_segments_batched(const std::vector<Primitive>& primitives, const std::vector<std::string>& locations,
                          const detail::FarRuleBatch& batch, const Vec3& p, Need need, double tolerance,
                          const std::uint8_t* chosen, FieldSample& total) {
  const std::size_t count = batch.size();
  const bool gradient = need != Need::value;
  boost::container::small_vector<std::uint8_t, 1024> own(chosen ? 0 : count);
  if (!chosen) {
    batch.choose(p, tolerance, own.data());
    chosen = own.data();
  }
  static_assert(detail::FarRuleBatch::chunk == far_rule_chunk, "the terms are added in add_segments_within's order");
  detail::FarRuleBatch::Terms terms;
  std::size_t position = 0;  // the segment being evaluated
  // The sums in locals, not through `total`, which the loop would
  // otherwise load and store at every term; the same additions.
  double value = total.value, x = total.gradient.x(), y = total.gradient.y(), z = total.gradient.z();
  try {
    for (std::size_t first = 0; first < count; first += detail::FarRuleBatch::chunk) {
      batch.terms(p, first, chosen, gradient, terms);
      for (std::size_t j = 0; j < terms.size; ++j) {
        if (!terms.exact[j]) continue;
        position = first + terms.order[j];
        const FieldSample term = exact_sample_of_ruled(primitives[position], p, need);
        terms.value[j] = term.value;
        terms.gradient_x[j] = term.gradient.x();
        terms.gradient_y[j] = term.gradient.y();
        terms.gradient_z[j] = term.gradient.z();
      }
      // No call in this loop: the sums stay in registers (the ABI keeps no
      // floating-point register across a call).
      for (std::size_t j = 0; j < terms.size; ++j) {
        if (need != Need::gradient) value += terms.value[j];  // else the value is not asked for
        if (gradient) {
          x += terms.gradient_x[j];
          y += terms.gradient_y[j];
          z += terms.gradient_z[j];
        }
      }
    }
    total.value = value;
    total.gradient = Vec3(x, y, z);
  } catch (const InputError& error) {
    throw error.inside(locations[position]);
  } catch (const EvaluationError& error) {
    throw error.inside(locations[position]);
  }
}

/// add_segments_within for rules of one kind and degree: at [Degree] of the
/// classical or the SCALIS table (FarSegmentRule's degrees: classical 1–16,
/// SCALIS 1–10), [0] for a list of mixed kinds or degrees.
template <class Need>
using AddSegmentsWithin = void (*)(const std::vector<Primitive>&, const std::vector<std::string>&,
                                   const std::vector<FarSegmentRule>&, const Vec3&, Need, double,
                                   const std::uint8_t*, FieldSample&);
template <int Scalis, class Need, int... Degree>
constexpr std::array<AddSegmentsWithin<Need>, sizeof...(Degree) + 1> add_segments_within_table(
    std::integer_sequence<int, Degree...>) {
  return {&add_segments_within<0, -1, Need>, &add_segments_within<Degree + 1, Scalis, Need>...};
}

/// The rules of add_segments_within chosen for every point within `radius`
/// of `centre` (Skeleton::rules_near), into nodes[k]: Q at the ends bounded
/// over the ball (FarSegmentRule::ball_nodes) and Q's mean too
/// (FarSegmentRule::ball_mean_square), so that f̲ is at most f at every
/// point of it and each rule meets its share of ε f̲ there.
/// `Degree`, `Scalis` as in add_segments_within.
template <int Degree, int Scalis>
void choose_near(const std::vector<FarSegmentRule>& rules, const Vec3& centre, double radius, double tolerance,
                 std::uint8_t* nodes) {
  const std::size_t count = rules.size();
  boost::container::small_vector<FarSegmentRule::EndRoots, far_rule_chunk> roots(count);
  double lower = 0;
  for (std::size_t k = 0; k < count; ++k) {
    roots[k] = rules[k].end_roots(rules[k].end_squares(centre));
    lower += rules[k].template lower_bound<Degree>(rules[k].ball_mean_square(centre, radius));
  }
  const double budget = tolerance * lower / double(count);
  for (std::size_t k = 0; k < count; ++k) {
    nodes[k] = std::uint8_t(budget > 0.0 ? rules[k].template ball_nodes<Degree, Scalis>(roots[k], radius, budget) : 0);
  }
}

using ChooseNear = void (*)(const std::vector<FarSegmentRule>&, const Vec3&, double, double, std::uint8_t*);
template <int Scalis, int... Degree>
constexpr std::array<ChooseNear, sizeof...(Degree) + 1> choose_near_table(std::integer_sequence<int, Degree...>) {
  return {&choose_near<0, -1>, &choose_near<Degree + 1, Scalis>...};
}

/// The EvaluationError of require_finite_blend, out of line (cold path).
[[noreturn, gnu::cold, gnu::noinline]] void throw_blend_overflow(const FieldSample& result, const char* location,
                                                               const Vec3& p) {
  throw EvaluationError(fmt::format("the blend overflowed double precision at P = {} (value {}, gradient {})",
                                    detail::format_point(p), result.value, detail::format_point(result.gradient)),
                        location);
}

/// A blend of finite children must be finite: otherwise it overflowed
/// double (a weight times a huge value, a large power), which is an
/// EvaluationError located at the node, never a value that could pass for
/// the +inf marker. Only the parts `need` asked for are checked. Inline:
/// every evaluation of a skeleton runs it at its root.
inline void require_finite_blend(const FieldSample& result, bool value_wanted, bool gradient_wanted,
                                 const char* location, const Vec3& p) {  // a C string: no std::string per evaluation
  if ((!value_wanted || std::isfinite(result.value)) && (!gradient_wanted || result.gradient.allFinite())) return;
  throw_blend_overflow(result, location, p);
}

}  // namespace

Skeleton::Skeleton() : nodes_{Node{Blend::sum(), {}, ""}}, cache_(std::make_shared<detail::IndexCache>()) {}

Skeleton::Skeleton(std::vector<Primitive> primitives, double iso) : Skeleton() {
  set_iso(iso);
  for (Primitive& primitive : primitives) add(std::move(primitive));
}

Skeleton::Skeleton(Skeleton&& other) : Skeleton() { swap(other); }

Skeleton& Skeleton::operator=(Skeleton&& other) {
  Skeleton taken(std::move(other));
  swap(taken);
  return *this;
}

void Skeleton::swap(Skeleton& other) noexcept {
  primitives_.swap(other.primitives_);
  primitive_locations_.swap(other.primitive_locations_);
  nodes_.swap(other.nodes_);
  std::swap(iso_, other.iso_);
  cache_.swap(other.cache_);
}

std::string Skeleton::child_location(NodeId parent) const {
  const std::size_t position = nodes_[parent].children.size();
  return parent == root ? fmt::format("primitives[{}]", position)
                        : fmt::format("{}.children[{}]", nodes_[parent].location, position);
}

void Skeleton::changed() { cache_ = std::make_shared<detail::IndexCache>(); }

std::size_t Skeleton::add(Primitive primitive, NodeId parent) {
  if (parent >= nodes_.size()) throw InputError(fmt::format("no blend node {} in this skeleton", parent));
  primitive_locations_.push_back(child_location(parent));
  primitives_.push_back(std::move(primitive));
  nodes_[parent].children.push_back({false, primitives_.size() - 1});
  changed();
  return primitives_.size() - 1;
}

Skeleton::NodeId Skeleton::add_blend(Blend blend, NodeId parent) {
  if (parent >= nodes_.size()) throw InputError(fmt::format("no blend node {} in this skeleton", parent));
  nodes_.push_back(Node{std::move(blend), {}, child_location(parent)});
  nodes_[parent].children.push_back({true, nodes_.size() - 1});
  changed();
  return nodes_.size() - 1;
}

void Skeleton::set_iso(double iso) {
  detail::require_positive_parameter(iso, "iso");
  iso_ = iso;
}

double Skeleton::checked_tolerance(double tolerance) {
  if (!(tolerance >= 0.0 && tolerance < 1.0)) {
    throw InputError(fmt::format("must be at least 0 (exact) and below 1, got {}", tolerance), "tolerance");
  }
  return tolerance;
}

void Skeleton::validate() const {
  for (NodeId id = 1; id < nodes_.size(); ++id) {  // the root may be empty: f = 0
    try {
      validate_blend(nodes_[id].blend, nodes_[id].children.size());
    } catch (const InputError& error) {
      throw error.inside(nodes_[id].location);
    }
  }
}

void Skeleton::prepare() const {
  // A reference, not a copy of the shared_ptr: its reference count would be
  // one cache line that every thread of a batch writes at every point.
  detail::IndexCache& cache = *cache_;
  if (cache.built.load(std::memory_order_acquire)) return;
  std::call_once(cache.once, [&] {
    validate();
    auto index = std::make_unique<detail::SkeletonIndex>();
    index->grids.resize(nodes_.size());
    index->one_primitive_type.assign(nodes_.size(), false);
    for (NodeId id = 0; id < nodes_.size(); ++id) {
      const Node& node = nodes_[id];
      index->one_primitive_type[id] =
          node.blend.kind == BlendKind::sum && !node.children.empty() &&
          std::all_of(node.children.begin(), node.children.end(), [&](const Child& child) {
            return !child.is_blend &&
                   primitives_[child.index].index() == primitives_[node.children.front().index].index();
          });
      // Every sum, union and plain super-elliptic node: a child outside its
      // support is an exact zero in each (docs/field.md, "Union and
      // super-elliptic nodes"). The angle-weighted blend has two children.
      if (node.blend.angle_weighted || node.children.size() < min_indexed_children) continue;
      std::vector<std::optional<SupportBox>> boxes;
      bool any_bounded = false;
      for (const Child& child : node.children) {
        boxes.push_back(child.is_blend ? std::nullopt : support_box(primitives_[child.index]));
        any_bounded = any_bounded || boxes.back().has_value();
      }
      if (any_bounded) index->grids[id].emplace(boxes);
    }
    index->nonnegative_sum.assign(nodes_.size(), false);
    std::vector<bool> decided(nodes_.size(), false);
    const auto nonnegative_sum = [&](const auto& self, NodeId id) -> bool {
      if (decided[id]) return index->nonnegative_sum[id];
      decided[id] = true;  // a node is never its own descendant
      const Node& node = nodes_[id];
      bool nonnegative = node.blend.kind == BlendKind::sum && node.blend.weights.empty();
      for (const Child& child : node.children) {
        if (!nonnegative) break;
        nonnegative = child.is_blend ? self(self, NodeId(child.index)) : never_negative(primitives_[child.index]);
      }
      return index->nonnegative_sum[id] = nonnegative;
    };
    for (NodeId id = 0; id < nodes_.size(); ++id) nonnegative_sum(nonnegative_sum, id);
    // The common skeleton: a list of primitives of one type, no blend node,
    // no weight, no grid (every primitive is then a child of the root, in
    // order).
    const bool plain_list = nodes_.size() == 1 && nodes_[root].blend.kind == BlendKind::sum &&
                            nodes_[root].blend.weights.empty() && !index->grids[root];
    index->primitive_list = plain_list && index->one_primitive_type[root];
    // The tolerance mode: a plain list of segments that all have a far rule,
    // of one kind or both.
    if (plain_list && primitives_.size() >= min_far_rule_segments) {
      for (const Primitive& primitive : primitives_) {
        const FarSegmentRule* rule = far_rule_of(primitive);
        if (rule == nullptr) {
          index->far_rules.clear();
          break;
        }
        index->far_rules.push_back(*rule);
      }
      // One kind and degree throughout: evaluate selects the loops made for it.
      const auto same = [&](const FarSegmentRule& rule) {
        return rule.degree() == index->far_rules.front().degree() &&
               rule.scalis() == index->far_rules.front().scalis();
      };
      if (!index->far_rules.empty() && std::all_of(index->far_rules.begin(), index->far_rules.end(), same)) {
        index->far_rule_degree = index->far_rules.front().degree();
        index->far_rule_scalis = index->far_rules.front().scalis();
        index->far_batch = detail::FarRuleBatch::make(index->far_rules);
      }
    }
    cache.index = std::move(index);
    cache.built.store(true, std::memory_order_release);
  });
}

FieldSample Skeleton::evaluate(const Vec3& p, Need need, Acceleration acceleration, double tolerance,
                               const std::uint8_t* chosen_nodes) const {
  // Checked once here, so that a bad point is not blamed on a primitive.
  detail::require_finite_query_point(p);
  // prepare()'s test inline: the out-of-line call was ~24 instructions of
  // every evaluation. It validates, even for the plain evaluation.
  const detail::IndexCache& cache = *cache_;
  if (!cache.built.load(std::memory_order_acquire)) prepare();
  const detail::SkeletonIndex& built = *cache.index;
  const detail::SkeletonIndex* index = acceleration == Acceleration::indexed ? &built : nullptr;
  if (tolerance > 0.0 && built.far_batch) {
    FieldSample total;
    add_segments_batched(primitives_, primitive_locations_, *built.far_batch, p, need, tolerance, chosen_nodes, total);
    require_finite_blend(total, need != Need::gradient, need != Need::value, "primitives", p);
    return total;
  }
  if (tolerance > 0.0 && !built.far_rules.empty()) {
    static constexpr auto classical = add_segments_within_table<0, Need>(std::make_integer_sequence<int, 16>{});
    static constexpr auto scalis = add_segments_within_table<1, Need>(std::make_integer_sequence<int, 10>{});
    const std::size_t degree = std::size_t(built.far_rule_degree);
    const AddSegmentsWithin<Need> add = built.far_rule_scalis ? scalis[std::min(degree, scalis.size() - 1)]
                                                              : classical[std::min(degree, classical.size() - 1)];
    FieldSample total;
    add(primitives_, primitive_locations_, built.far_rules, p, need, tolerance, chosen_nodes, total);
    require_finite_blend(total, need != Need::gradient, need != Need::value, "primitives", p);
    return total;
  }
  if (built.primitive_list) return evaluate_primitive_list(p, need);
  return evaluate_node(root, p, need, index);  // exact: the tolerance mode covers lists of segments only
}

FieldSample Skeleton::evaluate_primitive_list(const Vec3& p, Need need) const {
  // What evaluate_sum does for the root, without walking the tree.
  FieldSample total;
  bool marker = false;
  std::visit(
      [&](const auto& first) {
        add_primitives_of_one_type<std::decay_t<decltype(first)>>(
            primitives_, primitive_locations_, primitives_.size(), [](std::size_t position) { return position; }, p,
            need, total, marker);
      },
      primitives_.front());
  if (marker) return {infinity, Vec3::Constant(infinity)};
  require_finite_blend(total, need != Need::gradient, need != Need::value, "primitives", p);
  return total;
}

double Skeleton::value(const Vec3& p) const { return evaluate(p, Need::value, Acceleration::indexed, 0.0).value; }

bool Skeleton::reaches(const Vec3& p, double level, double tolerance) const {
  detail::require_finite_query_point(p);
  const detail::IndexCache& cache = *cache_;
  if (!cache.built.load(std::memory_order_acquire)) prepare();
  const detail::SkeletonIndex& built = *cache.index;
  const bool exact_path = tolerance == 0.0 || built.far_rules.empty();
  if (!exact_path || built.primitive_list || !built.nonnegative_sum[root] || !(level > 0.0) ||
      !std::isfinite(level)) {
    return value(p, tolerance) >= level;
  }
  double total = 0.0;
  // The margin: a term of a kernel ≥ 0 rounds below 0 by a few units in
  // the last place of its own size at most, far below the level.
  return sum_reaches(root, p, 2.0 * level, built, 0.0, total) || total >= level;
}

bool Skeleton::sum_reaches(NodeId id, const Vec3& p, double stop, const detail::SkeletonIndex& index, double before,
                           double& total) const {
  const Node& node = nodes_[id];
  const std::optional<SupportGrid>& grid = index.grids[id];
  total = 0.0;
  bool marker = false, reached = false;
  // evaluate_sum's additions, in its order, until before + total ≥ stop:
  // every term left is ≥ 0, and adding a term ≥ 0 to a double never
  // lowers it (rounding is monotone), so the whole sum, and the sums
  // above this node, would end at least as high.
  const auto add = [&](std::size_t position) {
    if (reached) return;
    const Child& child = node.children[position];
    double term = 0.0;
    if (child.is_blend) {
      if (sum_reaches(NodeId(child.index), p, stop, index, before + total, term)) {
        reached = true;
        return;
      }
    } else {
      const FieldSample sample = evaluate_leaf(child.index, p, Need::value);
      marker = marker || is_marker(sample);
      term = sample.value;
    }
    total += term;
    reached = marker || before + total >= stop;
  };
  if (grid.has_value()) {
    grid->for_each_active(p, add);
  } else {
    for (std::size_t position = 0; position < node.children.size(); ++position) add(position);
  }
  if (reached) return true;
  FieldSample sum{total, Vec3::Zero()};
  require_finite_blend(sum, true, false, id == root ? "primitives" : node.location.c_str(), p);
  return false;
}

Skeleton::NearbyRules Skeleton::rules_near(const Vec3& centre, double radius, double tolerance) const {
  detail::require_finite_query_point(centre);
  NearbyRules chosen;
  chosen.tolerance_ = checked_tolerance(tolerance);
  if (!(radius >= 0.0 && std::isfinite(radius))) return chosen;
  const detail::IndexCache& cache = *cache_;
  if (!cache.built.load(std::memory_order_acquire)) prepare();
  const detail::SkeletonIndex& built = *cache.index;
  if (tolerance == 0.0 || built.far_rules.empty()) return chosen;
  static constexpr auto classical = choose_near_table<0>(std::make_integer_sequence<int, 16>{});
  static constexpr auto scalis = choose_near_table<1>(std::make_integer_sequence<int, 10>{});
  const std::size_t degree = std::size_t(built.far_rule_degree);
  const ChooseNear choose = built.far_rule_scalis ? scalis[std::min(degree, scalis.size() - 1)]
                                                  : classical[std::min(degree, classical.size() - 1)];
  chosen.nodes_.resize(built.far_rules.size());
  if (built.far_batch) {
    built.far_batch->choose_near(centre, radius, tolerance, chosen.nodes_.data());
  } else {
    choose(built.far_rules, centre, radius, tolerance, chosen.nodes_.data());
  }
  chosen.centre_ = centre;
  chosen.radius_ = radius;
  chosen.index_ = cache_;
  return chosen;
}

FieldSample Skeleton::value_and_gradient(const Vec3& p, const NearbyRules& rules) const {
  const bool inside =
      rules.radius_ >= 0.0 && rules.index_ == cache_ && (p - rules.centre_).norm() <= rules.radius_;
  return evaluate(p, Need::both, Acceleration::indexed, rules.tolerance_, inside ? rules.nodes_.data() : nullptr);
}

double Skeleton::value(const Vec3& p, const NearbyRules& rules) const {
  const bool inside =
      rules.radius_ >= 0.0 && rules.index_ == cache_ && (p - rules.centre_).norm() <= rules.radius_;
  return evaluate(p, Need::value, Acceleration::indexed, rules.tolerance_, inside ? rules.nodes_.data() : nullptr)
      .value;
}

double Skeleton::value(const Vec3& p, double tolerance) const {
  return evaluate(p, Need::value, Acceleration::indexed, checked_tolerance(tolerance)).value;
}

FieldSample Skeleton::value_and_gradient(const Vec3& p, double tolerance) const {
  return evaluate(p, Need::both, Acceleration::indexed, checked_tolerance(tolerance));
}

Vec3 Skeleton::gradient(const Vec3& p) const {
  return evaluate(p, Need::gradient, Acceleration::indexed, 0.0).gradient;
}

FieldSample Skeleton::value_and_gradient(const Vec3& p) const {
  return evaluate(p, Need::both, Acceleration::indexed, 0.0);
}

FieldSample Skeleton::value_and_gradient(const Vec3& p, Acceleration acceleration, double tolerance) const {
  return evaluate(p, Need::both, acceleration, checked_tolerance(tolerance));
}

FieldSample Skeleton::evaluate_child(const Child& child, const Vec3& p, Need need,
                                     const detail::SkeletonIndex* index) const {
  return child.is_blend ? evaluate_node(child.index, p, need, index) : evaluate_leaf(child.index, p, need);
}

FieldSample Skeleton::evaluate_leaf(std::size_t k, const Vec3& p, Need need) const {
  try {
    return std::visit(
        [&](const auto& primitive) { return sample_of(primitive, p, need); },
        primitives_[k]);
  } catch (const InputError& error) {
    throw error.inside(primitive_locations_[k]);
  } catch (const EvaluationError& error) {
    throw error.inside(primitive_locations_[k]);
  }
}

FieldSample Skeleton::evaluate_node(NodeId id, const Vec3& p, Need need, const detail::SkeletonIndex* index) const {
  const Node& node = nodes_[id];
  switch (node.blend.kind) {
    case BlendKind::sum:
      return evaluate_sum(id, p, need, index);
    case BlendKind::union_max:
    case BlendKind::super_elliptic: {
      if (node.blend.angle_weighted) return evaluate_angle_blend(id, p, need, index);
      // Both operators need every child's value, and its gradient for ours.
      // A child the index skips is an exact zero (f = 0, ∇f = 0), written
      // in its place, so that the operator sees the same list as the plain
      // evaluation (docs/field.md, "Union and super-elliptic nodes").
      const Need child_need = need == Need::value ? Need::value : Need::both;
      boost::container::small_vector<ScalarSample<double>, small_blend_children> children(node.children.size());
      const auto evaluate_at = [&](std::size_t position) {
        children[position] = to_scalar(evaluate_child(node.children[position], p, child_need, index));
      };
      const std::optional<SupportGrid>* grid = index != nullptr ? &index->grids[id] : nullptr;
      if (grid != nullptr && grid->has_value()) {
        (*grid)->for_each_active(p, evaluate_at);
      } else {
        for (std::size_t position = 0; position < node.children.size(); ++position) evaluate_at(position);
      }
      const std::span<const ScalarSample<double>> view(children.data(), children.size());
      if (node.blend.kind == BlendKind::union_max) return from_scalar(blend_union(view));  // one child's sample
      const FieldSample result = from_scalar(blend_super_elliptic(node.blend, view));
      if (!detail::any_infinite(view)) {
        require_finite_blend(result, need != Need::gradient, need != Need::value, node.location.c_str(), p);
      }
      return result;
    }
  }
  return {};  // unreachable: every kind is handled above
}

FieldSample Skeleton::evaluate_sum(NodeId id, const Vec3& p, Need need, const detail::SkeletonIndex* index) const {
  const Node& node = nodes_[id];
  const std::optional<SupportGrid>* grid = index != nullptr ? &index->grids[id] : nullptr;
  const SupportGrid* active = grid != nullptr && grid->has_value() ? &**grid : nullptr;
  FieldSample total;
  bool marker = false;
  const bool unweighted = node.blend.weights.empty();
  // Left to right, from +0: the same additions whether or not the index
  // skips children (their terms are exactly 0; x + 0 = x for every x the
  // running total can hold, since it is never −0), and whichever way
  // term_at reaches the child.
  const auto sum_terms = [&](auto&& term_at) {
    const auto add = [&](std::size_t position) {
      const FieldSample term = term_at(position);
      marker = marker || is_marker(term);
      if (unweighted) {  // weight 1: 1·x = x exactly, so the same sums without the products
        total.value += term.value;
        if (need != Need::value) total.gradient += term.gradient;  // else every term's gradient is 0
        return;
      }
      const double weight = node.blend.weight_of(position);
      total.value += weight * term.value;
      total.gradient += weight * term.gradient;
    };
    if (active != nullptr) {
      active->for_each_active(p, add);
    } else {
      for (std::size_t position = 0; position < node.children.size(); ++position) add(position);
    }
  };
  if (index != nullptr && index->one_primitive_type[id] && unweighted && active == nullptr) {
    // The common skeleton (a file's list of primitives of one type, none
    // skipped by an index): one tight loop over them with that type's
    // evaluation, the same additions in the same order as sum_terms.
    std::visit(
        [&](const auto& first) {
          add_primitives_of_one_type<std::decay_t<decltype(first)>>(
              primitives_, primitive_locations_, node.children.size(),
              [&](std::size_t position) { return node.children[position].index; }, p, need, total, marker);
        },
        primitives_[node.children.front().index]);
  } else if (index != nullptr && index->one_primitive_type[id]) {
    // Every child a primitive of one type: one loop over them with that
    // type's evaluation, without choosing between blend node and primitive
    // and between primitive types at every child (evaluate_child,
    // evaluate_leaf); errors located as evaluate_leaf locates them.
    std::visit(
        [&](const auto& first) {
          using P = std::decay_t<decltype(first)>;
          std::size_t k = node.children.front().index;  // the primitive being evaluated
          try {
            sum_terms([&](std::size_t position) {
              k = node.children[position].index;
              return sample_of(*std::get_if<P>(&primitives_[k]), p, need);
            });
          } catch (const InputError& error) {
            throw error.inside(primitive_locations_[k]);
          } catch (const EvaluationError& error) {
            throw error.inside(primitive_locations_[k]);
          }
        },
        primitives_[node.children.front().index]);
  } else {
    sum_terms([&](std::size_t position) { return evaluate_child(node.children[position], p, need, index); });
  }
  if (marker) return {infinity, Vec3::Constant(infinity)};
  require_finite_blend(total, need != Need::gradient, need != Need::value,
                       id == root ? "primitives" : node.location.c_str(), p);
  return total;
}

FieldSample Skeleton::evaluate_angle_blend(NodeId id, const Vec3& p, Need need,
                                           const detail::SkeletonIndex* index) const {
  const Node& node = nodes_[id];
  const FieldSample first = evaluate_child(node.children[0], p, Need::both, index);
  const FieldSample second = evaluate_child(node.children[1], p, Need::both, index);
  const bool has_angle = first.gradient != Vec3::Zero() && second.gradient != Vec3::Zero();
  if (need == Need::value || !has_angle || is_marker(first) || is_marker(second)) {
    FieldSample result = from_scalar(blend_super_elliptic_angle<double>(node.blend, to_scalar(first),
                                                                        to_scalar(second), nullptr));
    if (need == Need::value) result.gradient = Vec3::Zero();
    if (!has_angle && need != Need::value && !is_marker(result)) {
      // cos θ is the constant 0 here (blend.hpp): ∇a = 0, no Hessian needed.
      const AngleHessianProducts<double> zero{};
      result = from_scalar(blend_super_elliptic_angle<double>(node.blend, to_scalar(first), to_scalar(second), &zero));
    }
    if (!is_marker(first) && !is_marker(second)) {
      require_finite_blend(result, true, need != Need::value, node.location.c_str(), p);
    }
    return result;
  }
  // H_k v by a central difference of child k's exact gradient along v.
  const double step = angle_hessian_step * (1.0 + p.cwiseAbs().maxCoeff());
  const auto hessian_times = [&](const Child& child, const Vec3& v) {
    const double length = v.norm();
    // |v|² underflowing: the blend sees no angle either (blend.hpp), and
    // ignores the product.
    if (length == 0.0) return std::array<double, 3>{0.0, 0.0, 0.0};
    const Vec3 u = v / length;
    const Vec3 ahead = evaluate_child(child, p + step * u, Need::gradient, index).gradient;
    const Vec3 behind = evaluate_child(child, p - step * u, Need::gradient, index).gradient;
    const Vec3 product = (ahead - behind) * (length / (2.0 * step));
    if (!product.allFinite()) {
      throw EvaluationError(fmt::format("the angle-weighted blend's gradient needs the children's gradients within "
                                        "{} of P = {}, and one is infinite there",
                                        step, detail::format_point(p)),
                            node.location);
    }
    return to_array(product);
  };
  const AngleHessianProducts<double> products{
      hessian_times(node.children[0], first.gradient), hessian_times(node.children[0], second.gradient),
      hessian_times(node.children[1], first.gradient), hessian_times(node.children[1], second.gradient)};
  const FieldSample result =
      from_scalar(blend_super_elliptic_angle<double>(node.blend, to_scalar(first), to_scalar(second), &products));
  require_finite_blend(result, true, true, node.location.c_str(), p);
  return result;
}

namespace {

/// a, the points a + (b − a) k / n for k = 1 … n − 1 (not b).
void add_points_along(const Vec3& a, const Vec3& b, int n, std::vector<Vec3>& points) {
  for (int k = 0; k < n; ++k) points.push_back(a + (b - a) * (double(k) / n));
}

/// Every vertex, the points along every edge of the closed polygon, and the
/// points from each vertex towards the centroid.
void add_polygon_points(std::span<const Vec3> vertices, int n, std::vector<Vec3>& points) {
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& v : vertices) centroid += v;
  centroid /= double(vertices.size());
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    add_points_along(vertices[k], vertices[(k + 1) % vertices.size()], n, points);
    // Towards the centroid, without the vertex itself (already added); for a
    // non-convex polygon these may leave it, which only adds seeds.
    for (int j = 1; j < n; ++j) points.push_back(vertices[k] + (centroid - vertices[k]) * (double(j) / n));
  }
  points.push_back(centroid);
}

}  // namespace

std::vector<Vec3> Skeleton::skeleton_points(int per_element) const {
  if (per_element < 1) throw InputError(fmt::format("per_element must be >= 1, got {}", per_element));
  std::vector<Vec3> points;
  for (const Primitive& primitive : primitives_) {  // every leaf of the tree
    std::visit(
        [&](const auto& p) {
          using P = std::decay_t<decltype(p)>;
          if constexpr (std::is_same_v<P, Segment> || std::is_same_v<P, ScalisSegment>) {
            add_points_along(p.a(), p.b(), per_element, points);
            points.push_back(p.b());
          } else if constexpr (std::is_same_v<P, Polygon>) {
            add_polygon_points(p.vertices(), per_element, points);
          } else if constexpr (std::is_same_v<P, PointPrimitive>) {
            points.push_back(p.center());
          } else {
            static_assert(std::is_same_v<P, ScalisTriangle>, "a new primitive type needs its skeleton points");
            add_polygon_points(p.vertices(), per_element, points);
          }
        },
        primitive);
  }
  return points;
}

}  // namespace skelconv
