#include "meshprep/pipeline/pipeline.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/core/mesh_patches.h"
#include "meshprep/core/user_size_demands.h"
#include "meshprep/fem/extrude.h"
#include "meshprep/fem/improve_tets.h"
#include "meshprep/fem/prepare_plc.h"
#include "meshprep/fem/quadratic.h"
#include "meshprep/fem/tet_boundary.h"
#include "meshprep/fem/tet_quality.h"
#include "meshprep/fem/tetrahedralize.h"
#include "meshprep/preprocess/compose/adaptive_reconstruction.h"
#include "meshprep/preprocess/enhance/enhance.h"
#include "meshprep/preprocess/patches/patches.h"
#include "meshprep/preprocess/reconstruct/reconstruct.h"
#include "meshprep/preprocess/compose/repair_solid.h"
#include "meshprep/preprocess/repair/repair.h"
#include "meshprep/preprocess/simplify/simplify.h"
#include "meshprep/preprocess/smooth/smooth.h"
#include "meshprep/quality/coincident_vertices.h"
#include "meshprep/quality/surface_distance.h"
#include "meshprep/quality/triangle_metrics.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <initializer_list>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <unordered_map>

namespace meshprep {
namespace {

// The enhancement's share of the time left when it starts, under a --time-limit.
constexpr double kEnhanceShareOfTimeLeft = 0.5;

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The keys of a stage's record (its Result's to_json) that the pipeline's summary keeps, in order.
nlohmann::ordered_json picked(const nlohmann::ordered_json& record, std::initializer_list<const char*> keys) {
  nlohmann::ordered_json kept;
  for (const char* key : keys) kept[key] = record.at(key);
  return kept;
}

// A figure for a one-line note: `digits` significant digits.
std::string figure(double value, int digits = 3) {
  std::ostringstream out;
  out << std::setprecision(digits) << value;
  return out.str();
}

class Run {
 public:
  Run(const std::string& input, const PipelineConfig& config, const PipelineObserver& observer,
      const PipelineInput* given = nullptr)
      : config_(config), observer_(observer), given_(given) {
    result_.input = input;
    result_.from_points = given ? given->points.has_value() : extension_of(input) == "xyz";
    stage_params_ = config.quality.params;
    stage_params_.distance_samples = std::max<std::size_t>(1000, config.quality.params.distance_samples / 5);
  }

  PipelineResult run() {
    const Clock::time_point start = Clock::now();
    try {
      if (result_.from_points) reconstruct();
      else check_input();
      patches_stage();
      input_self_intersections_ = result_.input_quality.self_intersections;
      simplify_stage();
      smooth_stage();
      enhance_stage();
      knife_edges_stage();
      quality_stage();
      tetrahedralize_stage();
      improve_stage();
      second_order_stage();
      refuse_flat_tets();
    } catch (const SolverError& e) {  // a stage could not do its work on this input: name the file
      throw PipelineFailed(result_.input + ": " + e.what());
    }
    if (result_.tets && result_.size_field)
      result_.size_conformity = measure_size_conformity(*result_.tets, *result_.size_field);
    deliver_verdict();  // judges the final tets: a stage that changes them goes before it
    result_.seconds = seconds_since(start);
    return std::move(result_);
  }

 private:
  void finish(StageRecord record) {
    if (observer_.stage_finished) observer_.stage_finished(record);
    result_.stages.push_back(std::move(record));
  }

  // A stage's result; what it cannot take (InvalidInput) named with the input file.
  template <class Stage>
  auto on_input(Stage&& stage) const -> decltype(stage()) {
    try {
      return stage();
    } catch (const InvalidInput& e) {
      throw InvalidInput(result_.input + ": " + e.what());
    }
  }

  // For the steps with nothing usable before their end (TetGen, the repair): the user's stop or the deadline.
  bool stop_or_deadline() const { return observer_.deadline.passed() || (observer_.cancelled && observer_.cancelled()); }

  // The user's stop ends the run anywhere; the deadline only until the tets exist (from there on the
  // improvement takes the time left, and the rest is finished).
  void stop_if_cancelled() const {
    if (observer_.cancelled && observer_.cancelled()) throw Cancelled(result_.input + ": stopped");
    if (!result_.tets && observer_.deadline.passed())
      throw TimeLimitReached(result_.input + ": time limit reached before the tets were made");
  }

  // A stage begins: the front end is told, and its record is opened on the current mesh.
  StageRecord started(const std::string& name) {
    stop_if_cancelled();
    if (observer_.stage_started) observer_.stage_started(name);
    StageRecord record;
    record.name = name;
    record.ran = true;
    record.faces_before = mesh_.n_faces();
    return record;
  }

  void skip(const std::string& name, const std::string& why) {
    StageRecord record;
    record.name = name;
    record.note = why;
    record.faces_before = record.faces_after = mesh_.n_faces();
    finish(std::move(record));
  }

  // The stages' progress callback: the front end's, and the safe point where a run stops.
  std::function<void(double)> progress() const {
    return [this](double fraction) {
      if (observer_.progress) observer_.progress(fraction);
      stop_if_cancelled();
    };
  }

