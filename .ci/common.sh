# Shared by .ci/run and .ci/example (sourced, not run). Debian 12 only.
#
# Everything is built from the repository root into:
#   build/              the ParaView plugin (and the tests)
#   build-vtk/          the VTK-only module, installed into build-vtk/install/

OSM_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# ParaView's bundled VTK, in Debian's multiarch folder (x86_64-linux-gnu on
# amd64, the machines tested): found once paraview-dev is installed
# (osm_install_packages looks again), else amd64's.
osm_paraview_vtk_dir() {
  local dir
  for dir in /usr/lib/*/cmake/paraview-5.11/vtk; do
    if [ -d "$dir" ]; then
      echo "$dir"
      return
    fi
  done
  echo /usr/lib/x86_64-linux-gnu/cmake/paraview-5.11/vtk
}
OSM_PARAVIEW_VTK_DIR=$(osm_paraview_vtk_dir)
OSM_JOBS=2
# Release, at -O2 rather than CMake's default -O3: quicker to compile on 2 cores.
# The system's Python for the test scripts, not one first on PATH (pyenv).
OSM_CMAKE_ARGS=(-G Ninja -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG"
  -DPython3_EXECUTABLE=/usr/bin/python3)

# Debian packages the build and the tests need.
OSM_PACKAGES=(
  # Compilers and build tools.
  cmake g++ ninja-build
  # ParaView 5.11 with its bundled VTK, its development files and Python.
  paraview paraview-dev python3-paraview python3-numpy
  # ParaView is built with MPI: even a serial pvpython initialises Open MPI.
  mpi-default-bin
  # What find_package(ParaView) needs but paraview-dev does not declare:
  # Qt 5, then the external libraries its bundled VTK was built against.
  qtbase5-dev qttools5-dev libqt5svg5-dev libqt5opengl5-dev libqt5x11extras5-dev
  qtxmlpatterns5-dev-tools
  libhdf5-openmpi-dev libopenmpi-dev libutfcpp-dev libogg-dev libtheora-dev
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libgl2ps-dev
  libnetcdf-dev libgdal-dev libglew-dev libdouble-conversion-dev liblz4-dev
  libtiff-dev libjpeg-dev libpng-dev libfreetype-dev liblzma-dev libexpat1-dev
  libxml2-dev zlib1g-dev libx11-dev libgl-dev libboost-dev libeigen3-dev python3-dev
  # Tests: GoogleTest, GMP (exact arithmetic checks), benchmarks, a virtual X server,
  # and the locale sources localedef makes a German locale from (TestNumberText).
  libgtest-dev libgmp-dev libbenchmark-dev xvfb xauth locales
)

osm_log() {
  printf '\n=== [%s] %s\n' "$(date +%H:%M:%S)" "$*"
}

# Install the packages that are missing, and only those (quick when all are there).
osm_install_packages() {
  local missing=() pkg
  for pkg in "${OSM_PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$pkg")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    osm_log "All ${#OSM_PACKAGES[@]} Debian packages are installed"
    return 0
  fi
  osm_log "Installing ${#missing[@]} Debian package(s): ${missing[*]}"
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    if ! command -v sudo > /dev/null; then
      osm_log "Cannot install them: run this as root, or install sudo and be allowed to use it"
      return 1
    fi
    sudo=(sudo)
  fi
  "${sudo[@]}" apt-get update
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y "${missing[@]}"
  OSM_PARAVIEW_VTK_DIR=$(osm_paraview_vtk_dir)
}

# The VTK-only module, built against ParaView's bundled VTK and installed.
osm_build_vtk_only() {
  osm_log "Configuring the VTK-only module (build-vtk/)"
  cmake -S "$OSM_ROOT" -B "$OSM_ROOT/build-vtk" "${OSM_CMAKE_ARGS[@]}" \
    -DOSM_BUILD_PARAVIEW_PLUGIN=OFF \
    -DBUILD_TESTING=OFF \
    -DVTK_DIR="$OSM_PARAVIEW_VTK_DIR" \
    -DCMAKE_INSTALL_PREFIX="$OSM_ROOT/build-vtk/install"
  osm_log "Building and installing the VTK-only module into build-vtk/install/"
  cmake --build "$OSM_ROOT/build-vtk" --parallel "$OSM_JOBS"
  cmake --install "$OSM_ROOT/build-vtk"
}

# The ParaView plugin; extra arguments go to the configure step.
osm_build_plugin() {
  osm_log "Configuring the ParaView plugin (build/)"
  cmake -S "$OSM_ROOT" -B "$OSM_ROOT/build" "${OSM_CMAKE_ARGS[@]}" \
    -DOSM_BUILD_PARAVIEW_PLUGIN=ON \
    "$@"
  osm_log "Building the ParaView plugin"
  cmake --build "$OSM_ROOT/build" --parallel "$OSM_JOBS"
}

# Path of the built plugin library.
osm_plugin_path() {
  # -quit, not "| head": under pipefail a second match could end find by SIGPIPE.
  find "$OSM_ROOT/build/lib" -name OverlayStitchMesher.so -path '*/OverlayStitchMesher/*' -print -quit
}
