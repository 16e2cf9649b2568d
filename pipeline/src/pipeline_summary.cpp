// pipeline_summary and pipeline_record: the JSON files of a run (report.json, pipeline.json).

#include "meshprep/pipeline/pipeline_outputs.h"

#include "meshprep/quality/json_values.h"
#include "meshprep/report/report_writers.h"

namespace meshprep {
namespace {

using Json = nlohmann::ordered_json;

Json optional_number(const std::optional<double>& v) { return v ? json_number(*v) : Json(nullptr); }

Json stage_json(const StageRecord& s) {
  Json json;
  json["name"] = s.name;
  json["ran"] = s.ran;
  json["note"] = s.note;
  json["seconds"] = s.seconds;
  json["faces_before"] = s.faces_before;
  json["faces_after"] = s.faces_after;
  json["hausdorff_relative"] = optional_number(s.hausdorff_relative);
  json["volume_change_percent"] = optional_number(s.volume_change_percent);
  json["radius_ratio_mean"] = json_number(s.radius_ratio_mean);
  json["radius_ratio_p95"] = json_number(s.radius_ratio_p95);
  json["faces_min_angle_below_20"] = json_number(s.faces_min_angle_below_20);
  json["self_intersections"] = s.self_intersections;
  json["details"] = s.details;
  return json;
}

// The per-face shapes are in report.vtu; the JSON keeps the report's figures.
Json quality_json(const QualityReport& report) {
  Json json = to_json(report);
  json.erase("worst_faces");
  return json;
}

}  // namespace

Json pipeline_summary(const PipelineResult& result, const PipelineConfig& config) {
  Json json;
  json["meshprep_version"] = MESHPREP_VERSION;
  json["input"] = result.input;
  json["input_kind"] = result.from_points ? "points" : "mesh";
  if (result.from_points) json["input_points"] = result.input_points;
  json["fem_ready"] = result.fem.ready;
  json["problems"] = result.fem.problems;
  json["thresholds"] = to_json(TetVerdict{result.fem.checks});  // each beside the final tets' figure
  Json stages = Json::array();
  for (const StageRecord& s : result.stages) stages.push_back(stage_json(s));
  json["stages"] = stages;
  json["input_quality"] = quality_json(result.input_quality);
  json["quality"] = quality_json(result.final_quality);
  Json tets;
  tets["enabled"] = config.tetrahedralize.enabled;
  tets["format"] = config.tetrahedralize.format;
  tets["switches"] = result.tetgen_switches.empty() ? Json(nullptr) : Json(result.tetgen_switches);
  tets["readiness"] = result.readiness ? to_json(*result.readiness) : Json(nullptr);
  tets["tet_quality"] = result.tet_quality ? to_json(*result.tet_quality) : Json(nullptr);
  // TetGen's own tets beside the final ones, and what the improvement did and found the surface forbids.
  tets["tetgen_quality"] = result.tetgen_quality ? to_json(*result.tetgen_quality) : Json(nullptr);
  tets["improvement"] = result.improvement ? to_json(*result.improvement) : Json(nullptr);
  json["tets"] = tets;
  json["time_seconds"] = result.seconds;
  return json;
}

Json pipeline_record(const PipelineConfig& config, const Json& run) {
  Json json;
  json["run"] = run;
  const Json sections = to_json(config);
  for (const auto& [section, keys] : sections.items()) json[section] = keys;
  return json;
}

}  // namespace meshprep
