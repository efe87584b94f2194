#pragma once
// The Properties dock: the numbers of the one selected object (PropertyTable.h), live while the
// simulation runs (or those of the recorded moment the timeline shows); a committed edit becomes
// one undo step, a refused one shows why.

#include "app/desktop/presenters/Presenter.h"

namespace phasebox {

class Document;
class SimulationController;
namespace ui {
class PropertiesPanel;
}

class PropertiesPresenter : public Presenter {
    Q_OBJECT

public:
    PropertiesPresenter(ui::PropertiesPanel& panel, Document& document,
                        SimulationController& controller, QObject* parent = nullptr);

    // The shown object's live values.
    void refresh() override { update(false); }

signals:
    // The selection gave the panel an object to show (MainWindow raises its dock).
    void objectShown();

private:
    // rebuild: the setup or the selection changed, so the form may need new fields.
    void update(bool rebuild);
    void edit(const QString& key, double value);

    ui::PropertiesPanel& panel_;
    Document& document_;
    const SimulationController& controller_;
    QString shownId_;  // the object the panel shows
};

}  // namespace phasebox
