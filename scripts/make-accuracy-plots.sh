#!/usr/bin/env bash
# Regenerates the work-precision diagrams of docs/accuracy.md (docs/images/accuracy-*.png) with
# `phasebox-cli accuracy` on built-in examples, and keeps each study's CSV next to the build
# (build/accuracy/*.csv) for the numbers quoted in the text.
#
# Uses the release preset's phasebox-cli (built when missing), or the one named by
# PHASEBOX_CLI. Timings are CPU times of this machine: run it on an otherwise idle machine.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

cli="${PHASEBOX_CLI:-}"
if [ -z "$cli" ]; then
    phasebox_build release phasebox-cli
    cli="$PHASEBOX_ROOT/build/release/app/phasebox-cli"
fi
scenes="$PHASEBOX_ROOT/resources/scenes"
images="$PHASEBOX_ROOT/docs/images"
tables="$PHASEBOX_ROOT/build/accuracy"
mkdir -p "$images" "$tables"
export QT_QPA_PLATFORM="${QT_QPA_PLATFORM:-offscreen}"

# study NAME SCENE [OPTIONS...]: one diagram and its CSV.
study() {
    local name="$1" scene="$2"
    shift 2
    phasebox_log "accuracy study: $name"
    "$cli" accuracy "$scenes/$scene.phasebox.json" "$@" \
        --plot "$images/accuracy-$name.png" --csv "$tables/accuracy-$name.csv"
}

# The spring oscillator's periods are 1 s and 2 s and its balls start at rest: at t = 10 s
# (its duration) every error is measured at a turning point after whole periods, where the
# leading error terms cancel and symplectic Euler looks third-order. 9.3 s is a generic time.
study oscillator spring-oscillator --duration 9.3
study orbit orbit
study bouncing-balls bouncing-balls
study stiff-spring stiff-spring-blowup
phasebox_log "diagrams in $images/accuracy-*.png, tables in $tables"
