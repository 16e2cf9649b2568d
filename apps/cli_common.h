#pragma once
// Pieces shared by the subcommands: how results are emitted and how failures become exit codes.

#include "meshprep/commands/outcome.h"
#include "meshprep/core/exit_codes.h"
#include "meshprep/core/io.h"
#include "meshprep/core/size_field.h"
#include "meshprep/core/taken_back.h"
#include "meshprep/fem/export.h"
#include "meshprep/fem/fem_verdict.h"
#include "meshprep/fem/improve_tets.h"
#include "meshprep/quality/report.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace meshprep::cli {

/// Exit codes of the CLI contract (meshprep/core/exit_codes.h), as main and the commands return them.
inline constexpr int kSuccess = as_int(ExitCode::ready);
inline constexpr int kNotReady = as_int(ExitCode::not_ready);
inline constexpr int kBadInput = as_int(ExitCode::bad_input);

/// The work is done and written, but the result is not ready (exit 1): the message names why and
/// where the outputs are.
class NotReady : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Write `json` to `target`: "-" is stdout, anything else a file written atomically.
void emit_json(const nlohmann::ordered_json& json, const std::string& target);

/// The files a mesh path stands for, what write_tet_mesh writes and read_tet_mesh reads
/// (tet_mesh_files): TetGen's .node or .ele stands for its .node, .ele and .face; an .xdmf for
/// itself and the .h5 beside it; a .vtu for itself and its <stem>_boundary.vtu; any other path for
/// itself.
std::vector<std::string> files_of(const std::string& path);

/// Whether a run makes the missing folders of its outputs (the pipeline's -o OUTDIR) or needs them.
enum class MissingFolders { refused, made };

/// Checks the files of a run before any work: no output may be an input (outputs never clobber
/// inputs) nor another output (`-o X --json X` would leave the JSON alone in X), and each must be
/// writable - its folder exists (or, with MissingFolders::made, its nearest existing ancestor is a
/// folder) and may be written in, and it is no folder itself. Paths are compared as the files
/// they name (symlinks, `..` and hard links resolved; files_of expanded); empty paths and "-"
/// (stdout) are skipped, and so is a character device named twice (`/dev/null`).
/// \throws InvalidInput naming the file and the problem (its two roles, or why it cannot be written).
void check_output_files(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs,
                        MissingFolders folders = MissingFolders::refused);

/// A command's notes and warnings on stderr, each as "meshprep: <message>" (among them one per
/// piece of work a guard took back, add_taken_back_notes; --json lists those under guards_taken_back).
void print_messages(const CommandMessages& messages);

/// The hooks of a command run from the terminal: `draw` shows its progress (may be empty), Ctrl-C
/// and the timeout stop it (interrupt.h), each long step is named on stderr when it is a terminal.
CommandHooks terminal_hooks(std::function<void(double)> draw = {});

/// A validator for a number that must be above 0: "must be positive, not 0" (CLI11's own
/// PositiveNumber prints its range to DBL_MAX's 309 digits).
CLI::Validator positive();

/// The name of a validator that marks a floating option for which infinity is meaningful
/// (--smoothing inf: the least-squares limit); refuse_non_finite_numbers leaves such an option alone.
inline const std::string kInfinityMeaningful = "infinity is meaningful";

/// Makes every floating option of every subcommand of `app` refuse NaN and infinities (exit 2 at
/// parsing): a NaN passes CLI11's Range (its comparisons are false) and then silently disables the
/// bound or guard it sets. Options whose validator is named kInfinityMeaningful still take inf (never
/// NaN). Called once, after every subcommand is registered, so that no flag is forgotten.
void refuse_non_finite_numbers(CLI::App& app);

/// Registers --samples on `cmd`: the random samples per direction behind the distances of the
/// report (QualityParams::distance_samples), bound to `samples`.
void add_samples_option(CLI::App& cmd, std::size_t& samples);

/// Registers --threads on `cmd`: threads for the parallel parts, bound to `threads` (0: all cores).
void add_threads_option(CLI::App& cmd, std::size_t& threads);

/// The FEM verdict's thresholds as given on the command line; an unset flag leaves the value it
/// is applied to (TetThresholds' default, or the pipeline configuration's).
struct ThresholdFlags {
  std::optional<double> min_dihedral_deg, max_dihedral_deg;
  std::optional<std::size_t> max_inverted_tets;
  /// `thresholds` with the flags that were given.
  TetThresholds applied_to(TetThresholds thresholds) const;
};

/// Registers --min-dihedral-threshold, --max-dihedral-threshold and --max-inverted-tets on `cmd`,
/// bound to `flags`; the help gives TetThresholds' defaults.
void add_threshold_options(CLI::App& cmd, ThresholdFlags& flags);

