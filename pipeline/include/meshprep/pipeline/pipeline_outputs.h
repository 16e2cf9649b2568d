#pragma once
/// \file pipeline_outputs.h
/// The files of a pipeline run, in its output folder:
///
/// | file | content |
/// | --- | --- |
/// | surface.ply | the final surface, with the surface variation sigma per vertex |
/// | tets.<format> | the tet mesh (msh, mesh, inp; node writes tets.node, .ele, .face; xdmf tets.xdmf, .h5; vtu tets.vtu, tets_boundary.vtu) |
/// | report.html | one self-contained page: stages, histograms, pictures, FEM readiness |
/// | report.json | the same figures for machines (pipeline_summary) |
/// | report.vtu | the final surface with per-face quality as cell data (ParaView) |
/// | pipeline.json | the effective configuration and the versions: `--config pipeline.json` replays the run |

#include "meshprep/pipeline/pipeline.h"
#include "meshprep/pipeline/pipeline_config.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace meshprep {

/// Checks, before the work and creating nothing, that `outdir` is a folder meshprep may write into
/// or can be created as one (its nearest existing ancestor is a writable folder): a run that fails
/// or is refused leaves no empty folder behind. write_pipeline_outputs creates it.
/// \throws IoError naming the folder and the reason.
void check_output_dir(const std::string& outdir);

/// The names of the files a run writes into its folder: surface.ply, tets.<format> (TetGen's
/// format: three files, XDMF and VTU two) when `with_tets`, report.html, report.json, report.vtu,
/// pipeline.json.
std::vector<std::string> pipeline_output_names(const PipelineConfig& config, bool with_tets);

/// The versions of meshprep and of the libraries it was built with.
nlohmann::ordered_json build_versions();

/// The machine summary of a run (the content of report.json): input, fem_ready and problems, the
/// thresholds of the verdict beside their figures ({check, threshold, value, ok} each), one record
/// per stage, the input's and the final surface's quality, the tets' quality (with the worst tets).
nlohmann::ordered_json pipeline_summary(const PipelineResult& result, const PipelineConfig& config);

/// The content of pipeline.json: {"run": `run`, then every configuration section}.
nlohmann::ordered_json pipeline_record(const PipelineConfig& config, const nlohmann::ordered_json& run);

/// Writes the files above into `outdir` (created if needed, with its parents) and returns their
/// names. All are written into a staging folder `.meshprep-staging-XXXXXX` inside `outdir` first and
/// then renamed into place, so that each file is either the previous run's or this run's, never
/// half-written, and a failure leaves the folder as it was (a folder this call created is removed
/// again). A tet mesh of another format (or any, when this run made none) left by an earlier run is
/// removed, so the folder always holds one run's files.
///
/// The staging folder is locked (flock) while the run writes. One that nobody holds locked was left
/// by a run that died while writing (SIGKILL, a power cut): it is removed before this run writes.
/// `cancelled`, if given, is asked before each file; when it says yes, the staging folder is
/// removed and Cancelled thrown (once the renames have begun, they are finished).
/// `tet_export`, if not null, receives what writing the tets rounded (export.h; all zero without tets).
/// \throws WriteError if a file or the folder cannot be written; Cancelled.
std::vector<std::string> write_pipeline_outputs(const PipelineResult& result, const PipelineConfig& config,
                                                const std::string& outdir, const nlohmann::ordered_json& run,
                                                const std::function<bool()>& cancelled = {},
                                                TetExportReport* tet_export = nullptr);

/// The pipeline's HTML report (report.html) as a string.
std::string pipeline_report_html(const PipelineResult& result, const PipelineConfig& config);

}  // namespace meshprep
