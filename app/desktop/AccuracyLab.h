#pragma once
// Tools > Accuracy Lab: the study dialog made on first use, given the open scene each time it
// is shown (unless a study is running), and its Apply sent to the parameters, only while the
// scene is still the one it studied (every edit, New, Open and Revert is checked).

#include <QObject>

QT_BEGIN_NAMESPACE
class QWidget;
QT_END_NAMESPACE

namespace phasebox {

class AccuracyDialog;
class Document;
class ParametersPresenter;

class AccuracyLab : public QObject {
    Q_OBJECT

public:
    // The dialog's parent is the window (its object name is "accuracyDialog"); the lab's own
    // object name is "accuracyLabController".
    AccuracyLab(QWidget& window, Document& document, ParametersPresenter& parameters);

    // The dialog, made on first use.
    AccuracyDialog* dialog();
    void show();

private:
    QWidget& window_;
    Document& document_;
    ParametersPresenter& parameters_;
    AccuracyDialog* dialog_ = nullptr;
};

}  // namespace phasebox
