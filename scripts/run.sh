#!/usr/bin/env bash
# Installs what is missing, builds the release preset and runs Phasebox on SCENE
# (default: the built-in demo scene).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

phasebox_install_dependencies
phasebox_build release
bin="$PHASEBOX_ROOT/build/release/app"
scene="${1:-$PHASEBOX_ROOT/resources/scenes/demo.phasebox.json}"
# Until the desktop window exists, Phasebox runs the scene headless and prints a summary.

if [ -x "$bin/phasebox" ]; then
    if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
        phasebox_log "no display found: running the scene headless with phasebox-cli"
    else
        exec "$bin/phasebox" "$@"
    fi
fi
"$bin/phasebox-cli" info "$scene"
echo
"$bin/phasebox-cli" run "$scene"