  // The figures of the table row, from a report of the stage's output against the input surface.
  static void fill_shape(StageRecord& record, const QualityReport& report) {
    record.faces_after = report.faces;
    record.radius_ratio_mean = report.radius_ratio.mean;
    record.radius_ratio_p95 = report.radius_ratio.p95;
    record.faces_min_angle_below_20 = report.faces_min_angle_below_20;
    record.self_intersections = report.self_intersections;
    if (report.reference) {
      record.hausdorff_relative = report.reference->hausdorff_relative;
      record.volume_change_percent = report.reference->volume_change_percent;
    }
  }

  // Measures the mesh after a stage; a stage that made the surface cross itself stops the run.
  void measure(StageRecord& record) {
    const QualityReport report = analyze_quality(MeshSoupView(mesh_), stage_params_, &result_.input_surface);
    fill_shape(record, report);
    if (const std::size_t new_pairs = new_self_intersections(report, input_self_intersections_))
      throw PipelineFailed(result_.input + ": " + record.name + " made the surface intersect itself at " +
                           std::to_string(new_pairs) +
                           " more face pairs than the input; switch the stage off or change its settings");
  }

  void reconstruct() {
    StageRecord record = started("reconstruct");
    const PointSet points = given_ ? PointSet{*given_->points, {}} : read_points(result_.input);
    result_.input_points = points.points.size();
    const ReconstructParams& params = config_.reconstruct.params;
    const Clock::time_point start = Clock::now();
    ReconstructResult reconstruction;
    try {
      reconstruction = config_.reconstruct.adaptive ? reconstruct_adaptive(points.points, {params, progress()})
                                                    : reconstruct_surface(points.points, params);
    } catch (const InvalidInput& e) {
      throw InvalidInput(result_.input + ": " + e.what());
    }
    record.seconds = seconds_since(start);
    if (reconstruction.mesh.triangles.empty())
      throw PipelineFailed(result_.input + ": every triangle is farther than max_gap " +
                           std::to_string(reconstruction.max_gap) + " from the samples");
    record.details = {{"points", points.points.size()},
                      {"grid", {reconstruction.columns, reconstruction.rows}},
                      {"patches", reconstruction.patches},
                      {"grown_patches", reconstruction.grown_patches},
                      {"max_gap", reconstruction.max_gap},
                      {"gap_faces_left_out", reconstruction.gap_triangles},
                      {"filled_faces", reconstruction.filled_triangles}};
    record.taken_back = reconstruction.taken_back;
    result_.input_surface = std::move(reconstruction.mesh);
    mesh_ = mesh_from_soup(result_.input_surface);  // manifold by construction
    record.faces_before = mesh_.n_faces();
    result_.input_quality = analyze_quality(result_.input_surface, stage_params_);
    double filled_area = 0;
    for (const std::size_t f : reconstruction.filled_faces) filled_area += result_.input_quality.face_shapes[f].area;
    const double filled_fraction = filled_area / result_.input_quality.area;
    record.details["filled_area_fraction"] = filled_fraction;
    record.note = std::to_string(points.points.size()) + " points; " + std::to_string(reconstruction.gap_triangles) +
                  " faces left out outside the footprint";
    if (reconstruction.filled_triangles > 0)
      record.note += "; " + std::to_string(reconstruction.filled_triangles) +
                     " faces over holes in the data kept and flagged (" + figure(100 * filled_fraction, 2) +
                     " % of the area)";
    fill_shape(record, result_.input_quality);
    finish(std::move(record));
  }

  // By default the repair leaves an open sheet's outline open (a terrain is no solid's hole), and
  // the check extrudes such a sheet into a block. A sheet that is no height field over an axis (a
  // dome, a bowl) cannot be extruded: when tets are wanted and the repair's default left one such
  // outline open, it is filled after all (the repair again, every loop filled), and said so.
  // Several sheets (stacked horizons) stay refused: their lids would cut through each other.
  bool close_sheet(TriangleSoup& soup, RepairResult& r) {
    if (!config_.tetrahedralize.enabled || config_.repair.params.max_hole) return false;
    try {
      extrude_to_block(soup, 1);
      return false;
    } catch (const InvalidInput&) {
    }
    RepairParams every_loop = config_.repair.params;
    every_loop.max_hole = std::numeric_limits<double>::infinity();
    every_loop.fidelity_bound = fidelity_bound();
    const RepairResult closing = on_input([&] { return repair_solid(soup, every_loop); });
    r.holes.erase(std::remove_if(r.holes.begin(), r.holes.end(), [](const RepairHole& h) { return !h.filled; }),
                  r.holes.end());
    r.holes.insert(r.holes.end(), closing.holes.begin(), closing.holes.end());
    r.filled_holes += closing.filled_holes;
    r.open_holes = closing.open_holes;
    r.intersecting_pairs += closing.intersecting_pairs;
    r.cut_faces += closing.cut_faces;
    r.removed_faces += closing.removed_faces;
    r.separated_pinches += closing.separated_pinches;
    if (closing.envelope) {
      r.route = closing.route;
      r.envelope = closing.envelope;
    }
    r.seconds += closing.seconds;
    return true;
  }

