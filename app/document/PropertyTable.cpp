#include "app/document/PropertyTable.h"

#include "physics/scene/SceneSchema.h"
#include "ui/panels/BuiltinText.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <functional>
#include <unordered_set>

namespace phasebox {

namespace {

namespace key = schema::key;

QString text(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

QString pairText(const char* english) {
    return QCoreApplication::translate(ui::kSchemaTextContext, english);
}

// The names of a pair's two rows: keys "size.w", labels "Width".
struct PairNames {
    const char* suffix[2];
    QString label[2];
};
template <typename D>
PairNames pairNames(const schema::Field<D>& f) {
    const QString label = ui::schemaText(f.label);
    switch (f.type) {
        case schema::Type::Size:
            return {{".w", ".h"},
                    {pairText(QT_TRANSLATE_NOOP("Schema", "Width")),
                     pairText(QT_TRANSLATE_NOOP("Schema", "Height"))}};
        case schema::Type::Grid:
            return {{".x", ".y"},
                    {pairText(QT_TRANSLATE_NOOP("Schema", "Columns")),
                     pairText(QT_TRANSLATE_NOOP("Schema", "Rows"))}};
        case schema::Type::Interval:
            return {{".lower", ".upper"},
                    {pairText(QT_TRANSLATE_NOOP("Schema", "%1 lower")).arg(label),
                     pairText(QT_TRANSLATE_NOOP("Schema", "%1 upper")).arg(label)}};
        default:
            return {{".x", ".y"},
                    {pairText(QT_TRANSLATE_NOOP("Schema", "%1 x")).arg(label),
                     pairText(QT_TRANSLATE_NOOP("Schema", "%1 y")).arg(label)}};
    }
}

// What forEachProperty() calls for each row: the row, its editor and set(value), which writes
// the property. One type for every caller, so that the walk over a description's fields (a
// visit of every member's type, nested descriptions included) is compiled once per description,
// not once per caller as well (the file took half a minute to compile).
using PropertySetter = std::function<void(double)>;
using PropertyVisitor =
    std::function<void(const PropertyRow&, const schema::Editor&, const PropertySetter&)>;

// The two rows of a pair (a point, a size, a grid), where set(value) writes one of them.
template <typename D, typename Pair, typename Row>
void pairRows(const schema::Field<D>& field, const QString& fieldKey, Pair& pair, Row&& row,
              const schema::Editor& e, const PropertyVisitor& fn) {
    const PairNames names = pairNames(field);
    for (std::size_t k = 0; k < 2; ++k)
        fn(row(fieldKey + QLatin1String(names.suffix[k]), names.label[k],
               static_cast<double>(pair[k])),
           e, [&pair, k](double x) {
               using Element = std::remove_reference_t<decltype(pair[k])>;
               if constexpr (std::is_same_v<Element, int>)
                   pair[k] = static_cast<int>(std::lround(x));
               else
                   pair[k] = x;
           });
}

// Calls fn(row, editor, set) for each property of d the editor shows, in its table's order,
// where set(value) writes the property into d. What the editor shows of a field is in its
// schema::Editor; a pair held in std::optional (a spring's anchor) only while it is set, a
// direction marked Editor::tilt as one angle.
template <typename D>
void forEachProperty(D& d, const PropertyVisitor& fn, const QString& prefix = {}) {
    for (const schema::Field<D>& field : schema::table<D>().fields) {
        if (field.uses && !field.uses(d)) continue;  // a field this joint's type does not use
        const QString fieldKey = prefix + text(field.key);
        const schema::Editor& e = field.editor;
        auto row = [&](const QString& rowKey, const QString& label, double value) {
            return PropertyRow{rowKey, label, text(field.unit), value,
                               e.min,  e.max, e.decimals,       field.type == schema::Type::Bool};
        };
        std::visit(
            [&]<typename V>(V D::*member) {
                V& v = d.*member;
                if constexpr (schema::Described<V>) {
                    forEachProperty(v, fn, fieldKey + QLatin1Char('.'));
                } else if constexpr (schema::OptionalDescribed<V>) {
                    if (v) forEachProperty(*v, fn, fieldKey + QLatin1Char('.'));
                } else if (e.decimals < 0) {
                    return;
                } else if constexpr (std::is_same_v<V, Point2>) {
                    if (!e.tilt) return pairRows(field, fieldKey, v, row, e, fn);
                    // The angle of the surface the direction is normal to.
                    fn({prefix + text(key::angle), QStringLiteral("Tilt"), QStringLiteral("rad"),
                        std::atan2(-v[0], v[1]), e.min, e.max, e.decimals, false},
                       e, [&v](double x) {
                           v = {-std::sin(x), std::cos(x)};
                       });
                    return;
                } else if constexpr (std::is_same_v<V, double>) {
                    fn(row(fieldKey, ui::schemaText(field.label), v), e, [&v](double x) { v = x; });
                } else if constexpr (std::is_same_v<V, std::optional<double>>) {
                    fn(row(fieldKey, ui::schemaText(field.label), v.value_or(0.0)), e,
                       [&v](double x) { v = x; });
                } else if constexpr (std::is_same_v<V, bool>) {
                    fn(row(fieldKey, ui::schemaText(field.label), v ? 1.0 : 0.0), e,
                       [&v](double x) { v = x != 0.0; });
                } else if constexpr (std::is_same_v<V, std::optional<Point2>>) {
                    if (v) pairRows(field, fieldKey, *v, row, e, fn);
                } else if constexpr (std::is_same_v<V, std::array<int, 2>>) {
                    pairRows(field, fieldKey, v, row, e, fn);
                }
            },
            field.member);
    }
}

// Whether d gives the length field key (held in std::optional) itself.
template <typename D>
bool lengthGiven(const D& d, const QString& key) {
    bool given = false;
    for (const schema::Field<D>& f : schema::table<D>().fields)
        if (text(f.key) == key)
            std::visit(
                [&]<typename V>(V D::*member) {
                    if constexpr (std::is_same_v<V, std::optional<double>>)
                        given = (d.*member).has_value();
                },
                f.member);
    return given;
}
}  // namespace

QString objectKindName(ObjectKind kind) {
    // The names are built-in texts (app/i18n/BuiltinTexts.h), None's "object" among them.
    const std::string name(schema::kindInfo(kind).name);
    return QCoreApplication::translate(kObjectKindTextContext, name.c_str());
}

std::string uniqueObjectId(const SceneDesc& scene, const std::string& prefix) {
    const std::vector<std::string> list = objectIds(scene);
    const std::unordered_set<std::string> used(list.begin(), list.end());
    // Cloth node ids contain '[', which a prefix+number never does, so they cannot collide.
    for (std::size_t n = 0;; ++n) {
        std::string id = prefix + std::to_string(n);
        if (!used.count(id)) return id;
    }
}

std::string defaultIdPrefix(ObjectKind kind) {
    return std::string(schema::kindInfo(kind).idPrefix);
}

std::vector<PropertyRow> propertiesOf(const SceneDesc& scene, const QString& id) {
    const ObjectRef ref = findObject(scene, id.toStdString());
    if (!ref.isValid()) return {};
    std::vector<std::pair<int, PropertyRow>> ranked;
    ObjectDesc object = objectDesc(scene, ref);
    std::visit(
        [&](auto& desc) {
            forEachProperty(desc, [&](const PropertyRow& row, const schema::Editor& e, auto&&) {
                ranked.emplace_back(e.rank, row);
            });
        },
        object);
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<PropertyRow> rows;
    for (auto& [rank, row] : ranked) rows.push_back(std::move(row));
    // A number the scene leaves out shows the value it then takes: a body's mass from its
    // density, a connector's length from its ends' initial distance.
    const QString massKey = text(schema::key::mass);
    const QString endsKey = text(schema::kindInfo(ref.kind).endsLengthKey);
    visitObject(scene, ref, [&]<typename D>(const D& d) {
        for (PropertyRow& row : rows) {
            if constexpr (requires { d.resolvedMass(); })
                if (row.key == massKey && !d.mass) row.value = d.resolvedMass();
            if constexpr (schema::Connector<D>)
                if (!endsKey.isEmpty() && row.key == endsKey && !lengthGiven(d, endsKey))
                    row.value = initialEndsDistance(scene, d).value_or(row.value);
        }
    });
    return rows;
}

std::optional<double> propertyValue(const SceneDesc& scene, const QString& id, const QString& key) {
    for (const PropertyRow& row : propertiesOf(scene, id))
        if (row.key == key) return row.value;
    return std::nullopt;
}

bool setPropertyValue(SceneDesc& scene, const QString& id, const QString& key, double value) {
    bool found = false;
    const auto set = [&](const QString& target) {
        visitObject(scene, findObject(scene, id.toStdString()), [&](auto& desc) {
            forEachProperty(desc, [&](const PropertyRow& row, const schema::Editor&, auto&& write) {
                if (found || row.key != target) return;
                write(value);
                found = true;
            });
        });
    };
    set(key);
    // The generic pin command pins a box by making it static.
    if (!found && key == text(schema::key::pinned)) set(text(schema::key::isStatic));
    return found;
}

QString pinPropertyKey(ObjectKind kind) {
    return text(schema::kindInfo(kind).pinKey);
}

bool propertyMovesObject(const SceneDesc& scene, const QString& id, const QString& key) {
    const ObjectRef ref = findObject(scene, id.toStdString());
    if (!ref.isValid()) return false;
    bool moves = false;
    ObjectDesc object = objectDesc(scene, ref);
    std::visit(
        [&](auto& desc) {
            forEachProperty(desc, [&](const PropertyRow& row, const schema::Editor& e, auto&&) {
                if (row.key == key) moves = e.movesObject;
            });
        },
        object);
    return moves;
}

}  // namespace phasebox
