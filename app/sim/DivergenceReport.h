#pragma once
// What the app tells a class when a run blows up, in the classroom's words: what happened and
// when, which object (a cloth node by its row and column, a body by its id and kind) and what to
// try, with the engine's technical message and the stability advisor's kept as details. The
// command line keeps the technical message (it is an interface, CONTRACT §4).

#include <QString>

namespace phasebox {

class World;

struct DivergenceReport {
    QString text;     // plain words: what happened, where, what to try
    QString details;  // the engine's message and the stability advisor's, for the curious
};

// Reads the world's divergence and asks the stability advisor at the restored state (the
// world's state is not changed).
DivergenceReport describeDivergence(World& world);

// An object id in the user's terms: "cloth 'cloth0', the node in row 3 from the top, column 2
// from the left", "box 'b3'", "disk 'wheel'", "particle 'bob'".
QString describeObject(const World& world, const QString& id);

}  // namespace phasebox
