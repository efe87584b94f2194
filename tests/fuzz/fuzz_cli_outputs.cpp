// libFuzzer target for phasebox-cli's outputs: every input is a command line (one argument per
// line, with placeholders for output targets of every kind, CliOutputCheck.h) run in-process
// through cli::run. Build and run with scripts/fuzz.sh 600 fuzz_cli_outputs; reproducers go to
// tests/fuzz/regressions-cli/, where tst_fuzz_cli_corpus replays them in every CI run.

#include "tests/fuzz/CliOutputCheck.h"

#include <QApplication>
#include <QDir>

#include <cstdio>
#include <cstdlib>
#include <memory>

namespace {
std::unique_ptr<phasebox::fuzz::CliWorkspace> gWorkspace;
}

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    // The plot options draw through Qt Charts, which needs a QApplication (offscreen).
    qputenv("QT_QPA_PLATFORM", "offscreen");
    static QApplication app(*argc, *argv);
    gWorkspace = std::make_unique<phasebox::fuzz::CliWorkspace>(QDir::temp().filePath(
        QStringLiteral("phasebox-fuzz-cli-%1").arg(QCoreApplication::applicationPid())));
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const QString broken = phasebox::fuzz::checkCliOutputInput(data, size, *gWorkspace);
    if (!broken.isEmpty()) {
        std::fprintf(stderr, "phasebox-cli output contract broken: %s\n", qPrintable(broken));
        std::abort();
    }
    return 0;
}
