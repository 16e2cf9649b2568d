#pragma once
/// \file pipeline_config.h
/// Every setting of `meshprep pipeline`, grouped by stage, with its JSON form. The defaults are the
/// stage libraries' own (reconstruct.h, adaptive_reconstruction.h, simplify.h, smooth.h, enhance.h, report.h,
/// tetrahedralize.h) except where a field says otherwise; docs/pipeline.md lists every key.
///
/// The file is one JSON object of sections ("repair", "reconstruct", "patches", "simplify", "smooth", "enhance",
/// "knife_edges", "quality", "tetrahedralize", "improve", "verdict"), each an object of keys; any subset may be given. A section "run"
/// (what meshprep wrote into pipeline.json about the run: input, versions) is ignored, so a
/// pipeline.json replays its run. Unknown sections and keys are rejected with the list of valid
/// ones, and every value is checked for its type and range.

#include "meshprep/fem/export.h"
#include "meshprep/fem/fem_verdict.h"
#include "meshprep/fem/improve_tets.h"
#include "meshprep/fem/quadratic.h"
#include "meshprep/fem/tetrahedralize.h"
#include "meshprep/preprocess/enhance/enhance.h"
#include "meshprep/preprocess/patches/patches.h"
#include "meshprep/preprocess/reconstruct/reconstruct.h"
#include "meshprep/preprocess/repair/repair.h"
#include "meshprep/preprocess/simplify/simplify.h"
#include "meshprep/preprocess/smooth/smooth.h"
#include "meshprep/quality/report.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace meshprep {

struct PipelineConfig {
  /// Surface input only: the repair stage (repair.h) before the input is checked. Off by
  /// default: it changes the user's file (welds, drops faces, flips), so it is asked for.
  struct Repair {
    bool enabled = false;
    RepairParams params;
  } repair;
  struct Reconstruct {  ///< points input only
    ReconstructParams params = defaults();
    /// Vertices placed by local features (adaptive_reconstruction.h) instead of the uniform grid.
    bool adaptive = false;
    /// The pipeline keeps interior gaps, flagged (ReconstructParams::fill_holes), so that the
    /// terrain has one boundary loop and can be closed into a block.
    static ReconstructParams defaults() {
      ReconstructParams p;
      p.fill_holes = true;
      return p;
    }
  } reconstruct;
  /// The boundary patches (patches.h): the file's groups, else the regions the creases bound.
  /// feature_angle_deg unset ("auto") is the enhancement's crease angle (enhance.feature_angle_deg),
  /// so that every patch border is a crease the enhancement keeps.
  struct Patches {
    PatchParams params;
  } patches;
  struct Simplify {
    bool enabled = true;
    /// Fraction of the faces kept (params.keep_ratio when the stage runs). Empty = automatic:
    /// kTerrainRatio for a reconstructed terrain (its grid oversamples the points), no
    /// simplification for an input mesh (its detail is the user's). params.target_faces > 0
    /// overrides it.
    std::optional<double> ratio;
    SimplifyParams params;  ///< target_faces, cost, min_angle_deg, max_error, polish
    /// A reconstructed terrain's grid oversamples its points (300 x 300 vertices for 10,000
    /// samples). 7 % of its faces stay within RMS 1.2e-4 of the diagonal of it on Jacksboro (5.4 m,
    /// under a third of the reconstruction's own 18.5 m error), and keep the block's tets (TetGen's
    /// time) within the pipeline's 10 s budget; 10 % gives 8.5e-5 with 32 % more tets
    /// (docs/pipeline.md).
    static constexpr double kTerrainRatio = 0.07;
  } simplify;
  struct Smooth {
    /// Off by default: smoothing removes noise, and on a clean surface it only moves the surface
    /// away from the input (docs/pipeline.md has the figures). Switch it on for noisy scans.
    bool enabled = false;
    SmoothParams params = defaults();
    static SmoothParams defaults() {
      SmoothParams p;
      p.preserve_volume = true;  // a closed part keeps its volume through the pipeline
      return p;
    }
  } smooth;
  /// The element size the surface's remeshing and the tets follow (core/size_field.h). Unset (the
  /// default): the enhancement's own field (the input's density, curvature, thickness) and TetGen's
  /// sizes; any size set makes the enhancement remesh to it and TetGen follow it (its -m sizes).
  SizeParams size;
  struct Enhance {
    bool enabled = true;
    /// A fixed deviation bound, EnhanceParams::kLargestAutoDeviation (`meshprep enhance`'s default
    /// is "auto", the input's own distance from its reference): with the bound a simplified
    /// surface's distance, 9.4e-4 for the corpus's reconstructed points, their copy translated to
    /// 1e9 ended with a largest radius ratio of 2.5706 against 2.5705, where the pipeline promises
    /// the same figures to 1e-5, and both worse than the 1.84 that the fixed bound gives.
    EnhanceParams params = defaults();
    static EnhanceParams defaults() {
      EnhanceParams p;
      p.max_deviation = EnhanceParams::kLargestAutoDeviation;
      return p;
    }
  } enhance;
  /// The knife edges of the final surface opened before the tets are made (knife_edges.h): on by
  /// default, where the surface itself caps the tets below improve.goal_min_dihedral_deg (at most
  /// the default goal's: a higher goal is climbed from the default run's tets), within
  /// enhance.max_deviation of the input. Skipped when no tets are made.
  struct KnifeEdges {
    bool enabled = true;
  } knife_edges;
  struct Quality {
    /// The final report's sampling; each stage's row uses a fifth of the samples. 200,000 per
    /// direction (meshprep quality: 10^6) keeps the report's time below the stages' own.
    QualityParams params = defaults();
    static QualityParams defaults() {
      QualityParams p;
      p.distance_samples = 200000;
      return p;
    }
  } quality;
  struct Tetrahedralize {
    bool enabled = true;
    TetParams params;
    /// An open height field (a terrain) is closed into a block with a flat base this far below its
    /// lowest point: extrude_base in absolute units if > 0, else extrude_base_relative x the
    /// bounding-box diagonal.
    double extrude_base = 0;
    double extrude_base_relative = 0.02;
    /// TetGen -Y, overriding params.keep_surface. Unset ("auto"): a closed surface keeps its
    /// triangles (the stages made them well shaped; TetGen's splits only add tets, 4x on bunny00
    /// at 10 %), an extruded block's are split (its walls are long thin triangles: kept, 11 % of
    /// the terrain's tets fall under 10 degrees).
    std::optional<bool> keep_surface;
    /// 2: the final tets (after the improvement) made second-order, their boundary's nodes on the
    /// input surface (make_quadratic).
    ElementOrderParams element_order;
    std::string format = "msh";  ///< msh, vtu, mesh, inp, node or xdmf: the file tets.<format>
    TetExportOptions export_options;
  } tetrahedralize;
  struct Improve {
    /// On by default: TetGen's tets keep slivers whatever its switches (improve_tets.h).
    bool enabled = true;
    ImproveParams params;  ///< goals, moves, pass and time limits
  } improve;
  /// What the final tets must meet to be FEM-ready (fem_verdict.h). A section of its own, not keys
  /// of "tetrahedralize": it judges the tets whichever stage made them last, and
  /// tetrahedralize.min_dihedral_deg is already TetGen's -q target, a wish, not a check.
  TetThresholds verdict;
};

