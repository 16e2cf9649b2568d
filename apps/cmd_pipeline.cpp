// meshprep pipeline IN -o OUTDIR [--config FILE.json] [--repair] [--target-faces N | --ratio R]
//   [--extrude-base DEPTH] [--format msh|vtu|mesh|inp|node|xdmf] [--msh-version 4.1|2.2] [--binary | --ascii] [--order 1|2]
//   [--size H] [--size-min H] [--size-max H] [--grading G] [--curvature-points N] [--thickness-layers K]
//   [--no-improve] [--tet-quality default|high] [--goal-min-dihedral DEG] [--goal-max-dihedral DEG] [--improve-time-limit S]
//   [--min-dihedral-threshold DEG] [--max-dihedral-threshold DEG] [--max-inverted-tets N]
//   [--fail-on CONDITIONS] [--threads N] [--time-limit S] [--quiet] [--json FILE|-] [--print-config] [--config-keys]
#include "cli_common.h"
#include "cli_parameters.h"
#include "interrupt.h"
#include "progress_bar.h"
#include "tet_second_order.h"

#include "meshprep/core/errors.h"
#include "meshprep/pipeline/pipeline.h"
#include "meshprep/preprocess/simplify/simplify_parameters.h"
#include "meshprep/pipeline/pipeline_config.h"
#include "meshprep/pipeline/pipeline_outputs.h"
#include "meshprep/quality/quality_gate.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>