/// --binary and --ascii as given: binary data where a format's default is ASCII (.msh, PLY, STL),
/// ASCII where it is binary (.vtu).
struct EncodingFlags {
  bool binary = false, ascii = false;
};

/// Registers --binary (with `binary_help`) and --ascii on `cmd`, excluding each other, bound to `flags`.
void add_encoding_options(CLI::App& cmd, EncodingFlags& flags, const std::string& binary_help);

/// How to write the tets to `output`: a solver target's options (target not empty; its extension
/// must be output's), else the .msh version ("4.1" or "2.2") and the encoding flags. Checked
/// before any work (check_tet_export_options): --binary for a text format (.inp, .mesh, .node,
/// .vtk, a target that reads ASCII) or --ascii for .xdmf is refused, naming the format.
/// \throws InvalidInput for an unknown target, an output of another extension, or such a flag.
TetExportOptions tet_export_options(const std::string& output, const std::string& target, const std::string& msh_version,
                                    const EncodingFlags& encoding);

/// Notes on stderr, in one line, that writing `output` rounded coordinates to fit the format
/// (TetExportReport; .inp's 20-character fields), with how many and by how much; nothing when none.
void note_export_rounding(const std::string& output, const TetExportReport& report);

/// The improvement's flags, each set only when given (the defaults stay ImproveParams').
struct ImproveFlags {
  bool off = false;  ///< --no-improve
  std::optional<std::string> tet_quality;  ///< --tet-quality: the goals' preset, before the goal flags
  std::optional<double> goal_min_dihedral_deg, goal_max_dihedral_deg, time_limit_seconds;
  /// --boundary-deviation: a number or auto (unset), applied only when the flag was given.
  std::optional<double> boundary_deviation;
  const CLI::Option* boundary_deviation_flag = nullptr;
  /// `params` with the flags that were given.
  ImproveParams applied_to(ImproveParams params) const;
};

/// Registers --goal-min-dihedral, --goal-max-dihedral, --boundary-deviation and --improve-time-limit on `cmd`, and
/// --no-improve when `can_switch_off`, bound to `flags`; the help gives ImproveParams' defaults.
void add_improve_options(CLI::App& cmd, ImproveFlags& flags, bool can_switch_off);

/// The size field's flags (--size, --size-min, --size-max, --grading, --curvature-points,
/// --thickness-layers), each set only when given (the defaults stay SizeParams').
struct SizeFlags {
  SizeParams given;  ///< the fields that were given
  /// `params` with the flags that were given.
  SizeParams applied_to(SizeParams params) const;
};

/// Registers the size field's flags on `cmd`, bound to `flags`.
void add_size_options(CLI::App& cmd, SizeFlags& flags);

/// Prints "meshprep: INPUT: not FEM-ready: <describe(check)>" to stderr for every failed check,
/// with what the surface allows (surface_limit_note) when `improvement` says it forbids the check.
void print_failed_thresholds(const std::string& input, const std::vector<ThresholdCheck>& checks,
                             const ImproveResult* improvement = nullptr);

/// The names of the failed checks, comma-separated: "min_dihedral_deg, max_dihedral_deg".
std::string failed_names(const TetVerdict& verdict);

/// While alive, the parallel parts (TBB) run on at most `threads` threads (0: all cores).
class ThreadLimit {
 public:
  explicit ThreadLimit(std::size_t threads);
  std::size_t threads() const { return threads_; }

 private:
  std::size_t threads_;
  tbb::global_control control_;
};

/// A subcommand: registers its options on `app` and returns the action to run once parsed.
using Action = std::function<int()>;

Action add_quality_command(CLI::App& app);
Action add_convert_command(CLI::App& app);
Action add_tetrahedralize_command(CLI::App& app);
Action add_simplify_command(CLI::App& app);
Action add_reconstruct_command(CLI::App& app);
Action add_smooth_command(CLI::App& app);
Action add_enhance_command(CLI::App& app);
Action add_pipeline_command(CLI::App& app);
Action add_improve_command(CLI::App& app);
Action add_repair_command(CLI::App& app);
Action add_patches_command(CLI::App& app);
Action add_batch_command(CLI::App& app);

/// `meshprep batch ARGUMENTS...`: runs the batch driver (python3 -m meshprep.batch) in this process's
/// place with `arguments`, this binary as the one each part runs. Returns only by throwing.
/// \throws InvalidInput when the driver cannot be started.
int run_batch(const std::vector<std::string>& arguments);

}  // namespace meshprep::cli
