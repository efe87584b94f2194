// libFuzzer target for the app's File → Open and File → Save paths: every input becomes a file
// (or a FIFO, device or folder) opened and saved through the Document (SceneFilesCheck.h).
// Build and run with scripts/fuzz.sh 600 fuzz_scene_files; reproducers go to
// tests/fuzz/regressions-files/, where tst_fuzz_corpus replays them in every CI run.

#include "tests/fuzz/SceneFilesCheck.h"

#include <QCoreApplication>
#include <QDir>

#include <cstdio>
#include <cstdlib>

namespace {
QString gRoot;
}

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    static QCoreApplication app(*argc, *argv);
    gRoot = QDir::temp().filePath(
        QStringLiteral("phasebox-fuzz-files-%1").arg(QCoreApplication::applicationPid()));
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const QString broken = phasebox::fuzz::checkSceneFilesInput(data, size, gRoot);
    if (!broken.isEmpty()) {
        std::fprintf(stderr, "open/save contract broken: %s\n", qPrintable(broken));
        std::abort();
    }
    return 0;
}
