#!/usr/bin/env bash
# Builds a libFuzzer target (libFuzzer + AddressSanitizer + UndefinedBehaviorSanitizer) with
# clang in a build directory of its own, build/fuzz, and runs it on one core.
# Usage: scripts/fuzz.sh [SECONDS (default 600)] [TARGET] [extra libFuzzer arguments]
#
# TARGET (default fuzz_scene_loader):
#   fuzz_scene_loader  the scene reader: parse, validate, save round trip, build, a few steps
#   fuzz_cli_outputs   phasebox-cli's output options onto every kind of target (files, full
#                      and null devices, folders, the scene itself, standard output)
#   fuzz_scene_files   the app's File -> Open and File -> Save paths (FIFOs, devices, folders,
#                      failed saves)
#   all                each of them for a third of SECONDS
#
# The seeds in tests/fuzz/corpus* stay as they are: what the fuzzer discovers goes to
# build/fuzz/corpus (the scene loader) or build/fuzz/corpus-TARGET, and a crash, timeout or
# broken promise to build/fuzz/artifacts/. To keep a finding as a regression test, fix it and
# copy the reproducer into the target's regressions folder (tests/fuzz/regressions,
# regressions-cli or regressions-files), which tst_fuzz_corpus and tst_fuzz_cli_corpus replay
# in every CI run.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

seconds="${1:-600}"
shift || true
target=fuzz_scene_loader
if [ $# -gt 0 ] && [[ "$1" != -* ]]; then
    target="$1"
    shift
fi
if [ "$target" = all ]; then
    for each in fuzz_scene_loader fuzz_cli_outputs fuzz_scene_files; do
        "${BASH_SOURCE[0]}" "$((seconds / 3))" "$each" "$@"
    done
    exit 0
fi
fuzz="$PHASEBOX_ROOT/tests/fuzz"
case "$target" in
    fuzz_scene_loader)
        dict="$fuzz/scene.dict" corpus="corpus" seeds=("$fuzz/corpus" "$fuzz/regressions") ;;
    fuzz_cli_outputs)
        dict="$fuzz/cli.dict" corpus="corpus-cli" seeds=("$fuzz/corpus-cli" "$fuzz/regressions-cli") ;;
    fuzz_scene_files)
        dict="$fuzz/scene.dict" corpus="corpus-files"
        seeds=("$fuzz/corpus-files" "$fuzz/regressions-files") ;;
    *)
        echo "fuzz.sh: unknown target '$target' (fuzz_scene_loader, fuzz_cli_outputs, fuzz_scene_files, all)" >&2
        exit 2 ;;
esac

if ! command -v clang++ >/dev/null; then
    phasebox_install_dependencies clang
fi

build="$PHASEBOX_ROOT/build/fuzz"
cd "$PHASEBOX_ROOT"
# -mavx2 -mfma: physics/linear/BlockSweeps.cpp enables its four-lane kernels with GCC's
# "#pragma GCC target", which clang ignores; without the flags clang refuses the AVX intrinsics.
if [ ! -f "$build/CMakeCache.txt" ]; then
    phasebox_log "configuring the fuzz build in $build"
    cmake -S . -B "$build" -G Ninja \
        -DCMAKE_CXX_COMPILER=clang++ \
        -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -mavx2 -mfma" \
        -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
        -DPHASEBOX_BUILD_FUZZ=ON -DPHASEBOX_BUILD_TESTS=OFF -DPHASEBOX_BUILD_BENCH=OFF >/dev/null
fi
phasebox_log "building $target"
cmake --build "$build" --target "$target" -j "${PHASEBOX_JOBS:-$(nproc)}"

mkdir -p "$build/$corpus" "$build/artifacts"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
# The system libraries' caches that the plot targets load (fontconfig, ...) are not leaks of
# ours: the suppressions of scripts/test-asan.sh.
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PHASEBOX_ROOT/scripts/lsan.supp}"
export QT_QPA_PLATFORM=offscreen
phasebox_log "fuzzing $target for $seconds s"
# -timeout: one input taking longer is a hang and is reported as such. -rss_limit_mb: a scene
# at the documented size limits needs a few hundred MB; more than 2 GB is a finding.
"$build/tests/fuzz/$target" \
    -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 -max_len=65536 \
    -dict="$dict" \
    -artifact_prefix="$build/artifacts/" -print_final_stats=1 \
    "$@" "$build/$corpus" "${seeds[@]}"
