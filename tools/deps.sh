# Sourced by tools/play and tools/test: installs the Debian packages ossa needs when any is
# missing (apt-get; sudo only when not root) and sets up shared variables.
set -euo pipefail

OSSA_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OSSA_JOBS="${OSSA_JOBS:-$(nproc 2>/dev/null || echo 2)}"

OSSA_PACKAGES=(
  build-essential cmake ninja-build pkg-config
  libglm-dev libeigen3-dev nlohmann-json3-dev libpugixml-dev zlib1g-dev libtbb-dev
  catch2 libbenchmark-dev
  libsdl2-dev libsdl2-image-dev libepoxy-dev libassimp-dev libimgui-dev libstb-dev libgif-dev
  xvfb xdotool librsvg2-bin
  clang-14 libfuzzer-14-dev ccache
)

ossa_install_deps() {
  local missing=()
  for p in "${OSSA_PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi
  echo "ossa: installing missing Debian packages: ${missing[*]}"
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    sudo="sudo"
  fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
  ossa_use_ccache  # (it may have been installed just now)
}

# Compiler caching (ccache, when installed): an unchanged tree rebuilds in seconds, also in
# another clone of it (paths below the tree are hashed relative to it) and after `rm -rf build`.
# OSSA_CCACHE=0 turns it off. Asked again once the packages are installed: on a clean machine
# the first run installs ccache, and its builds then fill the cache the next run reads.
ossa_use_ccache() {
  ossa_launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER= -DCMAKE_C_COMPILER_LAUNCHER=)
  if [ "${OSSA_CCACHE:-1}" != "0" ] && command -v ccache >/dev/null; then
    ossa_launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
    export CCACHE_BASEDIR="$OSSA_ROOT"
    export CCACHE_SLOPPINESS="${CCACHE_SLOPPINESS:-pch_defines,time_macros,include_file_mtime,include_file_ctime}"
    export CCACHE_NOHASHDIR=1
  fi
}
ossa_use_ccache

# ossa_build DIR BUILD_TYPE [extra cmake args...]
ossa_build() {
  local dir="$1" type="$2"
  shift 2
  cmake -S "$OSSA_ROOT" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE="$type" "${ossa_launcher[@]}" "$@" >/dev/null
  cmake --build "$dir" -j "$OSSA_JOBS"
}
