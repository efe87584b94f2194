#include "ui/panels/PropertiesPanel.h"

#include <QCheckBox>
#include <QFocusEvent>
#include <QFormLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace phasebox::ui {

namespace {
// "1.5e+06" → "1.5e6", "2e-05" → "2e-5": the exponent as a person writes it.
QString tidyExponent(const QString& text) {
    const qsizetype e = text.indexOf(QLatin1Char('e'));
    if (e < 0) return text;
    QString exponent = text.mid(e + 1);
    const bool negative = exponent.startsWith(QLatin1Char('-'));
    if (negative || exponent.startsWith(QLatin1Char('+'))) exponent.remove(0, 1);
    while (exponent.size() > 1 && exponent.startsWith(QLatin1Char('0'))) exponent.remove(0, 1);
    return text.left(e) + QLatin1Char('e') + (negative ? QStringLiteral("-") : QString()) +
           exponent;
}

QString withoutMnemonic(QString label) {
    label.remove(QRegularExpression(QStringLiteral("&(?!&)")));
    return label;
}

// Gives a label a mnemonic on its first letter not taken yet, so every field of a form the
// app describes is reachable with Alt+letter without the app choosing letters.
QString withMnemonic(const QString& label, QString& taken) {
    if (label.contains(QLatin1Char('&'))) return label;
    for (qsizetype i = 0; i < label.size(); ++i) {
        const QChar c = label.at(i).toLower();
        if (!c.isLetter() || taken.contains(c)) continue;
        taken.append(c);
        QString out = label;
        out.insert(i, QLatin1Char('&'));
        return out;
    }
    return label;
}

double finiteOr(double value, double fallback) {
    return std::isfinite(value) ? value : fallback;
}

// Range and unit of a field. Only what changed is set: setRange() re-renders the text.
void applyRange(ScientificSpinBox* spin, const PropertyField& field) {
    const double low = finiteOr(field.minimum, std::numeric_limits<double>::lowest());
    const double high = finiteOr(field.maximum, std::numeric_limits<double>::max());
    const QString suffix = field.unit.isEmpty() ? QString() : QLatin1Char(' ') + field.unit;
    const QSignalBlocker blocker(spin);
    if (spin->minimum() != low || spin->maximum() != high) spin->setRange(low, high);
    if (spin->suffix() != suffix) spin->setSuffix(suffix);
}
}  // namespace

// ---- ScientificSpinBox ---------------------------------------------------------------------

ScientificSpinBox::ScientificSpinBox(QWidget* parent) : QDoubleSpinBox(parent) {
    // QDoubleSpinBox rounds every value (and the range) to its decimals; the most it allows
    // keeps a double exactly, and what is shown is decided by textFromValue() below.
    QDoubleSpinBox::setDecimals(std::numeric_limits<double>::max_exponent10 +
                                std::numeric_limits<double>::digits10);
    setKeyboardTracking(false);
    setCorrectionMode(QAbstractSpinBox::CorrectToPreviousValue);
    setAccelerated(true);
}

void ScientificSpinBox::setDisplayDecimals(int decimals) {
    displayDecimals_ = std::clamp(decimals, 0, 12);
    significantDigits_ = 0;
    setValue(value());  // re-render with the new format
    updateGeometry();
}

void ScientificSpinBox::setSignificantDigits(int digits) {
    significantDigits_ = std::clamp(digits, 1, 17);
    setValue(value());
    updateGeometry();
}

bool ScientificSpinBox::isBeingEdited() const {
    return hasFocus() && lineEdit()->isModified();
}

QString ScientificSpinBox::formatNumber(double value) const {
    // C notation, then the locale's decimal point: the exponent stays readable everywhere.
    QString text;
    const double magnitude = std::abs(value);
    if (significantDigits_ > 0) {
        text = QString::number(value, 'g', significantDigits_);
    } else if (value != 0.0 &&
               (magnitude >= 1e6 || magnitude < 0.5 * std::pow(10.0, -displayDecimals_))) {
        // Fixed decimals would show 0 or a long row of digits.
        text = QString::number(value, 'g', 4);
    } else {
        text = QString::number(value, 'f', displayDecimals_);
    }
    text = tidyExponent(text);
    const QString point = locale().decimalPoint();
    if (point != QLatin1String(".")) text.replace(QLatin1Char('.'), point);
    return text;
}

