// skelconv/reconstruct/medial_fit.hpp — the spheres of a medial mesh, centres
// and radii, fitted to the input surface (docs/reconstruction_medial.md,
// "The fit").
//
// The skeleton's primitives are normalised so that f = iso at distance r
// from a long segment or a wide triangle of radius r. Each round evaluates
// f and the exact ∇f of the whole skeleton at area-weighted points of the
// input and takes each point's signed distance δ (> 0: the point is inside
// the reconstruction, which is too fat there): the Newton step
// (f − iso) / √(|∇f|² + ((f − iso)/R)²), R the radius of the sphere whose
// surface is nearest (|p − c| − r smallest), which is the first-order
// distance near the surface and stays within R far from it, followed by
// newton_steps more Newton steps along the gradient. Then every centre and
// every radius take one Levenberg–Marquardt step together on Σ w ρ(δ), ρ
// Huber's robust loss (quadratic up to huber_scale × the diagonal, linear
// beyond); a second stage then takes rounds on the L^p mean of δ, where the
// worst points lead, each distance with worst_newton_steps more Newton
// steps. The Jacobian ∂δ_k/∂θ = (∂f/∂θ) / slope is in closed form, from
// each primitive's own f and ∇f (medial_derivatives.hpp), sparse (a sphere
// couples only with the spheres whose primitives reach the same points);
// the normal equations (JᵀWJ + λ diag) Δθ = −JᵀWδ are solved by Eigen's
// sparse LDLᵀ, each radius step clamped to [−r/2, r] and above min_radius
// (radii stay positive), each centre step to a length of r/2,
// and each centre to its starting ball (the medial ball, inside the input);
// then radii are lowered until no ball lies inside its neighbour's
// (medial_slope.hpp; with a clearance, the smaller ball of a pair first
// grows within the input); where that turns every damped step of a round
// uphill, the round is tried again with the lowered radii tied to the
// neighbours that bounded them (bound_tie_passes). A step is kept only if it lowers the stage's
// objective (the first's: the weighted RMS of δ; the second's: the L^p
// mean, within an RMS limit);
// otherwise it is retried with λ × 10, and a stage stops when none is kept
// (its objective never rises). Neighbouring spheres share points, so a step
// per sphere on its own points alone overshoots and stalls; the joint step
// does not. The derivative is needed, not assumed: a triangle or segment
// much shorter than its radius has a field that *falls* as the radius grows
// (F → K(0) area / τ² for a triangle), so "grow where the surface is short"
// diverges there. The skeleton is rebuilt in memory each round (no files).
// Inside points (optional) add a residual where the reconstruction has
// left a point of the input's inside outside (a cavity); a topology error
// (optional) finds the first round that ended farther from the input's
// topology than the fit started (or than its middle round, where that was
// closer), takes that round's step without the spheres whose move does it
// (found by bisection in space), holds those where they are and runs on;
// where that fails, it resumes from the last round that passed with each
// step tested.
#pragma once

#include <functional>
#include <optional>
#include <string_view>
#include <vector>

#include "skelconv/reconstruct/medial_mesh.hpp"
#include "skelconv/reconstruct/medial_slope.hpp"
#include "skelconv/reconstruct/weighted_point.hpp"
#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv::reconstruct {

