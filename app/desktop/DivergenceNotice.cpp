#include "app/desktop/DivergenceNotice.h"

#include "app/document/Document.h"

#include <QMessageBox>
#include <QStringList>

namespace phasebox {

DivergenceNotice::DivergenceNotice(QWidget& window, Document& document)
    : QObject(&window), window_(window) {
    connect(&document, &Document::sceneReset, this, [this] {
        if (box_) box_->close();
    });
}

QString DivergenceNotice::statusLine(const QString& message) {
    return message.split(QLatin1Char('\n'), Qt::SkipEmptyParts).mid(0, 2).join(QLatin1Char(' '));
}

void DivergenceNotice::show(const QString& message, const QString& details) {
    if (!window_.isVisible()) return;
    if (!box_) {
        box_ = new QMessageBox(QMessageBox::Warning, tr("The simulation became unstable"),
                               QString(), QMessageBox::Ok, &window_);
        box_->setObjectName(QStringLiteral("divergenceDialog"));
        box_->setAttribute(Qt::WA_DeleteOnClose);
    }
    box_->setText(message);
    box_->setDetailedText(details);
    box_->open();
}

}  // namespace phasebox
