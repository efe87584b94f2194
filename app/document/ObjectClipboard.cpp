#include "app/document/ObjectClipboard.h"

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

void shift(Point2& p, const Point2& by) {
    p[0] += by[0];
    p[1] += by[1];
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
    std::unordered_set<std::string> bodies;
    keepCopied(copy.particles, chosen, bodies);
    keepCopied(copy.boxes, chosen, bodies);
    keepCopied(copy.disks, chosen, bodies);
    keepCopied(copy.polygons, chosen, bodies);
    keepCopied(copy.cloths, chosen, bodies);
    std::unordered_set<std::string> planes;
    keepCopied(copy.planes, chosen, planes);
    // A spring comes along with its bodies: when each end is copied or a fixed anchor.
    const auto leftBehind = [&](const std::string& a, const std::optional<std::string>& b) {
        return !bodies.count(bodyOf(a)) || (b && !bodies.count(bodyOf(*b)));
    };
    std::erase_if(copy.springs, [&](const SpringDesc& s) { return leftBehind(s.a, s.b); });
    // Joints likewise: both bodies copied, or one and the world.
    std::erase_if(copy.joints, [&](const JointDesc& j) { return leftBehind(j.a, j.b); });
    return copy;
}

std::vector<ObjectDesc> pastedObjects(const SceneDesc& target, const SceneDesc& fragment,
                                      const Point2& offset) {
    SceneDesc source = fragment;
    assignDefaultIds(source);
    SceneDesc trial = target;  // grows as ids are taken, so that each is fresh
    std::map<std::string, std::string> renamed;
    std::vector<ObjectDesc> out;
    const auto add = [&](auto desc) {
        using D = std::decay_t<decltype(desc)>;
        const ObjectDesc object = desc;
        const std::string fresh = uniqueObjectId(trial, defaultIdPrefix(objectKind(object)));
        renamed[desc.id] = fresh;
        desc.id = fresh;
        if constexpr (std::is_same_v<D, PlaneDesc>)
            shift(desc.point, offset);
        else if constexpr (std::is_same_v<D, ClothDesc>)
            shift(desc.origin, offset);
        else if constexpr (std::is_same_v<D, SpringDesc> || std::is_same_v<D, JointDesc>) {
            const auto rename = [&](const std::string& end) {
                const std::size_t bracket = end.find('[');
                const auto it = renamed.find(end.substr(0, bracket));
                const std::string body = it == renamed.end() ? end.substr(0, bracket) : it->second;
                return bracket == std::string::npos ? body : body + end.substr(bracket);
            };
            desc.a = rename(desc.a);
            if (desc.b) desc.b = rename(*desc.b);
            if (desc.anchor) shift(*desc.anchor, offset);
            if constexpr (std::is_same_v<D, JointDesc>) {
                // The world points a joint holds move with the copy.
                shift(desc.groundA, offset);
                shift(desc.groundB, offset);
                if (desc.circle) shift(desc.circle->center, offset);
                if (desc.line) shift(desc.line->point, offset);
            }
        } else {
            shift(desc.position, offset);
        }
        arrayOf(trial, desc).push_back(desc);
        out.push_back(std::move(desc));
    };
    // Bodies first, so that the springs after them find their ends' new ids.
    for (const ParticleDesc& d : source.particles) add(d);
    for (const BoxDesc& d : source.boxes) add(d);
    for (const DiskDesc& d : source.disks) add(d);
    for (const PolygonDesc& d : source.polygons) add(d);
    for (const ClothDesc& d : source.cloths) add(d);
    for (const PlaneDesc& d : source.planes) add(d);
    for (const SpringDesc& d : source.springs) add(d);
    for (const JointDesc& d : source.joints) add(d);
    return out;
}

}  // namespace phasebox
