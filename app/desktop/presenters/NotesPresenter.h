#pragma once
// The Notes dock: the scene's name and description, what to try with it.

#include "app/desktop/presenters/Presenter.h"

QT_BEGIN_NAMESPACE
class QTextBrowser;
QT_END_NAMESPACE

namespace phasebox {

class Document;

class NotesPresenter : public Presenter {
    Q_OBJECT

public:
    NotesPresenter(QTextBrowser& notes, Document& document, QObject* parent = nullptr);

    void refresh() override;

signals:
    // A scene with a description was opened (MainWindow raises the dock).
    void notesToRead();

private:
    QTextBrowser& notes_;
    Document& document_;
    QString shown_;  // the HTML last set: laying out long notes again costs a visible pause
};

}  // namespace phasebox
