#!/usr/bin/env bash
# Installs what is missing, builds the release preset and runs the whole CTest suite offscreen.
# Usage: scripts/test.sh [PRESET] [extra ctest arguments]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

preset="${1:-release}"
shift || true
phasebox_install_dependencies
phasebox_build "$preset"
cd "$PHASEBOX_ROOT"
export QT_QPA_PLATFORM=offscreen
ctest --preset "$preset" -j "$(nproc)" --timeout 600 "$@"
