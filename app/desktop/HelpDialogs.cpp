#include "app/desktop/HelpDialogs.h"

#include <QAbstractTextDocumentLayout>
#include <QAction>
#include <QDesktopServices>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFile>
#include <QHeaderView>
#include <QImage>
#include <QLabel>
#include <QMessageBox>
#include <QRegularExpression>
#include <QScrollBar>
#include <QTableWidget>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextCursor>
#include <QUrl>
#include <QVBoxLayout>

#include <algorithm>

namespace phasebox {

namespace {

// A QTextBrowser that scales pictures to the page (the guide's screenshots are wider than a
// dialog) and drops a picture it cannot load instead of showing a broken-image box.
class GuideBrowser : public QTextBrowser {
public:
    using QTextBrowser::QTextBrowser;

    QVariant loadResource(int type, const QUrl& name) override {
        const QVariant loaded = QTextBrowser::loadResource(type, name);
        if (type != QTextDocument::ImageResource) return loaded;
        QImage image;
        if (loaded.canConvert<QImage>()) image = loaded.value<QImage>();
        if (image.isNull() && loaded.canConvert<QByteArray>())
            image.loadFromData(loaded.toByteArray());
        if (image.isNull()) {
            // A 1×1 transparent pixel: the caption (alt text) is not shown and nothing breaks.
            QImage none(1, 1, QImage::Format_ARGB32);
            none.fill(Qt::transparent);
            return none;
        }
        const int width = std::max(320, viewport()->width() - 40);
        if (image.width() > width) image = image.scaledToWidth(width, Qt::SmoothTransformation);
        return image;
    }
};

// Qt 6.4's Markdown reader inserts an image once per line of its alt text, so a caption
// written over two lines ("![The demo scene …\n… one corner](images/app-demo.png)") shows the
// picture twice. One line each, then.
QString joinImageCaptions(QString markdown) {
    static const QRegularExpression caption(QStringLiteral("!\\[([^\\]]*)\\]\\("));
    QString out;
    qsizetype from = 0;
    for (auto it = caption.globalMatch(markdown); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        out += QStringView(markdown).mid(from, m.capturedStart(1) - from);
        out += m.captured(1).simplified();
        from = m.capturedEnd(1);
    }
    out += QStringView(markdown).mid(from);
    return out;
}

// GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens. The guide
// links its own sections that way ("#measuring-the-instruments-dock"); Qt's Markdown reader
// makes no anchors, so a link is followed by finding the heading it names.
QString headingSlug(const QString& heading) {
    QString slug;
    for (const QChar c : heading.toLower()) {
        if (c.isLetterOrNumber() || c == QLatin1Char('-') || c == QLatin1Char('_'))
            slug += c;
        else if (c == QLatin1Char(' '))
            slug += QLatin1Char('-');
    }
    return slug;
}

void followLink(QTextBrowser& browser, const QUrl& url) {
    if (url.scheme() == QLatin1String("http") || url.scheme() == QLatin1String("https")) {
        QDesktopServices::openUrl(url);
        return;
    }
    if (!url.hasFragment() || !url.path().isEmpty()) return;  // another file: not in the app
    for (QTextBlock b = browser.document()->begin(); b.isValid(); b = b.next()) {
        if (b.blockFormat().headingLevel() == 0 || headingSlug(b.text()) != url.fragment())
            continue;
        QTextCursor cursor(b);
        browser.setTextCursor(cursor);
        const QRectF at = browser.document()->documentLayout()->blockBoundingRect(b);
        browser.verticalScrollBar()->setValue(static_cast<int>(at.top()));
        return;
    }
}

QString withoutMnemonic(QString text) {
    text.replace(QStringLiteral("&&"), QStringLiteral("\x01"));
    text.remove(QLatin1Char('&'));
    text.replace(QStringLiteral("\x01"), QStringLiteral("&"));
    text.remove(QStringLiteral("…"));
    return text.trimmed();
}

}  // namespace

QDialog* createUserGuideDialog(QWidget* parent) {
    auto* dialog = new QDialog(parent);
    dialog->setObjectName(QStringLiteral("userGuideDialog"));
    dialog->setWindowTitle(QObject::tr("Phasebox User Guide"));
    dialog->resize(900, 680);
    auto* browser = new GuideBrowser(dialog);
    browser->setObjectName(QStringLiteral("userGuide"));
    browser->setAccessibleName(QObject::tr("User guide"));
    browser->setOpenLinks(false);
    QObject::connect(browser, &QTextBrowser::anchorClicked, browser,
                     [browser](const QUrl& url) { followLink(*browser, url); });
    // Relative links and pictures resolve beside the guide, in the resources.
    browser->setSearchPaths({QStringLiteral(":/docs")});
    QFile file(QStringLiteral(":/docs/user-guide.md"));
    if (file.open(QIODevice::ReadOnly)) {
        browser->document()->setBaseUrl(QUrl(QStringLiteral("qrc:/docs/")));
        browser->setMarkdown(joinImageCaptions(QString::fromUtf8(file.readAll())));
    } else {
        browser->setPlainText(QObject::tr("The user guide is missing from this build."));
    }
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    auto* layout = new QVBoxLayout(dialog);
    layout->addWidget(browser, 1);
    layout->addWidget(buttons);
    return dialog;
}

std::vector<ShortcutEntry> collectShortcuts(const QWidget& window) {
    std::vector<ShortcutEntry> entries;
    std::vector<const QAction*> seen;
    for (const QAction* a : window.findChildren<QAction*>()) {
        if (a->shortcuts().isEmpty() || a->isSeparator()) continue;
        if (std::find(seen.begin(), seen.end(), a) != seen.end()) continue;
        seen.push_back(a);
        QStringList keys;
        for (const QKeySequence& key : a->shortcuts())
            keys << key.toString(QKeySequence::NativeText);
        entries.push_back({withoutMnemonic(a->text()), keys.join(QStringLiteral("; ")),
                           a->toolTip() == withoutMnemonic(a->text()) ? QString() : a->toolTip()});
    }
    std::sort(entries.begin(), entries.end(), [](const ShortcutEntry& a, const ShortcutEntry& b) {
        return a.action.localeAwareCompare(b.action) < 0;
    });
    return entries;
}

QDialog* createShortcutsDialog(QWidget& window) {
    auto* dialog = new QDialog(&window);
    dialog->setObjectName(QStringLiteral("shortcutsDialog"));
    dialog->setWindowTitle(QObject::tr("Keyboard Shortcuts"));
    dialog->resize(560, 640);
    const std::vector<ShortcutEntry> entries = collectShortcuts(window);
    auto* table = new QTableWidget(static_cast<int>(entries.size()), 2, dialog);
    table->setObjectName(QStringLiteral("shortcutsTable"));
    table->setAccessibleName(QObject::tr("Keyboard shortcuts"));
    table->setHorizontalHeaderLabels({QObject::tr("action"), QObject::tr("keys")});
    table->verticalHeader()->hide();
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setSelectionBehavior(QAbstractItemView::SelectRows);
    table->setAlternatingRowColors(true);
    for (int row = 0; row < static_cast<int>(entries.size()); ++row) {
        const ShortcutEntry& e = entries[static_cast<std::size_t>(row)];
        auto* name = new QTableWidgetItem(e.action);
        name->setToolTip(e.toolTip);
        table->setItem(row, 0, name);
        table->setItem(row, 1, new QTableWidgetItem(e.keys));
    }
    table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    table->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    auto* note = new QLabel(
        QObject::tr("Every menu command that has a key, as this window has them now."), dialog);
    note->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    auto* layout = new QVBoxLayout(dialog);
    layout->addWidget(note);
    layout->addWidget(table, 1);
    layout->addWidget(buttons);
    return dialog;
}

HelpWindows::HelpWindows(QWidget& window) : QObject(&window), window_(window) {}

void HelpWindows::showUserGuide() {
    if (!guide_) guide_ = createUserGuideDialog(&window_);
    guide_->show();
    guide_->raise();
    guide_->activateWindow();
}

void HelpWindows::showKeyboardShortcuts() {
    delete shortcuts_;
    shortcuts_ = createShortcutsDialog(window_);
    shortcuts_->setAttribute(Qt::WA_DeleteOnClose);
    shortcuts_->show();
    shortcuts_->raise();
    shortcuts_->activateWindow();
}

void HelpWindows::showAbout() {
    QMessageBox::about(&window_, tr("About Phasebox"),
                       tr("<b>Phasebox %1</b><p>A 2D physics sandbox for the classroom: drop "
                          "particles, springs, cloth and boxes into a scene, switch the "
                          "integrator while it runs, and watch what accuracy costs.</p>")
                           .arg(QStringLiteral(PHASEBOX_VERSION)));
}

}  // namespace phasebox
