// The output folder of a run: written into a staging folder, then renamed into place.

#include "meshprep/pipeline/pipeline_outputs.h"

#include "meshprep/core/atomic_file.h"
#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/core/unique_fd.h"
#include "meshprep/fem/export.h"
#include "meshprep/quality/surface_variation.h"
#include "meshprep/report/report_writers.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

namespace meshprep {
namespace {

namespace fs = std::filesystem;

// The files of the tet mesh in `format` (tet_mesh_files: node writes three, xdmf and vtu two).
std::vector<std::string> tet_files_of(const std::string& format) { return tet_mesh_files("tets." + format); }

// Every file name a tet mesh of any format may have.
std::vector<std::string> all_tet_files() {
  std::vector<std::string> files;
  for (const char* format : {"msh", "vtu", "mesh", "inp", "node", "xdmf"})
    for (const std::string& file : tet_files_of(format)) files.push_back(file);
  return files;
}

const char kStagingPrefix[] = ".meshprep-staging-";

// An exclusive lock on a folder (flock), which the system releases when its holder dies.
bool try_lock(const UniqueFd& folder) { return folder.get() >= 0 && ::flock(folder.get(), LOCK_EX | LOCK_NB) == 0; }

// A folder that removes itself (and what it holds) unless released. It is locked for as long as it
// lives, and gets its name only once locked: a staging folder that can be locked belongs to a run
// that died (SIGKILL, a power cut), so remove_abandoned_staging may remove it.
class StagingFolder {
 public:
  explicit StagingFolder(const std::string& outdir) {
    std::string unlocked = (fs::path(outdir) / ".meshprep-new-XXXXXX").string();
    if (!::mkdtemp(unlocked.data())) throw WriteError(outdir + ": cannot write: " + std::strerror(errno));
    const std::string suffix = unlocked.substr(unlocked.size() - 6);
    lock_ = std::make_unique<UniqueFd>(::open(unlocked.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    path_ = fs::path(outdir) / (kStagingPrefix + suffix);
    if (!try_lock(*lock_) || std::rename(unlocked.c_str(), path_.c_str()) != 0) {
      const std::string reason = std::strerror(errno);
      ::rmdir(unlocked.c_str());
      throw WriteError(outdir + ": cannot write: " + reason);
    }
  }
  ~StagingFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  StagingFolder(const StagingFolder&) = delete;
  StagingFolder& operator=(const StagingFolder&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::unique_ptr<UniqueFd> lock_;
  fs::path path_;
};

// Removes the staging folders in `outdir` whose run died while writing: those nobody holds locked.
void remove_abandoned_staging(const std::string& outdir) {
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(outdir, ec)) {
    if (entry.path().filename().string().rfind(kStagingPrefix, 0) != 0 || !entry.is_directory(ec)) continue;
    const UniqueFd folder(::open(entry.path().c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (try_lock(folder)) fs::remove_all(entry.path(), ec);
  }
}

// Where `outdir` stands: its nearest ancestor that exists (or itself), and the topmost of the
// folders that do not exist yet (empty if none).
struct Ancestry {
  fs::path existing, topmost_missing;
};

Ancestry ancestry_of(const std::string& outdir) {
  Ancestry ancestry;
  std::error_code ec;
  ancestry.existing = fs::absolute(outdir, ec);
  while (!fs::exists(ancestry.existing, ec) && ancestry.existing != ancestry.existing.parent_path()) {
    ancestry.topmost_missing = ancestry.existing;
    ancestry.existing = ancestry.existing.parent_path();
  }
  return ancestry;
}

// Creates the folders of `outdir` that do not exist yet; returns the topmost of them (empty if
// none), for CreatedFolder to take back when the writing fails.
fs::path create_output_dir(const std::string& outdir) {
  const fs::path topmost = ancestry_of(outdir).topmost_missing;
  std::error_code ec;
  fs::create_directories(outdir, ec);
  if (ec) throw WriteError(outdir + ": cannot create the output folder: " + ec.message());
  return topmost;
}

// Removes a folder this run created unless told to keep it: a failed run leaves no empty folder.
class CreatedFolder {
 public:
  explicit CreatedFolder(fs::path path) : path_(std::move(path)) {}
  ~CreatedFolder() {
    std::error_code ignored;
    if (!kept_ && !path_.empty()) fs::remove_all(path_, ignored);
  }
  CreatedFolder(const CreatedFolder&) = delete;
  CreatedFolder& operator=(const CreatedFolder&) = delete;
  void keep() { kept_ = true; }

 private:
  fs::path path_;
  bool kept_ = false;
};

void write_json_file(const std::string& path, const nlohmann::ordered_json& json) {
  write_file_atomically(path, [&](std::ostream& out) { out << json.dump(2) << '\n'; });
}

}  // namespace

void check_output_dir(const std::string& outdir) {
  std::error_code ec;
  const fs::path at = ancestry_of(outdir).existing;
  if (fs::exists(outdir, ec) && !fs::is_directory(outdir, ec)) throw IoError(outdir + ": not a folder");
  if (!fs::is_directory(at, ec))
    throw IoError(outdir + ": cannot create the output folder: " + at.string() + " is not a folder");
  if (::access(at.c_str(), W_OK | X_OK) != 0)
    throw IoError(outdir + ": cannot create the output folder: " + at.string() + ": " + std::strerror(errno));
}

std::vector<std::string> pipeline_output_names(const PipelineConfig& config, bool with_tets) {
  std::vector<std::string> names = {"surface.ply", "report.html", "report.json", "report.vtu", "pipeline.json"};
  if (with_tets) {
    const std::vector<std::string> tets = tet_files_of(config.tetrahedralize.format);
    names.insert(names.begin() + 1, tets.begin(), tets.end());
  }
  return names;
}

std::vector<std::string> write_pipeline_outputs(const PipelineResult& result, const PipelineConfig& config,
                                                const std::string& outdir, const nlohmann::ordered_json& run,
                                                const std::function<bool()>& cancelled,
                                                TetExportReport* tet_export) {
  CreatedFolder created(create_output_dir(outdir));
  remove_abandoned_staging(outdir);
  const StagingFolder staging(outdir);
  // Each file is checked for a stop request before it is written; once the renames begin, they end.
  const auto stop_if_asked = [&] {
    if (cancelled && cancelled()) throw Cancelled(outdir + ": stopped while writing; nothing written");
  };

  stop_if_asked();
  WriteOptions surface_options;
  surface_options.vertex_scalars.push_back({"surface_variation", surface_variation(result.surface)});
  write_soup(result.surface, staging.file("surface.ply"), surface_options);
  stop_if_asked();
  write_file_atomically(staging.file("report.html"),
                        [&](std::ostream& out) { out << pipeline_report_html(result, config); });
  stop_if_asked();
  write_json_file(staging.file("report.json"), pipeline_summary(result, config));
  stop_if_asked();
  write_vtu(staging.file("report.vtu"), result.surface, result.final_quality);
  stop_if_asked();
  write_json_file(staging.file("pipeline.json"), pipeline_record(config, run));
  const std::vector<std::string> names = pipeline_output_names(config, result.tets.has_value());
  const std::vector<std::string> tet_names = result.tets ? tet_files_of(config.tetrahedralize.format)
                                                         : std::vector<std::string>{};
  if (result.tets) {
    stop_if_asked();
    const PipelineConfig::Tetrahedralize& t = config.tetrahedralize;
    write_tet_mesh(*result.tets, staging.file("tets." + t.format), t.export_options, tet_export);
  }
  stop_if_asked();

  // Two runs into one folder: each run's renames and removals happen whole, one run's after the
  // other's, so the folder holds one run's outputs (issue 45, item 13: two runs in other formats
  // each removed the other's tets, both exited 0, and no tets file was left).
  const UniqueFd folder_lock(::open(outdir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (folder_lock.get() < 0 || ::flock(folder_lock.get(), LOCK_EX) != 0)
    throw WriteError(outdir + ": cannot lock the output folder: " + std::strerror(errno));
  for (const std::string& name : names) {
    const std::string target = (fs::path(outdir) / name).string();
    if (std::rename(staging.file(name).c_str(), target.c_str()) != 0)
      throw WriteError(target + ": cannot write: " + std::strerror(errno));
  }
  created.keep();
  for (const std::string& name : all_tet_files())  // an earlier run's tets that this run did not replace
    if (std::find(tet_names.begin(), tet_names.end(), name) == tet_names.end()) {
      std::error_code ignored;
      fs::remove(fs::path(outdir) / name, ignored);
    }
  return names;
}

}  // namespace meshprep
