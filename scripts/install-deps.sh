#!/usr/bin/env bash
# Installs the Debian packages meshprep needs to build and test, if any is missing.
# Run as root (or with sudo available). Idempotent: does nothing when all are present.
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  libeigen3-dev libopenmesh-dev libtet1.5-dev libceres-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  nlohmann-json3-dev libcli11-dev libtbb-dev libnanoflann-dev libpng-dev
  zlib1g-dev  # .vtu data compressed by vtkZLibDataCompressor: the writer deflates it, the reader inflates it
  libhdf5-dev  # the heavy data of .xdmf files (the serial build; CMake's FindHDF5 finds it)
  libgmp-dev  # the exact stage of quality/'s orientation predicates
  python3
  python3-dev pybind11-dev  # the Python module (python/)
  ccache  # the builds of scripts/build.sh and run-tests.sh reuse what an earlier build compiled
  # third-party readers that the tests use to read back every tet-mesh format we write
  gmsh python3-meshio python3-numpy
  # tests/python/test_cad_formats.py: Gmsh's own Python API and VTK's readers read them back too
  python3-gmsh python3-vtk9
  # tests/python/test_xdmf_dolfinx.py (pytest): dolfinx reads our .xdmf and solves on it, h5py
  # reads its HDF5 data
  python3-pytest python3-dolfinx python3-h5py
  # meshprep batch --scheduler runs the parts on a Dask cluster; tests/python/test_batch.py
  # starts a local one
  python3-distributed
  # CalculiX, the solver that runs a static job on our Abaqus decks (tests/calculix.py)
  calculix-ccx
  # the browser that renders the HTML reports in the tests
  chromium
  # clang and its libFuzzer runtime, for scripts/fuzz.sh
  clang libclang-rt-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -eq 0 ]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo)
else
  echo "install-deps: missing packages: ${missing[*]}; run this script as root" >&2
  exit 2
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