struct MedialFitOptions {
  /// Rounds at most of the first stage, its first-order start's
  /// (first_order_start) and its Newton rounds' together (a cap: each stops
  /// before it when its objective has stalled, stall_fall below). With first-order
  /// distances the objective stalls within 14 rounds on the real shapes
  /// (the hand's RMS distance still fell ~10% a round after 8; 14 rounds
  /// took the elephant from 1.66% to 1.40%, Hausdorff); with a Newton step
  /// (newton_steps) it falls more slowly (a coarse sphere's 0.115 → 0.018
  /// of the diagonal in 14 rounds, still falling), so the cap is higher.
  int rounds = 40;
  /// A stage of the fit stops when its objective fell by less than this
  /// fraction a round, on average over its last stall_rounds rounds: the
  /// fit has stalled, and a round is one more evaluation of the skeleton's
  /// field at every point and a sparse solve. Over several rounds, not one:
  /// the damping alternates (a round that needed a larger λ takes a
  /// shorter step and falls less, the next one more). 1% a round: a round
  /// that moves the RMS distance by 1% moves the measured RMS by less than
  /// its run-to-run scatter on the real shapes (0.27 vs 0.28% of the
  /// diagonal on the coarse sphere). 0: a stage runs to its cap, or until
  /// no step is kept.
  double stall_fall = 0.01;
  int stall_rounds = 2;
  /// Rounds at most of the first-order start (first_order_start), within
  /// `rounds`.
  int first_order_rounds = 14;
  /// The first-order start stops sooner than the Newton phase: when its
  /// objective falls by less than this a round over stall_rounds rounds.
  /// It is there to bring the reconstruction near the input, where the
  /// Newton distances' linear model holds, not to converge: its last
  /// rounds at 1% fit first-order distances the Newton phase then undoes.
  /// 5%, with newton_phase_fresh_damping: the rotor's RMS distance 0.443% →
  /// 0.359%, the coarse sphere's 0.258% → 0.218%; alone it took the
  /// 3torus over its Hausdorff goal (docs/reconstruction_medial.md, "The
  /// start ended sooner").
  double first_order_stall_fall = 0.05;
  /// With newton_steps > 0, the first stage starts on first-order distances
  /// and takes the Newton steps only once that has stalled. From the
  /// medial balls the reconstruction is far from the input (0.1 of the
  /// diagonal on the coarse sphere), where the Newton distance's foot, the
  /// point its row is taken at, moves with every sphere the step moves:
  /// the linear model is poor and the damping climbs (λ 3.3 in the coarse
  /// sphere's second round, 7% gained in its first, where the first-order
  /// fit gains 17% and 79% in its first two). Near the surface the two
  /// distances differ only where the Newton step matters (sharp edges,
  /// saturated creases), and the Newton stage converges from there.
  bool first_order_start = true;
  /// The Levenberg–Marquardt damping λ of the first round (relative to the
  /// diagonal of JᵀWJ), and how many times a round may multiply it by 10
  /// before it gives up (the step then barely moves: the fit has stopped).
  double initial_damping = 1e-3;
  int damping_attempts = 6;
  /// The Newton phase starts from initial_damping, not from the λ the
  /// first-order start ended with: λ climbs while a phase stalls (the
  /// rotor's start ended at λ 140 after rounds that fell by 0.1%), and the
  /// Newton phase minimises other distances, whose steps that λ would
  /// shorten until the phase stops as stalled after two rounds
  /// (docs/reconstruction_medial.md, "The fit": two stages).
  bool newton_phase_fresh_damping = true;
  /// Whether the centres move too (otherwise only the radii do).
  bool fit_centres = true;
  /// Huber's loss is quadratic in δ up to this × the points' bounding-box
  /// diagonal, linear beyond.
  double huber_scale = 0.005;
  /// No radius ends below this (absolute length; radii below it start at
  /// it): a tube thinner than the resolution it is meshed at comes back in
  /// pieces, or not at all (docs/reconstruction_medial.md, "The fit": the radius floor).
  double min_radius = 0.0;
  /// How `field_of` takes each triangle's one radius from its spheres'
  /// (triangle_radius, MedialOptions::triangle_radius): the Jacobian's ∂τ/∂r.
  TriangleRadiusRule triangle_radius;
  /// Along every edge of the mesh the radii differ by at most this × the
  /// centres' distance (medial_slope.hpp: no ball inside its neighbour's,
  /// as on a medial axis); each step's radii are lowered to keep it.
  double max_radius_slope = 1.0;
  /// Where no damping makes a round's step descend, the round is tried
  /// again from its first damping with the step solved again with each
  /// radius the bound lowered tied to the neighbour that bounded it (its
  /// change that neighbour's plus max_radius_slope × the change of their
  /// distance, to first order), at most this many times an attempt
  /// (src/reconstruct/medial_step.hpp): where many edges sit at the bound,
  /// it cuts back, in proportion to the step, what the step's linear model
  /// counted on, and no damping makes such a step descend (homer's Newton
  /// phase stopped so at its round 5). Only then: the ties on every round
  /// slowed the fit where the bound did not stop it (the hand's RMS
  /// distance 0.196% → 0.213%, the dino in two components); and not where
  /// each step is tested for its topology, whose meshings the retry's steps
  /// would spend (docs/reconstruction_medial.md, "The fit"). 0 (the
  /// default): never. Off because where it changes a result the Hausdorff
  /// distance rose (homer 0.90% → 0.94%, the bear 0.37% → 0.61%, RMS a
  /// little lower) and no shape over its goal came nearer; 3 is the pass
  /// count that was measured.
  int bound_tie_passes = 0;
  /// Newton steps along the gradient after the first, for each point's
  /// distance, in both stages (`skeletonize --medial-newton-steps`): where
  /// the field saturates (deep inside a crease the blend filled) the
  /// first-order distance falls short, by nearly half at the hand's worst
  /// vertex (0.024 against 0.042), and where it fades (beyond a sharp edge
  /// or corner the convolution rounds off) the bounded step overshoots, by
  /// 91% at a cube's corner
  /// (`MedialFit.TheFirstStageMeasuresSharpCornersWithANewtonStep`). With
  /// 1 the least squares weigh each point by about its true distance, which
  /// the measure's RMS is. From the medial balls, far from the input, the
  /// Newton distance's linear model is poor (a coarse sphere's fit stalled
  /// at 0.509% RMS, `cli.skeletonize.inside_out_repair`'s goal 0.4%): the
  /// first stage starts on first-order distances (first_order_start) and
  /// takes the step once that has stalled, which lowered the RMS distance
  /// on the coarse sphere (0.278% → 0.258%) and on most real shapes
  /// (docs/reconstruction_medial.md, "The fit": the distance).
  /// 2 steps, on earlier code, opened a tunnel in homer (χ 2 → 0). Each
  /// step is one more field evaluation a point.
  int newton_steps = 1;
  /// The Newton steps after the first of the second stage (at least
  /// newton_steps, which counts in both stages): its points are the worst,
  /// where the field saturates most. 1: on eighteen real shapes it lowered
  /// the Hausdorff distance on eleven (homer 1.73% → 1.47%, the fandisk
  /// 2.01% → 1.48%) and raised it on four (the tetrahedron 1.78% → 2.31%,
  /// the triceratops 2.15% → 2.38%); 2 was no better on the hand and homer
  /// (docs/reconstruction_medial.md, "The fit"; measured with no Newton
  /// step in the first stage: with newton_steps = 1 both stages take the
  /// same one).
  int worst_newton_steps = 1;
  /// Rounds at most of the second stage, on the L^p mean of the distances
  /// (p = worst_exponent) instead of Huber's loss: the farther a point, the
  /// more it counts, so the few places that make the Hausdorff distance
  /// lead. 0: no second stage.
  /// p = 4 and 6 rounds: measured against p = 6 and 10 rounds
  /// (docs/reconstruction_medial.md, "The fit"). The stage takes them all
  /// unless no step is kept (no stall rule): its objective is the few worst
  /// points', which may fall little for a round and much at the next.
  int worst_rounds = 6;
  double worst_exponent = 4.0;
  /// The second stage keeps no step that raises the RMS distance above
  /// (1 + this) × where the first stage left it.
  double worst_rms_growth = 0.25;
  /// When the fit ends farther from the input's topology than it started
  /// (fit_medial_mesh's topology_error) and holding spheres (below) does
  /// not bring it back, it resumes from the last round that was not, with
  /// each step tested, at most this many tests (each meshes the skeleton:
  /// about 3 s for 500 primitives at diagonal / 120).
  int topology_checks = 10;
  /// Where the fit's end is farther from the input's topology, the first
  /// round that took it there is taken without the spheres whose move does
  /// it, found by bisection (the round's step split in space, each half
  /// tried, a failing half split again), and held where they are for the
  /// rest of the fit. At most this many meshings go to finding them over
  /// the whole fit (0: none; the fit goes back and tests each step). 16:
  /// what one search took on CGAL's lion and dragon, 500 spheres, down to
  /// hold_group (docs/reconstruction_medial.md, "The fit").
  int localize_checks = 16;
  /// The bisection stops at this many spheres and holds them together: a
  /// hole opens between a few neighbouring spheres (CGAL's lion: a loop of
  /// three tube edges), and each halving costs a meshing.
  int hold_group = 4;
  /// How many times at most the fit, its end farther from the input's
  /// topology, holds the spheres that took it there and runs on untested
  /// (each time: a bisection over the rounds, the spheres found, the rest
  /// of the rounds fitted, the end meshed). Where that leaves the end
  /// farther still, the fit goes back, nothing held, and tests each step
  /// (topology_checks): to the repair's last round that keeps the topology
  /// (found by bisection over its rounds) where its surface points are
  /// closer than at the round the first bisection left it, else to that
  /// round.
  int topology_repairs = 2;
  /// After a repair, the fit's first this many rounds are each meshed;
  /// where one is farther from the input's topology (the defect opened
  /// again: holding did not keep it), the repair stops there and the fit
  /// goes back as above, instead of fitting the rest of its rounds, meshing
  /// their end and searching again (docs/reconstruction_medial.md, "The
  /// guard acts where the defect is": on CGAL's dragon, coupling and femur
  /// the defect opens again in the repair's first round). Costs one meshing
  /// where the repair holds; 0: the end alone is tested.
  int repair_watch_rounds = 1;
};