namespace meshprep::cli {
namespace {

struct PipelineOptions {
  std::string input, outdir, config, json, format, msh_version, fail_on;
  ThresholdFlags thresholds;
  ImproveFlags improve;
  SizeFlags size;
  ElementOrderParams element_order;         ///< --order, over the configuration file's when given
  const CLI::Option* order_flag = nullptr;  ///< whether --order was given
  PatchParams patch_edits;  ///< --rename and --merge, after the configuration file's
  EncodingFlags encoding;
  double ratio = 0, extrude_base = 0;
  std::size_t target_faces = 0, threads = 0;
  bool repair = false, quiet = false, print_config = false, config_keys = false;
};

// Defaults, then the configuration file, then the command line's own flags.
PipelineConfig effective_config(const PipelineOptions& o) {
  PipelineConfig config;
  if (!o.config.empty()) read_config_file(o.config, config);
  if (o.repair) config.repair.enabled = true;
  if (o.ratio > 0) {
    config.simplify.ratio = o.ratio;
    config.simplify.params.target_faces = 0;
  }
  if (o.target_faces > 0) config.simplify.params.target_faces = o.target_faces;
  if (o.extrude_base > 0) config.tetrahedralize.extrude_base = o.extrude_base;
  if (!o.format.empty()) config.tetrahedralize.format = o.format;
  if (!o.msh_version.empty())
    config.tetrahedralize.export_options.msh_version = o.msh_version == "2.2" ? MshVersion::V22 : MshVersion::V41;
  if (o.encoding.binary || o.encoding.ascii) {  // either flag overrides both keys of the file
    config.tetrahedralize.export_options.binary = o.encoding.binary;
    config.tetrahedralize.export_options.ascii = o.encoding.ascii;
  }
  if (o.order_flag != nullptr && o.order_flag->count() > 0) config.tetrahedralize.element_order = o.element_order;
  config.verdict = o.thresholds.applied_to(config.verdict);
  config.improve.params = o.improve.applied_to(config.improve.params);
  config.size = o.size.applied_to(config.size);
  if (o.improve.off) config.improve.enabled = false;
  PatchParams& patches = config.patches.params;
  patches.merges.insert(patches.merges.end(), o.patch_edits.merges.begin(), o.patch_edits.merges.end());
  patches.renames.insert(patches.renames.end(), o.patch_edits.renames.begin(), o.patch_edits.renames.end());
  return config;
}

std::string stage_line(const StageRecord& s) {
  std::ostringstream line;
  line << std::left << std::setw(15) << s.name;
  if (!s.ran) {
    line << "skipped: " << s.note;
    return line.str();
  }
  line << std::right << std::fixed << std::setprecision(2) << std::setw(7) << s.seconds << " s  " << s.faces_before
       << " -> " << s.faces_after << " faces";
  if (s.hausdorff_relative) line << std::scientific << std::setprecision(2) << ", Hausdorff " << *s.hausdorff_relative;
  line << std::fixed << std::setprecision(3) << ", radius ratio p95 " << s.radius_ratio_p95 << std::setprecision(1)
       << ", min angle < 20 deg " << 100 * s.faces_min_angle_below_20 << " %";
  if (!s.note.empty()) line << "; " << s.note;
  return line.str();
}

// Every configuration key as a Markdown table (docs/pipeline.md holds this output).
void print_config_keys() {
  std::cout << "| key | value | default | meaning |\n| --- | --- | --- | --- |\n";
  for (const ConfigKeyDoc& key : describe_config())
    std::cout << "| `" << key.key << "` | " << key.type << " | `" << key.default_value.dump() << "` | " << key.description
              << " |\n";
}

// "FEM-ready: smallest dihedral angle 12.3 deg >= 10 deg (min_dihedral_deg), ...".
std::string verdict_line(const std::vector<ThresholdCheck>& checks) {
  std::string line = "FEM-ready:";
  for (std::size_t i = 0; i < checks.size(); ++i) line += (i ? ", " : " ") + describe(checks[i]);
  return line;
}

// The outputs are written: success, or exit 1 with one line per failed threshold and per --fail-on
// condition that holds, then the one "failed" line saying that the files are there.
int exit_code(const PipelineOptions& o, const PipelineResult& result, const PipelineConfig& config,
              const std::vector<GateCondition>& held) {
  std::string reasons;
  if (!result.fem.ready && config.tetrahedralize.enabled) {
    // One line per failed threshold, with what the surface allows where it forbids the threshold.
    if (result.tets)
      for (const std::string& problem : result.fem.problems)
        std::cerr << "meshprep: " << o.input << ": not FEM-ready: " << problem << '\n';
    const std::string failed = failed_names(TetVerdict{result.fem.checks});
    reasons = "not FEM-ready: " + (!result.tets        ? result.fem.problems.front()
                                   : failed.empty()    ? std::string("see above")
                                                       : "the tets fail " + failed + " (above)");
  }
  for (const GateCondition& c : held)
    std::cerr << "meshprep: " << o.input << ": --fail-on: " << c.text << " holds (is " << c.actual.dump() << ")\n";
  if (!held.empty())
    reasons += (reasons.empty() ? "" : "; ") + std::to_string(held.size()) + " --fail-on condition(s) hold (above)";
  if (reasons.empty()) return kSuccess;
  throw NotReady(o.input + ": " + reasons + "; the outputs are written in " + o.outdir + " (see " +
                   (std::filesystem::path(o.outdir) / "report.html").string() + ")");
}

// MESHPREP_TEST_WRITE_PAUSE=SECONDS makes the write phase wait that long before each file, so that
// a test can signal a run while it writes (tests/cli_corpus_test.sh); nothing else reads it.
void pause_while_writing_for_tests() {
  if (const char* seconds = std::getenv("MESHPREP_TEST_WRITE_PAUSE"))
    std::this_thread::sleep_for(std::chrono::duration<double>(std::atof(seconds)));
}

int run_pipeline_command(const PipelineOptions& o) {
  if (o.config_keys) {
    print_config_keys();
    return kSuccess;
  }
  const PipelineConfig config = effective_config(o);
  if (o.print_config) {
    std::cout << to_json(config).dump(2) << '\n';
    return kSuccess;
  }
  if (o.input.empty() || o.outdir.empty()) throw InvalidInput("pipeline: give the input and -o OUTDIR (see --help)");
  // A typo in the gate is a usage error, found before any work: its keys are looked up in the
  // summary of an empty run (what that leaves null, the tets' figures, is looked up after the run).
  const std::vector<GateCondition> gate = o.fail_on.empty() ? std::vector<GateCondition>{} : parse_quality_gate(o.fail_on);
  if (!gate.empty()) failed_conditions(gate, pipeline_summary(PipelineResult{}, config));
  if (!std::filesystem::exists(o.input)) throw IoError(o.input + ": cannot read: no such file");
  std::vector<std::string> outputs = {o.json};
  std::vector<std::string> covered;  // the files of the outputs listed (files_of: tets.node stands for tets.ele too)
  for (const std::string& name : pipeline_output_names(config, config.tetrahedralize.enabled)) {
    const std::string file = (std::filesystem::path(o.outdir) / name).string();
    if (std::find(covered.begin(), covered.end(), file) != covered.end()) continue;
    for (const std::string& sibling : files_of(file)) covered.push_back(sibling);
    outputs.push_back(file);
  }
  check_output_dir(o.outdir);  // before the work: an unusable folder fails at once (made when written)
  check_output_files({o.input, o.config}, outputs, MissingFolders::made);  // the folder -o is made
  check_output_files({}, {o.json});                                          // --json's is not

  const ThreadLimit parallelism(o.threads);
  std::ostream& log = o.json == "-" ? std::cerr : std::cout;
  std::unique_ptr<ProgressBar> bar;
  PipelineObserver observer;
  observer.cancelled = stop_requested;
  if (!o.quiet) {
    observer.stage_started = [&bar](const std::string& stage) {
      bar = std::make_unique<ProgressBar>(stage);
      bar->update(0);  // stages without progress (TetGen) still show their name
    };
    observer.progress = [&bar](double fraction) {
      if (bar) bar->update(fraction);
    };
    observer.stage_finished = [&bar, &log](const StageRecord& s) {
      bar.reset();
      log << stage_line(s) << std::endl;
      for (const TakenBack& t : s.taken_back) log << "  " << describe(t) << std::endl;
    };
  }
  observer.deadline = time_limit();
  PipelineResult result;
  try {
    result = run_pipeline(o.input, config, observer);
  } catch (const Cancelled&) {
    if (stop_requested()) throw Cancelled(o.input + ": " + stop_reason() + "; nothing written");
    throw;  // the time limit: main says so
  }
  bar.reset();

  nlohmann::ordered_json run;
  run["input"] = o.input;
  run["threads"] = parallelism.threads();
  run["versions"] = build_versions();
  std::vector<std::string> files;
  TetExportReport tet_export;
  try {
    files = write_pipeline_outputs(
        result, config, o.outdir, run,
        [] {
          pause_while_writing_for_tests();
          return stop_requested();
        },
        &tet_export);
  } catch (const Cancelled&) {
    throw Cancelled(o.input + ": " + stop_reason() + " while writing " + o.outdir + "; nothing written");
  }
  note_export_rounding((std::filesystem::path(o.outdir) / ("tets." + config.tetrahedralize.format)).string(), tet_export);
  const nlohmann::ordered_json summary = pipeline_summary(result, config);
  if (!o.json.empty()) emit_json(summary, o.json);
  if (!o.quiet) {
    log << "wrote " << o.outdir << ":";
    for (const std::string& f : files) log << ' ' << f;
    log << " (" << std::fixed << std::setprecision(1) << result.seconds << " s)" << std::endl;
    if (result.fem.ready) log << verdict_line(result.fem.checks) << std::endl;
  }
  return exit_code(o, result, config, gate.empty() ? gate : failed_conditions(gate, summary));
}

}  // namespace

Action add_pipeline_command(CLI::App& app) {
  auto o = std::make_shared<PipelineOptions>();
  CLI::App* cmd = app.add_subcommand(
      "pipeline",
      "Raw input to FEM-ready tets and a report: points are reconstructed, surfaces checked; then simplify, smooth, "
      "enhance, quality, tetrahedralize");
  cmd->add_option("input", o->input, "Point set (.xyz) or surface mesh (.off .obj .ply .stl)");
  cmd->add_option("-o,--output", o->outdir,
                  "Output folder: surface.ply, tets.<format>, report.html, report.json, report.vtu, pipeline.json");
  cmd->add_option("--config", o->config,
                  "Configuration file (JSON, keys in docs/pipeline.md; a pipeline.json replays its run)")
      ->check(CLI::ExistingFile);
  cmd->add_flag("--repair", o->repair,
                "Repair the input surface first, as meshprep repair does (weld split vertices where edges are open, "
                "split faces at T-junctions, drop degenerate and duplicate faces, split non-manifold edges and "
                "vertices, drop lone faces (fins), orient, fill holes, cut self-intersections and keep the union); "
                "a valid closed input is left as it is; off by default");
  const ParameterInfo& keep_ratio = simplify_parameters().keep_ratio;
  auto* ratio =
      cmd->add_option(keep_ratio.flag, o->ratio, "Simplify: " + keep_ratio.help)->check(range_check(keep_ratio.range));
  cmd->add_option("--target-faces", o->target_faces, "Simplify: target number of faces")
      ->check(positive())
      ->excludes(ratio);
  cmd->add_option("--extrude-base", o->extrude_base,
                  "An open height field (terrain) becomes a block with its base this far below its lowest point "
                  "(default: 2 % of the bounding-box diagonal)")
      ->check(positive());
  cmd->add_option("--format", o->format, "Tet mesh format: msh (default), vtu, mesh, inp, node, xdmf")
      ->check(CLI::IsMember({"msh", "vtu", "mesh", "inp", "node", "xdmf"}));
  cmd->add_option("--msh-version", o->msh_version, "Gmsh format version for msh: 4.1 (default) or 2.2")
      ->check(CLI::IsMember({"4.1", "2.2"}));
  add_encoding_options(*cmd, o->encoding, "Binary msh (vtu is binary unless --ascii, xdmf always)");
  o->order_flag = add_order_option(*cmd, o->element_order);
  add_patch_edits(*cmd, o->patch_edits);
  add_size_options(*cmd, o->size);
  add_improve_options(*cmd, o->improve, /*can_switch_off=*/true);
  add_threshold_options(*cmd, o->thresholds);
  cmd->add_option("--fail-on", o->fail_on,
                  "Exit 1 (the outputs written) if any condition on report.json holds, as quality --fail-on, e.g. "
                  "\"tets.tet_quality.min_dihedral_deg.p5<20,quality.radius_ratio.p95>2\"");
  add_threads_option(*cmd, o->threads);
  cmd->add_flag("--quiet", o->quiet, "No progress bars and no stage summaries");
  cmd->add_option("--json", o->json, "Write the run's summary (report.json) to FILE ('-' = stdout)");
  cmd->add_flag("--print-config", o->print_config,
                "Print the effective configuration (defaults, then --config, then the flags above) and exit");
  cmd->add_flag("--config-keys", o->config_keys, "Print every configuration key with its type, default and meaning, and exit");
  return [o] { return run_pipeline_command(*o); };
}

}  // namespace meshprep::cli
