// The Help menu: F1 opens the user guide (docs/user-guide.md, compiled in) with its first
// heading in view and its pictures loaded; Keyboard Shortcuts lists every action of the window
// that has a key, read from the actions when it opens.

#include "app/desktop/MainWindow.h"

#include <QAbstractTextDocumentLayout>
#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QFile>
#include <QScrollBar>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTest>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextFragment>
#include <QTextImageFormat>

using namespace phasebox;

namespace {

// The first "# " line of the guide as it is in the repository.
QString firstHeading() {
    QFile file(QStringLiteral(PHASEBOX_SOURCE_DIR "/docs/user-guide.md"));
    if (!file.open(QIODevice::ReadOnly)) return {};
    while (!file.atEnd()) {
        const QString line = QString::fromUtf8(file.readLine()).trimmed();
        if (line.startsWith(QLatin1String("# "))) return line.mid(2).trimmed();
    }
    return {};
}

void savePicture(QWidget* widget, const QString& name) {
    const QString dir = qEnvironmentVariable("PHASEBOX_SCREENSHOT_DIR");
    if (dir.isEmpty()) return;
    QApplication::processEvents();
    widget->grab().save(QStringLiteral("%1/%2.png").arg(dir, name));
}

QString plain(QString text) {
    return text.remove(QLatin1Char('&')).remove(QStringLiteral("…")).trimmed();
}

}  // namespace

class TestHelp : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void f1OpensTheGuideAtItsFirstHeading() {
        MainWindow w;
        w.resize(1024, 700);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        // The shortcut map asks the application which window is active (a bare X server has
        // no window manager to make it so).
        QApplication::setActiveWindow(&w);
        QCOMPARE(QApplication::activeWindow(), &w);
        QAction* guideAction = w.action(QStringLiteral("userGuide"));
        QVERIFY(guideAction);
        QCOMPARE(guideAction->shortcut(), QKeySequence(Qt::Key_F1));
        QVERIFY(!w.findChild<QDialog*>(QStringLiteral("userGuideDialog")));

        QTest::keyClick(&w, Qt::Key_F1);
        auto* dialog = w.findChild<QDialog*>(QStringLiteral("userGuideDialog"));
        QVERIFY(dialog);
        QVERIFY(dialog->isVisible());
        dialog->resize(1024, 700);
        auto* browser = dialog->findChild<QTextBrowser*>(QStringLiteral("userGuide"));
        QVERIFY(browser);

        // The first block is the guide's title, as a heading, at the top of the view.
        const QString heading = firstHeading();
        QVERIFY(!heading.isEmpty());
        QTextDocument* doc = browser->document();
        const QTextBlock first = doc->begin();
        QCOMPARE(first.text(), heading);
        QCOMPARE(first.blockFormat().headingLevel(), 1);
        QCOMPARE(browser->verticalScrollBar()->value(), 0);
        const QRectF at = doc->documentLayout()->blockBoundingRect(first);
        QVERIFY(at.height() > 0.0);
        QVERIFY2(at.bottom() < browser->viewport()->height(), "the heading is out of view");
        // And more of the guide than its title: a later section is there too.
        QVERIFY(browser->toPlainText().contains(QStringLiteral("Building a scene")));

        // The guide's pictures resolve beside it in the resources, scaled to the page.
        const QVariant picture =
            browser->loadResource(QTextDocument::ImageResource, QUrl("images/app-demo.png"));
        const QImage image = picture.value<QImage>();
        QVERIFY(image.width() > 100);
        QVERIFY(image.width() <= browser->viewport()->width());
        // Each picture once (Qt's reader repeats an image whose caption spans lines).
        int demoPictures = 0;
        for (QTextBlock b = doc->begin(); b.isValid(); b = b.next())
            for (auto f = b.begin(); !f.atEnd(); ++f)
                if (f.fragment().charFormat().isImageFormat() &&
                    f.fragment().charFormat().toImageFormat().name() ==
                        QStringLiteral("images/app-demo.png"))
                    ++demoPictures;
        QCOMPARE(demoPictures, 1);
        // One that is missing is dropped, not shown as a broken box.
        const QImage missing =
            browser->loadResource(QTextDocument::ImageResource, QUrl("images/none.png"))
                .value<QImage>();
        QCOMPARE(missing.size(), QSize(1, 1));
        savePicture(dialog, QStringLiteral("help-user-guide-1024x700"));