  // The input read as a soup and repaired (repair.h); its row comes before the check's, which
  // takes over `report` (the repaired surface's, measured once for both rows).
  LoadedMesh repaired_input(QualityReport& report) {
    StageRecord record = started("repair");
    LoadedMesh loaded;
    loaded.soup = given_ ? *given_->surface : read_soup(result_.input, &loaded.read);
    record.faces_before = loaded.soup.triangles.size();
    RepairParams params = config_.repair.params;
    params.fidelity_bound = fidelity_bound();
    params.cancelled = [this] { return stop_or_deadline(); };
    RepairResult r = on_input([&] {
      try {
        return repair_solid(loaded.soup, params);
      } catch (const Cancelled&) {
        stop_if_cancelled();  // the user's stop or the deadline, said as such
        throw;
      }
    });
    // A closed input stays a solid: the terrain rule (an open sheet extruded into a block) is for
    // sheets the file holds, never for what the repair left open of a solid.
    if (r.input_closed && r.open_holes > 0)
      throw PipelineFailed(result_.input + ": the repair left " + std::to_string(r.open_holes) +
                           " holes open in a closed input (" + std::to_string(r.removed_faces) +
                           " pieces removed where faces cross); nothing is written");
    const bool outline_filled = r.open_holes == 1 && close_sheet(loaded.soup, r);
    envelope_ = r.envelope;
    loaded.mesh = mesh_from_soup(loaded.soup, &loaded.build);
    record.seconds = r.seconds;
    report = analyze_quality(loaded.soup, stage_params_);
    fill_shape(record, report);
    record.details = picked(to_json(r), {"input_closed", "welded_vertices", "degenerate_faces", "duplicate_faces",
                                         "t_junction_splits", "split_edges", "split_vertices", "dropped_lone_faces",
                                         "flipped_faces", "inverted_components", "filled_holes",
                                         "open_holes", "holes", "intersecting_pairs", "cut_faces", "removed_faces",
                                         "nested_components", "cavities", "separated_pinches", "route", "envelope"});
    record.note = std::to_string(r.welded_vertices) + " vertices welded, " +
                  std::to_string(r.degenerate_faces + r.duplicate_faces) + " faces removed, " +
                  std::to_string(r.split_edges + r.split_vertices) + " non-manifold edges and vertices split, " +
                  std::to_string(r.flipped_faces) + " flipped, " + std::to_string(r.filled_holes) + " holes filled (" +
                  std::to_string(r.open_holes) + " left open), " + std::to_string(r.intersecting_pairs) +
                  " crossing face pairs cut (" + std::to_string(r.removed_faces) + " pieces inside removed, " +
                  std::to_string(r.nested_components) + " nested parts dropped)" + envelope_summary(r) +
                  (outline_filled ? "; an open sheet's outline filled: it is no height field to extrude" : "");
    finish(std::move(record));
    return loaded;
  }

  // The surface given in memory, as load_mesh would have read it from a file.
  LoadedMesh given_surface() const {
    LoadedMesh loaded;
    loaded.soup = *given_->surface;
    loaded.read.path = result_.input;
    loaded.mesh = mesh_from_soup(loaded.soup, &loaded.build);
    return loaded;
  }

  void check_input() {
    std::optional<LoadedMesh> repaired;
    QualityReport repaired_report;
    if (config_.repair.enabled) repaired = repaired_input(repaired_report);
    StageRecord record = started("check");
    const Clock::time_point start = Clock::now();
    LoadedMesh loaded = repaired ? std::move(*repaired) : given_ ? given_surface() : load_mesh(result_.input);
    require_all_faces(loaded, "the pipeline");
    result_.input_surface = std::move(loaded.soup);
    mesh_ = std::move(loaded.mesh);
    record.faces_before = record.faces_after = mesh_.n_faces();
    result_.input_quality =
        repaired ? std::move(repaired_report) : analyze_quality(result_.input_surface, stage_params_);
    const QualityReport& report = result_.input_quality;
    record.seconds = seconds_since(start);
    fill_shape(record, report);
    record.details = {{"closed", report.closed},
                      {"manifold", report.manifold},
                      {"genus", report.genus ? nlohmann::ordered_json(*report.genus) : nlohmann::ordered_json(nullptr)},
                      {"border_edges", report.border_edges},
                      {"degenerate_faces", report.degenerate_faces},
                      {"self_intersections", report.self_intersections}};
    record.note = std::string(report.closed ? "closed" : "open") + ", manifold" +
                  (report.genus ? ", genus " + std::to_string(*report.genus) : std::string()) + ", " +
                  std::to_string(report.self_intersections) + " self-intersecting face pairs";
    finish(std::move(record));
    if (!config_.tetrahedralize.enabled) return;
    // What no later stage can mend is refused before any work is done, as bad input (exit 2); after
    // --repair it is what the repair could not mend (exit 3), and the advice to repair goes.
    const auto refuse = [&](const std::string& what, const std::string& advice) {
      if (repaired)
        throw PipelineFailed(result_.input + ": the repair could not mend the surface: " + what + "; nothing is written");
      throw InvalidInput(result_.input + ": not FEM-ready: " + what + advice);
    };
    // Split vertices first: they open every seam and make touching faces count as crossings, so
    // the figures would mislead.
    if (report.self_intersections > 0 || !report.closed)
      if (const std::size_t merged = find_coincident_vertices(result_.input_surface).merged)
        refuse(std::to_string(merged) + " vertices lie exactly on another vertex",
               ": the file splits its vertices (as VTK's normals filter writes them), so its faces are not connected; "
               "weld them first (--repair)");
    // Simplification may remove crossings (its collapses merge the crossing faces); if it runs,
    // the final surface's readiness check judges what is left.
    if (report.self_intersections > 0 && !simplifies())
      refuse("the surface intersects itself at " + std::to_string(report.self_intersections) +
                 " face pairs (meshprep quality lists them)",
             ", which the stages that run do not remove (simplification may: give --ratio or --target-faces); repair "
             "the surface first (--repair cuts the crossings and keeps the solid's outer surface), or switch "
             "tetrahedralize off to process the surface only");
    if (!report.closed) {
      try {
        extrude_to_block(result_.input_surface, 1);
      } catch (const InvalidInput& e) {
        refuse("the surface is open (" + std::to_string(report.border_edges) +
                   " border edges) and cannot be closed into a block (" + e.what() + ")",
               "; fill its holes first (--repair; repair.max_hole sets the longest rim filled), or switch tetrahedralize "
               "off to process the surface only");
      }
    }
  }

