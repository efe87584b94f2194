// The translations (docs/translations.md): lupdate run over today's sources into copies of
// translations/phasebox_{de,es,fr}.ts leaves nothing unfinished, so a text added anywhere in the
// app or the views (a tr() call, a built-in scene, a schema label) without its German, Spanish
// and French translation fails here; the translations keep their placeholders, plural forms and
// keyboard accelerators; the compiled-in translations translate the built-in texts; installing a
// language translates the window and its numbers, and files stay '.'-decimal under it.

#include "app/i18n/BuiltinTexts.h"
#include "app/i18n/Language.h"
#include "app/io/NumberFormat.h"
#include "app/io/SceneIO.h"

#include <QCoreApplication>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QLocale>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>
#include <QXmlStreamReader>

#include <algorithm>

using namespace phasebox;

namespace {

const QString kRoot = QStringLiteral(PHASEBOX_SOURCE_DIR);
const QStringList kLanguages{QStringLiteral("de"), QStringLiteral("es"), QStringLiteral("fr")};

struct Message {
    QString context;
    QString source;
    QStringList translations;  // one, or one per plural form
    bool numerus = false;
    bool unfinished = false;
};

// The messages of a .ts file, obsolete ones left out.
QList<Message> readTs(const QString& path, QString* error) {
    QList<Message> out;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = path + QStringLiteral(": cannot read");
        return out;
    }
    QXmlStreamReader xml(&file);
    QString context;
    Message m;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement()) continue;
        const auto name = xml.name();
        if (name == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (name == QLatin1String("message")) {
            m = Message{context,
                        {},
                        {},
                        xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes")};
        } else if (name == QLatin1String("source")) {
            m.source = xml.readElementText();
        } else if (name == QLatin1String("translation")) {
            const auto type = xml.attributes().value(QLatin1String("type"));
            if (type == QLatin1String("obsolete") || type == QLatin1String("vanished")) continue;
            m.unfinished = type == QLatin1String("unfinished");
            if (m.numerus) {
                while (xml.readNextStartElement())
                    if (xml.name() == QLatin1String("numerusform"))
                        m.translations << xml.readElementText();
            } else {
                m.translations << xml.readElementText();
            }
            out << m;
        }
    }
    if (xml.hasError()) *error = path + QStringLiteral(": ") + xml.errorString();
    return out;
}

// The sources lupdate reads, as the update_translations target lists them (app/CMakeLists.txt):
// the app and the views, not the command line, which stays English.
QStringList translatedSources() {
    QStringList files;
    for (const QString& folder : {QStringLiteral("app"), QStringLiteral("ui")}) {
        QDirIterator it(kRoot + QLatin1Char('/') + folder,
                        {QStringLiteral("*.cpp"), QStringLiteral("*.h")}, QDir::Files,
                        QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString path = it.next();
            if (!path.contains(QLatin1String("/app/cli/")) &&
                !path.contains(QLatin1String("/app/tools/")))
                files << path;
        }
    }
    files.sort();
    return files;
}

QString describe(const Message& m) {
    return QStringLiteral("[%1] \"%2\"").arg(m.context, m.source.left(100));
}

// %1…%99 and %L1 in a text, sorted; %n apart.
QStringList placeholders(const QString& text) {
    static const QRegularExpression re(QStringLiteral("%L?(\\d{1,2})"));
    QStringList found;
    for (auto it = re.globalMatch(text); it.hasNext();) found << it.next().captured(1);
    found.sort();
    return found;
}

// Keyboard accelerators: an & before a letter or digit that is not itself escaped (&&).
int accelerators(const QString& text) {
    int n = 0;
    for (qsizetype i = 0; i + 1 < text.size(); ++i) {
        if (text[i] != QLatin1Char('&')) continue;
        if (text[i + 1] == QLatin1Char('&')) {
            ++i;
            continue;
        }
        if (text[i + 1].isLetterOrNumber()) ++n;
    }
    return n;
}

}  // namespace

class TestTranslations : public QObject {
    Q_OBJECT

private slots:
    void noTextLacksATranslation();
    void translationsKeepPlaceholdersAndAccelerators();
    void builtinTextsAreTranslatedInTheApp();
    void installedLanguageTranslatesTextsAndNumbers();
    void filesStayDotDecimalUnderAGermanLocale();
};

