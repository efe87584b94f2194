#include "app/document/ObjectClipboard.h"

#include <initializer_list>
#include <map>
#include <string>
#include <type_traits>
#include <unordered_set>

namespace phasebox {

namespace {

// The body a spring end names: the object itself, or the cloth of a node id ID[i,j].
std::string bodyOf(const std::string& end) {
    return end.substr(0, end.find('['));
}

template <typename D>
void keepCopied(std::vector<D>& array, const std::unordered_set<std::string>& ids,
                std::unordered_set<std::string>& kept) {
    std::erase_if(array, [&](const D& d) { return !ids.count(d.id); });
    for (const D& d : array) kept.insert(d.id);
}

}  // namespace

SceneDesc copyObjects(const SceneDesc& scene, const QStringList& ids) {
    SceneDesc copy = scene;
    assignDefaultIds(copy);  // ids are what the selection names
    std::unordered_set<std::string> chosen;
    for (const QString& id : ids) chosen.insert(bodyOf(id.toStdString()));
    std::unordered_set<std::string> bodies, others;
    forEachKind([&]<typename D>(std::type_identity<D>, ObjectKind kind) {
        if constexpr (!schema::Connector<D>)
            keepCopied(arrayOf<D>(copy), chosen, schema::kindInfo(kind).body ? bodies : others);
    });
    // A connector (a spring, a joint) comes along with its bodies: when each end is copied or
    // the world (a fixed anchor).
    const auto leftBehind = [&](const std::string& a, const std::optional<std::string>& b) {
        return !bodies.count(bodyOf(a)) || (b && !bodies.count(bodyOf(*b)));
    };
    forEachKind([&]<typename D>(std::type_identity<D>, ObjectKind) {
        if constexpr (schema::Connector<D>)
            std::erase_if(arrayOf<D>(copy), [&](const D& d) { return leftBehind(d.a, d.b); });
    });
    return copy;
}

std::vector<ObjectDesc> pastedObjects(const SceneDesc& target, const SceneDesc& fragment,
                                      const Point2& offset) {
    SceneDesc source = fragment;
    assignDefaultIds(source);
    SceneDesc trial = target;  // grows as ids are taken, so that each is fresh
    std::map<std::string, std::string> renamed;
    std::vector<ObjectDesc> out;
    const auto add = [&]<typename D>(D desc) {
        const std::string fresh = uniqueObjectId(trial, defaultIdPrefix(kindOf<D>()));
        renamed[desc.id] = fresh;
        desc.id = fresh;
        if constexpr (schema::Connector<D>) {
            const auto rename = [&](const std::string& end) {
                const std::size_t bracket = end.find('[');
                const auto it = renamed.find(end.substr(0, bracket));
                const std::string body = it == renamed.end() ? end.substr(0, bracket) : it->second;
                return bracket == std::string::npos ? body : body + end.substr(bracket);
            };
            desc.a = rename(desc.a);
            if (desc.b) desc.b = rename(*desc.b);
        }
        ObjectDesc object = std::move(desc);
        translateObject(object, offset);
        arrayOf<D>(trial).push_back(std::get<D>(object));
        out.push_back(std::move(object));
    };
    // Bodies first, so that the connectors after them find their ends' new ids.
    for (const bool bodies : {true, false})
        forEachKind([&]<typename D>(std::type_identity<D>, ObjectKind kind) {
            if (schema::kindInfo(kind).body == bodies)
                for (const D& d : arrayOf<D>(source)) add(d);
        });
    return out;
}

}  // namespace phasebox
