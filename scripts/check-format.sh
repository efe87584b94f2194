#!/usr/bin/env bash
# Checks, without changing anything, that every C++ source and header of the project (*.cpp, *.h
# and *.inc under physics/, app/, ui/ and tests/) is formatted as Debian's clang-format 14 would
# format it with the root .clang-format. Installs clang-format if it is missing.
# Exits 0 if all are formatted, 1 listing the files that are not, 2 if it cannot check.
# Usage: scripts/check-format.sh [-v] [FILE...]
#   -v     also print clang-format's diagnostics (where each file differs)
#   FILE   check only these files (default: the whole project)
# To format a file: clang-format -i --style=file:.clang-format FILE
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

verbose=0
if [ "${1:-}" = "-v" ]; then
    verbose=1
    shift
fi

# Other clang-format versions format some constructs differently: insist on 14, the version the
# tree is formatted with (Debian 12's clang-format package).
phasebox_install_packages clang-format
formatter=""
for candidate in clang-format-14 clang-format; do
    if command -v "$candidate" >/dev/null &&
        "$candidate" --version | grep -q 'clang-format version 14\.'; then
        formatter="$candidate"
        break
    fi
done
if [ -z "$formatter" ]; then
    phasebox_log "clang-format 14 not found ($(clang-format --version 2>/dev/null || echo none))"
    exit 2
fi

style="file:$PHASEBOX_ROOT/.clang-format"
if [ $# -gt 0 ]; then
    files=("$@")  # as given, relative to the caller's directory
else
    cd "$PHASEBOX_ROOT"
    mapfile -d '' files < <(find physics app ui tests -type f \
        \( -name '*.cpp' -o -name '*.h' -o -name '*.inc' \) -print0 | sort -z)
fi

unformatted=()
for file in "${files[@]}"; do
    if [ ! -f "$file" ]; then
        phasebox_log "format: no such file: $file"
        exit 2
    fi
    if [ "$verbose" -eq 1 ]; then
        "$formatter" --dry-run -Werror --style="$style" "$file" || unformatted+=("$file")
    elif ! "$formatter" --dry-run -Werror --style="$style" "$file" >/dev/null 2>&1; then
        unformatted+=("$file")
    fi
done

if [ ${#unformatted[@]} -eq 0 ]; then
    phasebox_log "format: all ${#files[@]} files formatted ($("$formatter" --version))"
    exit 0
fi
phasebox_log "format: ${#unformatted[@]} of ${#files[@]} files are not formatted:"
printf '  %s\n' "${unformatted[@]}" >&2
phasebox_log "format them with: $formatter -i --style=file:.clang-format FILE..."
exit 1
