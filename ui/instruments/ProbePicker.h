#pragma once
// A probe chooser: an editable combo box that lists the probes the scene offers (all of them
// valid: the app fills it from the world) and completes what is typed against them. Picking an
// item or pressing Enter emits probeEntered(); the app checks typed text and answers with
// setInvalid() when it is not a probe. An optional first item that is not a probe ("time" on
// an axis, "—" for nothing) is entered as "".

#include <QComboBox>
#include <QString>
#include <QStringList>

namespace phasebox::ui {

class ProbePicker : public QComboBox {
    Q_OBJECT

public:
    // noneText: the first item, entered as "" (empty: no such item).
    explicit ProbePicker(const QString& placeholder, const QString& noneText = {},
                         QWidget* parent = nullptr);

    // Replaces the list (no signal); what is shown stays.
    void setOffered(const QStringList& probes);
    QStringList offered() const { return offered_; }
    // The probe shown ("" for the none item).
    QString probe() const;
    // Shows this probe (no signal); "" shows the none item, or nothing.
    void setProbe(const QString& text);
    // A red frame and the reason as tool tip; an empty reason clears it.
    void setInvalid(const QString& reason);
    bool isInvalid() const { return invalid_; }
    // As if the user had typed text and pressed Enter.
    void enter(const QString& text);

signals:
    void probeEntered(const QString& text);

private:
    void onActivated(int index);
    void onReturnPressed();

    QString noneText_;
    QStringList offered_;
    bool invalid_ = false;
};

}  // namespace phasebox::ui
