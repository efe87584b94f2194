#include "ui/instruments/InstrumentsPanel.h"

#include "ui/instruments/GraphsView.h"
#include "ui/instruments/ProbePicker.h"
#include "ui/instruments/ProbeTableView.h"
#include "ui/instruments/ReadoutView.h"
#include "ui/instruments/TimerView.h"

#include <QTabBar>
#include <QTabWidget>
#include <QVBoxLayout>

namespace phasebox::ui {

InstrumentsPanel::InstrumentsPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    tabs_ = new QTabWidget(this);
    tabs_->setObjectName(QStringLiteral("instrumentTabs"));
    tabs_->setDocumentMode(true);
    // Four tabs in the dock's width at 1024 x 700 in German, Spanish and French: a little less
    // padding than the style's, and never cut ("Zeitm…") or scrolled.
    tabs_->tabBar()->setStyleSheet(QStringLiteral("QTabBar::tab { padding: 4px 6px; }"));
    tabs_->setElideMode(Qt::ElideNone);
    readouts_ = new ReadoutView(tabs_);
    graphs_ = new GraphsView(tabs_);
    timer_ = new TimerView(tabs_);
    table_ = new ProbeTableView(tabs_);
    tabs_->addTab(readouts_, tr("Rea&douts"));
    tabs_->addTab(graphs_, tr("&Graphs"));
    tabs_->addTab(timer_, tr("&Timer"));
    tabs_->addTab(table_, tr("Ta&ble"));
    tabs_->setTabToolTip(0, tr("The selected object's state, live or as set up"));
    tabs_->setTabToolTip(1, tr("Any probe against time or against another"));
    tabs_->setTabToolTip(2, tr("The period of any probe, and a stopwatch"));
    tabs_->setTabToolTip(3, tr("The recorded probes, for CSV and spreadsheets"));
    layout->addWidget(tabs_);
    connect(tabs_, &QTabWidget::currentChanged, this,
            [this](int index) { emit tabChanged(static_cast<Tab>(index)); });
}

InstrumentsPanel::Tab InstrumentsPanel::currentTab() const {
    return static_cast<Tab>(tabs_->currentIndex());
}

void InstrumentsPanel::showTab(Tab tab) {
    tabs_->setCurrentIndex(static_cast<int>(tab));
}

void InstrumentsPanel::setOffered(const QStringList& probes) {
    graphs_->setOffered(probes);
    timer_->picker()->setOffered(probes);
    table_->picker()->setOffered(probes);
}

}  // namespace phasebox::ui