void TestTranslations::noTextLacksATranslation() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    // The built-in texts as the update_translations target lists them for lupdate.
    const QString builtins = dir.filePath(QStringLiteral("builtin-texts.cpp"));
    {
        QFile out(builtins);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(i18n::lupdateSource(i18n::builtinTexts()).toUtf8());
    }
    QStringList tsCopies;
    for (const QString& lang : kLanguages) {
        const QString copy = dir.filePath(QStringLiteral("phasebox_%1.ts").arg(lang));
        QVERIFY(
            QFile::copy(kRoot + QStringLiteral("/translations/phasebox_%1.ts").arg(lang), copy));
        tsCopies << copy;
    }
    QProcess lupdate;
    QStringList args{QStringLiteral("-I"),           kRoot,
                     QStringLiteral("-no-obsolete"), QStringLiteral("-locations"),
                     QStringLiteral("none"),         QStringLiteral("-silent")};
    args << translatedSources() << builtins << QStringLiteral("-ts") << tsCopies;
    lupdate.start(QStringLiteral(PHASEBOX_LUPDATE), args);
    QVERIFY2(lupdate.waitForFinished(300'000), qPrintable(lupdate.errorString()));
    QCOMPARE(lupdate.exitCode(), 0);

    QStringList problems;
    for (int k = 0; k < tsCopies.size(); ++k) {
        QString error;
        const QList<Message> messages = readTs(tsCopies[k], &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY(messages.size() > 500);
        int unfinished = 0;
        for (const Message& m : messages) {
            const bool empty = std::any_of(m.translations.begin(), m.translations.end(),
                                           [](const QString& t) { return t.isEmpty(); });
            if (!m.unfinished && !empty && !m.translations.isEmpty()) continue;
            if (++unfinished <= 5) problems << kLanguages[k] + QStringLiteral(": ") + describe(m);
        }
        if (unfinished > 5)
            problems
                << QStringLiteral("%1: … %2 unfinished in all").arg(kLanguages[k]).arg(unfinished);
    }
    QVERIFY2(problems.isEmpty(),
             qPrintable(QStringLiteral("texts without a translation (translate them in "
                                       "translations/*.ts after `cmake --build --preset release "
                                       "--target update_translations`, docs/translations.md):\n") +
                        problems.join(QLatin1Char('\n'))));
}

void TestTranslations::translationsKeepPlaceholdersAndAccelerators() {
    static const QRegularExpression entity(QStringLiteral("&[a-z]+;|&#"));
    QStringList problems;
    for (const QString& lang : kLanguages) {
        QString error;
        const QList<Message> messages =
            readTs(kRoot + QStringLiteral("/translations/phasebox_%1.ts").arg(lang), &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        for (const Message& m : messages) {
            if (m.unfinished) continue;  // noTextLacksATranslation's business
            if (m.numerus && m.translations.size() != 2)
                problems << lang + QStringLiteral(": two plural forms expected: ") + describe(m);
            for (const QString& t : m.translations) {
                if (placeholders(t) != placeholders(m.source))
                    problems << lang + QStringLiteral(": placeholders differ: ") + describe(m);
                if (m.numerus && !t.contains(QLatin1String("%n")) &&
                    m.source.contains(QLatin1String("%n")))
                    problems << lang + QStringLiteral(": %n missing: ") + describe(m);
                if (!m.source.contains(entity) && accelerators(t) != accelerators(m.source))
                    problems << lang + QStringLiteral(": accelerators differ: ") + describe(m) +
                                    QStringLiteral(" → \"") + t + QLatin1Char('"');
            }
        }
    }
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
}

void TestTranslations::builtinTextsAreTranslatedInTheApp() {
    const std::vector<i18n::BuiltinText> texts = i18n::builtinTexts();
    // The scenes, the lessons, the schema and the integrators all take part.
    QVERIFY(texts.size() > 150);
    for (const QString& lang : kLanguages) {
        QTranslator translator;
        QVERIFY2(translator.load(QStringLiteral(":/i18n/phasebox_%1.qm").arg(lang)),
                 qPrintable(lang));
        QStringList missing;
        for (const i18n::BuiltinText& t : texts) {
            const QByteArray source = t.text.toUtf8();
            if (translator.translate(t.context, source.constData()).isEmpty()) missing << t.origin;
        }
        QVERIFY2(missing.isEmpty(), qPrintable(lang + QStringLiteral(": ") + missing.join(", ")));
    }
}

void TestTranslations::installedLanguageTranslatesTextsAndNumbers() {
    QVERIFY(i18n::install(QStringLiteral("de")));
    QCOMPARE(i18n::installedLanguage(), QStringLiteral("de"));
    QCOMPARE(QCoreApplication::translate("phasebox::MainWindow", "&File"),
             QStringLiteral("&Datei"));
    QCOMPARE(QLocale().toString(0.25), QStringLiteral("0,25"));
    QVERIFY(i18n::install(QStringLiteral("fr")));
    QCOMPARE(QCoreApplication::translate("phasebox::MainWindow", "&File"),
             QStringLiteral("&Fichier"));
    QVERIFY(i18n::install(QStringLiteral("es")));
    QCOMPARE(QCoreApplication::translate("phasebox::MainWindow", "&File"),
             QStringLiteral("&Archivo"));
    QVERIFY(i18n::install(QStringLiteral("en")));
    QCOMPARE(QCoreApplication::translate("phasebox::MainWindow", "&File"), QStringLiteral("&File"));
    QCOMPARE(i18n::resolve(QStringLiteral("fr")), QStringLiteral("fr"));
    QVERIFY(i18n::languages().contains(i18n::resolve(QString())));
    QVERIFY(!i18n::install(QStringLiteral("xx")));
    QVERIFY(i18n::install(QStringLiteral("en")));
}

void TestTranslations::filesStayDotDecimalUnderAGermanLocale() {
    QVERIFY(i18n::install(QStringLiteral("de")));
    QCOMPARE(QLocale().decimalPoint(), QStringLiteral(","));
    SceneDesc scene;
    scene.name = "Komma";
    scene.simulation.dt = 0.025;
    ParticleDesc p;
    p.id = "ball";
    p.position = {1.5, -0.25};
    p.mass = 2.75;
    scene.particles.push_back(p);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("komma.phasebox.json"));
    QString error;
    QVERIFY2(SceneIO::save(scene, path, &error), qPrintable(error));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray json = file.readAll();
    for (const char* number : {"0.025", "1.5", "-0.25", "2.75"})
        QVERIFY2(json.contains(number), number);
    QVERIFY(!json.contains("0,025"));
    QVERIFY(!json.contains("2,75"));
    // CSV numbers (Recorder, ProbeRecorder, the accuracy table) go through formatNumber.
    QCOMPARE(formatNumber(2.75), QStringLiteral("2.75"));
    const SceneLoadResult loaded = SceneIO::load(path);
    QVERIFY(loaded.ok());
    QCOMPARE(loaded.scene->particles.at(0).mass, 2.75);
    QVERIFY(i18n::install(QStringLiteral("en")));
}

QTEST_GUILESS_MAIN(TestTranslations)
#include "tst_translations.moc"
