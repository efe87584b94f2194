// libFuzzer target for the scene loader: every input goes through SceneIO::parse and, when
// accepted, validateScene, buildWorld and a few World::step() calls (SceneLoaderCheck.h).
// Build and run with scripts/fuzz.sh; reproducers go to tests/fuzz/regressions/, where
// tst_fuzz_corpus replays them in every CI run.

#include "tests/fuzz/SceneLoaderCheck.h"

#include <QCoreApplication>

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    // Nothing in the loader needs an event loop, but Qt's text codecs and the resource system
    // expect an application object, as in the real programs.
    static QCoreApplication app(*argc, *argv);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const QString broken = phasebox::fuzz::checkSceneLoaderInput(data, size);
    if (!broken.isEmpty()) {
        std::fprintf(stderr, "scene loader contract broken: %s\n", qPrintable(broken));
        std::abort();  // libFuzzer saves the input as a crash reproducer
    }
    return 0;
}
