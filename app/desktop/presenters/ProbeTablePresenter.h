#pragma once
// The Instruments dock's data table (Table tab): t and every recorded probe, with the table's own
// columns, its CSV export and copying its rows.

#include "app/desktop/presenters/InstrumentBase.h"

#include <QString>
#include <QStringList>

namespace phasebox {

class ProbeTablePresenter : public InstrumentBase {
    Q_OBJECT

public:
    ProbeTablePresenter(ui::InstrumentsPanel& panel, Document& document, ProbeRecorder& probes,
                        QObject* parent = nullptr);

    void refresh() override;

    bool addColumn(const QString& probe, QString* error = nullptr);
    void removeColumn(const QString& probe);
    // The table's own columns (a lesson's probes), replacing the ones there.
    void setColumns(const QStringList& probes);
    QStringList columns() const { return columns_; }

    // The data table as CSV: t and every recorded probe.
    bool exportTable(const QString& path, QString* error) const;
    // Copies the table's selected rows (all when none) as tab-separated text.
    void copyTable() const;
    void exportTableInteractively();

private:
    QStringList columns_;
    long long clears_ = 0;  // recordings cleared, for the table's model
};

}  // namespace phasebox
