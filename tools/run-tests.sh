#!/usr/bin/env bash
# The whole test suite.
set -euo pipefail
# The plots of the bench and shading reports (python3-matplotlib), the engine tests' browser, and
# dpkg-shlibdeps for the package test's `cpack -G DEB`.
IBLKIT_EXTRA_PACKAGES=(python3-matplotlib chromium dpkg-dev)
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
install_engine_test_packages
# Independent tests side by side, one per core; lavapipe's threads share the same cores.
ctest --preset default --parallel "$(nproc)"
