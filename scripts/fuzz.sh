#!/usr/bin/env bash
# Builds the scene-loader fuzzer (libFuzzer + AddressSanitizer + UndefinedBehaviorSanitizer)
# with clang in a build directory of its own, build/fuzz, and runs it on one core.
# Usage: scripts/fuzz.sh [SECONDS (default 600)] [extra libFuzzer arguments]
#
# The seeds in tests/fuzz/corpus stay as they are: what the fuzzer discovers goes to
# build/fuzz/corpus, and a crash, timeout or broken promise to build/fuzz/artifacts/. To keep a
# finding as a regression test, fix it and copy the reproducer into tests/fuzz/regressions/
# (tst_fuzz_corpus replays that folder in every CI run).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

seconds="${1:-600}"
shift || true
if ! command -v clang++ >/dev/null; then
    phasebox_install_dependencies clang
fi

build="$PHASEBOX_ROOT/build/fuzz"
cd "$PHASEBOX_ROOT"
if [ ! -f "$build/CMakeCache.txt" ]; then
    phasebox_log "configuring the fuzz build in $build"
    cmake -S . -B "$build" -G Ninja \
        -DCMAKE_CXX_COMPILER=clang++ \
        -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer" \
        -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
        -DPHASEBOX_BUILD_FUZZ=ON -DPHASEBOX_BUILD_TESTS=OFF -DPHASEBOX_BUILD_BENCH=OFF >/dev/null
fi
phasebox_log "building fuzz_scene_loader"
cmake --build "$build" --target fuzz_scene_loader -j "${PHASEBOX_JOBS:-$(nproc)}"

mkdir -p "$build/corpus" "$build/artifacts"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
phasebox_log "fuzzing for $seconds s"
# -timeout: one input taking longer is a hang and is reported as such. -rss_limit_mb: a scene
# at the documented size limits needs a few hundred MB; more than 2 GB is a finding.
"$build/tests/fuzz/fuzz_scene_loader" \
    -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 -max_len=65536 \
    -dict="$PHASEBOX_ROOT/tests/fuzz/scene.dict" \
    -artifact_prefix="$build/artifacts/" -print_final_stats=1 \
    "$@" "$build/corpus" "$PHASEBOX_ROOT/tests/fuzz/corpus" "$PHASEBOX_ROOT/tests/fuzz/regressions"