  // The boundary patches of the input surface (the file's, else the creases'), edited as asked,
  // given to the halfedge mesh the stages work on: they carry them to the tets.
  void patches_stage() {
    StageRecord record = started("patches");
    PatchParams params = config_.patches.params;
    if (!params.feature_angle_deg) params.feature_angle_deg = config_.enhance.params.feature_angle_deg;
    const Clock::time_point start = Clock::now();
    const PatchResult r = on_input([&] { return find_patches(result_.input_surface, params); });
    set_face_patches(mesh_, result_.input_surface.patches, result_.input_surface.patch_names);
    // A size asked for a patch the surface does not have is a typo to name now, not after the work.
    on_input([&] { return patch_size_demands(config_.size, result_.input_surface, result_.input_quality.bbox_diagonal); });
    record.seconds = seconds_since(start);
    fill_shape(record, result_.input_quality);
    record.details = to_json(r);
    record.note = std::to_string(r.patches) + (r.patches == 1 ? " patch" : " patches") +
                  (r.segmented ? ", bounded by the creases sharper than " + figure(r.feature_angle_deg) + " deg"
                               : ", named by the file");
    if (r.merged) record.note += ", " + std::to_string(r.merged) + " merged";
    if (!r.renamed.empty()) record.note += ", " + std::to_string(r.renamed.size()) + " renamed";
    finish(std::move(record));
  }

  // Whether the simplify stage runs: switched on, with a target (points always have one).
  bool simplifies() const {
    const PipelineConfig::Simplify& c = config_.simplify;
    return c.enabled && (c.params.target_faces != 0 || c.ratio.has_value() || result_.from_points);
  }

  void simplify_stage() {
    const PipelineConfig::Simplify& c = config_.simplify;
    if (!c.enabled) return skip("simplify", "switched off");
    const bool has_ratio = c.ratio.has_value() || result_.from_points;
    if (!simplifies()) return skip("simplify", "no target for a mesh input (give --ratio or --target-faces)");
    StageRecord record = started("simplify");
    SimplifyParams params = c.params;
    params.keep_ratio = c.ratio ? *c.ratio : has_ratio ? PipelineConfig::Simplify::kTerrainRatio : 1.0;
    params.progress = progress();
    const SimplifyResult s = on_input([&] { return simplify(mesh_, params); });
    record.seconds = s.seconds;
    record.details =
        picked(to_json(s), {"target_faces", "reached_target", "collapses", "intersection_retries", "stuck_restarts"});
    if (!s.reached_target) record.note = "target " + std::to_string(s.target_faces) + " faces not reached";
    record.taken_back = s.taken_back;
    measure(record);
    finish(std::move(record));
  }

  void smooth_stage() {
    if (!config_.smooth.enabled) return skip("smooth", "switched off (the default: the stage removes noise)");
    StageRecord record = started("smooth");
    SmoothParams params = config_.smooth.params;
    params.progress = progress();
    const SmoothResult s = on_input([&] { return smooth(mesh_, params); });
    record.seconds = s.seconds;
    record.details = {{"iterations", s.iterations},
                      {"max_displacement", s.max_displacement},
                      {"feature_line_vertices", s.feature_line_vertices},
                      {"corner_vertices", s.corner_vertices}};
    record.note = std::to_string(s.iterations) + " iteration(s)";
    record.taken_back = s.taken_back;
    measure(record);
    finish(std::move(record));
  }

