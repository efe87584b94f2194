#!/usr/bin/env bash
# Installs what is missing, builds the release preset and opens Phasebox on SCENE (default:
# the built-in demo scene). With no display it says so, runs the scene headless with
# phasebox-cli and saves a picture of the window as it would look.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

phasebox_install_dependencies
phasebox_build release
bin="$PHASEBOX_ROOT/build/release/app"

if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
    exec "$bin/phasebox" "$@"
fi

scene="${1:-:/scenes/demo.phasebox.json}"
picture="$PHASEBOX_ROOT/build/phasebox-window.png"
phasebox_log "no display found (DISPLAY and WAYLAND_DISPLAY are unset): running headless"
"$bin/phasebox-cli" info "$scene"
echo
"$bin/phasebox-cli" run "$scene" --duration 5
QT_QPA_PLATFORM=offscreen "$bin/phasebox" --screenshot "$picture" --run-for 5 "$scene" 2>/dev/null
phasebox_log "the window after 5 simulated seconds: $picture (under X: xvfb-run -a scripts/run.sh)"
