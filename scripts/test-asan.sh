#!/usr/bin/env bash
# Builds the asan preset (AddressSanitizer + UndefinedBehaviorSanitizer, build/asan) and runs
# the whole CTest suite under it, offscreen. Exit status: 0 when every test passes, non-zero
# on a build failure, a failing test or any sanitizer report (the preset builds with
# -fno-sanitize-recover=undefined, so UBSan findings abort the test like ASan's do).
#
# Not part of .ci/run: a full sanitizer build takes 15–25 minutes on two cores and the tests
# run 2–5 times slower, which would break CI's 20-minute budget. Run it nightly or before a
# release:  scripts/test-asan.sh [extra ctest arguments, e.g. -L unit]
# PHASEBOX_JOBS sets the build and test parallelism (default: the number of cores).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

jobs="${PHASEBOX_JOBS:-$(nproc)}"
start=$(date +%s)

phasebox_install_dependencies
cd "$PHASEBOX_ROOT"
if [ ! -f build/asan/CMakeCache.txt ]; then
    phasebox_log "configuring preset asan"
    cmake --preset asan >/dev/null
fi
phasebox_log "building preset asan with $jobs jobs"
cmake --build --preset asan -j "$jobs"

export QT_QPA_PLATFORM=offscreen
# Leak checking stays on; the suppressions cover allocations that Qt's and fontconfig's
# process-lifetime caches make once and never free (not ours, not growing).
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PHASEBOX_ROOT/scripts/lsan.supp:print_suppressions=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

phasebox_log "running the suite under ASan + UBSan"
status=0
ctest --preset asan -j "$jobs" "$@" || status=$?
phasebox_log "asan suite finished with status $status in $(( $(date +%s) - start )) s"
exit "$status"