  void enhance_stage() {
    if (!config_.enhance.enabled) return skip("enhance", "switched off");
    StageRecord record = started("enhance");
    EnhanceParams params = config_.enhance.params;
    params.size = config_.size;
    params.progress = progress();
    // Anytime: it ends with its best rounds at its own limit or at half the run's time left, so that
    // the report, TetGen and the improvement still have the other half.
    params.deadline = observer_.deadline.share(kEnhanceShareOfTimeLeft);
    const EnhanceResult e = on_input([&] { return enhance(mesh_, &result_.input_surface, params); });
    result_.enhance_stopped_by_time_limit = e.stopped_by_time_limit;
    if (config_.size.any_set()) result_.size_field = e.size_field;
    record.seconds = e.seconds;
    record.details = picked(to_json(e, params),
                            {"rounds", "kept_round", "flips", "cap_flips", "removed_vertices", "split_edges", "stopped"});
    record.details["smallest_angle_before_deg"] = e.before.min_angle_deg;
    record.details["smallest_angle_after_deg"] = e.after.min_angle_deg;
    record.note = std::to_string(e.kept_round) + " round(s) kept, " + std::to_string(e.flips) + " flips";
    if (e.cap_flips > 0) record.note += ", " + std::to_string(e.cap_flips) + " cap(s) flipped";
    record.taken_back = e.taken_back;
    measure(record);
    finish(std::move(record));
  }

  // Where the final surface itself caps the tets below the improvement's goal (a thin wedge at an
  // edge), a local edit within the fidelity bound opens it (knife_edges.h); before the quality
  // stage, so that the final surface's distance from the input counts it.
  void knife_edges_stage() {
    if (!config_.knife_edges.enabled) return skip("knife_edges", "switched off");
    if (!config_.tetrahedralize.enabled) return skip("knife_edges", "no tets to make");
    for (const auto h : mesh_.halfedges())
      if (mesh_.is_boundary(h)) return skip("knife_edges", "the surface is open (a terrain's block has no knife edge of its own)");
    StageRecord record = started("knife_edges");
    // Opened for the improvement's goals, but never past the default's: a goal past it is
    // climbed from the default's tets (improve_tets.h), which must be those of the default run's
    // surface for the climb to end no worse. Opened for 20 deg, elephant-with-holes' surface gave
    // 1.9 deg tets where the default's gives 6.7.
    const ImproveParams floor_goals;
    KnifeEdgeParams params;
    params.goal_min_dihedral_deg = std::min(config_.improve.params.goal_min_dihedral_deg, floor_goals.goal_min_dihedral_deg);
    params.goal_max_dihedral_deg = std::max(config_.improve.params.goal_max_dihedral_deg, floor_goals.goal_max_dihedral_deg);
    params.max_deviation = fidelity_bound() *
                           result_.input_quality.bbox_diagonal;
    const KnifeEdgeResult r = open_knife_edges(mesh_, result_.input_surface, params);
    record.seconds = r.seconds;
    record.details = to_json(r);
    const double diagonal = result_.input_quality.bbox_diagonal;
    if (r.knife_edges_before == 0) {
      record.note = "none: no edge or face of the surface caps the tets below " + figure(params.goal_min_dihedral_deg) + " deg";
    } else {
      const std::size_t flips = static_cast<std::size_t>(std::count_if(
          r.edits.begin(), r.edits.end(), [](const KnifeEdgePlace& e) { return std::string(e.edit) == "flip"; }));
      record.note = std::to_string(flips) + " flip(s), " + std::to_string(r.edits.size() - flips) +
                    " collapse(s), the largest move " + figure(r.max_displacement / diagonal) +
                    " of the diagonal; knife edges, caps and short edges " + std::to_string(r.knife_edges_before) +
                    " -> " + std::to_string(r.knife_edges_after) + ", the surface's bound " +
                    figure(r.surface_bound_before_deg) + " -> " + figure(r.surface_bound_after_deg) + " deg";
    }
    result_.knife_edges = r;
    measure(record);
    finish(std::move(record));
  }

  void quality_stage() {
    StageRecord record = started("quality");
    result_.surface = soup_from_mesh(mesh_);
    record.faces_before = result_.surface.triangles.size();
    const Clock::time_point start = Clock::now();
    result_.final_quality = analyze_quality(result_.surface, config_.quality.params, &result_.input_surface);
    record.seconds = seconds_since(start);
    fill_shape(record, result_.final_quality);
    record.note = "the final surface against the input, " + std::to_string(result_.final_quality.reference->samples) +
                  " samples per direction";
    finish(std::move(record));
  }

  // The final surface as TetGen's input (prepare_plc.h): checked when closed, extruded into a block
  // when open.
  std::optional<SurfacePlc> prepare_tet_input(StageRecord& record) {
    std::optional<double> depth;
    if (!result_.final_quality.closed) {
      const PipelineConfig::Tetrahedralize& c = config_.tetrahedralize;
      depth = c.extrude_base > 0 ? c.extrude_base : c.extrude_base_relative * result_.final_quality.bbox_diagonal;
      record.details["extrude_base_depth"] = *depth;
    }
    PreparedPlc prepared = prepare_plc(result_.surface, depth);
    result_.readiness = prepared.readiness;
    if (result_.readiness)
      for (const ReadinessProblem& p : result_.readiness->problems) result_.fem.problems.push_back(p.what + "; " + p.hint);
    if (!prepared.extrusion_problem.empty())
      result_.fem.problems.push_back("the open surface cannot be closed into a block: " + prepared.extrusion_problem);
    if (depth && prepared.plc) result_.extrusion_depth = depth;
    return std::move(prepared.plc);
  }

