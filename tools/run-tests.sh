#!/usr/bin/env bash
# The whole test suite.
set -euo pipefail
# The plots of the bench and shading reports (python3-matplotlib), the engine tests' browser and
# Node.js, dpkg-shlibdeps for the package test's `cpack -G DEB`, and the batch test's Slurm (a
# single-node cluster the test starts and stops itself; docs/batch.md).
IBLKIT_EXTRA_PACKAGES=(python3-matplotlib chromium dpkg-dev slurmctld slurmd slurm-client munge)
command -v node >/dev/null && command -v npm >/dev/null || IBLKIT_EXTRA_PACKAGES+=(nodejs npm)
# The engine tests' npm packages install while the build compiles; the engine tests register once
# they are there.
IBLKIT_BESIDE_BUILD=install_engine_test_npm_packages
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
# Independent tests side by side, one per core; lavapipe's threads share the same cores.
ctest --preset default --parallel "$(nproc)"
