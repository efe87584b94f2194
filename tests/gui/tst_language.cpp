// The window in another language: built after a language is installed, its menus, docks, tools
// and a built-in lesson's name are translated and the numbers it shows follow the language's
// locale; View > Language stores the choice (or forgets it for the system's) for the next start.

#include "app/desktop/MainWindow.h"
#include "app/i18n/Language.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>

using namespace phasebox;

class TestLanguage : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void cleanup() { i18n::install(QStringLiteral("en")); }
    void windowSpeaksTheInstalledLanguage();
    void languageMenuStoresTheChoice();
};

void TestLanguage::windowSpeaksTheInstalledLanguage() {
    QVERIFY(i18n::install(QStringLiteral("de")));
    MainWindow window;
    QStringList menus;
    for (QAction* a : window.menuBar()->actions()) menus << a->text();
    QVERIFY2(menus.contains(QStringLiteral("&Datei")), qPrintable(menus.join(' ')));
    QVERIFY(menus.contains(QStringLiteral("&Ansicht")));
    QCOMPARE(window.action(QStringLiteral("toolParticle"))->text(),
             QStringLiteral("Teilchen hinzufügen"));
    QStringList docks;
    for (QDockWidget* dock : window.findChildren<QDockWidget*>()) docks << dock->windowTitle();
    QVERIFY(docks.contains(QStringLiteral("Eigenschaften")));
    QVERIFY(window.openFile(QStringLiteral(":/lessons/simple-pendulum.phasebox.json"), true));
    QVERIFY2(window.windowTitle().startsWith(QStringLiteral("Lektion: das Fadenpendel")),
             qPrintable(window.windowTitle()));
    QCOMPARE(QLocale().toString(0.5), QStringLiteral("0,5"));
}

void TestLanguage::languageMenuStoresTheChoice() {
    QSettings().remove(QStringLiteral("language"));
    MainWindow window;
    auto* menu = window.findChild<QMenu*>(QStringLiteral("languageMenu"));
    QVERIFY(menu);
    QCOMPARE(menu->actions().size(), 1 + i18n::languages().size());  // the system's and each
    auto* french = window.findChild<QAction*>(QStringLiteral("language_fr"));
    QVERIFY(french);
    QCOMPARE(french->text(), QStringLiteral("Français"));
    french->trigger();
    QCOMPARE(QSettings().value(QStringLiteral("language")).toString(), QStringLiteral("fr"));
    QCOMPARE(MainWindow::storedLanguage(), QStringLiteral("fr"));
    window.findChild<QAction*>(QStringLiteral("language_system"))->trigger();
    QVERIFY(!QSettings().contains(QStringLiteral("language")));
    QCOMPARE(MainWindow::storedLanguage(), QString());
}

QTEST_MAIN(TestLanguage)
#include "tst_language.moc"
