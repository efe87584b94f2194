#include "ui/instruments/ProbePicker.h"

#include <QCompleter>
#include <QLineEdit>
#include <QSignalBlocker>

namespace phasebox::ui {

ProbePicker::ProbePicker(const QString& placeholder, const QString& noneText, QWidget* parent)
    : QComboBox(parent), noneText_(noneText) {
    setEditable(true);
    setInsertPolicy(QComboBox::NoInsert);
    setMaxVisibleItems(20);
    setMinimumContentsLength(10);
    setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    lineEdit()->setPlaceholderText(placeholder);
    lineEdit()->setClearButtonEnabled(false);
    // Typing "omega" finds every object's ω: match anywhere, in a list under the box.
    completer()->setFilterMode(Qt::MatchContains);
    completer()->setCaseSensitivity(Qt::CaseInsensitive);
    completer()->setCompletionMode(QCompleter::PopupCompletion);
    setToolTip(
        tr("Pick a probe, or type one (CONTRACT §7: ID.x, system.total, "
           "distance(A,B), …) and press Enter"));
    if (!noneText_.isEmpty()) addItem(noneText_, QString());
    connect(this, &QComboBox::activated, this, &ProbePicker::onActivated);
    connect(lineEdit(), &QLineEdit::returnPressed, this, &ProbePicker::onReturnPressed);
}

void ProbePicker::setOffered(const QStringList& probes) {
    if (probes == offered_) return;
    const QString shown = currentText();
    const QSignalBlocker block(this);
    offered_ = probes;
    clear();
    if (!noneText_.isEmpty()) addItem(noneText_, QString());
    for (const QString& p : probes) addItem(p, p);
    const int index = findText(shown, Qt::MatchExactly);
    setCurrentIndex(index);
    if (index < 0) setEditText(shown);
}

QString ProbePicker::probe() const {
    const QString text = currentText().trimmed();
    return !noneText_.isEmpty() && text == noneText_ ? QString() : text;
}

void ProbePicker::setProbe(const QString& text) {
    const QSignalBlocker block(this);
    const QString shown = text.isEmpty() ? noneText_ : text;
    const int index = findText(shown, Qt::MatchExactly);
    setCurrentIndex(index);
    if (index < 0) setEditText(shown);
}

void ProbePicker::setInvalid(const QString& reason) {
    invalid_ = !reason.isEmpty();
    setStyleSheet(invalid_ ? QStringLiteral("QComboBox { border: 2px solid #d62728; }")
                           : QString());
    setToolTip(invalid_ ? reason
                        : tr("Pick a probe, or type one (CONTRACT §7: ID.x, system.total, "
                             "distance(A,B), …) and press Enter"));
}

void ProbePicker::enter(const QString& text) {
    setEditText(text);
    onReturnPressed();
}

void ProbePicker::onActivated(int index) {
    const QVariant data = itemData(index);
    emit probeEntered(data.isValid() ? data.toString() : itemText(index));
}

void ProbePicker::onReturnPressed() {
    // QComboBox may also emit activated() for an item's text on Enter: the app takes a probe
    // entered twice as once.
    const QString text = currentText().trimmed();
    emit probeEntered(!noneText_.isEmpty() && text == noneText_ ? QString() : text);
}

}  // namespace phasebox::ui
