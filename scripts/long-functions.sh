#!/bin/sh
# Lists the functions longer than 150 lines (or --limit N) in physics/ and the app's command
# line, accuracy and I/O code; exits 1 when there is one. `--top N` lists the N longest.
# Usage: scripts/long-functions.sh [--limit N] [--top N] [PATH...]
cd "$(dirname "$0")/.." || exit 2
exec python3 scripts/long-functions.py "$@"
