#include "meshprep/commands/tet_commands.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/size_parameters.h"
#include "meshprep/core/user_size_demands.h"
#include "meshprep/fem/size_conformity.h"
#include "meshprep/fem/fem_check.h"
#include "meshprep/fem/prepare_plc.h"
#include "meshprep/fem/tet_boundary.h"
#include "meshprep/quality/report.h"
#include "meshprep/quality/surface_distance.h"
#include "meshprep/report/number_format.h"

#include <chrono>
#include <limits>

namespace meshprep {
namespace {

// The improvement and the second order, on tets made or read; then the quality and the verdict.
void finish_tets(TetOutcome& outcome, const TriangleSoup* reference, const TetFinishing& finishing, bool improve,
                 const CommandHooks& hooks, const std::function<void()>& before_second_order = {}) {
  nlohmann::ordered_json& json = outcome.report;
  TetMesh& tets = outcome.tets;
  if (improve) {
    const ImproveParams& goals = finishing.improve_params;
    hooks.announce("improving " + std::to_string(tets.tets.size()) + " tets (goal: dihedral angles between " +
                   format_number(goals.goal_min_dihedral_deg, 4) + " and " + format_number(goals.goal_max_dihedral_deg, 4) +
                   " deg) ...");
    ImproveParams params = goals;
    params.progress = hooks.progress;
    params.cancelled = hooks.cancelled;
    params.deadline = hooks.deadline;
    outcome.improvement = improve_tets(tets, params);
    json["improvement"] = to_json(*outcome.improvement);
    // The figures below are then the best tets the time allowed.
    json["stopped"] = outcome.improvement->stopped_by == "time limit" ? nlohmann::ordered_json("time limit") : nullptr;
    add_taken_back_notes(outcome.improvement->taken_back, outcome.messages);
  }
  if (before_second_order) before_second_order();
  if (finishing.element_order.order == 2)
    outcome.second_order = make_second_order(tets, reference, json, outcome.messages, hooks);
  outcome.quality = analyze_tet_quality(tets);
  outcome.verdict = judge_tets(outcome.quality, finishing.thresholds);
  json["tet_quality"] = to_json(outcome.quality);
  json["fem_ready"] = outcome.verdict.ok();
  json["thresholds"] = to_json(outcome.verdict);
}

// No command hands on a tet that is flat or inverted (the writers refuse them too).
void refuse_flat_tets(const TetMesh& tets, const CommandNames& names) {
  const std::string flat = describe_flat_tets(tets);
  if (!flat.empty())
    throw SolverError(names.input + ": " + flat + "; a solver cannot take such tets: " + names.output + " is not written");
}

// "meshprep: not FEM-ready: ..." problems of the surface, one reason per check.
std::string readiness_failure(const Readiness& readiness) {
  std::string reasons;
  for (const ReadinessProblem& p : readiness.problems) reasons += (reasons.empty() ? "" : ", ") + p.check;
  return "the surface is not FEM-ready (" + reasons + ")";
}

}  // namespace

TetOutcome tetrahedralize_command(const TriangleSoup& surface, const TetrahedralizeCommand& command,
                                  const CommandNames& names, const CommandHooks& hooks) {
  check_tet_params(command.params);  // a bound TetGen cannot meet is bad usage, whatever the surface
  check_size_params(command.size);
  check_improve_params(command.finishing.improve_params);
  check_thresholds(command.finishing.thresholds);
  TetOutcome outcome;
  nlohmann::ordered_json& json = outcome.report;
  json["order"] = command.finishing.element_order.order;
  // The boundary patches, as the pipeline finds them, become the tets' named boundary tags. A
  // surface the halfedge mesh cannot hold has none: the readiness check below says why.
  TriangleSoup soup = surface;
  MeshBuildReport build;
  mesh_from_soup(soup, &build);
  if (build.dropped_faces.empty()) {
    try {
      json["patches"] = to_json(find_patches(soup, command.patches));
    } catch (const InvalidInput& e) {
      throw InvalidInput(names.input + ": " + e.what());
    }
  }
  // The user's sizes (a patch's by its name, so after the patches are found).
  std::shared_ptr<const SizeField> size_field;
  try {
    size_field = user_size_field(command.size, soup);
  } catch (const InvalidInput& e) {
    throw InvalidInput(names.input + ": " + e.what());
  }
  // The surface as a PLC (prepare_plc.h): an open height field extruded when asked, else checked.
  std::optional<double> depth;
  if (command.extrude_depth > 0 || command.extrude_relative > 0) {
    depth = command.extrude_depth > 0 ? command.extrude_depth : command.extrude_relative * bbox_diagonal(soup);
    json["extrude_base_depth"] = *depth;
  }
  PreparedPlc prepared = prepare_plc(soup, depth);
  if (depth && !prepared.plc) throw InvalidInput(names.input + ": cannot extrude: " + prepared.extrusion_problem);
  if (!depth) {
    outcome.readiness = *prepared.readiness;
    json["readiness"] = to_json(*prepared.readiness);
    if (!prepared.readiness->ready()) {
      json["fem_ready"] = false;
      outcome.failure = readiness_failure(*prepared.readiness);
      return outcome;
    }
    if (prepared.readiness->isolated_vertices > 0)
      outcome.messages.push_back("note: " + names.input + ": " + std::to_string(prepared.readiness->isolated_vertices) +
                                 " isolated vertices (no face uses them) are left out of the tets");
    if (prepared.flipped_inward) json["flipped_inward_orientation"] = true;
  }
  const SurfacePlc plc = std::move(*prepared.plc);

  hooks.announce("tetrahedralizing " + std::to_string(plc.facets.size()) + " facets with TetGen ...");
  const auto start = std::chrono::steady_clock::now();
  // Until the tets exist there is nothing usable: TetGen and the figures of its tets stop at the
  // deadline; from there on the improvement takes the time left and the rest is finished.
  const CommandHooks bounded = hooks.until_deadline();
  TetParams params = command.params;
  params.cancelled = bounded.cancelled;
  params.size_field = size_field;
  json["switches"] = tetgen_switches(params, 0);
  try {
    outcome.tets = tetrahedralize_plc(plc, params);
  } catch (const TetgenError& e) {
    json["tetgen_error"] = {{"code", e.code()}, {"message", e.what()}};
    json["fem_ready"] = false;
    outcome.failure = e.what();
    return outcome;
  }
  if (bounded.cancelled && bounded.cancelled()) throw Cancelled("cancelled");  // TetGen had just finished
  json["tetgen_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (command.finishing.improve) {
    outcome.quality_before = analyze_tet_quality(outcome.tets, kDefaultWorstTets, hooks.cancelled);
    json["tetgen_quality"] = to_json(*outcome.quality_before);
  }
  finish_tets(outcome, &soup, command.finishing, command.finishing.improve, hooks, [&] {
    // The improvement keeps the boundary: the change is TetGen's (tetrahedralize.h).
    const double change = volume_change_relative(plc, outcome.tets);
    json["volume_change_relative"] = change;
    if (const std::string note = volume_change_note(change); !note.empty())
      outcome.messages.push_back("note: " + names.input + ": " + note);
    if (command.fem_check) {  // on the linear tets: the check's solve is P1
      hooks.announce("FEM check: P1 Poisson solve on " + std::to_string(outcome.tets.tets.size()) + " tets ...");
      json["fem_check"] = to_json(run_fem_check(outcome.tets));
    }
  });
  // The final tets against the field they were made to (the improvement moves and adds points).
  if (params.size_field) json["size_conformity"] = to_json(measure_size_conformity(outcome.tets, *params.size_field));
  refuse_flat_tets(outcome.tets, names);
  return outcome;
}

TetOutcome improve_command(TetMesh tets, const TriangleSoup* reference, const TetFinishing& finishing,
                           const CommandNames& names, const CommandHooks& hooks) {
  check_improve_params(finishing.improve_params);
  check_thresholds(finishing.thresholds);
  TetOutcome outcome;
  outcome.tets = std::move(tets);
  nlohmann::ordered_json& json = outcome.report;
  json["order"] = finishing.element_order.order;
  outcome.quality_before = analyze_tet_quality(outcome.tets, kDefaultWorstTets, hooks.cancelled);
  json["tet_quality_before"] = to_json(*outcome.quality_before);
  try {
    finish_tets(outcome, reference, finishing, /*improve=*/true, hooks);
  } catch (const InvalidInput& e) {
    throw InvalidInput(names.input + ": " + e.what());  // tets that overlap, a face of three tets
  }
  refuse_flat_tets(outcome.tets, names);
  return outcome;
}

QuadraticResult make_second_order(TetMesh& tets, const TriangleSoup* reference, nlohmann::ordered_json& report,
                                  CommandMessages& messages, const CommandHooks& hooks) {
  hooks.announce("making " + std::to_string(tets.tets.size()) + " tets second-order (10 nodes) ...");
  const TriangleSoup own_boundary = reference ? TriangleSoup{} : boundary_surface(tets);
  QuadraticResult result = make_quadratic(tets, reference ? reference : &own_boundary);
  report["second_order"] = to_json(result);
  add_taken_back_notes(result.taken_back, messages);
  return result;
}

std::string improvement_summary(const ImproveResult& r) {
  std::string line = "smallest dihedral " + format_number(r.min_dihedral_before_deg, 3) + " -> " +
                     format_number(r.min_dihedral_after_deg, 3) + " deg, largest " +
                     format_number(r.max_dihedral_before_deg, 4) + " -> " + format_number(r.max_dihedral_after_deg, 4) +
                     " deg (" + r.stopped_by + ", " + format_number(r.seconds, 3) + " s)";
  if (r.flat_boundary_tets_removed > 0)
    line += "; " + std::to_string(r.flat_boundary_tets_removed) +
            " flat tet(s) on the boundary removed (its triangles flipped in their plane)";
  const std::string limit = surface_limit_note(r, std::numeric_limits<double>::infinity());
  return limit.empty() ? line : line + "; " + limit;
}

std::string second_order_summary(const QuadraticResult& r) {
  const std::size_t straight = r.straight_inverting + r.straight_off_reference;
  return std::to_string(r.curved_edges) + " of " + std::to_string(r.boundary_edges) + " boundary edges curved, " +
         std::to_string(r.on_reference) + " on the surface already, " + std::to_string(straight) + " left straight (" +
         std::to_string(r.straight_inverting) + " would fold a tet, " + std::to_string(r.straight_off_reference) +
         " off the surface), smallest scaled Jacobian " + format_number(r.min_scaled_jacobian, 3);
}

}  // namespace meshprep