  void tetrahedralize_stage() {
    if (!config_.tetrahedralize.enabled) return skip("tetrahedralize", "switched off");
    StageRecord record = started("tetrahedralize");
    record.faces_before = record.faces_after = result_.surface.triangles.size();
    fill_shape(record, result_.final_quality);
    const Clock::time_point start = Clock::now();
    TetParams params = config_.tetrahedralize.params;
    double volume_change = 0;
    if (std::optional<SurfacePlc> plc = prepare_tet_input(record)) {
      params.keep_surface = config_.tetrahedralize.keep_surface.value_or(!result_.extrusion_depth);
      if (config_.size.any_set() && !result_.size_field)
        result_.size_field = on_input([&] { return user_size_field(config_.size, result_.surface); });
      params.size_field = result_.size_field;
      params.cancelled = [this] { return stop_or_deadline(); };
      try {
        result_.tets = tetrahedralize_plc(*plc, params);
        volume_change = volume_change_relative(*plc, *result_.tets);
      } catch (const TetgenError& e) {
        result_.fem.problems.push_back(std::string("TetGen: ") + e.what());
      } catch (const Cancelled&) {
        stop_if_cancelled();  // the user's stop or the deadline, said as such
        throw;
      }
    }
    record.seconds = seconds_since(start);
    if (result_.tets) {
      result_.tet_quality = analyze_tet_quality(*result_.tets);
      result_.tetgen_switches = tetgen_switches(params, result_.tet_quality->volume);
      const TetQualityReport& q = *result_.tet_quality;
      record.details = {{"tets", q.tetrahedra},
                        {"points", q.points},
                        {"volume", q.volume},
                        {"volume_change_relative", volume_change},
                        {"min_dihedral_deg", q.min_dihedral_deg.min},
                        {"switches", result_.tetgen_switches}};
      record.note = std::to_string(q.tetrahedra) + " tets, smallest dihedral " +
                    figure(q.min_dihedral_deg.min) + " deg";
      if (const std::string note = volume_change_note(volume_change); !note.empty()) record.note += "; " + note;
    } else {
      record.note = "not FEM-ready: " + result_.fem.problems.front();
    }
    finish(std::move(record));
  }

  // Tets flat to rounding that the improvement could not remove (or that it did not run to
  // remove) cannot be written: no solver takes them (certainly_positive, tet_quality.h).
  void refuse_flat_tets() const {
    if (!result_.tets) return;
    const std::string flat = describe_flat_tets(*result_.tets);
    if (!flat.empty())
      throw PipelineFailed(result_.input + ": " + flat + "; a solver cannot take such tets" +
                           (config_.improve.enabled ? "" : " (the improvement, switched off, removes those on the boundary)") +
                           "; nothing is written");
  }

