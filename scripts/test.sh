#!/usr/bin/env bash
# Installs what is missing, checks the format, builds the release preset and runs the whole CTest
# suite offscreen. The suite includes the stability suites twice: against the engine as shipped
# (label stability) and against the engine with its expensive internal checks (label checked:
# Release optimisation, PHASEBOX_EXPENSIVE_CHECKS on the two sources that read it, linked as
# phasebox_physics_checked; physics/CMakeLists.txt).
# Usage: scripts/test.sh [PRESET] [extra ctest arguments]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

preset="${1:-release}"
shift || true
phasebox_install_dependencies
# Style first: an unformatted source fails the run before anything is built.
"$PHASEBOX_ROOT/scripts/check-format.sh"
phasebox_build "$preset"
cd "$PHASEBOX_ROOT"
export QT_QPA_PLATFORM=offscreen
ctest --preset "$preset" -j "$(nproc)" --timeout 600 "$@"
