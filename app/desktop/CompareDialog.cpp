#include "app/desktop/CompareDialog.h"

#include "physics/integrators/Integrator.h"
#include "ui/panels/BuiltinText.h"
#include "ui/panels/ParametersPanel.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace phasebox {

QString CompareDialog::integratorLabel(const std::string& name) {
    const IntegratorInfo* info = findIntegrator(name);
    return info ? ui::integratorText(info->label) : QString::fromStdString(name);
}

CompareDialog::CompareDialog(const SimulationDesc& current, const SimulationSettings& recorded,
                             double t, QWidget* parent)
    : QDialog(parent), current_(current), recordedDt_(recorded.dt), shownDt_(0.0) {
    setObjectName(QStringLiteral("compareDialog"));
    setWindowTitle(tr("Compare from Here"));
    auto* column = new QVBoxLayout(this);
    auto* intro = new QLabel(tr("From t = %L1 s the run goes on with the settings below, while "
                                "the recorded run (%2, dt %L3 s) is drawn beside it as a ghost.")
                                 .arg(t, 0, 'f', 3)
                                 .arg(integratorLabel(recorded.integrator))
                                 .arg(recorded.dt, 0, 'g', 4),
                             this);
    intro->setWordWrap(true);
    column->addWidget(intro);

    auto* form = new QFormLayout;
    integrator_ = new QComboBox(this);
    integrator_->setObjectName(QStringLiteral("compareIntegrator"));
    const auto methods = integratorRegistry();
    int proposed = 0;
    for (std::size_t i = 0; i < methods.size(); ++i) {
        integrator_->addItem(ui::integratorText(methods[i].label),
                             QString::fromUtf8(methods[i].name.data(),
                                               static_cast<qsizetype>(methods[i].name.size())));
        if (methods[i].name == recorded.integrator)
            proposed = static_cast<int>((i + 1) % methods.size());
    }
    integrator_->setCurrentIndex(proposed);
    dt_ = new QDoubleSpinBox(this);
    dt_->setObjectName(QStringLiteral("compareDt"));
    dt_->setDecimals(6);
    dt_->setRange(1e-5, 1.0);
    dt_->setSingleStep(0.001);
    dt_->setSuffix(tr(" s"));
    dt_->setValue(recorded.dt);
    shownDt_ = dt_->value();
    contactModel_ = new QComboBox(this);
    contactModel_->setObjectName(QStringLiteral("compareContactModel"));
    for (const QString& name :
         {ui::ParametersPanel::tr("Impulse"), ui::ParametersPanel::tr("Penalty"),
          ui::ParametersPanel::tr("Kinematic")})
        contactModel_->addItem(name);
    contactModel_->setCurrentIndex(static_cast<int>(recorded.contactModel));
    form->addRow(tr("&Integrator:"), integrator_);
    form->addRow(tr("&dt:"), dt_);
    form->addRow(tr("&Contacts:"), contactModel_);
    column->addLayout(form);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Co&mpare"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    column->addWidget(buttons);
}

SimulationDesc CompareDialog::settings() const {
    SimulationDesc s = current_;
    s.integrator = integrator_->currentData().toString().toStdString();
    s.dt = dt_->value() == shownDt_ ? recordedDt_ : dt_->value();
    s.contactModel = static_cast<ContactModel>(contactModel_->currentIndex());
    return s;
}

}  // namespace phasebox
