#include "app/desktop/presenters/NotesPresenter.h"

#include "app/document/Document.h"
#include "ui/panels/BuiltinText.h"
#include "ui/panels/DisplayText.h"

#include <QTextBrowser>

namespace phasebox {

NotesPresenter::NotesPresenter(QTextBrowser& notes, Document& document, QObject* parent)
    : Presenter(parent), notes_(notes), document_(document) {
    notes_.setOpenExternalLinks(true);
    // A long word (a URL, a formula, a damaged file's single million-character word) wraps
    // anywhere instead of being laid out as one line.
    notes_.setWordWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    connect(&document_, &Document::sceneReset, this, [this] {
        refresh();
        if (!document_.setup().description.empty()) emit notesToRead();
    });
}

void NotesPresenter::refresh() {
    const SceneDesc& scene = document_.setup();
    const QString html =
        QStringLiteral("<h3>%1</h3><p>%2</p>")
            .arg(ui::shownText(ui::sceneText(scene.name)).toHtmlEscaped(),
                 ui::shownDescription(ui::sceneText(scene.description)).toHtmlEscaped());
    if (html == shown_) return;  // only this presenter writes the notes
    notes_.setHtml(html);
    shown_ = html;
}

}  // namespace phasebox