struct MedialFitReport {
  /// With first_order_start and newton_steps > 0: the weighted RMS of the
  /// first-order δ before the fit and after each round of the first-order
  /// start (absolute; decreasing); empty otherwise.
  std::vector<double> first_order;
  /// The weighted RMS of δ (with newton_steps Newton steps) before the first
  /// stage and after each of its rounds (absolute; decreasing).
  std::vector<double> rms;
  /// The L^p mean of δ before the second stage and after each of its rounds
  /// (absolute; decreasing; empty without a second stage).
  std::vector<double> worst;
  /// When the fit went back to an earlier round to keep the topology: how
  /// many rounds (of both stages) it kept.
  std::optional<std::size_t> rounds_kept;
  /// When the fit went back after a failed repair (holding spheres did not
  /// keep the topology): true where it went back to the repair's last round
  /// that keeps it (closer to the points), false where to the round the
  /// first bisection left it (then rounds_kept counts rounds before the
  /// repair).
  std::optional<bool> back_to_repair;
};

/// Whether a stage of the fit whose objective went through `values` (before
/// its first round, then after each round) has stalled: over its last
/// `stall_rounds` rounds it fell by less than `stall_fall` a round on
/// average, i.e. its last value is above (1 − stall_fall)^stall_rounds × the
/// value stall_rounds rounds before (MedialFitOptions::stall_fall). Never
/// with stall_fall ≤ 0 or fewer rounds than stall_rounds.
bool fit_stalled(const std::vector<double>& values, double stall_fall, int stall_rounds);

