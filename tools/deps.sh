# Sourced by tools/run and tools/test: installs the Debian packages qacc needs when any is
# missing (as root: apt-get update, then apt-get install -y). Safe to call repeatedly.
QACC_PACKAGES=(
  g++ make cmake pkg-config          # toolchain (OpenMP comes with g++: libgomp)
  ninja-build                        # tools/test's builds (ninja overlaps the layers' libraries; make builds them one by one)
  clang libclang-rt-dev libomp-dev   # the sanitized and fuzz builds (ASan, UBSan, libFuzzer, clang's OpenMP)
  libeigen3-dev                      # linear algebra
  libpng-dev                         # images
  nlohmann-json3-dev                 # scenes
  libcli11-dev                       # command line
  libgtest-dev                       # tests
  libosmesa6-dev                     # triangles through OSMesa (llvmpipe)
  libopencsg-dev libglew-dev         # CSG of triangles (OpenCSG, which calls GL through GLEW)
  pymol-data                         # real PDB files for the molecule scene
  python3                            # tools/behaviour_check, plots
  python3-matplotlib                 # tools/plot_sweep.py, plot_crossover.py, compose_side_by_side.py: sweep and compare figures
  parallel                           # GNU parallel: sweep shards (README, tests)
)

qacc_install_deps() {
  local missing=()
  for p in "${QACC_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi
  echo "qacc: installing ${missing[*]}" >&2
  if [ "$(id -u)" -ne 0 ]; then
    echo "qacc: missing Debian packages (${missing[*]}); run as root or install them" >&2
    return 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q >&2
  apt-get install -y -q --no-install-recommends "${missing[@]}" >&2
}
