// pipeline_summary and pipeline_record: the JSON files of a run (report.json, pipeline.json).

#include "meshprep/pipeline/pipeline_outputs.h"

#include "meshprep/core/patch_names.h"
#include "meshprep/quality/json_values.h"
#include "meshprep/quality/patch_table.h"
#include "meshprep/report/report_writers.h"

#include <map>

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

// One row per boundary patch: the input's and the final surface's faces and area (each stage
// keeps its patches: the change is the stages' own), its normal spread, and the tets' boundary
// faces with its tag. A block's sides and bottom are patches of the tets alone.
Json patches_json(const PipelineResult& result) {
  std::map<int, Json> rows;
  const auto row_of = [&rows](int tag, const std::string& name) -> Json& {
    Json& json = rows[tag];
    json["tag"] = tag;
    json["name"] = name;
    return json;
  };
  for (const PatchRow& row : patch_table(result.input_surface)) {
    Json& json = row_of(row.tag, row.name);
    json["input_faces"] = row.faces;
    json["input_area"] = json_number(row.area);
  }
  for (const PatchRow& row : patch_table(result.surface)) {
    Json& json = row_of(row.tag, row.name);
    json["faces"] = row.faces;
    json["area"] = json_number(row.area);
    json["normal_spread_deg"] = json_number(row.normal_spread_deg);
    if (json.contains("input_area") && json["input_area"].get<double>() > 0)
      json["area_change_percent"] = json_number(100 * (row.area / json["input_area"].get<double>() - 1));
  }
  if (result.tets) {
    std::map<int, std::size_t> tet_faces;
    for (const int tag : result.tets->boundary_tags) ++tet_faces[tag];
    for (const auto& [tag, count] : tet_faces)
      row_of(tag, tag_name(result.tets->boundary_names, tag, "boundary"))["tet_boundary_faces"] = count;
  }
  Json table = Json::array();
  for (auto& [tag, row] : rows) table.push_back(std::move(row));
  return table;
}

}  // namespace

Json to_json(const SecondOrderRecord& record) {
  Json json = {{"hausdorff_linear_relative", record.hausdorff_linear_relative},
               {"hausdorff_second_order_relative", record.hausdorff_second_order_relative}};
  json.update(to_json(record.quadratic));
  return json;
}

Json pipeline_summary(const PipelineResult& result, const PipelineConfig& config) {
  Json json;
  json["meshprep_version"] = MESHPREP_VERSION;
  json["input"] = result.input;
  json["input_kind"] = result.from_points ? "points" : "mesh";
  if (result.from_points) json["input_points"] = result.input_points;
  json["fem_ready"] = result.fem.ready;
  json["problems"] = result.fem.problems;
  // "time limit" when an anytime step (the enhancement, the improvement) ended at its time limit or
  // at the run's deadline: the figures are its best result's; the stage's record says which.
  const bool improvement_stopped = result.improvement && result.improvement->stopped_by == "time limit";
  json["stopped"] = improvement_stopped || result.enhance_stopped_by_time_limit ? Json("time limit") : Json(nullptr);
  json["thresholds"] = to_json(TetVerdict{result.fem.checks});  // each beside the final tets' figure
  Json stages = Json::array();
  for (const StageRecord& s : result.stages) stages.push_back(stage_json(s));
  json["stages"] = stages;
  std::vector<TakenBack> taken_back;  // every stage's, in the order they ran
  for (const StageRecord& s : result.stages) taken_back.insert(taken_back.end(), s.taken_back.begin(), s.taken_back.end());
  json[kGuardsTakenBackKey] = json_taken_back(taken_back);
  json["input_quality"] = quality_json(result.input_quality);
  json["quality"] = quality_json(result.final_quality);
  json["patches"] = patches_json(result);
  Json tets;
  tets["enabled"] = config.tetrahedralize.enabled;
  tets["format"] = config.tetrahedralize.format;
  tets["switches"] = result.tetgen_switches.empty() ? Json(nullptr) : Json(result.tetgen_switches);
  tets["readiness"] = result.readiness ? to_json(*result.readiness) : Json(nullptr);
  tets["tet_quality"] = result.tet_quality ? to_json(*result.tet_quality) : Json(nullptr);
  // TetGen's own tets beside the final ones, and what the improvement did and found the surface forbids.
  tets["tetgen_quality"] = result.tetgen_quality ? to_json(*result.tetgen_quality) : Json(nullptr);
  tets["improvement"] = result.improvement ? to_json(*result.improvement) : Json(nullptr);
  tets["size_conformity"] = result.size_conformity ? to_json(*result.size_conformity) : Json(nullptr);
  tets["order"] = config.tetrahedralize.element_order.order;
  tets["second_order"] = result.second_order ? to_json(*result.second_order) : Json(nullptr);
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
