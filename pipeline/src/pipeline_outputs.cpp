// The output folder of a run: written into a staging folder, then renamed into place.

#include "meshprep/pipeline/pipeline_outputs.h"

#include "meshprep/core/atomic_file.h"
#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/fem/export.h"
#include "meshprep/quality/report_writers.h"
#include "meshprep/quality/surface_variation.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace meshprep {
namespace {

namespace fs = std::filesystem;

// Every file name a tet mesh of any format may have (node writes three).
const std::vector<std::string> kTetFiles = {"tets.msh", "tets.vtu", "tets.mesh", "tets.inp",
                                            "tets.node", "tets.ele", "tets.face"};

std::vector<std::string> tet_files_of(const std::string& format) {
  if (format == "node") return {"tets.node", "tets.ele", "tets.face"};
  return {"tets." + format};
}

// A folder that removes itself (and what it holds) unless released.
class StagingFolder {
 public:
  explicit StagingFolder(const std::string& outdir) {
    std::string pattern = (fs::path(outdir) / ".meshprep-staging-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw IoError(outdir + ": cannot write: " + std::strerror(errno));
    path_ = pattern;
  }
  ~StagingFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  StagingFolder(const StagingFolder&) = delete;
  StagingFolder& operator=(const StagingFolder&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};

void write_json_file(const std::string& path, const nlohmann::ordered_json& json) {
  write_file_atomically(path, [&](std::ostream& out) { out << json.dump(2) << '\n'; });
}

}  // namespace

void prepare_output_dir(const std::string& outdir) {
  std::error_code ec;
  fs::create_directories(outdir, ec);
  if (ec) throw IoError(outdir + ": cannot create the output folder: " + ec.message());
  if (!fs::is_directory(outdir)) throw IoError(outdir + ": not a folder");
  StagingFolder probe(outdir);  // throws if nothing can be created in it
}

std::vector<std::string> write_pipeline_outputs(const PipelineResult& result, const PipelineConfig& config,
                                                const std::string& outdir, const nlohmann::ordered_json& run) {
  const StagingFolder staging(outdir);
  std::vector<std::string> names = {"surface.ply", "report.html", "report.json", "report.vtu", "pipeline.json"};

  WriteOptions surface_options;
  surface_options.vertex_scalars.push_back({"surface_variation", surface_variation(result.surface)});
  write_soup(result.surface, staging.file("surface.ply"), surface_options);
  write_file_atomically(staging.file("report.html"),
                        [&](std::ostream& out) { out << pipeline_report_html(result, config); });
  write_json_file(staging.file("report.json"), pipeline_summary(result, config));
  write_vtu(staging.file("report.vtu"), result.surface, result.final_quality);
  write_json_file(staging.file("pipeline.json"), pipeline_record(config, run));
  std::vector<std::string> tet_names;
  if (result.tets) {
    const PipelineConfig::Tetrahedralize& t = config.tetrahedralize;
    write_tet_mesh(*result.tets, staging.file("tets." + t.format), t.export_options);
    tet_names = tet_files_of(t.format);
    names.insert(names.begin() + 1, tet_names.begin(), tet_names.end());
  }

  for (const std::string& name : names) {
    const std::string target = (fs::path(outdir) / name).string();
    if (std::rename(staging.file(name).c_str(), target.c_str()) != 0)
      throw IoError(target + ": cannot write: " + std::strerror(errno));
  }
  for (const std::string& name : kTetFiles)  // an earlier run's tets that this run did not replace
    if (std::find(tet_names.begin(), tet_names.end(), name) == tet_names.end()) {
      std::error_code ignored;
      fs::remove(fs::path(outdir) / name, ignored);
    }
  return names;
}

}  // namespace meshprep