  // The verdict on the final tets (result_.tets, described by result_.tet_quality): FEM-ready when
  // they exist and meet every threshold of the configuration's verdict section.
  void improve_stage() {
    if (!config_.improve.enabled) return skip("improve", "switched off");
    if (!result_.tets) return skip("improve", "no tets to improve");
    StageRecord record = started("improve");
    record.faces_before = record.faces_after = result_.surface.triangles.size();
    fill_shape(record, result_.final_quality);
    ImproveParams params = config_.improve.params;
    params.progress = progress();
    params.cancelled = observer_.cancelled;
    params.deadline = observer_.deadline;
    // The boundary may slide (improve.boundary_deviation): the final surface follows it, and the
    // slides are taken back if the surface then leaves the fidelity bound (the deviation is sampled).
    std::vector<std::uint32_t> surface_in_tets;
    std::optional<TetMesh> unslid;
    params.boundary_deviation = 0;
    if (config_.improve.params.boundary_deviation.value_or(1) > 0) {
      surface_in_tets = surface_points_in_tets();
      params.boundary_deviation = boundary_deviation(surface_in_tets);
      if (*params.boundary_deviation > 0) unslid = *result_.tets;
    }
    ImproveResult r = improve_tets(*result_.tets, params);
    std::optional<SlidSurface> slid;
    if (r.boundary_vertex_moves > 0) {
      slid = slid_surface(surface_in_tets);
      const double bound = fidelity_bound();
      if (slid->hausdorff_after > bound && slid->hausdorff_before <= bound) {
        TakenBack taken{"improve", "fidelity bound", "boundary slides", r.boundary_vertex_moves,
                        "the slides moved the surface past the fidelity bound (" + figure(bound) +
                            " of the diagonal); the tets are improved again with the boundary kept",
                        {{"hausdorff_relative", slid->hausdorff_after}, {"min_dihedral_deg", r.min_dihedral_after_deg}},
                        {}};
        slid.reset();
        *result_.tets = std::move(*unslid);
        params.boundary_deviation = 0;
        r = improve_tets(*result_.tets, params);
        taken.after = {{"hausdorff_relative", result_.final_quality.reference->hausdorff_relative},
                       {"min_dihedral_deg", r.min_dihedral_after_deg}};
        r.taken_back.push_back(std::move(taken));
      }
    }
    record.seconds = r.seconds;
    record.details = to_json(r);
    record.details["boundary_deviation"] = *params.boundary_deviation;
    if (r.passes > 0) {
      result_.tetgen_quality = std::move(result_.tet_quality);
      result_.tet_quality = analyze_tet_quality(*result_.tets);
    }

    record.note = "smallest dihedral " + figure(r.min_dihedral_before_deg) + " -> " + figure(r.min_dihedral_after_deg) +
                  " deg, largest " + figure(r.max_dihedral_before_deg) + " -> " + figure(r.max_dihedral_after_deg) +
                  " deg (" + r.stopped_by + ")";
    if (r.flat_boundary_tets_removed > 0)
      record.note += "; " + std::to_string(r.flat_boundary_tets_removed) +
                     " flat tet(s) on the boundary removed (its triangles flipped in their plane)";
    const std::string limit = surface_limit_note(r, params.goal_min_dihedral_deg);
    if (!limit.empty()) record.note += "; " + limit;
    if (slid) {
      record.details["surface_hausdorff_relative_before"] = slid->hausdorff_before;
      record.details["surface_hausdorff_relative_after"] = slid->hausdorff_after;
      record.note += "; " + std::to_string(r.boundary_vertex_moves) + " boundary vertex slide(s), the farthest " +
                     figure(r.boundary_max_displacement_relative) + " of the diagonal; the surface's distance from the input " +
                     figure(slid->hausdorff_before) + " -> " + figure(slid->hausdorff_after) + " of the diagonal";
      result_.surface = std::move(slid->surface);
      result_.final_quality = std::move(slid->quality);
    }
    record.taken_back = r.taken_back;
    result_.improvement = r;
    finish(std::move(record));
  }

  // For each point of the final surface, the tet point at the same place (kNotInTets if none).
  static constexpr std::uint32_t kNotInTets = ~std::uint32_t(0);
  std::vector<std::uint32_t> surface_points_in_tets() const {
    struct PlaceHash {
      std::size_t operator()(const std::array<double, 3>& p) const {
        std::size_t h = 0;
        for (const double x : p) h = h * 0x9E3779B97F4A7C15ull ^ std::hash<double>()(x);
        return h;
      }
    };
    std::unordered_map<std::array<double, 3>, std::uint32_t, PlaceHash> at;
    at.reserve(result_.tets->points.size());
    for (std::size_t i = 0; i < result_.tets->points.size(); ++i) {
      const Vec3& p = result_.tets->points[i];
      at.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, static_cast<std::uint32_t>(i));
    }
    std::vector<std::uint32_t> in_tets(result_.surface.points.size(), kNotInTets);
    for (std::size_t i = 0; i < in_tets.size(); ++i) {
      const Vec3& p = result_.surface.points[i];
      const auto found = at.find({p.x(), p.y(), p.z()});
      if (found != at.end()) in_tets[i] = found->second;
    }
    return in_tets;
  }

  // How far the improvement may slide the boundary, relative to the tets' diagonal: the set value,
  // or (auto) a share of what the fidelity bound leaves after the surface stages. None when a point
  // of the final surface is not among the tets' (it could not follow).
  double boundary_deviation(const std::vector<std::uint32_t>& surface_in_tets) const {
    if (config_.improve.params.boundary_deviation) return *config_.improve.params.boundary_deviation;
    for (const Triangle& t : result_.surface.triangles)
      for (const std::uint32_t i : t)
        if (surface_in_tets[i] == kNotInTets) return 0;
    Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
    for (const Vec3& p : result_.tets->points) low = low.cwiseMin(p), high = high.cwiseMax(p);
    const double tets_diagonal = result_.tets->points.empty() ? 0.0 : (high - low).norm();
    if (!result_.final_quality.reference) return 0;
    const double used = result_.final_quality.reference->hausdorff_relative;
    const double left = std::max(0.0, fidelity_bound() - used) * result_.input_quality.bbox_diagonal;
    return tets_diagonal > 0 ? kBoundaryShareOfFidelityLeft * left / tets_diagonal : 0;
  }

  // The final surface with the places the improvement slid its vertices to, measured again (its
  // distance from the input, its faces), so that the report describes the tets' boundary.
  struct SlidSurface {
    TriangleSoup surface;
    QualityReport quality;
    double hausdorff_before = 0, hausdorff_after = 0;  ///< from the input, relative to its diagonal
  };
  SlidSurface slid_surface(const std::vector<std::uint32_t>& surface_in_tets) const {
    SlidSurface slid{result_.surface, {}, 0, 0};
    for (std::size_t i = 0; i < surface_in_tets.size(); ++i)
      if (surface_in_tets[i] != kNotInTets) slid.surface.points[i] = result_.tets->points[surface_in_tets[i]];
    slid.quality = analyze_quality(slid.surface, config_.quality.params, &result_.input_surface);
    slid.hausdorff_before = result_.final_quality.reference->hausdorff_relative;
    slid.hausdorff_after = slid.quality.reference->hausdorff_relative;
    return slid;
  }

