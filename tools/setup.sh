#!/usr/bin/env bash
# Installs the Debian 12 packages iblkit needs (when missing), then configures and builds it.
# Sourced by tools/run-main.sh (which builds the program alone: IBLKIT_BUILD_PRESET=main) and
# tools/run-tests.sh (the default preset, everything), and by tools/fuzz.sh, which sets
# IBLKIT_PRESET=fuzz and IBLKIT_EXTRA_PACKAGES (its compiler) first.
set -euo pipefail
IBLKIT_PRESET=${IBLKIT_PRESET:-default}

readonly IBLKIT_PACKAGES=(
  cmake ninja-build g++ pkg-config
  glslang-dev glslang-tools spirv-tools spirv-headers libspirv-cross-c-shared-dev
  nlohmann-json3-dev libcli11-dev libfmt-dev libgtest-dev
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers libglm-dev
  libegl-dev libgl-dev libgl1-mesa-dri
  libopenexr-dev libpng-dev libstb-dev libssl-dev libtinygltf-dev
  ${IBLKIT_EXTRA_PACKAGES[@]+"${IBLKIT_EXTRA_PACKAGES[@]}"}
)

missing_packages() {
  local package
  for package in "${IBLKIT_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || echo "$package"
  done
}

install_missing_packages() {
  local missing
  missing=$(missing_packages)
  [ -z "$missing" ] && return 0
  local as_root=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "iblkit: these packages are missing and sudo is not available: $missing" >&2; exit 1; }
    as_root=(sudo)
  fi
  echo "iblkit: installing $(echo $missing)" >&2
  "${as_root[@]}" apt-get update -q
  # shellcheck disable=SC2086
  DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y -q --no-install-recommends $missing
}

# The engine tests' npm packages, exactly as tests/engines/package-lock.json pins them; the browser
# is Debian's chromium, never one npm fetches. Node.js itself is one of the packages
# tools/run-tests.sh asks for where the machine has none.
install_engine_test_npm_packages() {
  local engines=tests/engines
  if [ ! -f "$engines/node_modules/.package-lock.json" ] || [ "$engines/package-lock.json" -nt "$engines/node_modules/.package-lock.json" ]; then
    echo "iblkit: installing the engine tests' npm packages" >&2
    PUPPETEER_SKIP_DOWNLOAD=1 npm ci --prefix "$engines" --no-audit --no-fund --loglevel=error
  fi
}

build_iblkit() {
  cmake --preset "$IBLKIT_PRESET"
  cmake --build --preset "${IBLKIT_BUILD_PRESET:-$IBLKIT_PRESET}"
}

cd "$(dirname "${BASH_SOURCE[0]}")/.."
install_missing_packages
# IBLKIT_BESIDE_BUILD names a function to run while the build compiles (the tests' npm packages,
# mostly waiting on the network); the configuration is made again once it is done.
if [ -n "${IBLKIT_BESIDE_BUILD:-}" ]; then
  "$IBLKIT_BESIDE_BUILD" &
  beside=$!
fi
build_iblkit
if [ -n "${IBLKIT_BESIDE_BUILD:-}" ]; then
  wait "$beside"
  cmake --preset "$IBLKIT_PRESET" >/dev/null
fi
