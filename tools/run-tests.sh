#!/usr/bin/env bash
# The whole test suite.
set -euo pipefail
IBLKIT_EXTRA_PACKAGES=(chromium)
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
install_engine_test_packages
ctest --preset default