  // tetrahedralize.order 2: the final tets made second-order, the boundary's nodes onto the input
  // surface (what every stage is measured against), after the improvement, which moves linear
  // tets. A stage only when asked for: order 1 is the tets as they are.
  void second_order_stage() {
    if (config_.tetrahedralize.element_order.order != 2 || !result_.tets) return;
    StageRecord record = started("second_order");
    record.faces_before = record.faces_after = result_.surface.triangles.size();
    fill_shape(record, result_.final_quality);
    const TriangleSoup& reference = result_.input_surface;
    DistanceParams distance;
    distance.samples = stage_params_.distance_samples;
    const double diagonal = bbox_diagonal(reference);
    SecondOrderRecord r;
    r.hausdorff_linear_relative = surface_distance(boundary_surface(*result_.tets), reference, distance).hausdorff() / diagonal;
    r.quadratic = on_input([&] { return make_quadratic(*result_.tets, &reference); });
    // 4 steps per edge: a curved face's chord error is then 1/16 of its nodes' offset.
    r.hausdorff_second_order_relative =
        surface_distance(quadratic_boundary(*result_.tets, 4), reference, distance).hausdorff() / diagonal;
    result_.tet_quality = analyze_tet_quality(*result_.tets);
    record.seconds = r.quadratic.seconds;
    record.details = to_json(r);
    record.note = std::to_string(r.quadratic.curved_edges) + " boundary edges curved, " +
                  std::to_string(r.quadratic.straight_inverting) + " left straight (a tet would fold); Hausdorff to the input " +
                  figure(100 * r.hausdorff_linear_relative) + " -> " + figure(100 * r.hausdorff_second_order_relative) +
                  " % of the diagonal";
    record.taken_back = r.quadratic.taken_back;
    result_.second_order = r;
    finish(std::move(record));
  }

  void deliver_verdict() {
    if (result_.tet_quality) {
      const TetVerdict verdict = judge_tets(*result_.tet_quality, config_.verdict);
      result_.fem.checks = verdict.checks;
      for (const ThresholdCheck& c : verdict.failed()) {
        std::string problem = describe(c);
        // Why the smallest angle cannot pass with this surface, if it cannot.
        const std::string limit =
            c.check == "min_dihedral_deg" && result_.improvement ? surface_limit_note(*result_.improvement, c.threshold) : "";
        result_.fem.problems.push_back(limit.empty() ? problem : problem + "; " + limit);
      }
    }
    // The stages after the repair hold the surface to the repaired one: what the envelope route
    // moved it from the input is the repair's to judge.
    if (envelope_ && envelope_->distance_max > envelope_->bound)
      result_.fem.problems.push_back(
          "the repair's envelope route moved the surface up to " + figure(envelope_->distance_max) +
          " of the diagonal from the input (bound " + figure(envelope_->bound) + "; the repair row lists the places)" +
          "; a finer grid (repair.envelope_cells) comes closer, or allow more with enhance.max_deviation");
    result_.fem.ready = result_.tets.has_value() && result_.fem.problems.empty();
  }

  // The share of what the fidelity bound leaves that the improvement's boundary slides may take:
  // their deviation is sampled (boundary_slides.h), the final surface measured again after them.
  static constexpr double kBoundaryShareOfFidelityLeft = 0.5;

  // How far the surface may move from the input, as a fraction of its diagonal: the enhancement's
  // bound, which the knife-edge stage and the repair's envelope route answer to as well.
  double fidelity_bound() const {
    return config_.enhance.params.max_deviation.value_or(EnhanceParams::kLargestAutoDeviation);
  }

  const PipelineConfig& config_;
  const PipelineObserver& observer_;
  QualityParams stage_params_;
  PipelineResult result_;
  TriMesh mesh_;
  std::size_t input_self_intersections_ = 0;
  const PipelineInput* given_;  ///< the input in memory, or null: the file result_.input
  std::optional<RepairEnvelope> envelope_;  ///< what the repair's envelope route did, if it ran
};

}  // namespace

PipelineResult run_pipeline(const std::string& input, const PipelineConfig& config, const PipelineObserver& observer) {
  check_config(config);  // before any work, whoever built the configuration
  return Run(input, config, observer).run();
}

PipelineResult run_pipeline(const PipelineInput& input, const PipelineConfig& config, const PipelineObserver& observer) {
  if (input.surface.has_value() == input.points.has_value())
    throw InvalidInput(input.name + ": give the pipeline a surface or points, not " + (input.surface ? "both" : "neither"));
  check_config(config);
  return Run(input.name, config, observer, &input).run();
}

}  // namespace meshprep
