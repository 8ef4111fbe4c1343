#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Install cable's dependencies from Debian packages, only those missing.
# Usage: scripts/install-deps.sh [--check | --check-build]
#   (no option)    install every missing package: the build's and those of the
#                  tests, benchmarks and pictures (make deps, make check, make demo)
#   --check        report every missing package, install nothing
#   --check-build  report the missing build dependencies, install nothing (plain
#                  make): exit 1 with their names and the command that installs them
# CABLE_DEPS_ROOT (tests only): a directory the probes are looked up under.
set -euo pipefail

# header-or-library probe  ->  Debian package that provides it.  build_probes:
# what `make` needs to compile and link cable, libcable.so and the Python
# extension; probes: the rest (tests, benchmarks, pictures, the 3-D view).
build_probes=(
  "/usr/include/kinsol/kinsol.h:libsundials-dev"
  "/usr/include/sunlinsol/sunlinsol_klu.h:libsundials-dev"
  "/usr/include/suitesparse/klu.h:libsuitesparse-dev"
  "/usr/include/lapacke.h:liblapacke-dev"
  "/usr/lib/x86_64-linux-gnu/liblapack.so:liblapack-dev"
  "/usr/lib/x86_64-linux-gnu/libopenblas.so:libopenblas-dev"
  "/usr/lib/x86_64-linux-gnu/openblas-pthread/libopenblas.a:libopenblas-pthread-dev"   # libcable.so's private BLAS
  "/usr/lib/x86_64-linux-gnu/liblapacke.a:liblapacke-dev"
  "/usr/include/gsl/gsl_version.h:libgsl-dev"
  "/usr/include/cairo/cairo.h:libcairo2-dev"
  "/usr/bin/gfortran:gfortran"             # the private OpenBLAS links libgfortran
  "/usr/bin/python3:python3"
  "/usr/include/python3*/Python.h:python3-dev"
  "/usr/lib/python3/dist-packages/numpy/core/include/numpy/arrayobject.h:python3-numpy"
)
probes=(
  "/usr/bin/auto-07p:auto-07p"
  "/usr/lib/python3/dist-packages/pytest/__init__.py:python3-pytest"
  "/usr/lib/python3/dist-packages/distributed/__init__.py:python3-distributed"
  "/usr/lib/python3/dist-packages/matplotlib/__init__.py:python3-matplotlib"   # plot() returns a figure
  "/usr/lib/python3/dist-packages/ipykernel/__init__.py:python3-ipykernel"   # import cable in a Jupyter kernel (a test)
  "/usr/lib/python3/dist-packages/jupyter_client/__init__.py:python3-jupyter-client"
  "/usr/bin/pkg-config:pkgconf"            # make check builds against an installed libcable
  "/usr/bin/time:time"                     # make bench: CPU and wall time of the knot72 runs
  "/usr/bin/bc:bc"                         # make bench: arithmetic in scripts/bench.sh
  "/usr/share/javascript/three/three.min.js:libjs-three"   # cable view: the 3-D view's WebGL library
  "/usr/bin/chromium:chromium"             # make check: the view's page in a real browser
  "/usr/bin/chromedriver:chromium-driver"
  "/usr/lib/python3/dist-packages/selenium/__init__.py:python3-selenium"
)

arch_dir=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || echo x86_64-linux-gnu)
root=${CABLE_DEPS_ROOT:-}
mode=${1:-}
case "$mode" in
  ""|--check) probes=("${build_probes[@]}" "${probes[@]}") ;;
  --check-build) probes=("${build_probes[@]}") ;;
  *) echo "usage: scripts/install-deps.sh [--check | --check-build]" >&2; exit 2 ;;
esac
missing=()
for p in "${probes[@]}"; do
  file=${p%%:*}; pkg=${p##*:}
  file=$root${file//x86_64-linux-gnu/$arch_dir}
  # shellcheck disable=SC2086  # a probe may be a glob (python3.X)
  compgen -G "$file" >/dev/null || missing+=("$pkg")
done
# de-duplicate
mapfile -t missing < <(printf '%s\n' "${missing[@]}" | sed '/^$/d' | sort -u)

if [ ${#missing[@]} -eq 0 ]; then
  [ "$mode" = --check-build ] || echo "install-deps: all dependencies present"
  exit 0
fi
if [ "$mode" = --check-build ]; then
  echo "cable: missing build dependencies (Debian packages): ${missing[*]}" >&2
  echo "cable: install them with: sudo apt-get install ${missing[*]}" >&2
  echo "cable: (or: make deps, which installs the test and benchmark tools too)" >&2
  exit 1
fi
if [ "$mode" = --check ]; then
  echo "install-deps: missing packages: ${missing[*]}" >&2
  exit 1
fi

echo "install-deps: installing ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: not root and no sudo; install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
