#include "app/desktop/AccuracyLab.h"

#include "app/desktop/AccuracyDialog.h"
#include "app/desktop/presenters/ParametersPresenter.h"
#include "app/document/Document.h"

namespace phasebox {

AccuracyLab::AccuracyLab(QWidget& window, Document& document, ParametersPresenter& parameters)
    : QObject(&window), window_(window), document_(document), parameters_(parameters) {
    setObjectName(QStringLiteral("accuracyLabController"));
}

AccuracyDialog* AccuracyLab::dialog() {
    if (!dialog_) {
        dialog_ = new AccuracyDialog(&window_);
        connect(dialog_, &AccuracyDialog::applyRequested, &parameters_,
                &ParametersPresenter::applyStudyChoice);
        // Apply only to the scene it studied: every edit, New, Open and Revert is checked.
        for (auto signal : {&Document::sceneEdited, &Document::sceneReset})
            connect(&document_, signal, dialog_,
                    [this] { dialog_->setCurrentScene(document_.setup()); });
    }
    return dialog_;
}

void AccuracyLab::show() {
    AccuracyDialog* shown = dialog();
    if (!shown->study().isRunning()) shown->setScene(document_.setup());
    shown->setSceneFile(document_.filePath());
    shown->show();
    shown->raise();
}

}  // namespace phasebox
