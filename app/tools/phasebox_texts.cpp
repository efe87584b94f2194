// phasebox-texts FILE: writes the app's built-in texts (app/i18n/BuiltinTexts.h) as a C++ file
// of QT_TRANSLATE_NOOP entries for lupdate. The update_translations target runs it before
// lupdate; it is no part of the installed app.

#include "app/i18n/BuiltinTexts.h"

#include <QCoreApplication>
#include <QFile>
#include <QTextStream>

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    const QStringList args = QCoreApplication::arguments();
    if (args.size() != 2) {
        QTextStream(stderr) << "usage: phasebox-texts FILE\n";
        return 2;
    }
    const QByteArray source =
        phasebox::i18n::lupdateSource(phasebox::i18n::builtinTexts()).toUtf8();
    QFile out(args[1]);
    if (out.open(QIODevice::ReadOnly) && out.readAll() == source) return 0;  // no rebuild
    out.close();
    if (!out.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
        out.write(source) != source.size()) {
        QTextStream(stderr) << "phasebox-texts: error: cannot write " << args[1] << "\n";
        return 3;
    }
    return 0;
}
