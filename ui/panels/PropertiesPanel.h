#pragma once
// The properties panel: the selected object's numbers in a form. It shows what it is given and
// reports what the user commits (propertyEdited); the app turns that into an undo command and
// answers with updateValues() or showError().

#include <QDoubleSpinBox>
#include <QHash>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <optional>
#include <vector>

QT_BEGIN_NAMESPACE
class QCheckBox;
class QFormLayout;
class QLabel;
class QStackedWidget;
QT_END_NAMESPACE

namespace phasebox::ui {

// A spin box for physical quantities whose range spans many decades (a stiffness of 1e6 N/m,
// a dt of 1e-4 s, a tolerance of 1e-9): accepts scientific notation, shows very large and very
// small numbers in it, and keeps the exact double it was given. QDoubleSpinBox alone rounds
// every value to its fixed decimals, so 1/60 would come back as 0.01667 and 1e-9 as 0.
// The parameters panel uses it too (dt, tolerance); it lives here because the properties form
// is its main user.
class ScientificSpinBox : public QDoubleSpinBox {
    Q_OBJECT
public:
    explicit ScientificSpinBox(QWidget* parent = nullptr);

    // Everyday magnitudes with this many fixed decimals; scientific outside [1e-3, 1e6).
    void setDisplayDecimals(int decimals);
    // Shortest form with at most this many significant digits (dt: 0.01667, 0.001, 1e-5).
    void setSignificantDigits(int digits);
    // factor > 1: the arrows multiply or divide by it (log-scale quantities such as dt and
    // tolerance); 0: steps of a tenth of the value's order of magnitude.
    void setStepFactor(double factor) { stepFactor_ = factor; }

    // The user has typed into the field and not yet committed it.
    bool isBeingEdited() const;

    QString formatNumber(double value) const;
    // Parses a number in the widget's locale or in C notation ("1e6", "0.5"), without affixes.
    std::optional<double> parseNumber(const QString& text) const;

    QValidator::State validate(QString& text, int& pos) const override;
    double valueFromText(const QString& text) const override;
    QString textFromValue(double value) const override;
    void fixup(QString& input) const override;
    void stepBy(int steps) override;

signals:
    // Committed text that is not a number in range; the spin box has gone back to its value.
    void inputRejected(const QString& reason);

protected:
    void keyPressEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;

private:
    QString stripAffixes(const QString& text) const;
    void reportIfRejected();

    int displayDecimals_ = 3;
    int significantDigits_ = 0;  // 0: fixed decimals
    double stepFactor_ = 0.0;
};

struct PropertyField {
    QString key;    // what propertyEdited reports, e.g. `mass`, `position.x`
    QString label;  // for people; may hold a mnemonic: "&Mass"
    QString unit;   // shown as the suffix: "kg", "N/m"; empty for none
    double value = 0.0;
    double minimum = 0.0;
    double maximum = 1e9;
    int decimals = 3;
    bool isBool = false;  // a check box; value 0 or 1
};

class PropertiesPanel : public QWidget {
    Q_OBJECT
public:
    explicit PropertiesPanel(QWidget* parent = nullptr);

    // Shows an object. The same keys as shown already only update title and values, so a
    // selection refreshed every frame neither rebuilds the form nor moves the focus.
    void setObject(const QString& title, const std::vector<PropertyField>& fields);
    // Nothing selected: the empty-state hint.
    void clearObject();
    bool hasObject() const;
    QString title() const;
    QStringList keys() const { return keys_; }

    // New numbers for the fields shown (by key) while the simulation runs. A field the user
    // is typing into keeps the typed text; unknown keys are ignored.
    void updateValues(const std::vector<PropertyField>& fields);

    // Under the title: whether the numbers are the live state of a run (live: true, set every
    // frame) or the setup that Reset returns to.
    void setStateNote(const QString& text, bool live);
    QString stateNote() const;
    bool showsLiveState() const { return live_; }

    // A validation message under the form, in red; cleared by the next committed edit.
    void showError(const QString& message);
    void clearError();
    QString errorText() const;

    // The editor of a field (a ScientificSpinBox or a QCheckBox), for tests and focus.
    QWidget* editor(const QString& key) const { return editors_.value(key); }

signals:
    void propertyEdited(const QString& key, double value);

private:
    void buildForm(const std::vector<PropertyField>& fields);
    void setFieldValue(const QString& key, double value);
    void commitEdit(const QString& key, double value);

    QStackedWidget* pages_ = nullptr;
    QLabel* emptyHint_ = nullptr;
    QLabel* title_ = nullptr;
    QLabel* stateNote_ = nullptr;
    bool live_ = false;
    QWidget* form_ = nullptr;
    QFormLayout* formLayout_ = nullptr;
    QLabel* error_ = nullptr;
    QStringList keys_;
    QHash<QString, QWidget*> editors_;
};

}  // namespace phasebox::ui
