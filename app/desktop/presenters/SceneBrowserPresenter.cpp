#include "app/desktop/presenters/SceneBrowserPresenter.h"

#include "app/document/Document.h"
#include "app/document/ObjectClipboard.h"
#include "app/io/SceneIO.h"
#include "ui/panels/SceneBrowser.h"

#include <QClipboard>
#include <QGuiApplication>
#include <QMimeData>

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

bool SceneBrowserPresenter::copySelection() {
    const SceneDesc copy = copyObjects(document_.setup(), document_.selection());
    std::size_t count = 0;
    forEachKind([&](auto, ObjectKind kind) { count += objectCount(copy, kind); });
    if (count == 0) {
        emit message(
            tr("Nothing to copy: select objects first (a spring goes along with the "
               "objects it joins)."));
        return false;
    }
    const QByteArray text = SceneIO::serialize(copy);
    auto* data = new QMimeData;
    data->setData(QString::fromLatin1(kSceneMimeType), text);
    data->setText(QString::fromUtf8(text));
    QGuiApplication::clipboard()->setMimeData(data);
    pastes_ = 0;
    emit message(tr("Copied %n object(s)", nullptr, static_cast<int>(count)));
    return true;
}

void SceneBrowserPresenter::cutSelection() {
    if (copySelection()) deleteSelection();
}

void SceneBrowserPresenter::paste() {
    const QMimeData* data = QGuiApplication::clipboard()->mimeData();
    if (!data) return;
    const QString mime = QString::fromLatin1(kSceneMimeType);
    const QByteArray text = data->hasFormat(mime) ? data->data(mime) : data->text().toUtf8();
    if (text.trimmed().isEmpty()) {
        emit message(tr("Nothing to paste: copy objects first."));
        return;
    }
    const SceneLoadResult parsed = SceneIO::parse(text, tr("the clipboard"));
    if (!parsed.ok()) {
        emit message(tr("The clipboard holds no Phasebox objects: %1").arg(parsed.errors.value(0)));
        return;
    }
    ++pastes_;
    const double shift = kPasteOffset * pastes_;
    QStringList ids;
    QString error;
    if (!document_.addObjects(pastedObjects(document_.setup(), *parsed.scene, {shift, shift}),
                              &error, &ids)) {
        --pastes_;
        emit message(error.isEmpty() ? tr("Nothing to paste: the clipboard's scene is empty.")
                                     : error);
        return;
    }
    document_.setSelection(ids);
}

}  // namespace phasebox
