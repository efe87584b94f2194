// MeasureTools: a lesson's rulers, protractors and free body, set from its file and collected
// for Save (CONTRACT §7 `instruments`).

#include "app/desktop/MeasureTools.h"
#include "app/document/Document.h"
#include "physics/scene/InstrumentsDesc.h"

#include <QLocale>

namespace phasebox {

QString MeasureTools::endText(const End& end) {
    if (!end.object.isEmpty()) return end.object;
    const auto number = [](double v) {
        return QString::number(v, 'g', QLocale::FloatingPointShortest);
    };
    return number(end.point.x()) + QLatin1Char(':') + number(end.point.y());
}

void MeasureTools::applyInstruments(const InstrumentsDesc& in) {
    clear();
    // The file was checked against the world when it was built: every end parses.
    const auto end = [this](const std::string& text) {
        return parseEnd(QString::fromStdString(text)).value_or(End{});
    };
    for (const RulerDesc& r : in.rulers) rulers_.push_back({{end(r.ends[0]), end(r.ends[1])}});
    for (const ProtractorDesc& p : in.protractors)  // ∠ABC in both
        protractors_.push_back({{end(p.ends[0]), end(p.ends[1]), end(p.ends[2])}});
    if (!in.freeBody.empty()) document_.setSelection({QString::fromStdString(in.freeBody)});
    setFreeBodyShown(!in.freeBody.empty());
    refresh();
}

void MeasureTools::collectInstruments(InstrumentsDesc& out) const {
    for (const Ruler& r : rulers_)
        out.rulers.push_back(
            {{endText(r.ends[0]).toStdString(), endText(r.ends[1]).toStdString()}});
    for (const Protractor& p : protractors_)
        out.protractors.push_back(
            {{endText(p.ends[0]).toStdString(), endText(p.ends[1]).toStdString(),
              endText(p.ends[2]).toStdString()}});
    if (!freeBodyShown_) return;
    for (const QString& id : document_.selection())
        if (freeBodyOf(document_.world(), id.toStdString())) {
            out.freeBody = id.toStdString();
            return;
        }
}

}  // namespace phasebox