std::optional<double> ScientificSpinBox::parseNumber(const QString& text) const {
    QString body = text.trimmed();
    body.remove(QLatin1Char(' '));
    if (body.isEmpty()) return std::nullopt;
    QLocale local = locale();
    local.setNumberOptions(QLocale::RejectGroupSeparator);
    QLocale c = QLocale::c();
    c.setNumberOptions(QLocale::RejectGroupSeparator);
    bool ok = false;
    double value = local.toDouble(body, &ok);
    if (!ok) value = c.toDouble(body, &ok);
    if (!ok || !std::isfinite(value)) return std::nullopt;
    return value;
}

QString ScientificSpinBox::stripAffixes(const QString& text) const {
    QString body = text;
    if (!prefix().isEmpty() && body.startsWith(prefix())) body.remove(0, prefix().size());
    if (!suffix().isEmpty() && body.endsWith(suffix())) body.chop(suffix().size());
    return body.trimmed();
}

QValidator::State ScientificSpinBox::validate(QString& text, int& pos) const {
    (void)pos;
    const QString body = stripAffixes(text);
    if (body.isEmpty()) return QValidator::Intermediate;
    // The current value as shown is always fine, even when rounding put the text just past a
    // bound (a maximum of 2/3 shown as 0.6667).
    if (body == textFromValue(value())) return QValidator::Acceptable;
    if (const auto value = parseNumber(body))
        return *value >= minimum() && *value <= maximum() ? QValidator::Acceptable
                                                          : QValidator::Intermediate;
    // Something on its way to a number ("-", "1e", "2.5e-") may be typed on.
    static const QRegularExpression partial(
        QStringLiteral(R"(^[+-]?\d*([.,]\d*)?([eE][+-]?\d*)?$)"));
    return partial.match(body).hasMatch() ? QValidator::Intermediate : QValidator::Invalid;
}

double ScientificSpinBox::valueFromText(const QString& text) const {
    // Text the user left as shown means the value as given: 1/60 shown as 0.01667 stays 1/60.
    const QString body = stripAffixes(text);
    if (body == textFromValue(value())) return value();
    return parseNumber(body).value_or(value());
}

QString ScientificSpinBox::textFromValue(double value) const {
    return formatNumber(value);
}

void ScientificSpinBox::fixup(QString& input) const {
    // Nothing to repair: text that is not a number in range is refused, and the spin box goes
    // back to its value (CorrectToPreviousValue) rather than guessing what was meant.
    (void)input;
}

void ScientificSpinBox::stepBy(int steps) {
    const double current = value();
    double next = current;
    if (stepFactor_ > 1.0) {
        next = current > 0.0 ? current * std::pow(stepFactor_, steps) : minimum();
    } else {
        // A tenth of the order of magnitude, taken on the side we move to: 1 → 1.1 going up,
        // 1 → 0.99 going down, so the arrows are useful from 1e-3 to 1e9 alike.
        const bool towardZero = (steps < 0) == (current > 0.0);
        const double magnitude = std::abs(current) * (towardZero ? 1.0 - 1e-12 : 1.0);
        double step =
            magnitude > 0.0 ? std::pow(10.0, std::floor(std::log10(magnitude)) - 1.0) : 0.0;
        step = std::max(step, std::pow(10.0, -std::max(displayDecimals_, 1)));
        next = std::round((current + steps * step) / step) * step;
    }
    setValue(std::clamp(next, minimum(), maximum()));
    selectAll();
}

