#pragma once
/// \file pipeline_outputs.h
/// The files of a pipeline run, in its output folder:
///
/// | file | content |
/// | --- | --- |
/// | surface.ply | the final surface, with the surface variation sigma per vertex |
/// | tets.<format> | the tet mesh (msh, vtu, mesh, inp; node writes tets.node, .ele, .face) |
/// | report.html | one self-contained page: stages, histograms, pictures, FEM readiness |
/// | report.json | the same figures for machines (pipeline_summary) |
/// | report.vtu | the final surface with per-face quality as cell data (ParaView) |
/// | pipeline.json | the effective configuration and the versions: `--config pipeline.json` replays the run |

#include "meshprep/pipeline/pipeline.h"
#include "meshprep/pipeline/pipeline_config.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace meshprep {

/// Creates `outdir` (and its parents) if needed and checks that files can be created in it.
/// \throws IoError naming the folder and the reason.
void prepare_output_dir(const std::string& outdir);

/// The versions of meshprep and of the libraries it was built with.
nlohmann::ordered_json build_versions();

/// The machine summary of a run (the content of report.json): input, fem_ready and problems, the
/// thresholds of the verdict beside their figures ({check, threshold, value, ok} each), one record
/// per stage, the input's and the final surface's quality, the tets' quality (with the worst tets).
nlohmann::ordered_json pipeline_summary(const PipelineResult& result, const PipelineConfig& config);

/// The content of pipeline.json: {"run": `run`, then every configuration section}.
nlohmann::ordered_json pipeline_record(const PipelineConfig& config, const nlohmann::ordered_json& run);

/// Writes the files above into `outdir` (prepared) and returns their names. All are written into
/// a staging folder inside `outdir` first and then renamed into place, so that each file is
/// either the previous run's or this run's, never half-written, and a failure leaves the folder
/// as it was. A tet mesh of another format (or any, when this run made none) left by an earlier
/// run is removed, so the folder always holds one run's files.
/// \throws IoError if a file cannot be written.
std::vector<std::string> write_pipeline_outputs(const PipelineResult& result, const PipelineConfig& config,
                                                const std::string& outdir, const nlohmann::ordered_json& run);

/// The pipeline's HTML report (report.html) as a string.
std::string pipeline_report_html(const PipelineResult& result, const PipelineConfig& config);

}  // namespace meshprep
