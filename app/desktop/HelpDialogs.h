#pragma once
// Help > User Guide and Help > Keyboard Shortcuts. The guide is docs/user-guide.md compiled in
// (:/docs/user-guide.md, its pictures in :/docs/images), shown as Markdown, so the app and the
// repository read the same text. The shortcut table is made from the window's actions each time
// it opens: a key added or changed anywhere shows there without anyone editing a list.

#include <QObject>
#include <QPointer>
#include <QString>

#include <vector>

QT_BEGIN_NAMESPACE
class QDialog;
class QWidget;
QT_END_NAMESPACE

namespace phasebox {

// The guide in a non-modal dialog (object name "userGuideDialog"; its QTextBrowser is
// "userGuide"). A picture is scaled down to the page's width; one that is missing is left out.
// A link to a section of the guide scrolls there, a web link opens in the browser; a link to
// another file of docs/ does nothing (only the guide is compiled in).
QDialog* createUserGuideDialog(QWidget* parent);

// One action with a shortcut: its text without the mnemonic '&', every key that triggers it
// (in the platform's own spelling, "; " between them) and its tool tip.
struct ShortcutEntry {
    QString action;
    QString keys;
    QString toolTip;
};
// Every QAction under window (its whole object tree) with at least one shortcut, each once,
// sorted by the action's text.
std::vector<ShortcutEntry> collectShortcuts(const QWidget& window);

// The table of collectShortcuts(window) in a dialog (object name "shortcutsDialog"; its
// QTableWidget is "shortcutsTable", columns action and keys).
QDialog* createShortcutsDialog(QWidget& window);

// Help > User Guide, Keyboard Shortcuts and About for a window: the guide is made once and
// kept; the shortcut table is made anew each time from the actions as they are then.
class HelpWindows : public QObject {
    Q_OBJECT

public:
    explicit HelpWindows(QWidget& window);
    void showUserGuide();
    void showKeyboardShortcuts();
    void showAbout();

private:
    QWidget& window_;
    QDialog* guide_ = nullptr;
    QPointer<QDialog> shortcuts_;  // deletes itself on close
};

}  // namespace phasebox
