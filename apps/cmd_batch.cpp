// meshprep batch INPUTS... -o OUT [options]: many parts, each a `meshprep pipeline` of its own.
// The driver is Python (python/meshprep/batch.py, docs/batch.md): it runs the parts in a pool of
// worker processes or on a Dask cluster, both of which Python has and C++ would have to rebuild.
// This door hands it every argument, with this binary as the one each part runs.
#include "cli_common.h"

#include "meshprep/core/errors.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace meshprep::cli {
namespace {

#ifdef MESHPREP_PYTHON
// The folder holding the meshprep package: the build's (a binary run from its build tree), else
// the installed one.
std::string package_folder() {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  const bool in_build_tree = !error && self.parent_path().parent_path() / "python" == fs::path(MESHPREP_PYTHON_BUILD_DIR);
  const std::string installed = MESHPREP_PYTHON_INSTALL_DIR;
  return in_build_tree || installed.empty() ? MESHPREP_PYTHON_BUILD_DIR : installed;
}
#endif

}  // namespace

int run_batch(const std::vector<std::string>& arguments) {
#ifdef MESHPREP_PYTHON
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (error) throw IoError("batch: cannot find this program's own path: " + error.message());
  const std::string folder = package_folder();
  const char* old_path = std::getenv("PYTHONPATH");
  const std::string python_path = folder + (old_path && *old_path ? ":" + std::string(old_path) : "");
  ::setenv("PYTHONPATH", python_path.c_str(), 1);
  ::setenv("MESHPREP_BIN", self.c_str(), 1);
  std::vector<std::string> words = {MESHPREP_PYTHON, "-m", "meshprep.batch"};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  ::execv(MESHPREP_PYTHON, argv.data());
  throw InvalidInput(std::string("batch: cannot run ") + MESHPREP_PYTHON + " (" + std::strerror(errno) +
                     "): the batch driver is Python (scripts/install-deps.sh installs it)");
#else
  (void)arguments;
  throw InvalidInput("batch: this meshprep was built without its Python module (MESHPREP_BUILD_PYTHON), which runs the batch");
#endif
}

Action add_batch_command(CLI::App& app) {
  // Listed in the help; main hands the arguments to run_batch before CLI11 parses them (which would
  // take `--` and the pipeline flags after it for its own).
  CLI::App* cmd = app.add_subcommand(
      "batch",
      "Many parts: the pipeline on each, in parallel worker processes or on a Dask cluster, resumable, with a "
      "summary (meshprep batch --help; docs/batch.md)");
  cmd->set_help_flag();
  cmd->allow_extras();
  return [] { return run_batch({}); };
}

}  // namespace meshprep::cli