void ScientificSpinBox::reportIfRejected() {
    QString text = lineEdit()->displayText();
    int pos = 0;
    if (validate(text, pos) == QValidator::Acceptable) return;
    const QString body = stripAffixes(text);
    const auto number = parseNumber(body);
    QString reason;
    if (!number)
        reason = body.isEmpty() ? tr("a number is needed") : tr("“%1” is not a number").arg(body);
    else if (*number < minimum())
        reason = tr("must be ≥ %1").arg(formatNumber(minimum()) + suffix());
    else
        reason = tr("must be ≤ %1").arg(formatNumber(maximum()) + suffix());
    emit inputRejected(reason);
}

void ScientificSpinBox::keyPressEvent(QKeyEvent* event) {
    const bool commit = event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter;
    if (commit) reportIfRejected();
    QDoubleSpinBox::keyPressEvent(event);
    // Committed: no longer "being edited", even when the text happened to stay the same (the
    // spin box does not reset the line edit then).
    if (commit) lineEdit()->setModified(false);
}

void ScientificSpinBox::focusOutEvent(QFocusEvent* event) {
    if (lineEdit()->isModified()) reportIfRejected();
    QDoubleSpinBox::focusOutEvent(event);
    lineEdit()->setModified(false);
}

// ---- PropertiesPanel -----------------------------------------------------------------------

