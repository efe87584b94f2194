#pragma once
// The dialog that says the simulation blew up: window-modal and opened, not exec()'d, so the
// window stays responsive behind it, and a later blow-up updates the one dialog instead of
// stacking another (object name "divergenceDialog"). New, Open, Reset and Revert end the run it
// speaks of, so the scene's reset closes it.

#include <QObject>
#include <QPointer>
#include <QString>

QT_BEGIN_NAMESPACE
class QMessageBox;
class QWidget;
QT_END_NAMESPACE

namespace phasebox {

class Document;

class DivergenceNotice : public QObject {
    Q_OBJECT

public:
    DivergenceNotice(QWidget& window, Document& document);

    // Shows the report (message, with details behind a button) while the window is visible.
    void show(const QString& message, const QString& details);
    // The line for the status bar: what happened and where, the message's first two lines.
    static QString statusLine(const QString& message);

private:
    QWidget& window_;
    QPointer<QMessageBox> box_;  // while it is open
};

}  // namespace phasebox
