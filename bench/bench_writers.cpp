// The cost of writing the same tets in every format, side by side with .msh (Gmsh 4.1 ASCII, the
// default), and each file's size. Run: bench/bench_writers.sh (it makes the femur's tets first), or
// build/bin/bench_writers TETS.msh. Each format's time over .msh's is the figure of issue 44
// (<= 1.5x); the sizes give binary VTU over ASCII VTU.
#include "meshprep/fem/export.h"
#include "meshprep/fem/import.h"
#include "meshprep/fem/quadratic.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

struct Format {
  std::string label, extension;
  meshprep::TetExportOptions options;
};

std::vector<Format> formats() {
  meshprep::TetExportOptions msh22, binary_msh, ascii_vtu;
  msh22.msh_version = meshprep::MshVersion::V22;
  binary_msh.binary = true;
  ascii_vtu.ascii = true;
  return {{"msh_4.1", ".msh", {}}, {"msh_2.2", ".msh", msh22}, {"msh_binary", ".msh", binary_msh},
          {"vtu", ".vtu", {}},     {"vtu_ascii", ".vtu", ascii_vtu}, {"vtk", ".vtk", {}},
          {"mesh", ".mesh", {}},   {"inp", ".inp", {}},         {"node", ".node", {}},
          {"xdmf", ".xdmf", {}}};
}

std::uintmax_t bytes_of(const std::string& path) {
  std::uintmax_t bytes = 0;
  for (const std::string& file : meshprep::tet_mesh_files(path)) bytes += fs::file_size(file);
  return bytes;
}

void write(benchmark::State& state, const meshprep::TetMesh& mesh, const Format& format, const std::string& path) {
  for (auto _ : state) meshprep::write_tet_mesh(mesh, path, format.options);
  state.counters["bytes"] = static_cast<double>(bytes_of(path));
  for (const std::string& file : meshprep::tet_mesh_files(path)) fs::remove(file);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (argc != 2) {
    std::cerr << "usage: bench_writers [benchmark flags] TETS (a tet mesh meshprep reads)\n";
    return 2;
  }
  const meshprep::TetMesh linear = meshprep::read_tet_mesh(argv[1]);
  meshprep::TetMesh quadratic = linear;
  meshprep::make_quadratic(quadratic);  // straight mid-edge nodes: the writers' cost, not the curving's
  const fs::path folder = fs::temp_directory_path() / ("bench_writers_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  for (const auto& [order, mesh] : {std::pair<int, const meshprep::TetMesh*>{1, &linear}, {2, &quadratic}})
    for (const Format& format : formats()) {
      if (order == 2 && format.extension == ".node") continue;  // TetGen has no second-order tets
      const std::string path = (folder / (format.label + "_p" + std::to_string(order) + format.extension)).string();
      benchmark::RegisterBenchmark(("write/p" + std::to_string(order) + "/" + format.label).c_str(),
                                   [mesh = mesh, format, path](benchmark::State& state) { write(state, *mesh, format, path); })
          ->Unit(benchmark::kMillisecond);
    }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  fs::remove_all(folder);
  return 0;
}
