#pragma once
// The Scene dock: the scene's objects by kind; selecting there selects in the document (and so
// on the canvas), and Delete removes the selection as one undo step.

#include "app/desktop/presenters/Presenter.h"

namespace phasebox {

class Document;
namespace ui {
class SceneBrowser;
}

class SceneBrowserPresenter : public Presenter {
    Q_OBJECT

public:
    SceneBrowserPresenter(ui::SceneBrowser& browser, Document& document, QObject* parent = nullptr);

    void refresh() override;
    // Deletes the selected objects (Edit → Delete, the Delete key in the browser).
    void deleteSelection();

private:
    ui::SceneBrowser& browser_;
    Document& document_;
};

}  // namespace phasebox
