#!/usr/bin/env bash
# Installs what is missing, builds the release preset and runs the whole CTest suite offscreen.
# Then, on a full release run, builds the engine again with its expensive internal checks
# (preset checked: Release optimisation, PHASEBOX_EXPENSIVE_CHECKS=ON, in build/checked; only
# the engine and the stability suites are compiled) and runs the stability label there.
# Usage: scripts/test.sh [PRESET] [extra ctest arguments]
#   The checked run follows only `scripts/test.sh` or `scripts/test.sh release` with no extra
#   ctest arguments; PHASEBOX_SKIP_CHECKED=1 leaves it out.
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

if [ "$preset" != "release" ] || [ $# -gt 0 ] || [ "${PHASEBOX_SKIP_CHECKED:-0}" = "1" ]; then
    phasebox_log "checked: not run (only after a full release run without PHASEBOX_SKIP_CHECKED=1)"
    exit 0
fi
checked_start=$SECONDS
phasebox_log "checked: building the engine with PHASEBOX_EXPENSIVE_CHECKS=ON and the stability" \
    "suites (build preset checked, target phasebox_tests_stability, in build/checked)"
phasebox_build checked
phasebox_log "checked: running the stability label (ctest --preset checked)"
ctest --preset checked -j "$(nproc)" --timeout 600
phasebox_log "checked: built and passed in $((SECONDS - checked_start)) s"
