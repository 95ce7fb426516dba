#!/usr/bin/env bash
# Installs everything sinew needs to build, test and render, from Debian 12's packages.
# Safe to run again: apt-get skips what is already there.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  libeigen3-dev          # dense/sparse linear algebra, iterative solvers
  libsuitesparse-dev     # CHOLMOD sparse Cholesky
  libopenblas0-pthread   # an optimized BLAS: CHOLMOD's supernodal factorization is ~10x slower on reference BLAS
  libgmsh-dev gmsh       # Gmsh C++ API: OpenCASCADE geometry, meshing, .msh reading
  libtbb-dev             # parallel assembly
  libpetsc-real-dev libopenmpi-dev  # PETSc (MUMPS, hypre, PT-Scotch) over OpenMPI: the petsc-gamg and petsc-mumps solvers
  libscotch-dev          # Scotch, whose random generator the mesh partition resets (parallel/partition.cpp)
  libassimp-dev          # surface meshes in: STL, OBJ, PLY, glTF/GLB
  libcgal-dev            # surfaces to meshes: repair, inside/distance queries, Mesh_3 tetrahedralization
  nlohmann-json3-dev     # scene files
  libcli11-dev           # command line
  libfmt-dev libspdlog-dev  # formatting and logging
  libgtest-dev libgmock-dev # unit tests
  python3-meshio         # tests read our VTU files back with an independent reader
  libbenchmark-dev       # benchmarks
  python3 python3-numpy python3-matplotlib  # plots and renders
)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