/// One documented key, for `--print-config` users and docs/pipeline.md.
struct ConfigKeyDoc {
  std::string key;          ///< "section.name"
  std::string type;         ///< e.g. "number in (0, 1]", "bool", "one of msh, vtu, mesh, inp, node"
  nlohmann::ordered_json default_value;
  std::string description;
};

/// Apply `json` (a configuration object) onto `config`. `origin` (a file name) starts every message.
/// \throws InvalidInput naming the key and the problem: not an object, an unknown section or key
///         (with the valid ones), a value of the wrong type or out of range.
void apply_config(const nlohmann::json& json, const std::string& origin, PipelineConfig& config);

/// Checks, before any work, the settings whose ranges the stage libraries define: TetGen's
/// (check_tet_params: a radius-edge bound under 1 never ends), the improvement's
/// (check_improve_params), the verdict's (check_thresholds), the extrusion depths (positive,
/// finite) and that the tet format can be binary or ASCII as asked (check_tet_export_options:
/// binary inp is refused). apply_config and run_pipeline call it, so a configuration file and the command line's
/// flags meet the same checks. The preprocessing stages check theirs when they start.
/// \throws InvalidInput "<section>: <key> must be ..., not <value>".
void check_config(const PipelineConfig& config);

/// Read a configuration file onto `config`. \throws IoError if unreadable; InvalidInput as above
/// and for malformed JSON (with the line and column).
void read_config_file(const std::string& path, PipelineConfig& config);

/// The effective configuration: every key of every section.
nlohmann::ordered_json to_json(const PipelineConfig& config);

/// Every key with its type, default and meaning, in file order.
std::vector<ConfigKeyDoc> describe_config();

}  // namespace meshprep
