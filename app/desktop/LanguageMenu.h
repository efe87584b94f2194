#pragma once
// View > Language: the system's language and every translation, the stored choice checked.
// The choice is stored at once and applies from the next start, since every text of the
// window is translated once, when it is made; the menu says so (a dialog, or under the
// offscreen platform a message for the status bar).

#include <QObject>
#include <QString>

QT_BEGIN_NAMESPACE
class QMenu;
class QWidget;
QT_END_NAMESPACE

namespace phasebox {

class LanguageMenu : public QObject {
    Q_OBJECT

public:
    // Fills menu (object name "languageMenu"; its actions "language_system", "language_de", …);
    // stored is the language chosen before ("" = follow the system).
    LanguageMenu(QMenu& menu, const QString& stored, QWidget& window);

signals:
    void message(const QString& text);

private:
    void choose(const QString& code);

    QWidget& window_;
};

}  // namespace phasebox
