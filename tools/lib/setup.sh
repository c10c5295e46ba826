# Shared set-up for ./tools/test and ./tools/play: Debian packages, configure, build.
# Sourced, not run. Idempotent: a second call with nothing changed costs a few seconds.

# fonts-dejavu-core: the game's font, with the glyphs its text needs beyond Latin-1 (ImGui's own
# font has none of them).
TIRE_PACKAGES=(g++ cmake pkg-config libsdl2-dev libbox2d-dev nlohmann-json3-dev catch2
  libcli11-dev libimgui-dev libssl-dev fonts-dejavu-core)
# What the test suite needs besides: the format check (tools/check-format); the editor's tests in a
# real X window (Xvfb, xdotool, ImageMagick's import, python3).
TIRE_TEST_PACKAGES=(clang-format xvfb xdotool imagemagick python3)

tire_missing_packages() {
  local p missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  echo "${missing[@]}"
}

# Installs what is missing when root; otherwise prints the one command and fails.
tire_ensure_packages() {
  local missing
  missing=$(tire_missing_packages "$@")
  [ -z "$missing" ] && return 0
  if ! command -v dpkg-query >/dev/null; then
    echo "tools: not a Debian system; install the equivalents of: $missing" >&2
    return 1
  fi
  if [ "$(id -u)" -ne 0 ]; then
    echo "tools: missing Debian packages. Run:" >&2
    echo "  sudo apt-get install -y $missing" >&2
    return 1
  fi
  echo "tools: installing $missing" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q >/dev/null
  # shellcheck disable=SC2086
  apt-get install -y -q $missing >/dev/null
}

# The build folder of TIRE_BUILD_TYPE (default Release): build/ for Release, build-debug/ for
# Debug, build-<type>/ for any other, so that no build type ever reuses another's cache.
tire_build_dir() {
  local root build_type=${TIRE_BUILD_TYPE:-Release}
  root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
  if [ "$build_type" = Release ]; then echo "$root/build"
  else echo "$root/build-$(echo "$build_type" | tr '[:upper:]' '[:lower:]')"; fi
}

# Configures once, then builds incrementally into tire_build_dir.
tire_build() {
  local root build
  root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
  build=$(tire_build_dir)
  if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE="${TIRE_BUILD_TYPE:-Release}" >/dev/null
  fi
  cmake --build "$build" -j "$(nproc)"
}
