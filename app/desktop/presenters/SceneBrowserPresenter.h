#pragma once
// The Scene dock: the scene's objects by kind; selecting there selects in the document (and so
// on the canvas), and Delete removes the selection as one undo step. Copy, cut and paste work on
// the selection too: the clipboard holds a scene file's text (ObjectClipboard.h), and each
// paste lands 0.5 m further right and up than the one before, so copies do not hide each other.

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
    // Edit → Copy / Cut / Paste. Copying nothing (or only what cannot go alone, a spring whose
    // ends stay behind) leaves the clipboard as it was and says so.
    bool copySelection();
    void cutSelection();
    void paste();

    // The shift of each paste from the one before (m).
    static constexpr double kPasteOffset = 0.5;

private:
    ui::SceneBrowser& browser_;
    Document& document_;
    int pastes_ = 0;  // since the last copy
};

}  // namespace phasebox