PropertiesPanel::PropertiesPanel(QWidget* parent) : QWidget(parent) {
    pages_ = new QStackedWidget(this);

    emptyHint_ = new QLabel(tr("Select an object on the canvas or in the scene list"));
    emptyHint_->setObjectName(QStringLiteral("emptyHint"));
    emptyHint_->setAlignment(Qt::AlignCenter);
    emptyHint_->setWordWrap(true);
    emptyHint_->setForegroundRole(QPalette::PlaceholderText);
    emptyHint_->setMargin(12);
    pages_->addWidget(emptyHint_);

    auto* objectPage = new QWidget;
    auto* objectLayout = new QVBoxLayout(objectPage);
    objectLayout->setContentsMargins(0, 0, 0, 0);
    title_ = new QLabel;
    title_->setObjectName(QStringLiteral("title"));
    QFont bold = title_->font();
    bold.setBold(true);
    title_->setFont(bold);
    title_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    objectLayout->addWidget(title_);
    stateNote_ = new QLabel;
    stateNote_->setObjectName(QStringLiteral("stateNote"));
    stateNote_->setWordWrap(true);
    objectLayout->addWidget(stateNote_);
    auto* scroll = new QScrollArea;
    scroll->setObjectName(QStringLiteral("formScroll"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    // The form takes the dock's height (a scroll area's own hint is a few rows, which showed
    // 2 to 4 fields in a tall dock), scrolling only when the dock is shorter than the form.
    scroll->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Expanding);
    objectLayout->addWidget(scroll, 1);

    error_ = new QLabel;
    error_->setObjectName(QStringLiteral("error"));
    error_->setWordWrap(true);
    error_->setTextFormat(Qt::PlainText);
    // A fixed red reads as "error" on light and dark palettes alike; bold keeps it legible.
    error_->setStyleSheet(QStringLiteral("QLabel { color: #c62828; font-weight: bold; }"));
    error_->hide();
    objectLayout->addWidget(error_);
    pages_->addWidget(objectPage);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->addWidget(pages_, 1);
    setMinimumWidth(220);
}

void PropertiesPanel::setStateNote(const QString& text, bool live) {
    if (live != live_ || stateNote_->styleSheet().isEmpty()) {
        // Live numbers in the highlight colour, so a glance tells them from the setup.
        stateNote_->setStyleSheet(live ? QStringLiteral("QLabel { color: palette(highlight); "
                                                        "font-weight: bold; }")
                                       : QStringLiteral("QLabel { color: palette(mid); }"));
        live_ = live;
    }
    if (stateNote_->text() != text) stateNote_->setText(text);
}

QString PropertiesPanel::stateNote() const {
    return stateNote_->text();
}

bool PropertiesPanel::hasObject() const {
    return pages_->currentIndex() == 1;
}

QString PropertiesPanel::title() const {
    return hasObject() ? title_->text() : QString();
}

void PropertiesPanel::clearObject() {
    pages_->setCurrentIndex(0);
    buildForm({});
    clearError();
}

void PropertiesPanel::setObject(const QString& title, const std::vector<PropertyField>& fields) {
    QStringList keys;
    for (const PropertyField& field : fields) keys.append(field.key);
    if (title != title_->text() || !hasObject()) clearError();
    title_->setText(title);
    if (keys != keys_ || !form_)
        buildForm(fields);
    else
        for (const PropertyField& field : fields) {
            auto* spin = qobject_cast<ScientificSpinBox*>(editors_.value(field.key));
            if (spin && !spin->isBeingEdited()) applyRange(spin, field);
            setFieldValue(field.key, field.value);
        }
    pages_->setCurrentIndex(1);
}

void PropertiesPanel::buildForm(const std::vector<PropertyField>& fields) {
    auto* scroll = pages_->findChild<QScrollArea*>(QStringLiteral("formScroll"));
    // The old form may be the sender of the edit that led here: delete it later, not now.
    if (QWidget* old = scroll->takeWidget()) {
        old->hide();
        old->deleteLater();
    }
    editors_.clear();
    keys_.clear();
    form_ = new QWidget;
    formLayout_ = new QFormLayout(form_);
    formLayout_->setContentsMargins(0, 4, 0, 4);
    formLayout_->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    formLayout_->setLabelAlignment(Qt::AlignRight | Qt::AlignVCenter);

    QString takenMnemonics;
    for (const PropertyField& field : fields) {
        const QString label = withMnemonic(field.label, takenMnemonics) + QLatin1Char(':');
        const QString plainLabel = withoutMnemonic(field.label);
        QWidget* editor = nullptr;
        if (field.isBool) {
            auto* box = new QCheckBox;
            box->setChecked(field.value != 0.0);
            connect(box, &QCheckBox::clicked, this, [this, key = field.key](bool checked) {
                commitEdit(key, checked ? 1.0 : 0.0);
            });
            editor = box;
        } else {
            auto* spin = new ScientificSpinBox;
            spin->setDisplayDecimals(field.decimals);
            applyRange(spin, field);
            spin->setValue(field.value);
            spin->setToolTip(tr("%1: %2 … %3 %4 (scientific notation such as 1e6 is accepted)")
                                 .arg(plainLabel, spin->formatNumber(spin->minimum()),
                                      spin->formatNumber(spin->maximum()), field.unit));
            connect(spin, &QDoubleSpinBox::valueChanged, this,
                    [this, key = field.key](double value) { commitEdit(key, value); });
            connect(spin, &ScientificSpinBox::inputRejected, this,
                    [this, plainLabel](const QString& reason) {
                        showError(tr("%1 %2").arg(plainLabel, reason));
                    });
            editor = spin;
        }
        editor->setObjectName(field.key);
        editor->setAccessibleName(plainLabel);
        formLayout_->addRow(label, editor);
        editors_.insert(field.key, editor);
        keys_.append(field.key);
    }
    scroll->setWidget(form_);
}

void PropertiesPanel::setFieldValue(const QString& key, double value) {
    QWidget* editor = editors_.value(key);
    if (auto* spin = qobject_cast<ScientificSpinBox*>(editor)) {
        if (spin->isBeingEdited()) return;  // the user's typing wins until committed
        const QSignalBlocker blocker(spin);
        spin->setValue(value);
    } else if (auto* box = qobject_cast<QCheckBox*>(editor)) {
        const QSignalBlocker blocker(box);
        box->setChecked(value != 0.0);
    }
}

void PropertiesPanel::updateValues(const std::vector<PropertyField>& fields) {
    for (const PropertyField& field : fields) setFieldValue(field.key, field.value);
}

void PropertiesPanel::commitEdit(const QString& key, double value) {
    clearError();
    emit propertyEdited(key, value);
}

void PropertiesPanel::showError(const QString& message) {
    error_->setText(message);
    error_->setVisible(!message.isEmpty());
}

void PropertiesPanel::clearError() {
    showError(QString());
}

QString PropertiesPanel::errorText() const {
    return error_->text();
}

}  // namespace phasebox::ui