        // A link to a section scrolls to its heading (Qt's reader makes no anchors itself).
        emit browser->anchorClicked(QUrl(QStringLiteral("#measuring-the-instruments-dock")));
        QCOMPARE(browser->textCursor().block().text(),
                 QStringLiteral("Measuring: the Instruments dock"));
        QVERIFY(browser->verticalScrollBar()->value() > 0);
        browser->verticalScrollBar()->setValue(0);

        // F1 again brings back the same dialog, not a second one.
        dialog->close();
        QApplication::setActiveWindow(&w);
        QCOMPARE(QApplication::activeWindow(), &w);
        QTest::keyClick(&w, Qt::Key_F1);
        QCOMPARE(w.findChildren<QDialog*>(QStringLiteral("userGuideDialog")).size(), 1);
        QVERIFY(dialog->isVisible());
    }

    void shortcutsListEveryActionWithAKey() {
        MainWindow w;
        w.resize(1024, 700);
        w.show();
        QAction* list = w.action(QStringLiteral("keyboardShortcuts"));
        QVERIFY(list);
        list->trigger();
        auto* dialog = w.findChild<QDialog*>(QStringLiteral("shortcutsDialog"));
        QVERIFY(dialog && dialog->isVisible());
        auto* table = dialog->findChild<QTableWidget*>(QStringLiteral("shortcutsTable"));
        QVERIFY(table);
        const auto hasRow = [&](const QString& action, const QString& key) {
            for (int row = 0; row < table->rowCount(); ++row)
                if (table->item(row, 0)->text() == action &&
                    table->item(row, 1)->text().split(QStringLiteral("; ")).contains(key))
                    return true;
            return false;
        };
        int withKeys = 0;
        QList<QAction*> seen;
        for (QAction* a : w.findChildren<QAction*>()) {
            if (a->shortcuts().isEmpty() || seen.contains(a)) continue;
            seen.append(a);
            ++withKeys;
            for (const QKeySequence& key : a->shortcuts())
                QVERIFY2(hasRow(plain(a->text()), key.toString(QKeySequence::NativeText)),
                         qPrintable(QStringLiteral("missing: %1 (%2)")
                                        .arg(a->text(), key.toString(QKeySequence::NativeText))));
        }
        QCOMPARE(table->rowCount(), withKeys);
        QVERIFY(withKeys > 30);  // the window has dozens: a broken walk would find a few
        QVERIFY(hasRow(QStringLiteral("User Guide"), QStringLiteral("F1")));
        QVERIFY(hasRow(QStringLiteral("Accuracy Lab"), QStringLiteral("Ctrl+Shift+A")));
        dialog->resize(1024, 700);
        savePicture(dialog, QStringLiteral("help-shortcuts-1024x700"));

        // Made from the actions each time: a key added later shows up the next time.
        auto* added = new QAction(QStringLiteral("Test &Action"), &w);
        added->setShortcut(QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_J));
        w.addAction(added);
        list->trigger();
        QCOMPARE(w.findChildren<QDialog*>(QStringLiteral("shortcutsDialog")).size(), 1);
        dialog = w.findChild<QDialog*>(QStringLiteral("shortcutsDialog"));
        table = dialog->findChild<QTableWidget*>(QStringLiteral("shortcutsTable"));
        QCOMPARE(table->rowCount(), withKeys + 1);
        QVERIFY(hasRow(QStringLiteral("Test Action"), QStringLiteral("Ctrl+Alt+J")));
    }
};

QTEST_MAIN(TestHelp)
#include "tst_help.moc"
