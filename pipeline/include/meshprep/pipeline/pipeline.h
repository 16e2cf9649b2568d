#pragma once
/// \file pipeline.h
/// From raw input to an FEM-ready tetrahedral mesh and its report, in one call (the stages of
/// the paper, chained):
/// - points (.xyz): reconstruct -> simplify -> smooth -> enhance -> quality -> tetrahedralize (the
///   terrain closed into a block) -> improve;
/// - a surface mesh: check -> simplify -> smooth -> enhance -> quality -> tetrahedralize -> improve.
///
/// Every stage is measured against the pipeline's input surface (the mesh read, or the
/// reconstruction): faces, Hausdorff distance, volume change, triangle shape, time. A stage that
/// would make the surface cross itself is an error, never a silent result. write_pipeline_outputs
/// (pipeline_outputs.h) turns the result into files.

#include "meshprep/core/deadline.h"
#include "meshprep/core/mesh.h"
#include "meshprep/core/taken_back.h"
#include "meshprep/fem/fem_verdict.h"
#include "meshprep/fem/improve_tets.h"
#include "meshprep/fem/knife_edges.h"
#include "meshprep/fem/quadratic.h"
#include "meshprep/fem/readiness.h"
#include "meshprep/fem/size_conformity.h"
#include "meshprep/fem/tet_mesh.h"
#include "meshprep/fem/tet_quality.h"
#include "meshprep/pipeline/pipeline_config.h"
#include "meshprep/quality/report.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace meshprep {

/// What one stage did, measured on its output against the pipeline's input surface.
struct StageRecord {
  std::string name;            ///< reconstruct, repair, check, patches, simplify, smooth, enhance, quality, tetrahedralize, improve
  bool ran = false;            ///< false: switched off or nothing to do (see note)
  std::string note;            ///< one line: why it was skipped, or what it found
  double seconds = 0;          ///< the stage's own work (not the measurement)
  std::size_t faces_before = 0, faces_after = 0;
  std::optional<double> hausdorff_relative;     ///< to the input surface, / its bounding-box diagonal
  std::optional<double> volume_change_percent;  ///< closed surfaces
  double radius_ratio_mean = 0, radius_ratio_p95 = 0;
  double faces_min_angle_below_20 = 0;  ///< fraction
  std::size_t self_intersections = 0;
  nlohmann::ordered_json details = nlohmann::ordered_json::object();  ///< the stage's own figures
  std::vector<TakenBack> taken_back;  ///< work the stage's guards took back (taken_back.h)
};

/// Whether the final tets are FEM-ready, and why not.
struct FemVerdict {
  /// Tets were made from a valid surface and meet every threshold (PipelineConfig::verdict).
  bool ready = false;
  /// One line each when not ready: a problem of the surface, TetGen's refusal, or a failed
  /// threshold (describe(ThresholdCheck)).
  std::vector<std::string> problems;
  /// Every threshold beside its figure; empty when no tets were made.
  std::vector<ThresholdCheck> checks;
};

/// What making the final tets second-order did (tetrahedralize.order 2), and the boundary's
/// Hausdorff distance to input_surface before (the linear boundary) and after (the curved one,
/// sampled), over input_surface's bounding-box diagonal.
struct SecondOrderRecord {
  QuadraticResult quadratic;
  double hausdorff_linear_relative = 0;
  double hausdorff_second_order_relative = 0;
};

/// {"hausdorff_linear_relative", "hausdorff_second_order_relative", then quadratic.h's figures}.
nlohmann::ordered_json to_json(const SecondOrderRecord& record);

struct PipelineResult {
  std::string input;             ///< the input path
  bool from_points = false;      ///< the input was a point set
  std::size_t input_points = 0;  ///< points read (point input)
  TriangleSoup input_surface;    ///< the mesh read, or the reconstruction: every stage is measured against it
  TriangleSoup surface;          ///< the final surface
  QualityReport input_quality;   ///< of input_surface (no reference)
  QualityReport final_quality;   ///< of surface, against input_surface
  std::vector<StageRecord> stages;
  std::optional<TetMesh> tets;                 ///< the final tets
  std::optional<TetQualityReport> tet_quality;  ///< of the final tets (improved, when the stage ran)
  std::optional<TetQualityReport> tetgen_quality;  ///< of TetGen's own tets, when the improvement changed them
  std::optional<ImproveResult> improvement;  ///< of `tets`: what the verdict judges
  std::optional<KnifeEdgeResult> knife_edges;  ///< the knife_edges stage's edits and what it left, when it ran
  bool enhance_stopped_by_time_limit = false;  ///< the enhancement ended at its time limit (its best rounds kept)
  std::optional<SecondOrderRecord> second_order;  ///< tetrahedralize.order 2: the tets made second-order
  std::optional<Readiness> readiness;  ///< of the final surface (closed surfaces)
  std::optional<double> extrusion_depth;  ///< an open surface closed into a block: its base's depth
  std::string tetgen_switches;
  /// With a size set (PipelineConfig::size): the field the tets followed, and how well they did.
  std::shared_ptr<const SizeField> size_field;
  std::optional<SizeConformity> size_conformity;
  FemVerdict fem;
  double seconds = 0;            ///< the whole run
};

/// Hooks for a front end; every member may be empty. Called from the calling thread.
struct PipelineObserver {
  std::function<void(const std::string& stage)> stage_started;
  std::function<void(double fraction)> progress;  ///< within the current stage, in [0, 1]
  std::function<void(const StageRecord&)> stage_finished;
  /// Asked at every stage's start, at every progress report and every 50 ms while TetGen runs;
  /// true stops the run at that point (run_pipeline throws Cancelled).
  std::function<bool()> cancelled;
  /// The whole run's deadline: until the tets exist, passing it stops the run (TimeLimitReached);
  /// the improvement then takes the time left as its time limit and ends with its best tets.
  Deadline deadline;
};

/// Run the pipeline on the file `input` (.xyz points, or a surface mesh).
/// \throws InvalidInput for an unreadable, malformed or non-manifold input, or one no stage that
///         runs can make FEM-ready (split vertices, crossings, an open surface that is no height
///         field; the message names the file); IoError if unreadable; PipelineFailed when the work
///         cannot be done (a stage made the surface cross itself, the repair left holes); Cancelled
///         when the observer said so, TimeLimitReached when its deadline came before the tets. A
///         surface TetGen rejects is not an exception: the result says why in `fem`.
PipelineResult run_pipeline(const std::string& input, const PipelineConfig& config,
                            const PipelineObserver& observer = {});

/// The pipeline's input in memory instead of a file: a surface (with its patches) or points. `name`
/// stands for the file in the result and the messages ("input" of report.json).
struct PipelineInput {
  std::string name;
  std::optional<TriangleSoup> surface;
  std::optional<std::vector<Vec3>> points;
};

/// run_pipeline on an input in memory (exactly one of surface and points), with the same figures
/// as on a file holding it. \throws as above; InvalidInput when neither or both are given.
PipelineResult run_pipeline(const PipelineInput& input, const PipelineConfig& config,
                            const PipelineObserver& observer = {});

/// The pipeline could not do its work on a valid input; the message gives the reason.
class PipelineFailed : public Error {
 public:
  using Error::Error;
};

}  // namespace meshprep
