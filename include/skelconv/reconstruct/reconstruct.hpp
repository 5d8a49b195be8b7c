// skelconv/reconstruct/reconstruct.hpp — the whole skeleton half of Ferley
// 1996: closed mesh → medial graph → pruned → curve skeleton → branches →
// simplified (Pavlidis, 4-D) → smoothed (B-spline, 4-D) → skeleton file of
// SCALIS segments. docs/reconstruction.md describes each step and its
// parameters, and measures it.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "skelconv/reconstruct/bezier_triangle.hpp"
#include "skelconv/reconstruct/branch_graph.hpp"
#include "skelconv/reconstruct/medial_fit.hpp"
#include "skelconv/reconstruct/medial_mesh.hpp"
#include "skelconv/reconstruct/pruning.hpp"
#include "skelconv/reconstruct/surface_distance.hpp"
#include "skelconv/reconstruct/surface_fit.hpp"

namespace skelconv::reconstruct {

/// Which skeleton `reconstruct` builds: Ferley's curve skeleton (tubes,
/// branches, junctions), a medial mesh (sheets as SCALIS triangles, tubes as
/// segments: medial_mesh.hpp), or both, keeping the one that fits better.
enum class SkeletonMethod { curve, medial, automatic };

/// Which cavities of the fit's rounds the medial fit's topology guard counts
/// as the cavity fill after the fit will leave them (no defect), the
/// unfitted spheres' surface always as it is (docs/reconstruction_medial.md,
/// "The guard counting a crease's bubbles of air as filled").
enum class GuardFilledCavities {
  none,  ///< every cavity a defect
  air,   ///< the bubbles of a crease's air (centre outside the input) filled, hollows in its solid defects
  all,   ///< every cavity the fill fills, hollows in the input's solid too
};

/// When the medial path joins each thin protrusion it keeps (pruning.hpp,
/// TipOptions) to the body again, along its pruned medial path or by an
/// edge between overlapping balls (TipOptions::connect). Kept apart, the
/// piece meets the body where two tube ends' spheres overlap, a neck that
/// may be thinner than the measuring mesh's facet (CGAL's camel: the tail
/// came back as a second component). Joined always, the cow's teats change
/// the medial mesh and the fit's path, and the cow came back worse (1.67 /
/// 0.163 → 1.75 / 0.256, χ −2): hence only where needed by default.
enum class TipJoin {
  never,
  /// Only where the result with the pieces apart has more components than
  /// the input: the medial path again with them joined, kept where its
  /// topology is closer to the input's.
  where_apart,
  always,
};

/// The medial-mesh path (docs/reconstruction_medial.md).
struct MedialOptions {
  /// At most this many primitives (SCALIS triangles, segments, points).
  std::size_t budget = 500;
  /// Fewer where they are not needed: once within `budget`, the medial
  /// mesh's collapses go on while the merged sphere stays within this ×
  /// the diagonal of every tangent plane at the samples it stands for
  /// (QuadricOptions::error_target says exactly what it bounds). 0: off,
  /// the mesh simplified to the budget. Off by default: it bounds the
  /// medial mesh's balls, not the fitted surface, and no value keeps every
  /// shape measured as good (0.4%: homer 0.90 → 1.76% of the diagonal;
  /// 0.8%: the cow 1.67 → 1.92%, while the dumbbell needs 16 primitives
  /// for 482; docs/reconstruction_medial.md, "The error target").
  double error_target = 0.0;
  /// An input of several closed parts shares `budget` out per part, in
  /// proportion to their areas, each at least this many primitives (or an
  /// equal share where the parts are too many for that): with one budget
  /// for the whole shape, a small part was left one or two spheres, which
  /// bulge past the gap into a neighbour (docs/reconstruction_medial.md,
  /// "Separate parts").
  std::size_t part_minimum_budget = 20;
  /// Pruning angle θ_min of the medial path, degrees. Lower than the curve
  /// path's 90°: on a sheet that meets the surface at a right-angled edge
  /// (a box) the contacts subtend exactly 90°, and the sheet must stay.
  double prune_angle_degrees = 60.0;
  /// Also pruned: Voronoi vertices whose contact samples span less than
  /// this × the diagonal (pruning.hpp, the λ-medial axis): the spikes a
  /// coarse mesh's every sharp vertex sends into the medial axis.
  double prune_span = 0.0;
  /// The small pieces the islands rule keeps as lobes (pruning.hpp): a
  /// ball on a body (CGAL's elk) would go otherwise.
  LobeOptions lobes{0.5, 0.5};
  /// The small pieces the islands rule keeps as thin protrusions
  /// (pruning.hpp, TipOptions): one of its balls reaches at least
  /// `tip_reach` sample spacings (diagonal / sample_divisions) and
  /// `tip_thinness` × its radius beyond the large pieces' balls. Half a
  /// spacing: as far as Voronoi balls through samples may reach past a
  /// curved surface (merged_overhang): below that, noise cannot be told
  /// from the shape. Twice the radius: a protrusion longer than it is
  /// thick. On the real shapes the noise pieces reach at most 0.68
  /// spacings and 1.4 radii, the cow's teats 0.92 spacings and 4 radii.
  /// 0 = none kept.
  double tip_reach = 0.5;
  double tip_thinness = 2.0;
  /// When the thin protrusions kept are joined to the body again
  /// (TipJoin, TipOptions::connect).
  TipJoin tip_join = TipJoin::where_apart;
  /// The samples at a protrusion's end that pruning left out of every ball's
  /// reach (src/reconstruct/unreached_tips.hpp: a gap of at least
  /// `tip_end_reach` sample spacings and `tip_end_thinness` × the radius of
  /// the ball falling shortest of it, no other such sample within a
  /// spacing) are held by that ball through the collapses
  /// (QuadricOptions::reach_points, weight `tip_end_weight`), so that a
  /// horn keeps its length. A quarter spacing: the devil's horn's tip is
  /// 0.42 spacings beyond its last ball; thinness 1: a cone under 30°
  /// half-angle (the devil's last ball is 1.19 radii short). 0 = none held.
  double tip_end_reach = 0.25;
  double tip_end_thinness = 1.0;
  double tip_end_weight = 1.0;
  /// Where, after the collapses, the nearest sphere of such a sample still
  /// falls short of it by `tip_tube_reach` spacings and `tip_end_thinness`
  /// radii (a sharp tip: a cone's medial axis runs to its apex, its radius
  /// falling to 0, but the samples' spacing stops the medial graph about a
  /// spacing short of it), that sphere gets a tube edge towards the sample,
  /// ending one radius short of it with a sphere at the fit's radius floor
  /// (`min_radius_facets`), where the way is inside the input
  /// (src/reconstruct/tube_ends.hpp, reach_unreached_tips). It takes CGAL's
  /// drop (blob-closed.off, whose tip came back as a knob 2.1% of the
  /// diagonal short; its ball 0.72 spacings short) from 2.14% to 0.77%.
  bool tip_end_tube = true;
  /// Half a spacing (1.25% of the diagonal at 40 divisions): a tip the
  /// mesh falls shorter of than that is within the goal as it is, and a
  /// tube there changes the fit's path over the whole shape for little
  /// (the cow's horn, 0.29 spacings short: 0.68% there without a tube,
  /// 0.24% with one, but the fit stopped its first-order rounds one round
  /// later and ended 1.67% → 1.78% in the crease between tail and rump).
  double tip_tube_reach = 0.5;
  /// A tube's free end is extended by one sphere this many radii beyond it
  /// (the medial axis stops short of a cap); 0 = none.
  double end_extension = 1.0;
  /// A tube end whose centre is less deep than this × its radius is a
  /// spike towards the surface, not a tube's end: its sphere beyond is
  /// kept inside the input (docs/reconstruction_medial.md, "The medial mesh").
  double end_spike_depth = 0.5;
  /// A tube end shallower than its radius whose input tapers on along the
  /// edge more than this × as far as its sphere beyond (a horn's tip) gets
  /// its sphere beyond where the input ends instead; 0 = never.
  double end_taper_reach = 2.0;
  /// A tube end whose radius exceeds its neighbour's by more than this ×
  /// their distance, and whose sphere beyond would stick out of the input
  /// by more than half its radius, is a bulb (a round lobe reached through
  /// a neck): its ball is given as an isolated sphere, no sphere beyond
  /// (docs/reconstruction_medial.md, "Bulbs at tube ends"); 0 = never.
  /// 0.5: a tube's radius grows along its length far less steeply than
  /// that (a cone of 30° half-angle); the elk's ball at the end of its
  /// neck, 0.76.
  double end_bulb_slope = 0.5;
  /// The primitives' kernel: compact, degree 4, this σ (docs/cli_skeleton.md:
  /// support σ × the radius). Compact, not Cauchy: the field's index then
  /// evaluates only the primitives near a point, and a medial mesh has
  /// hundreds (341 Cauchy primitives on a hand took 110 s to mesh). 1.5:
  /// a support narrower than 2 radii adds less of one sheet's field to its
  /// neighbours' (less bulging where sheets fold or lie close; measured in
  /// docs/reconstruction_medial.md), and fewer primitives reach each point.
  double kernel_sigma = 1.5;
  /// A sphere the collapses merge must lie inside the input, reaching at
  /// most this × the diagonal beyond its surface (QuadricOptions::overhang):
  /// half the samples' spacing (sample_divisions), as far as the Voronoi
  /// balls through samples themselves may reach past a curved surface
  /// between them. Not tuned.
  double merged_overhang = 0.0125;
  /// QuadricOptions::radius_weight: the collapses' cost of the radius
  /// varying along an edge, which keeps the sheets' triangles narrow where a
  /// one-radius triangle would step (at sharp edges most). Off by default:
  /// 0.03 brought CGAL's 3torus, coupling and oblong box within the CAD
  /// goals but put the rotor's thin shell over them (2.05% → 3.32% of the
  /// diagonal: its fit's guard spent its tests), and 0.01 was not measured
  /// on every shape (docs/reconstruction_medial.md, "The medial mesh").
  double quadric_radius_weight = 0.0;
  /// The medial graph's samples are at most the diagonal / this apart
  /// (surface_samples.hpp; the curve path's 12 leaves a coarse mesh's large
  /// triangles with few samples, and the medial sheets full of holes).
  double sample_divisions = 40.0;
  /// Thin walls (`thin_walls`, on by default; `--no-medial-thin-walls`
  /// turns it off): the parts of the pruned medial graph that are a thin
  /// wall (a sheet of radius below `thin_wall_radius` × the samples'
  /// spacing, about 6 spacings or more across, its two faces under a
  /// spacing apart: src/reconstruct/thin_walls.hpp)
  /// are sampled again, each wall at the spacing of its median half-thickness (two
  /// samples across it), at most `thin_wall_max_refinement` times finer,
  /// and the graph is built again; a shape with no thin wall keeps the graph
  /// built first. A wall sampled about once across its thickness has
  /// Delaunay cells spanning both faces, whose circumcentres fall outside:
  /// its sheet comes out full of holes, each one a tunnel in the result
  /// (CGAL's rotor: medial complex χ −47 for a genus-1 solid). A thin limb
  /// has a curve for its medial axis, no sheet, and is left as it is.
  /// 0.75: the elephant (median radius 0.84 spacings) resampled as a
  /// whole came back farther from its input (docs/reconstruction_medial.md,
  /// "Thin walls").
  bool thin_walls = true;
  double thin_wall_radius = 0.75;
  double thin_wall_max_refinement = 2.5;
  /// The fit's points are about this × the diagonal apart.
  double fit_spacing = 1.0 / 64.0;
  /// The fit keeps one point per facing within each cell (the two
  /// angles below) rather than one per cell (`--medial-fit-facings`). Off
  /// by default: it takes the coupling to 2.47 / 0.411, the 3torus to
  /// 1.92 / 0.356 and the blade within the RMS goal, but the femur from
  /// 3.57% to 3.69% and the joint from 3.60% to 3.81%, past their
  /// shortfalls (docs/reconstruction_medial.md, "What limits it").
  bool fit_by_facing = false;
  /// With fit_by_facing: within a cell of the fit's spacing, points whose
  /// triangles' normals differ by more than this (degrees) are kept apart,
  /// one point per face
  /// (surface_points_in_cells): the two faces of a wall thinner than a
  /// cell, or of a sharp edge, each get their own point. 60: a right-angled
  /// edge's faces (90°) and a wall's two (180°) are split, while a smooth
  /// surface bends by less within a cell (diagonal / 64) but at its
  /// sharpest creases and tips. 180: one point per cell, whatever its
  /// faces.
  double fit_facing_angle_degrees = 60.0;
  /// A facing that holds less than this × the cell's face area (the fit's
  /// spacing squared) within a cell joins the cell's largest facing
  /// (surface_points_in_cells' least_area). A flat face that crosses a
  /// cell holds up to √2 of it (h² where it crosses square), a face that
  /// only clips a corner less, and each facing of a part thinner than a
  /// cell (a claw, whose sides face every way within it) less still: kept
  /// apart, those hold the fit's spheres to both sides of the part and
  /// thin it until it comes apart at the measure. CGAL's dino keeps one
  /// component from 0.15 to 0.35 (at 0 and 0.1: 4 and 2); 0.2, within
  /// that, is the best measured on the 3torus, whose distances swing
  /// between 1.9% and 3.7% over that range (docs/reconstruction_medial.md,
  /// "What limits it"). 0: every facing keeps its point.
  double fit_facing_least_area = 0.2;
  /// No sphere's radius ends below this × the facet size of the
  /// measuring mesh (diagonal / ReconstructOptions::measure_divisions;
  /// MedialFitOptions::min_radius). A thinner tube (a dinosaur's claw, a
  /// spike the fit shrank) falls between the mesher's samples and comes back
  /// in pieces; a higher floor makes thin parts too fat (the dino's
  /// measurements in docs/reconstruction_medial.md, "The fit").
  double min_radius_facets = 0.75;
  /// Whether the fit takes inside points (medial_stage.cpp): the medial
  /// vertices at least `inside_depth_facets` facets of the measuring mesh
  /// deep (their radius). Off by default: on the real shapes they took the
  /// hand from 1.90% to 1.80% but the femur from 3.36% to 3.63% and the
  /// coupling from χ −14 to −12 (docs/reconstruction_medial.md, "Inside
  /// points").
  bool inside_points = false;
  double inside_depth_facets = 3.0;
  /// Whether the fit's radius bound (medial_slope.hpp) first grows the
  /// smaller ball of a pair out of the bound, up to its centre's distance to
  /// the input's surface, before it shrinks the larger. Off by default: on
  /// shapes nobody tuned for it took the bear's RMS distance from 0.240% to
  /// 0.108%, homer from 1.73% to 1.47% and the knot from 1.66% to 1.51%
  /// (Hausdorff), but the anchor from 2.65% to 3.22% and the hand from 1.91%
  /// to 1.97% (docs/reconstruction_medial.md, "What limits it").
  bool grow_within_input = false;
  /// How each medial triangle's SCALIS triangle takes its one radius from
  /// its spheres' (medial_mesh.hpp, triangle_radius): by default the
  /// arithmetic mean, the geometric where the radii differ most (a fan from
  /// a thick part into a thin one); `skeletonize
  /// --medial-geometric-triangle-radius` takes the geometric mean
  /// everywhere, `--medial-arithmetic-triangle-radius` the arithmetic.
  TriangleRadiusRule triangle_radius;
  /// Which of the fitted rounds' cavities the fit's topology guard counts
  /// as filled. `air` (the default): a bubble of a crease's air that a round
  /// seals is no loss, the fill takes it away after the fit (CGAL's man
  /// `--repair`: counted as defects, the bubbles stopped the fit after round
  /// 4 of 30 at 3.64 / 0.482; counted as filled, all 30 rounds run, 2.94 /
  /// 0.252, one component), while
  /// a hollow in the input's solid stays a defect: counted as filled
  /// (`all`, `skelconv skeletonize --medial-guard-counts-filled-cavities`),
  /// the Chinese dragon's hollows no longer paid for the tunnels its rounds
  /// opened with them, and the fill closed the hollows and left the tunnels
  /// (χ 2 → −2). `none` (`--medial-guard-counts-every-cavity`) counts every
  /// cavity as a defect.
  GuardFilledCavities guard_filled_cavities = GuardFilledCavities::air;
  /// Where the fitted result has more tunnels than the input, the medial
  /// mesh is simplified again with every loop of three edges, tube edge
  /// across a sheet's hole and hole through a sheet closed whose triangles
  /// the input holds (QuadricOptions::inside_samples: the input's depth
  /// positive on a grid of this many steps a side), fitted again, and
  /// kept if its topology is closer to the input's (medial_stage.cpp;
  /// docs/reconstruction_medial.md, "Tunnels too many"). 0 turns it off.
  int close_inside_samples = 4;
  /// Where the result still has more tunnels than the input, a tunnel
  /// through a pipe of air that the input does not have (a crease sealed
  /// at its mouth along a stretch, both ends open: homer's mouth) is
  /// plugged by an isolated sphere where taking a small box of the meshed
  /// surface's triangles out lowers its genus, one tunnel at a time, kept
  /// where the topology defects drop and the farthest distance between the
  /// surface and the input stays within the larger of what it was and two
  /// facets of the measure (plug_tunnels.hpp;
  /// docs/reconstruction_medial.md, "Tunnels through air"). False turns it
  /// off.
  bool plug_air_tunnels = true;
  /// Where the result has more outer shells than the input has
  /// components, a piece apart (a tip beyond a neck the fit thinned below
  /// the measure's facet) is bridged to the nearest other shell by an
  /// isolated sphere across the gap, the smallest piece first, kept where
  /// the topology defects drop and the farthest distance between the
  /// surface and the input stays within the larger of what it was and two
  /// facets of the measure (fill_cavities.hpp, piece_bridges;
  /// docs/reconstruction_medial.md, "Pieces apart"). False turns it off.
  bool bridge_pieces = true;
  MedialFitOptions fit;
};

struct ReconstructOptions {
  SkeletonMethod method = SkeletonMethod::automatic;
  MedialOptions medial;
  /// Ferley's pruning threshold θ_min, degrees, in [0, 180).
  double prune_angle_degrees = 90.0;
  /// Pruning also removes the Voronoi vertices whose contact samples span
  /// less than this × the input's bounding-box diagonal (pruning.hpp: the
  /// scale the angle does not see). 0 (default) for clean samples; for
  /// samples with noise of amplitude a (× the diagonal), about 4a: a
  /// sample moves by up to a√3, a span by twice that.
  double prune_span = 0.0;
  /// Pavlidis tolerance ε, relative to the largest extent of the skeleton's
  /// bounding box (Ferley's fig. 3.2 uses 0.02).
  double epsilon = 0.02;
  /// Level-set bin width, × the median radius of the inner balls.
  double bin_factor = 1.0;
  /// A branch between two junctions shorter than this × the larger end
  /// radius is contracted; with explained_factor = 0, a terminal branch
  /// shorter than this × its junction's radius is a spur.
  double spur_factor = 1.5;
  /// With explained_factor = 0: a terminal branch whose balls reach less
  /// than this × its junction's radius beyond the rest of the skeleton's
  /// balls is a spur too (remove_spurs; the noise spurs of the test shapes
  /// reach at most 1.03 (noisy tree; 0.48 on the noisy ring), their real
  /// branches at least 1.8: 1.5 is between, with margin both ways).
  double spur_protrusion = 1.5;
  /// The spur rule by explained area (branch_graph.hpp, SpurRule): a
  /// terminal branch stays when it explains at least `explained_factor` ×
  /// π R² of the input's area (R its junction's radius), counting the
  /// points the rest of the skeleton misses by more than
  /// `explained_tolerance` × its radius; the input's area is taken as
  /// points merged in cells of `explained_spacing` × the diagonal.
  /// explained_factor = 0: the length and protrusion rules above instead.
  double explained_factor = 0.5;
  double explained_tolerance = 0.25;
  double explained_spacing = 0.01;
  /// Junctions moved to where their branches' axes meet
  /// (relocate_junctions), in every stage after `raw`.
  bool relocate_junctions = true;
  /// B-spline sampling: segments per span.
  int samples_per_span = 4;
  /// SCALIS Cauchy kernel of the output segments (docs/cli_skeleton.md), normalised
  /// so that f = iso at distance r from a long segment of radius r.
  int kernel_degree = 4;
  /// Each free end (an end node, not a junction) is extended along its end
  /// tangent by this × its radius, at that radius (docs/reconstruction.md,
  /// "Ends"): the medial axis stops short of a cap, and a SCALIS surface
  /// falls short of its radius near a skeleton end. 0 = no extension.
  double end_extension = 1.5;
  double kernel_sigma = 1.5;
  /// Cap trimming (surface_fit.hpp): free-end points where the radius falls
  /// faster than this per unit length are cap balls, dropped. 0.5 = contacts
  /// more than 30° off the axis normal (dr/ds = −sin 30°).
  double cap_slope = 0.5;
  /// The last stage's fit of radii and end extensions to the input.
  FitOptions fit;
  /// Junctions of three branches as cubic Bézier triangles (bezier_triangle.hpp)
  /// in the fitted stage, with Ferley's k (corner distance / junction
  /// radius) and n² SCALIS triangles per patch. Off by default: measured
  /// in docs/reconstruction.md.
  bool junction_triangles = false;
  bool junction_cuts_branches = false;  ///< Ferley's layout (see place_junction_triangles)
  double junction_k = 1.5;
  int junction_subdivisions = 3;
  /// Measuring a stage (measure_stage) is refused beyond this many
  /// primitive evaluations (measure_work), so that a report ends in
  /// bounded time. The fitted stages of the test shapes need at most
  /// 3.4·10⁷, the raw stage of the clean tree 9·10⁷; the raw stage of the
  /// noisy tree (32 313 segments from the unpruned Voronoi graph) needs
  /// 5·10⁹, fifty times as much.
  double measure_budget = 2e8;
  /// Measuring meshes a stage with facets of the diagonal / this (and
  /// `auto` chooses on those measures): the resolution at which the
  /// output's Euler characteristic must be the input's.
  double measure_divisions = 100.0;
  /// `auto` keeps the curve path's result without building the medial
  /// mesh when, measured as above, it keeps the input's Euler
  /// characteristic and components and its two-sided Hausdorff and RMS
  /// distances are at most these fractions of the diagonal: the curve
  /// path's own goal (docs/reconstruction.md), which the medial mesh, with
  /// its goal of 1.5% and 0.4%, would not beat by a margin worth its fit
  /// (seconds to a minute; a sphere's ball or a capsule's one segment).
  double curve_accepted_hausdorff = 0.01;
  double curve_accepted_rms = 0.002;
  /// Called with one line per step ("medial graph: 5230 vertices, ...").
  std::function<void(std::string_view)> progress;
};

/// A stage's skeleton meshed at the default size and measured against the
/// input (measure): distances, the Euler characteristic and the connected
/// components of its surface, the surface itself, and the seconds meshing
/// and measuring took.
struct StageMeasure {
  SurfaceDistance distance;
  TriangleMesh surface;  ///< the skeleton's iso-surface, meshed at the default size
  long long euler_characteristic = 0;
  std::size_t components = 0;
  double seconds = 0.0;
};

/// One stage's skeleton: its branches as polylines of (x, y, z, r).
struct Stage {
  std::string name;  ///< raw, pruned, simplified, simplified_3d, smoothed, fitted; or ball; or medial
  std::vector<Branch> branches;
  std::vector<Facet> facets;  ///< junction patches (fitted stage, if asked)
  /// Point primitives (x, y, z, radius): the `ball` stage of a shape
  /// without branches (ball_fit.hpp); the iso-surface of each alone is the
  /// sphere of that radius.
  std::vector<Vec4> balls;
  /// The `medial` stage's medial mesh: each triangle a SCALIS triangle (at
  /// the mean radius of its spheres: the closed form), each edge a SCALIS
  /// segment, each isolated sphere a point, all of MedialOptions' compact
  /// kernel.
  MedialMesh medial;
  std::size_t ends = 0, junctions = 0, points = 0;
  double seconds = 0.0;  ///< wall time spent computing this stage
  /// Its measure, when reconstruct() took it to choose between the two
  /// paths (`auto`); measure() returns it instead of meshing again.
  std::optional<StageMeasure> measured;
  /// Its skeleton meshed as measure() meshes it, when the medial fit's
  /// topology guard meshed these very spheres already (medial_stage, which
  /// meshes without projecting and projects only this one): measure()
  /// measures that mesh instead of meshing again.
  std::optional<TriangleMesh> meshed;
};

/// What the medial path saw and did (medial_stage).
struct MedialPathReport {
  std::size_t samples = 0, vertices = 0;  ///< its own medial graph (denser samples)
  std::size_t pruned = 0, spheres = 0;
  MedialFitReport fit;
};

/// The primitives a stage's skeleton file holds.
struct PrimitiveCounts {
  std::size_t segments = 0, triangles = 0, points = 0;
  std::size_t total() const { return segments + triangles + points; }
};
PrimitiveCounts primitive_counts(const Stage& stage, const ReconstructOptions& options);

struct Reconstruction {
  std::size_t samples = 0, medial_vertices = 0, medial_edges = 0;
  double medial_seconds = 0.0;  ///< wall time of sampling and the medial graph
  PruningReport pruning;
  std::size_t spurs_removed = 0;
  FitReport fit;
  MedialPathReport medial_path;
  std::vector<Stage> stages;  ///< in the order above; the last is the result
  double tolerance = 0.0;     ///< ε × skeleton size, absolute
  /// `auto` only: the curve path's primitives when they were more than the
  /// budget (ReconstructOptions::medial.budget), so that its stage was no
  /// candidate (and, counted before the fit, not fitted); 0 otherwise.
  std::size_t curve_over_budget = 0;
};

/// Runs every step on `surface` (a closed mesh). Throws InputError for bad
/// options (located at "--prune-angle", "--epsilon") or a bad mesh.
Reconstruction reconstruct(const TriangleMesh& surface, const ReconstructOptions& options);

/// The `medial` stage of `surface`: its inner Voronoi graph (sampled at
/// options.medial.sample_divisions), pruned at options.medial's angle,
/// simplified to a medial mesh within the budget, tube ends extended, radii
/// fitted.
Stage medial_stage(const TriangleMesh& surface, const ReconstructOptions& options, MedialPathReport* report);

/// The skelconv skeleton file (JSON text) of a stage: one "scalis_segment"
/// per polyline segment (plus the end extensions), one "scalis_triangle"
/// per junction facet, one "point" per ball, summed, with the top-level
/// "iso": 1. Throws std::logic_error for a stage without any primitive
/// (reconstruct() never returns one: it falls back to a ball).
std::string skeleton_file_text(const Stage& stage, const ReconstructOptions& options);

/// What measuring a stage costs, estimated before meshing it: the
/// primitive evaluations of the grid mesher over the nodes of the input's
/// bounding box at spacing `size`. The field's index visits a
/// compact-support primitive (the medial mesh's) only at the nodes inside
/// its support box, an infinite-support one (a Cauchy SCALIS segment of
/// the curve path, a ball) at every node: the work is the sum over the
/// primitives of the nodes each is evaluated at, an upper estimate (the
/// mesher's continuation visits only the cells near the surface). It grows
/// with the stage, not with the input alone: the `raw` stage of noisy
/// samples (every inner Voronoi vertex, no pruning) holds tens of
/// thousands of Cauchy segments.
struct MeasureWork {
  std::size_t primitives = 0;
  double grid_nodes = 0.0;
  double evaluations = 0.0;  ///< Σ over the primitives of the nodes it is evaluated at
};
MeasureWork measure_work(const TriangleMesh& surface, const Stage& stage, const ReconstructOptions& options,
                         double size = 0.0);

/// Why `stage` is not measured within `budget` primitive evaluations
/// (measure_work), in the user's terms; empty when it is.
std::string over_measure_budget(const MeasureWork& work, double budget);

/// The skeleton file of `stage` meshed at its iso (skelconv's mesher, grid
/// method with facet size `size`, the input's diagonal /
/// options.measure_divisions when 0), over the bounding box of `surface`.
TriangleMesh mesh_stage(const TriangleMesh& surface, const Stage& stage, const ReconstructOptions& options,
                        double size = 0.0);

/// mesh_stage with its vertices not projected onto the surface
/// (MeshOptions::project): the same triangles, hence the same topology,
/// for a part of the work. project_stage_mesh (same arguments) turns it
/// into mesh_stage's mesh, to the bit.
TriangleMesh mesh_stage_unprojected(const TriangleMesh& surface, const Stage& stage, const ReconstructOptions& options,
                                    double size = 0.0);
void project_stage_mesh(TriangleMesh& mesh, const TriangleMesh& surface, const Stage& stage,
                        const ReconstructOptions& options, double size = 0.0);

/// mesh_stage, measured against `surface`. `mesh_out`, if given, receives the mesh.
/// Throws InputError (located at the stage's name) when the estimated work
/// exceeds options.measure_budget (over_measure_budget says why): callers
/// that measure every stage check first and skip that one.
SurfaceDistance measure_stage(const TriangleMesh& surface, const Stage& stage, const ReconstructOptions& options,
                              double size = 0.0, TriangleMesh* mesh_out = nullptr);

/// measure_stage at the default size, with the Euler characteristic of the
/// meshed surface and the time taken; `stage.measured` when it is set, and
/// `stage.meshed` measured (no meshing) when that is set.
/// Throws as measure_stage does.
StageMeasure measure(const TriangleMesh& surface, const Stage& stage, const ReconstructOptions& options);

}  // namespace skelconv::reconstruct