/// The field of a medial mesh.
using MedialField = std::function<Skeleton(const MedialMesh&)>;

/// The spheres fit_medial_mesh starts from (its round 0, the topology
/// guard's bound): each radius raised to options.min_radius, then the
/// radius bound applied (limit_radius_slope, with `clearance`).
MedialMesh fit_start(MedialMesh mesh, const MedialFitOptions& options, const Clearance& clearance = {});

/// How far the surface of a medial mesh is from the input's topology
/// (meshed at the user's resolution): 0 when its components and Euler
/// characteristic are the input's, more the more they differ.
using TopologyError = std::function<long long(const MedialMesh&)>;

/// `mesh` with its spheres fitted to `points` as described above. `field_of`
/// must turn a medial mesh into its edges' SCALIS segments, its triangles'
/// SCALIS triangles (at the mean radius) and its isolated spheres' points,
/// in that order, all of a compact kernel of even degree (as
/// skeleton_file_text does). `progress` (if set) gets one line per round.
/// `clearance` (if set), each centre's distance to the input's surface,
/// lets the radius bound grow a smaller ball before it shrinks the larger
/// (limit_radius_slope). Where `mesh.parts` is set (an input of several
/// parts, medial_parts.hpp), `point_parts` gives the part of each point
/// (the surface points, then the inside points), and each point is fitted
/// against the sum of its own part's primitives alone (skeleton_file_text
/// joins the parts' sums by a union).
MedialMesh fit_medial_mesh(MedialMesh mesh, const std::vector<WeightedPoint>& points,
                           const std::vector<Vec3>& inside_points, const MedialField& field_of,
                           const MedialFitOptions& options, MedialFitReport* report,
                           const std::function<void(std::string_view)>& progress = {},
                           const TopologyError& topology_error = {}, const Clearance& clearance = {},
                           const std::vector<std::int32_t>& point_parts = {});

}  // namespace skelconv::reconstruct
