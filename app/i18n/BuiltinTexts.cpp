#include "app/i18n/BuiltinTexts.h"

#include "app/document/PropertyTable.h"
#include "physics/integrators/Integrator.h"
#include "physics/scene/SceneSchema.h"
#include "ui/panels/BuiltinText.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>

namespace phasebox::i18n {

namespace {
QString text(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

class Collector {
public:
    void add(const char* context, const QString& text, const QString& origin) {
        if (text.isEmpty()) return;
        const QString key = QLatin1String(context) + QChar(u'\x1f') + text;
        if (seen_.contains(key)) return;
        seen_.insert(key);
        texts_.push_back({context, text, origin});
    }
    template <typename D>
    void addTable(const schema::Table<D>& table) {
        const QString where = QStringLiteral("schema: ") + text(table.key);
        add(ui::kSchemaTextContext, text(table.description), where);
        for (const schema::Field<D>& f : table.fields)
            add(ui::kSchemaTextContext, text(f.label), where + QLatin1Char('.') + text(f.key));
    }
    std::vector<BuiltinText> take() { return std::move(texts_); }

private:
    QSet<QString> seen_;
    std::vector<BuiltinText> texts_;
};

// The name and notes of each scene in a folder of the resources, read as JSON (a scene that
// does not parse has nothing to show).
void addScenes(Collector& out, const QString& folder) {
    const QDir dir(folder);
    for (const QString& name : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
        QFile file(dir.filePath(name));
        if (!file.open(QIODevice::ReadOnly)) continue;
        const QJsonObject scene = QJsonDocument::fromJson(file.readAll()).object();
        const QString where = folder.mid(2) + QLatin1Char('/') + name;
        out.add(ui::kSceneTextContext, scene.value(QStringLiteral("name")).toString(),
                where + ": name");
        out.add(ui::kSceneTextContext, scene.value(QStringLiteral("description")).toString(),
                where + ": description");
    }
}

// A C string literal for text: UTF-8 kept as it is, quotes, backslashes and line breaks
// escaped.
QString cLiteral(const QString& text) {
    QString out = QStringLiteral("\"");
    for (const QChar c : text) {
        if (c == QLatin1Char('"') || c == QLatin1Char('\\'))
            out += QLatin1Char('\\') + c;
        else if (c == QLatin1Char('\n'))
            out += QStringLiteral("\\n");
        else if (c == QLatin1Char('\t'))
            out += QStringLiteral("\\t");
        else
            out += c;
    }
    return out + QLatin1Char('"');
}
}  // namespace

std::vector<BuiltinText> builtinTexts() {
    Collector out;
    addScenes(out, QStringLiteral(":/scenes"));
    addScenes(out, QStringLiteral(":/lessons"));
    out.addTable(schema::table<SimulationDesc>());
    schema::forEachEffect([&](const auto& table, auto) { out.addTable(table); });
    out.addTable(schema::table<AttractorDesc>());
    schema::forEachObjectKind([&](const auto& table, auto) { out.addTable(table); });
    for (std::size_t kind = 0; kind <= kObjectKindCount; ++kind) {
        const std::string_view name = schema::kindInfo(static_cast<ObjectKind>(kind)).name;
        out.add(kObjectKindTextContext, text(name), QStringLiteral("kind: ") + text(name));
    }
    out.addTable(schema::table<ClothStiffnessDesc>());
    out.addTable(schema::table<JointMotorDesc>());
    out.addTable(schema::table<TrackCircleDesc>());
    out.addTable(schema::table<TrackLineDesc>());
    for (const IntegratorInfo& info : integratorRegistry()) {
        const QString where = QStringLiteral("integrator: ") + text(info.name);
        out.add(ui::kIntegratorTextContext, text(info.label), where);
        out.add(ui::kIntegratorTextContext, text(info.evaluations),
                where + QStringLiteral(" evaluations"));
        out.add(ui::kIntegratorTextContext, text(info.summary), where + QStringLiteral(" summary"));
    }
    return out.take();
}

QString lupdateSource(const std::vector<BuiltinText>& texts) {
    QString out = QStringLiteral(
        "// The app's texts that are data (app/i18n/BuiltinTexts.h), for lupdate only: written "
        "by\n// phasebox-texts, never compiled.\n\nstatic const char* const texts[] = {\n");
    for (const BuiltinText& t : texts)
        out += QStringLiteral("    //: %1\n    QT_TRANSLATE_NOOP(\"%2\", %3),\n")
                   .arg(t.origin, QLatin1String(t.context), cLiteral(t.text));
    return out + QStringLiteral("};\n");
}

}  // namespace phasebox::i18n
