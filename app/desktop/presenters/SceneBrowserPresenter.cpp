#include "app/desktop/presenters/SceneBrowserPresenter.h"

#include "app/document/Document.h"
#include "ui/panels/SceneBrowser.h"

namespace phasebox {

SceneBrowserPresenter::SceneBrowserPresenter(ui::SceneBrowser& browser, Document& document,
                                             QObject* parent)
    : Presenter(parent), browser_(browser), document_(document) {
    connect(&document_, &Document::sceneReset, this, &SceneBrowserPresenter::refresh);
    connect(&document_, &Document::sceneEdited, this, &SceneBrowserPresenter::refresh);
    connect(&document_, &Document::selectionChanged, this,
            [this] { browser_.setSelection(document_.selection()); });
    connect(&browser_, &ui::SceneBrowser::selectionChanged, &document_, &Document::setSelection);
    connect(&browser_, &ui::SceneBrowser::deleteRequested, this,
            &SceneBrowserPresenter::deleteSelection);
}

void SceneBrowserPresenter::refresh() {
    browser_.setScene(document_.setup());
    browser_.setSelection(document_.selection());
}

void SceneBrowserPresenter::deleteSelection() {
    QString error;
    if (!document_.deleteObjects(document_.selection(), &error) && !error.isEmpty())
        emit message(error);
}

}  // namespace phasebox
