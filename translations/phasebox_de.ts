<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de" sourcelanguage="en">
<context>
    <name>Charts</name>
    <message>
        <source>kinetic</source>
        <translation>kinetisch</translation>
    </message>
    <message>
        <source>potential</source>
        <translation>potentiell</translation>
    </message>
    <message>
        <source>total</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <source>work_nc</source>
        <translation>W_nk</translation>
    </message>
    <message>
        <source>drift</source>
        <translation>Drift</translation>
    </message>
    <message>
        <source>correction</source>
        <translation>Korrektur</translation>
    </message>
    <message>
        <source>time [s]</source>
        <translation>Zeit [s]</translation>
    </message>
    <message>
        <source>energy [J]</source>
        <translation>Energie [J]</translation>
    </message>
    <message>
        <source>local error per step</source>
        <translation>lokaler Fehler pro Schritt</translation>
    </message>
    <message>
        <source>error [m]</source>
        <translation>Fehler [m]</translation>
    </message>
    <message>
        <source>simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <source>start</source>
        <translation>Start</translation>
    </message>
</context>
<context>
    <name>CompareRun</name>
    <message>
        <source>Drag the timeline to an earlier moment first: the run is compared from there.</source>
        <translation>Ziehen Sie die Zeitleiste zuerst auf einen früheren Moment: Von dort aus wird der Lauf verglichen.</translation>
    </message>
    <message>
        <source>The recording holds no state before this moment.</source>
        <translation>Die Aufzeichnung enthält keinen Zustand vor diesem Moment.</translation>
    </message>
    <message>
        <source>The scene cannot be built for the ghost.</source>
        <translation>Die Szene lässt sich für den Geist nicht aufbauen.</translation>
    </message>
    <message>
        <source>The recorded frames are of other objects than the scene&apos;s.</source>
        <translation>Die aufgezeichneten Bilder zeigen andere Objekte als die der Szene.</translation>
    </message>
    <message>
        <source>Compare from here</source>
        <translation>Von hier vergleichen</translation>
    </message>
</context>
<context>
    <name>DivergenceText</name>
    <message>
        <source>a position or speed grew so large that it is no longer a number</source>
        <translation>eine Position oder Geschwindigkeit wurde so groß, dass sie keine Zahl mehr ist</translation>
    </message>
    <message>
        <source>its energy grew without bound</source>
        <translation>seine Energie wuchs unbegrenzt</translation>
    </message>
    <message>
        <source>the adaptive method could not keep its error small enough</source>
        <translation>das adaptive Verfahren konnte seinen Fehler nicht klein genug halten</translation>
    </message>
    <message>
        <source>cloth &apos;%1&apos;, the node in row %2 from the top, column %3 from the left</source>
        <translation>Tuch „%1“, der Knoten in Zeile %2 von oben, Spalte %3 von links</translation>
    </message>
    <message>
        <source>particle &apos;%1&apos;</source>
        <translation>Teilchen „%1“</translation>
    </message>
    <message>
        <source>disk &apos;%1&apos;</source>
        <translation>Scheibe „%1“</translation>
    </message>
    <message>
        <source>polygon &apos;%1&apos;</source>
        <translation>Vieleck „%1“</translation>
    </message>
    <message>
        <source>box &apos;%1&apos;</source>
        <translation>Quader „%1“</translation>
    </message>
    <message>
        <source>The simulation became unstable. Try a smaller time step, more sub-steps or Implicit Euler.</source>
        <translation>Die Simulation wurde instabil. Versuchen Sie einen kleineren Zeitschritt, mehr Teilschritte oder das implizite Euler-Verfahren.</translation>
    </message>
    <message>
        <source>The simulation became unstable at t = %1: %2. It was paused and put back to t = %3.</source>
        <translation>Die Simulation wurde bei t = %1 instabil: %2. Sie wurde angehalten und auf t = %3 zurückgesetzt.</translation>
    </message>
    <message>
        <source>It started at %1.</source>
        <translation>Es begann bei %1.</translation>
    </message>
    <message>
        <source>a smaller time step: dt below %1</source>
        <translation>einen kleineren Zeitschritt: dt unter %1</translation>
    </message>
    <message>
        <source>%1 sub-steps per step (same dt, each step cut into %1 pieces)</source>
        <translation>%1 Teilschritte pro Schritt (gleiches dt, jeder Schritt in %1 Stücke geteilt)</translation>
    </message>
    <message>
        <source>a smaller time step (half of dt = %1)</source>
        <translation>einen kleineren Zeitschritt (die Hälfte von dt = %1)</translation>
    </message>
    <message>
        <source>%1 sub-steps per step</source>
        <translation>%1 Teilschritte pro Schritt</translation>
    </message>
    <message>
        <source>%1, which stays stable at any time step (it damps fast motion)</source>
        <translation>%1, das bei jedem Zeitschritt stabil bleibt (es dämpft schnelle Bewegungen)</translation>
    </message>
    <message>
        <source>start the chain from joint &apos;%1&apos; to joint &apos;%2&apos; with some sag: it is pulled straight between two fixed points, where it cannot sag without stretching, and the forces that keep it straight grow without bound as it moves</source>
        <translation>den Strang vom Gelenk „%1“ bis zum Gelenk „%2“ mit etwas Durchhang beginnen: Er ist zwischen zwei festen Punkten straff gezogen, wo er nicht durchhängen kann, ohne sich zu dehnen, und die Kräfte, die ihn gerade halten, wachsen ohne Grenze, sobald er sich bewegt</translation>
    </message>
    <message>
        <source>or free one end of that chain</source>
        <translation>oder ein Ende dieses Strangs lösen</translation>
    </message>
    <message>
        <source>softer springs or cloth (a lower stiffness)</source>
        <translation>weichere Federn oder Tücher (eine kleinere Steifigkeit)</translation>
    </message>
    <message>
        <source>impulse contacts instead of penalty contacts</source>
        <translation>Impulskontakte statt Strafkontakte</translation>
    </message>
    <message>
        <source>What to try:</source>
        <translation>Was Sie versuchen können:</translation>
    </message>
    <message>
        <source>Stability advisor: %1</source>
        <translation>Stabilitätsberater: %1</translation>
    </message>
</context>
<context>
    <name>Integrators</name>
    <message>
        <source>Explicit Euler</source>
        <extracomment>integrator: explicit_euler</extracomment>
        <translation>Euler explizit</translation>
    </message>
    <message>
        <source>1</source>
        <extracomment>integrator: explicit_euler evaluations</extracomment>
        <translation>1</translation>
    </message>
    <message>
        <source>Forward Euler on (x, v): first order, gains energy on every oscillation.</source>
        <extracomment>integrator: explicit_euler summary</extracomment>
        <translation>Vorwärts-Euler auf (x, v): erste Ordnung, gewinnt bei jeder Schwingung Energie.</translation>
    </message>
    <message>
        <source>Symplectic Euler</source>
        <extracomment>integrator: symplectic_euler</extracomment>
        <translation>Euler symplekt.</translation>
    </message>
    <message>
        <source>Semi-implicit Euler: velocity first, then position with the new velocity; bounded energy.</source>
        <extracomment>integrator: symplectic_euler summary</extracomment>
        <translation>Halbimplizites Euler: zuerst die Geschwindigkeit, dann die Position mit der neuen Geschwindigkeit; beschränkte Energie.</translation>
    </message>
    <message>
        <source>Midpoint (RK2)</source>
        <extracomment>integrator: midpoint</extracomment>
        <translation>Mittelp. (RK2)</translation>
    </message>
    <message>
        <source>2</source>
        <extracomment>integrator: midpoint evaluations</extracomment>
        <translation>2</translation>
    </message>
    <message>
        <source>Explicit midpoint: a half step to estimate the slope, then a full step with it.</source>
        <extracomment>integrator: midpoint summary</extracomment>
        <translation>Explizite Mittelpunktregel: ein halber Schritt, um die Steigung zu schätzen, dann ein ganzer Schritt damit.</translation>
    </message>
    <message>
        <source>Heun (explicit trapezoid)</source>
        <extracomment>integrator: heun</extracomment>
        <translation>Heun (expl. Trapez)</translation>
    </message>
    <message>
        <source>Average of the slopes at the start and at an Euler-predicted end point.</source>
        <extracomment>integrator: heun summary</extracomment>
        <translation>Mittelwert der Steigungen am Anfang und an einem mit Euler vorhergesagten Endpunkt.</translation>
    </message>
    <message>
        <source>Runge–Kutta 4</source>
        <extracomment>integrator: rk4</extracomment>
        <translation>Runge-Kutta 4</translation>
    </message>
    <message>
        <source>4</source>
        <extracomment>integrator: rk4 evaluations</extracomment>
        <translation>4</translation>
    </message>
    <message>
        <source>Classic fourth-order Runge–Kutta: four slopes weighted 1/6, 1/3, 1/3, 1/6.</source>
        <extracomment>integrator: rk4 summary</extracomment>
        <translation>Klassisches Runge-Kutta-Verfahren vierter Ordnung: vier Steigungen mit den Gewichten 1/6, 1/3, 1/3, 1/6.</translation>
    </message>
    <message>
        <source>Velocity Verlet</source>
        <extracomment>integrator: velocity_verlet</extracomment>
        <translation>Velocity-Verlet</translation>
    </message>
    <message>
        <source>Position from the current acceleration, velocity from the average of old and new ones.</source>
        <extracomment>integrator: velocity_verlet summary</extracomment>
        <translation>Position aus der aktuellen Beschleunigung, Geschwindigkeit aus dem Mittel von alter und neuer.</translation>
    </message>
    <message>
        <source>Implicit Euler</source>
        <extracomment>integrator: implicit_euler</extracomment>
        <translation>Euler implizit</translation>
    </message>
    <message>
        <source>1 + Jacobian per Newton iteration</source>
        <extracomment>integrator: implicit_euler evaluations</extracomment>
        <translation>1 + Jacobi-Matrix pro Newton-Iteration</translation>
    </message>
    <message>
        <source>Backward Euler, Newton-linearised (Baraff &amp; Witkin): unconditionally stable, dissipative.</source>
        <extracomment>integrator: implicit_euler summary</extracomment>
        <translation>Rückwärts-Euler, Newton-linearisiert (Baraff &amp; Witkin): unbedingt stabil, dissipativ.</translation>
    </message>
    <message>
        <source>Implicit midpoint</source>
        <extracomment>integrator: implicit_midpoint</extracomment>
        <translation>Impl. Mittelpunkt</translation>
    </message>
    <message>
        <source>1 + Jacobian per Newton iteration (to convergence)</source>
        <extracomment>integrator: implicit_midpoint evaluations</extracomment>
        <translation>1 + Jacobi-Matrix pro Newton-Iteration (bis zur Konvergenz)</translation>
    </message>
    <message>
        <source>Implicit midpoint rule: symplectic, second order, conserves a linear spring&apos;s energy.</source>
        <extracomment>integrator: implicit_midpoint summary</extracomment>
        <translation>Implizite Mittelpunktregel: symplektisch, zweite Ordnung, erhält die Energie einer linearen Feder.</translation>
    </message>
    <message>
        <source>Adaptive Euler (step doubling)</source>
        <extracomment>integrator: adaptive_euler</extracomment>
        <translation>Euler adaptiv (Schrittverdopplung)</translation>
    </message>
    <message>
        <source>2 per attempt</source>
        <extracomment>integrator: adaptive_euler evaluations</extracomment>
        <translation>2 pro Versuch</translation>
    </message>
    <message>
        <source>Explicit Euler whose step size follows the error of one step against two half steps.</source>
        <extracomment>integrator: adaptive_euler summary</extracomment>
        <translation>Explizites Euler, dessen Schrittweite dem Fehler eines Schritts gegenüber zwei halben Schritten folgt.</translation>
    </message>
    <message>
        <source>Dormand–Prince 5(4)</source>
        <extracomment>integrator: rk45</extracomment>
        <translation>Dormand-Prince 5(4)</translation>
    </message>
    <message>
        <source>6 per attempt (+1 per call)</source>
        <extracomment>integrator: rk45 evaluations</extracomment>
        <translation>6 pro Versuch (+1 pro Aufruf)</translation>
    </message>
    <message>
        <source>Embedded Runge–Kutta pair with error control; the reference for the accuracy lab.</source>
        <extracomment>integrator: rk45 summary</extracomment>
        <translation>Eingebettetes Runge-Kutta-Paar mit Fehlerkontrolle; die Referenz des Genauigkeitslabors.</translation>
    </message>
</context>
<context>
    <name>MeasureOverlay</name>
    <message>
        <source>gravity</source>
        <translation>Gewichtskraft</translation>
    </message>
    <message>
        <source>drag</source>
        <translation>Luftwiderstand</translation>
    </message>
    <message>
        <source>newtonian gravity</source>
        <translation>Newtonsche Gravitation</translation>
    </message>
    <message>
        <source>buoyancy</source>
        <translation>Auftrieb</translation>
    </message>
    <message>
        <source>wind</source>
        <translation>Wind</translation>
    </message>
    <message>
        <source>flocking</source>
        <translation>Schwarmverhalten</translation>
    </message>
    <message>
        <source>coulomb</source>
        <translation>Coulomb</translation>
    </message>
    <message>
        <source>penalty contacts</source>
        <translation>Strafkontakte</translation>
    </message>
    <message>
        <source>spring %1</source>
        <translation>Feder %1</translation>
    </message>
    <message>
        <source>contact</source>
        <translation>Kontakt</translation>
    </message>
    <message>
        <source>joint %1</source>
        <translation>Gelenk %1</translation>
    </message>
    <message>
        <source>Free body: %1, m = %2 kg</source>
        <translation>Freikörperbild: %1, m = %2 kg</translation>
    </message>
    <message>
        <source>forces: 1 px = %1 N, net %2 N</source>
        <translation>Kräfte: 1 px = %1 N, resultierend %2 N</translation>
    </message>
    <message>
        <source>momentum 0</source>
        <translation>Impuls 0</translation>
    </message>
    <message>
        <source>momentum: 1 px = %1 kg·m/s</source>
        <translation>Impuls: 1 px = %1 kg·m/s</translation>
    </message>
    <message>
        <source>Free body: select a moving body</source>
        <translation>Freikörperbild: einen bewegten Körper auswählen</translation>
    </message>
    <message>
        <source>system: p = (%1, %2) kg·m/s, CM ◑</source>
        <translation>System: p = (%1, %2) kg·m/s, SP ◑</translation>
    </message>
</context>
<context>
    <name>ObjectKind</name>
    <message>
        <source>particle</source>
        <extracomment>kind: particle</extracomment>
        <translation>Teilchen</translation>
    </message>
    <message>
        <source>box</source>
        <extracomment>kind: box</extracomment>
        <translation>Quader</translation>
    </message>
    <message>
        <source>disk</source>
        <extracomment>kind: disk</extracomment>
        <translation>Scheibe</translation>
    </message>
    <message>
        <source>polygon</source>
        <extracomment>kind: polygon</extracomment>
        <translation>Vieleck</translation>
    </message>
    <message>
        <source>plane</source>
        <extracomment>kind: plane</extracomment>
        <translation>Ebene</translation>
    </message>
    <message>
        <source>spring</source>
        <extracomment>kind: spring</extracomment>
        <translation>Feder</translation>
    </message>
    <message>
        <source>cloth</source>
        <extracomment>kind: cloth</extracomment>
        <translation>Tuch</translation>
    </message>
    <message>
        <source>joint</source>
        <extracomment>kind: joint</extracomment>
        <translation>Gelenk</translation>
    </message>
    <message>
        <source>object</source>
        <extracomment>kind: object</extracomment>
        <translation>Objekt</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>diverged</source>
        <translation>divergiert</translation>
    </message>
    <message>
        <source>Phasebox User Guide</source>
        <translation>Phasebox-Benutzerhandbuch</translation>
    </message>
    <message>
        <source>User guide</source>
        <translation>Benutzerhandbuch</translation>
    </message>
    <message>
        <source>The user guide is missing from this build.</source>
        <translation>Das Benutzerhandbuch fehlt in diesem Build.</translation>
    </message>
    <message>
        <source>Keyboard Shortcuts</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <source>action</source>
        <translation>Aktion</translation>
    </message>
    <message>
        <source>keys</source>
        <translation>Tasten</translation>
    </message>
    <message>
        <source>Every menu command that has a key, as this window has them now.</source>
        <translation>Jeder Menübefehl mit Tastenkürzel, so wie dieses Fenster sie jetzt hat.</translation>
    </message>
    <message>
        <source>Phasebox scenes (*.phasebox.json *.json);;All files (*)</source>
        <translation>Phasebox-Szenen (*.phasebox.json *.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Add %1 %2</source>
        <translation>%1 %2 hinzufügen</translation>
    </message>
    <message numerus="yes">
        <source>Paste %n objects</source>
        <translation>
            <numerusform>%n Objekt einfügen</numerusform>
            <numerusform>%n Objekte einfügen</numerusform>
        </translation>
    </message>
    <message>
        <source>nothing to add</source>
        <translation>nichts hinzuzufügen</translation>
    </message>
    <message>
        <source>nothing to delete: no object has the id %1</source>
        <translation>nichts zu löschen: kein Objekt hat die Kennung %1</translation>
    </message>
    <message>
        <source>Delete %1</source>
        <translation>%1 löschen</translation>
    </message>
    <message numerus="yes">
        <source>Delete %n objects</source>
        <translation>
            <numerusform>%n Objekt löschen</numerusform>
            <numerusform>%n Objekte löschen</numerusform>
        </translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>%1 verschieben</translation>
    </message>
    <message>
        <source>unknown object id %1</source>
        <translation>unbekannte Objektkennung %1</translation>
    </message>
    <message>
        <source>the position of %1 must be finite</source>
        <translation>die Position von %1 muss endlich sein</translation>
    </message>
    <message>
        <source>the position of %1 must lie within ±%2 m</source>
        <translation>die Position von %1 muss innerhalb von ±%2 m liegen</translation>
    </message>
    <message>
        <source>%1 %2 has no property &quot;%3&quot;</source>
        <translation>%1 %2 hat keine Eigenschaft „%3“</translation>
    </message>
    <message>
        <source>Set %1 of %2</source>
        <translation>%1 von %2 setzen</translation>
    </message>
    <message>
        <source>Pin %1</source>
        <translation>%1 fixieren</translation>
    </message>
    <message>
        <source>Unpin %1</source>
        <translation>%1 lösen</translation>
    </message>
    <message>
        <source>Make %1 static</source>
        <translation>%1 statisch machen</translation>
    </message>
    <message>
        <source>Make %1 dynamic</source>
        <translation>%1 dynamisch machen</translation>
    </message>
    <message>
        <source>only particles and rigid bodies can be pinned</source>
        <translation>nur Teilchen und starre Körper können fixiert werden</translation>
    </message>
    <message>
        <source>Change simulation settings</source>
        <translation>Simulationseinstellungen ändern</translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation>%1 ändern</translation>
    </message>
    <message>
        <source>the CSV file</source>
        <translation>die CSV-Datei</translation>
    </message>
    <message>
        <source>position error [m], lower is better</source>
        <translation>Positionsfehler [m], kleiner ist besser</translation>
    </message>
    <message>
        <source>CPU time [s], left is faster</source>
        <translation>CPU-Zeit [s], weiter links ist schneller</translation>
    </message>
    <message>
        <source>%1 %2 hangs between two bodies; move them instead</source>
        <translation>%1 %2 hängt zwischen zwei Körpern; verschieben Sie stattdessen die Körper</translation>
    </message>
    <message>
        <source>%1 %2 moves with its bodies; move them instead</source>
        <translation>%1 %2 bewegt sich mit seinen Körpern; verschieben Sie stattdessen die Körper</translation>
    </message>
</context>
<context>
    <name>RewindCommand</name>
    <message>
        <source>Play from t = %1 s</source>
        <translation>Ab t = %1 s abspielen</translation>
    </message>
</context>
<context>
    <name>SceneTexts</name>
    <message>
        <source>Bouncing balls: restitution</source>
        <extracomment>scenes/bouncing-balls.phasebox.json: name</extracomment>
        <translation>Springende Bälle: Stoßzahl</translation>
    </message>
    <message>
        <source>Four balls fall from 2 m onto a hard floor. The coefficient of restitution e is the ratio of the speeds after and before the bounce, so each ball climbs back to e²·h: 2 m, 1.28 m, 0.5 m and 0.08 m for e = 1, 0.8, 0.5 and 0.2. Watch the kinetic and potential energy trade places, and each bounce of the lossy balls move energy into work_nc.</source>
        <extracomment>scenes/bouncing-balls.phasebox.json: description</extracomment>
        <translation>Vier Bälle fallen aus 2 m auf einen harten Boden. Die Stoßzahl e ist das Verhältnis der Geschwindigkeiten nach und vor dem Aufprall, also steigt jeder Ball wieder auf e²·h: 2 m, 1,28 m, 0,5 m und 0,08 m für e = 1, 0,8, 0,5 und 0,2. Beobachten Sie, wie kinetische und potentielle Energie die Plätze tauschen und jeder Aufprall der verlustbehafteten Bälle Energie nach work_nc verschiebt.</translation>
    </message>
    <message>
        <source>Box on an incline: stick or slide</source>
        <extracomment>scenes/box-incline.phasebox.json: name</extracomment>
        <translation>Quader auf der schiefen Ebene: Haften oder Gleiten</translation>
    </message>
    <message>
        <source>Two boxes sit on two ramps, both at θ = 30° (tan θ = 0.58). On the left the friction coefficient is μ = 0.7 &gt; tan θ, so static friction holds the box still; on the right μ = 0.4 &lt; tan θ, so the box slides down with a = g(sin θ − μ cos θ) = 1.5 m/s². The rule: a box sticks when tan θ ≤ μ. Change the friction of a box and of its ramp to find the tipping point (their contact takes √(μ₁·μ₂) of the two).</source>
        <extracomment>scenes/box-incline.phasebox.json: description</extracomment>
        <translation>Zwei Quader liegen auf zwei Rampen, beide mit θ = 30° (tan θ = 0,58). Links ist die Reibungszahl μ = 0,7 &gt; tan θ, also hält die Haftreibung den Quader fest; rechts ist μ = 0,4 &lt; tan θ, also gleitet der Quader mit a = g(sin θ − μ cos θ) = 1,5 m/s² hinab. Die Regel: ein Quader haftet, wenn tan θ ≤ μ. Ändern Sie die Reibungszahl eines Quaders und seiner Rampe, um den Kipppunkt zu finden (ihr Kontakt nimmt √(μ₁·μ₂) der beiden).</translation>
    </message>
    <message>
        <source>Pyramid of boxes</source>
        <extracomment>scenes/box-pyramid.phasebox.json: name</extracomment>
        <translation>Pyramide aus Quadern</translation>
    </message>
    <message>
        <source>Fifty-five 1 m boxes stacked in 10 rows on the ground, friction 0.6. A good contact solver keeps the pyramid standing still, with no creeping or jitter. It runs velocity Verlet, which is exact under constant gravity, so the drift stays at zero; switch to symplectic Euler and the drift stays flat too once the stack has settled in its first second (about −0.15 J): the contacts&apos; forces act inside the method&apos;s step, so a box at rest leaves the method nothing to get wrong. The contact solver takes the inner sub-steps a stack needs by itself: the scene runs at the format&apos;s defaults, one step per frame.</source>
        <extracomment>scenes/box-pyramid.phasebox.json: description</extracomment>
        <translation>Fünfundfünfzig 1-m-Quader in 10 Reihen auf dem Boden gestapelt, Reibung 0,6. Ein guter Kontaktlöser hält die Pyramide still, ohne Kriechen oder Zittern. Sie läuft mit Velocity-Verlet, das unter konstanter Schwerkraft exakt ist, also bleibt die Drift bei null; wechseln Sie zu symplektischem Euler, und auch dann bleibt die Drift flach, sobald sich der Stapel in seiner ersten Sekunde gesetzt hat (etwa −0,15 J): die Kräfte der Kontakte wirken im Schritt des Verfahrens, also lässt ein ruhender Quader dem Verfahren nichts, was es falsch machen könnte. Der Kontaktlöser wählt die inneren Teilschritte, die ein Stapel braucht, selbst: die Szene läuft mit den Vorgaben des Formats, ein Schritt pro Bild.</translation>
    </message>
    <message>
        <source>Motor car climbing a ramp</source>
        <extracomment>scenes/car.phasebox.json: name</extracomment>
        <translation>Motorauto fährt eine Rampe hinauf</translation>
    </message>
    <message>
        <source>A toy car climbs a ramp: a 4 kg box body rides on two rigid disk wheels (radius 0.3 m, 2 kg, friction 1) hinged at their axles, and each axle has a motor that turns its wheel at −3 rad/s relative to the body with at most 40 N·m. The joint angle is the wheel&apos;s angle minus the body&apos;s, so a negative speed turns the wheels clockwise and drives the car towards +x at about 0.9 m/s. It rolls along the ground, climbs the 15° ramp and drives on along the 1 m high plateau. The motors&apos; work ends up as the car&apos;s potential energy (78 J by the plateau) and its motion: the energy plot books it in work_nc (82 J in 10 s, the motors&apos; push less what friction takes) while correction stays near zero, because the motors push inside the method&apos;s step, as the contacts do; the hinges hold the wheels to well under a millimetre.</source>
        <extracomment>scenes/car.phasebox.json: description</extracomment>
        <translation>Ein Spielzeugauto fährt eine Rampe hinauf: ein 4-kg-Quader als Karosserie fährt auf zwei starren Scheibenrädern (Radius 0,3 m, 2 kg, Reibung 1), die an ihren Achsen mit Scharnieren befestigt sind, und jede Achse hat einen Motor, der ihr Rad mit −3 rad/s relativ zur Karosserie dreht, mit höchstens 40 N·m. Der Gelenkwinkel ist der Winkel des Rads minus der der Karosserie, also dreht eine negative Geschwindigkeit die Räder im Uhrzeigersinn und fährt das Auto mit etwa 0,9 m/s in Richtung +x. Es rollt über den Boden, fährt die 15°-Rampe hinauf und weiter über das 1 m hohe Plateau. Die Arbeit der Motoren wird zur potentiellen Energie des Autos (78 J bis zum Plateau) und zu seiner Bewegung: Das Energiediagramm bucht sie in work_nc (82 J in 10 s, der Schub der Motoren abzüglich dessen, was die Reibung nimmt), während die Korrektur nahe null bleibt, weil die Motoren innerhalb des Schritts des Verfahrens schieben, so wie die Kontakte; die Scharniere halten die Räder auf deutlich unter einen Millimeter genau.</translation>
    </message>
    <message>
        <source>Chain bridge</source>
        <extracomment>scenes/chain-bridge.phasebox.json: name</extracomment>
        <translation>Kettenbrücke</translation>
    </message>
    <message>
        <source>A bridge of ten wooden planks, 0.6 m by 0.12 m and 2 kg each, hinged end to end and hinged to the world at both ends, hangs between two pillars, and a 4 kg crate falls onto it from 2 m. Frictionless hinges pass forces but no turning moments, so the bridge hangs like a chain: the horizontal pull is the same all along it and each plank is steeper than its inner neighbour by the same step in slope, a discrete catenary, which is the shape it starts in. Watch the crate land, the bridge bounce and sway and the dip settle under the crate; drag the crate along the bridge, or drop more boxes on it. The hinges hold the planks together to well under a millimetre.</source>
        <extracomment>scenes/chain-bridge.phasebox.json: description</extracomment>
        <translation>Eine Brücke aus zehn Holzbrettern, je 0,6 m mal 0,12 m und 2 kg, Ende an Ende mit Scharnieren verbunden und an beiden Enden mit der Welt, hängt zwischen zwei Pfeilern, und eine 4-kg-Kiste fällt aus 2 m auf sie. Reibungsfreie Scharniere übertragen Kräfte, aber keine Drehmomente, also hängt die Brücke wie eine Kette: der waagrechte Zug ist überall gleich, und jedes Brett ist um denselben Steigungsschritt steiler als sein inneres Nachbarbrett, eine diskrete Kettenlinie, die Form, in der sie startet. Beobachten Sie, wie die Kiste landet, die Brücke federt und schwankt und die Senke unter der Kiste zur Ruhe kommt; ziehen Sie die Kiste über die Brücke oder lassen Sie weitere Quader darauf fallen. Die Scharniere halten die Bretter auf deutlich unter einen Millimeter zusammen.</translation>
    </message>
    <message>
        <source>Flag in the wind</source>
        <extracomment>scenes/cloth-flag.phasebox.json: name</extracomment>
        <translation>Fahne im Wind</translation>
    </message>
    <message>
        <source>A 2 m × 1.2 m cloth of 20 × 12 nodes (0.5 kg) is held along its left edge by a pole and released level. Each node feels its weight m·g and the wind&apos;s drag b·(w − v), so the flag swings down and settles where they balance, at tan α = m·g/(b·w) = 0.51, α = 27° below level. The cloth springs are stiff, so it runs implicit Euler at the frame step: switch to symplectic Euler and watch it blow up and be stopped as diverging.</source>
        <extracomment>scenes/cloth-flag.phasebox.json: description</extracomment>
        <translation>Ein Tuch von 2 m × 1,2 m aus 20 × 12 Knoten (0,5 kg) wird an seiner linken Kante von einer Stange gehalten und waagrecht losgelassen. Jeder Knoten spürt seine Gewichtskraft m·g und den Luftwiderstand des Winds b·(w − v), also schwingt die Fahne nach unten und kommt dort zur Ruhe, wo beide im Gleichgewicht sind, bei tan α = m·g/(b·w) = 0,51, α = 27° unter der Waagrechten. Die Tuchfedern sind steif, daher läuft es mit implizitem Euler beim Bildschritt: wechseln Sie zu symplektischem Euler und sehen Sie, wie es explodiert und als divergierend gestoppt wird.</translation>
    </message>
    <message>
        <source>Damped oscillators</source>
        <extracomment>scenes/damped-oscillators.phasebox.json: name</extracomment>
        <translation>Gedämpfte Schwinger</translation>
    </message>
    <message>
        <source>Three 1 kg balls hang on springs of k = 20 N/m and rest length 1 m, with damping c = 1, 8.944 and 25 N·s/m: under-damped, critically damped and over-damped (ζ = c/(2·√(k·m)) = 0.11, 1 and 2.8). Each is released at the spring&apos;s rest length and falls toward its equilibrium m·g/k = 0.49 m lower. What to watch: the under-damped ball overshoots and rings down with the envelope e^(−ζωt) at ω = √(k/m) = 4.47 rad/s; the critically damped one gets there fastest without overshooting; the over-damped one creeps in slowly, held back by its own damper. View → Exact Solution draws the closed form of each (dashed), and the energy plot shows work_nc taking the energy the dampers turn into heat.</source>
        <extracomment>scenes/damped-oscillators.phasebox.json: description</extracomment>
        <translation>Drei 1-kg-Bälle hängen an Federn mit k = 20 N/m und 1 m Ruhelänge, mit Dämpfung c = 1, 8,944 und 25 N·s/m: unterdämpft, kritisch gedämpft und überdämpft (ζ = c/(2·√(k·m)) = 0,11, 1 und 2,8). Jeder wird bei der Ruhelänge seiner Feder losgelassen und fällt zu seiner Gleichgewichtslage m·g/k = 0,49 m tiefer. Worauf zu achten ist: der unterdämpfte Ball schießt über und klingt mit der Einhüllenden e^(−ζωt) bei ω = √(k/m) = 4,47 rad/s ab; der kritisch gedämpfte kommt am schnellsten an, ohne überzuschießen; der überdämpfte kriecht langsam heran, von seinem eigenen Dämpfer gebremst. Ansicht → Exakte Lösung zeichnet die geschlossene Lösung jedes Balls (gestrichelt), und das Energiediagramm zeigt, wie work_nc die Energie aufnimmt, die die Dämpfer in Wärme umwandeln.</translation>
    </message>
    <message>
        <source>Springs, a pendulum and a swinging box</source>
        <extracomment>scenes/demo.phasebox.json: name</extracomment>
        <translation>Federn, ein Pendel und ein schwingender Quader</translation>
    </message>
    <message>
        <source>A ball on a spring, a two-ball spring pendulum and a box hung from one corner. Switch the integrator while it runs and watch the drift line in the energy plot: explicit Euler gains energy so fast that the run is stopped as diverging within a second and a half; symplectic Euler and Verlet keep the drift small, swinging about zero; implicit Euler steadily loses energy. The total falls a little under every method because the box&apos;s spring has a damper: that loss is work_nc, not drift.</source>
        <extracomment>scenes/demo.phasebox.json: description</extracomment>
        <translation>Ein Ball an einer Feder, ein Federpendel mit zwei Bällen und ein an einer Ecke aufgehängter Quader. Wechseln Sie den Integrator während des Laufs und beobachten Sie die Driftlinie im Energiediagramm: explizites Euler gewinnt so schnell Energie, dass der Lauf innerhalb von anderthalb Sekunden als divergent angehalten wird; symplektisches Euler und Verlet halten die Drift klein, sie schwankt um null; implizites Euler verliert stetig Energie. Die Gesamtenergie sinkt bei jedem Verfahren ein wenig, weil die Feder des Quaders einen Dämpfer hat: dieser Verlust ist work_nc, nicht Drift.</translation>
    </message>
    <message>
        <source>Dominoes</source>
        <extracomment>scenes/dominoes.phasebox.json: name</extracomment>
        <translation>Dominosteine</translation>
    </message>
    <message>
        <source>Twenty dominoes (0.1 m × 1 m) stand 0.5 m apart and the first is given a push. Each one tips the next, and the wave of falling dominoes runs down the row at a steady speed. Watch the potential energy fall steadily while the wave passes (several dominoes are falling at any moment), and the contacts&apos; work_nc take it away: about 7 J in all.</source>
        <extracomment>scenes/dominoes.phasebox.json: description</extracomment>
        <translation>Zwanzig Dominosteine (0,1 m × 1 m) stehen 0,5 m auseinander, und der erste bekommt einen Stoß. Jeder kippt den nächsten, und die Welle fallender Steine läuft mit gleichmäßiger Geschwindigkeit die Reihe entlang. Beobachten Sie, wie die potentielle Energie gleichmäßig sinkt, während die Welle durchläuft (es fallen immer mehrere Steine zugleich), und wie die work_nc der Kontakte sie wegnimmt: insgesamt etwa 7 J.</translation>
    </message>
    <message>
        <source>Elastic gas</source>
        <extracomment>scenes/elastic-gas.phasebox.json: name</extracomment>
        <translation>Elastisches Gas</translation>
    </message>
    <message>
        <source>212 disks bounce in a closed 6 m box with restitution 1, no friction and no gravity; all start at nearly the same speed (1.3 to 1.7 m/s) in random directions. Collisions share the energy out into a spread of speeds (the Maxwell–Boltzmann distribution) while the total kinetic energy stays constant: watch the flat line in the energy plot. The big heavy disk in the middle jiggles under the random kicks: Brownian motion.</source>
        <extracomment>scenes/elastic-gas.phasebox.json: description</extracomment>
        <translation>212 Scheiben prallen in einem geschlossenen 6-m-Kasten umher, mit Stoßzahl 1, ohne Reibung und ohne Schwerkraft; alle starten mit fast gleicher Geschwindigkeit (1,3 bis 1,7 m/s) in zufälligen Richtungen. Die Stöße verteilen die Energie auf eine Streuung von Geschwindigkeiten (die Maxwell-Boltzmann-Verteilung), während die gesamte kinetische Energie konstant bleibt: beachten Sie die flache Linie im Energiediagramm. Die große schwere Scheibe in der Mitte zittert unter den zufälligen Stößen: Brownsche Bewegung.</translation>
    </message>
    <message>
        <source>Galton board</source>
        <extracomment>scenes/galton-board.phasebox.json: name</extracomment>
        <translation>Galtonbrett</translation>
    </message>
    <message>
        <source>A Galton board: sixty balls fall in a column onto nine staggered rows of pegs and pile up in the bins below. At each row a ball goes left or right about equally often, so where it lands counts its rights against its lefts: for many balls and rows the piles would approach the binomial distribution, which looks like the bell curve. These sixty make a rough mound under the drop, wider than the binomial, because the balls bounce and knock each other across more than one peg at a time. The pegs are static rigid disks; the balls are particles that collide with each other (particle_collisions) and with the pegs, walls and floor. The pegs and the bin walls are frictionless: a ball is a particle, which slides rather than rolls, and friction would hold one that lands near a peg&apos;s top there for good, while in a real board it rolls off.</source>
        <extracomment>scenes/galton-board.phasebox.json: description</extracomment>
        <translation>Ein Galtonbrett: sechzig Bälle fallen in einer Säule auf neun versetzte Reihen von Stiften und stapeln sich in den Fächern darunter. In jeder Reihe geht ein Ball etwa gleich oft nach links oder rechts, also zählt sein Landeplatz seine Rechts- gegen seine Linksschritte: bei vielen Bällen und Reihen würden sich die Stapel der Binomialverteilung nähern, die wie die Glockenkurve aussieht. Diese sechzig bilden einen groben Hügel unter der Einwurfstelle, breiter als die Binomialverteilung, weil die Bälle springen und einander über mehr als einen Stift auf einmal stoßen. Die Stifte sind statische starre Scheiben; die Bälle sind Teilchen, die miteinander (particle_collisions) und mit Stiften, Wänden und Boden zusammenstoßen. Stifte und Fachwände sind reibungsfrei: ein Ball ist ein Teilchen, das gleitet statt rollt, und Reibung würde einen, der nahe der Spitze eines Stifts landet, dort für immer festhalten, während er auf einem echten Brett herunterrollt.</translation>
    </message>
    <message>
        <source>Newton&apos;s cradle</source>
        <extracomment>scenes/newtons-cradle.phasebox.json: name</extracomment>
        <translation>Newton-Pendel</translation>
    </message>
    <message>
        <source>Five steel balls hang on stiff strings, touching; the left ball is pulled out and let go. With restitution 1 the collision passes momentum and energy down the row, so the last ball flies out at the speed the first came in, and the middle balls hardly move. Count the balls that swing out, and watch the kinetic and potential energy trade places.</source>
        <extracomment>scenes/newtons-cradle.phasebox.json: description</extracomment>
        <translation>Fünf Stahlkugeln hängen an steifen Fäden und berühren sich; die linke Kugel wird ausgelenkt und losgelassen. Mit Stoßzahl 1 gibt der Stoß Impuls und Energie die Reihe entlang weiter, also fliegt die letzte Kugel mit der Geschwindigkeit hinaus, mit der die erste ankam, und die mittleren Kugeln bewegen sich kaum. Zählen Sie die Kugeln, die ausschwingen, und beobachten Sie, wie kinetische und potentielle Energie die Plätze tauschen.</translation>
    </message>
    <message>
        <source>Orbit around a star</source>
        <extracomment>scenes/orbit.phasebox.json: name</extracomment>
        <translation>Umlaufbahn um einen Stern</translation>
    </message>
    <message>
        <source>A ship on a circular orbit (r = 4 m, v = √(GM/r) = 5 m/s, one lap in 5.0 s) and a comet on an ellipse go round a star of GM = 100 (G = 1, so the numbers stay classroom-sized). RK4 keeps both orbits closed and the energy flat. Switch to explicit Euler and watch the orbits spiral outwards as the total energy climbs; symplectic Euler keeps them closed.</source>
        <extracomment>scenes/orbit.phasebox.json: description</extracomment>
        <translation>Ein Raumschiff auf einer Kreisbahn (r = 4 m, v = √(GM/r) = 5 m/s, ein Umlauf in 5,0 s) und ein Komet auf einer Ellipse umkreisen einen Stern mit GM = 100 (G = 1, damit die Zahlen klassenzimmergerecht bleiben). RK4 hält beide Bahnen geschlossen und die Energie flach. Wechseln Sie zu explizitem Euler und sehen Sie, wie die Bahnen nach außen spiralen, während die Gesamtenergie steigt; symplektisches Euler hält sie geschlossen.</translation>
    </message>
    <message>
        <source>Pendulum on a stiff spring</source>
        <extracomment>scenes/pendulum-stiff-spring.phasebox.json: name</extracomment>
        <translation>Pendel an einer steifen Feder</translation>
    </message>
    <message>
        <source>A 1 kg bob swings on a 2 m rod that is really a stiff spring (k = 10 000 N/m). The swing is slow (T ≈ 2π√(L/g) = 2.8 s, about 7% longer at this 60° amplitude) but the rod&apos;s stretching mode is fast (ω = √(k/m) = 100 rad/s), and that fast mode is what limits the time step. Try explicit Euler and watch it blow up; implicit Euler is stable but visibly damps the swing; symplectic Euler with sub-steps keeps the energy bounded.</source>
        <extracomment>scenes/pendulum-stiff-spring.phasebox.json: description</extracomment>
        <translation>Ein 1-kg-Pendelkörper schwingt an einer 2-m-Stange, die eigentlich eine steife Feder ist (k = 10 000 N/m). Die Schwingung ist langsam (T ≈ 2π√(L/g) = 2,8 s, bei dieser Amplitude von 60° etwa 7 % länger), aber die Dehnungsmode der Stange ist schnell (ω = √(k/m) = 100 rad/s), und diese schnelle Mode begrenzt den Zeitschritt. Probieren Sie explizites Euler und sehen Sie es explodieren; implizites Euler ist stabil, dämpft die Schwingung aber sichtbar; symplektisches Euler mit Teilschritten hält die Energie beschränkt.</translation>
    </message>
    <message>
        <source>Pendulum wave</source>
        <extracomment>scenes/pendulum-wave.phasebox.json: name</extracomment>
        <translation>Pendelwelle</translation>
    </message>
    <message>
        <source>Twelve pendulums hang side by side, their lengths chosen so that in 60 s the longest makes 51 swings, the next 52, and so on to 62 for the shortest (T = 60/(51 + n) s, L = g·(T/2π)²). Released together from 10°, they drift out of step: after 15 s they form a travelling snake, after 30 s two rows swinging against each other, and at 60 s they all line up again. Each one is a simple pendulum, so View → Exact Solution draws where the closed form puts it (dashed): at 10° the period is 0.19% longer than the small-angle 2π·√(L/g) the lengths were chosen for, so the real line-up comes about 0.1 s late. Try RK4 or a smaller dt and watch the bobs stay on their ghosts; explicit Euler lets every swing grow until, after about 8 s, the run is stopped as diverging.</source>
        <extracomment>scenes/pendulum-wave.phasebox.json: description</extracomment>
        <translation>Zwölf Pendel hängen nebeneinander, ihre Längen so gewählt, dass in 60 s das längste 51 Schwingungen macht, das nächste 52 und so weiter bis 62 für das kürzeste (T = 60/(51 + n) s, L = g·(T/2π)²). Gemeinsam aus 10° losgelassen, geraten sie aus dem Takt: nach 15 s bilden sie eine wandernde Schlange, nach 30 s zwei gegeneinander schwingende Reihen, und nach 60 s stehen sie wieder alle in einer Linie. Jedes ist ein mathematisches Pendel, also zeichnet Ansicht → Exakte Lösung, wo die geschlossene Lösung es hinstellt (gestrichelt): bei 10° ist die Periode 0,19 % länger als das 2π·√(L/g) für kleine Winkel, nach dem die Längen gewählt wurden, also kommt die echte Aufreihung etwa 0,1 s zu spät. Probieren Sie RK4 oder ein kleineres dt und sehen Sie, wie die Pendelkörper auf ihren Geistern bleiben; explizites Euler lässt jede Schwingung wachsen, bis der Lauf nach etwa 8 s als divergent angehalten wird.</translation>
    </message>
    <message>
        <source>Polygon pile</source>
        <extracomment>scenes/polygon-pile.phasebox.json: name</extracomment>
        <translation>Vieleckhaufen</translation>
    </message>
    <message>
        <source>A pile of polygons: triangles to heptagons of several sizes dropped into a bin. Each is a rigid convex polygon whose mass and moment of inertia come from its vertices; they collide face to face and corner to face, tumble, and settle into a heap that stands. Select one to see its properties, or add more with the Add polygon tool and watch the heap take them.</source>
        <extracomment>scenes/polygon-pile.phasebox.json: description</extracomment>
        <translation>Ein Haufen Vielecke: Dreiecke bis Siebenecke verschiedener Größen, in einen Behälter geworfen. Jedes ist ein starres konvexes Vieleck, dessen Masse und Trägheitsmoment aus seinen Ecken folgen; sie stoßen Fläche an Fläche und Ecke an Fläche zusammen, purzeln und kommen zu einem stehenden Haufen zur Ruhe. Wählen Sie eines aus, um seine Eigenschaften zu sehen, oder fügen Sie mit dem Werkzeug „Vieleck hinzufügen“ weitere hinzu und sehen Sie, wie der Haufen sie aufnimmt.</translation>
    </message>
    <message>
        <source>Projectiles with air drag</source>
        <extracomment>scenes/projectile-drag.phasebox.json: name</extracomment>
        <translation>Würfe mit Luftwiderstand</translation>
    </message>
    <message>
        <source>Four balls of the same size are launched together at 10 m/s and 45° through air with quadratic drag F = −c‖v‖v (c = 0.004 kg/m). The drag force is the same on all, so the light balls slow down far more: the terminal speed √(mg/c) is 7 m/s for 20 g, 16 m/s for 0.1 kg, 35 m/s for 0.5 kg and 157 m/s for 10 kg. Without drag all would land 10.2 m away: compare the ranges and the lopsided paths. In the energy plot work_nc slopes gently down in flight as drag takes its share (most of the 20 g ball&apos;s energy, a hundredth of the 10 kg ball&apos;s), then drops as each ball lands dead in the ground, which work_nc counts too.</source>
        <extracomment>scenes/projectile-drag.phasebox.json: description</extracomment>
        <translation>Vier gleich große Bälle werden zusammen mit 10 m/s unter 45° durch Luft mit quadratischem Widerstand F = −c‖v‖v (c = 0,004 kg/m) geworfen. Die Widerstandskraft ist für alle gleich, also werden die leichten Bälle viel stärker gebremst: die Endgeschwindigkeit √(mg/c) beträgt 7 m/s für 20 g, 16 m/s für 0,1 kg, 35 m/s für 0,5 kg und 157 m/s für 10 kg. Ohne Luftwiderstand würden alle 10,2 m entfernt landen: vergleichen Sie die Weiten und die schiefen Bahnen. Im Energiediagramm fällt work_nc im Flug sanft ab, während der Luftwiderstand seinen Anteil nimmt (den größten Teil der Energie des 20-g-Balls, ein Hundertstel der des 10-kg-Balls), und dann steil, wenn jeder Ball tot im Boden landet, was work_nc ebenfalls zählt.</translation>
    </message>
    <message>
        <source>Ragdoll on the stairs</source>
        <extracomment>scenes/ragdoll.phasebox.json: name</extracomment>
        <translation>Gliederpuppe auf der Treppe</translation>
    </message>
    <message>
        <source>A ragdoll of ten boxes (torso, head, upper and lower arms, thighs and shins; 32 kg in all) joined by nine hinges with limits: the neck turns half a radian either way, elbows and knees bend one way only, shoulders and hips swing outwards but not across the body. It is pushed off the top of a flight of stairs and tumbles down them. Where it ends is chaotic: a nanometre&apos;s nudge to the torso changes the whole tumble, and it may end up on the bottom step, on the floor or against the low wall at the foot of the stairs. Hinged neighbours do not collide with each other, but every other pair of limbs does, and so do the limbs and the steps. Watch the hinges hold (well under a millimetre) while the limits stop the joints at their ends.</source>
        <extracomment>scenes/ragdoll.phasebox.json: description</extracomment>
        <translation>Eine Gliederpuppe aus zehn Quadern (Rumpf, Kopf, Ober- und Unterarme, Oberschenkel und Schienbeine; 32 kg insgesamt), verbunden durch neun Scharniere mit Grenzen: der Hals dreht sich einen halben Radiant nach jeder Seite, Ellbogen und Knie beugen sich nur in eine Richtung, Schultern und Hüften schwingen nach außen, aber nicht vor den Körper. Sie wird oben von einer Treppe gestoßen und purzelt hinunter. Wo sie endet, ist chaotisch: ein Anstoß von einem Nanometer am Rumpf ändert das ganze Purzeln, und sie kann auf der untersten Stufe, auf dem Boden oder an der niedrigen Mauer am Fuß der Treppe liegen bleiben. Durch Scharniere verbundene Nachbarn stoßen nicht zusammen, aber jedes andere Paar von Gliedern schon, ebenso die Glieder und die Stufen. Beobachten Sie, wie die Scharniere halten (deutlich unter einem Millimeter), während die Grenzen die Gelenke an ihren Enden stoppen.</translation>
    </message>
    <message>
        <source>Chain of springs</source>
        <extracomment>scenes/spring-chain.phasebox.json: name</extracomment>
        <translation>Federkette</translation>
    </message>
    <message>
        <source>Ten 0.1 kg beads joined by springs hang from a fixed hook and are released from a horizontal line. Watch the chain whip down and swing like a rope, and notice that the top spring stretches most: it carries the weight of every bead below it. The spring damping turns the swing&apos;s energy into work_nc in the energy plot, so the total slowly falls while the drift stays near zero.</source>
        <extracomment>scenes/spring-chain.phasebox.json: description</extracomment>
        <translation>Zehn 0,1-kg-Perlen, durch Federn verbunden, hängen an einem festen Haken und werden aus einer waagrechten Linie losgelassen. Beobachten Sie, wie die Kette herunterpeitscht und wie ein Seil schwingt, und bemerken Sie, dass die oberste Feder am meisten gedehnt wird: sie trägt das Gewicht jeder Perle darunter. Die Federdämpfung wandelt die Energie der Schwingung im Energiediagramm in work_nc um, also sinkt die Gesamtenergie langsam, während die Drift nahe null bleibt.</translation>
    </message>
    <message>
        <source>Spring oscillator: T = 2π√(m/k)</source>
        <extracomment>scenes/spring-oscillator.phasebox.json: name</extracomment>
        <translation>Federschwinger: T = 2π√(m/k)</translation>
    </message>
    <message>
        <source>Two balls bounce on identical springs (k = 39.48 N/m); the right one is 4 times heavier. The period T = 2π√(m/k) is exactly 1 s for the 1 kg ball and 2 s for the 4 kg ball, and gravity only moves the equilibrium down by mg/k without changing the period. Switch to explicit Euler and watch the bounce grow and the total energy climb in the energy plot; symplectic Euler and Verlet keep it bounded.</source>
        <extracomment>scenes/spring-oscillator.phasebox.json: description</extracomment>
        <translation>Zwei Bälle schwingen an gleichen Federn (k = 39,48 N/m); der rechte ist 4-mal schwerer. Die Periode T = 2π√(m/k) beträgt genau 1 s für den 1-kg-Ball und 2 s für den 4-kg-Ball, und die Schwerkraft verschiebt nur die Gleichgewichtslage um mg/k nach unten, ohne die Periode zu ändern. Wechseln Sie zu explizitem Euler und sehen Sie die Schwingung wachsen und die Gesamtenergie im Energiediagramm steigen; symplektisches Euler und Verlet halten sie beschränkt.</translation>
    </message>
    <message>
        <source>Stiff spring: explicit methods blow up</source>
        <extracomment>scenes/stiff-spring-blowup.phasebox.json: name</extracomment>
        <translation>Steife Feder: explizite Verfahren explodieren</translation>
    </message>
    <message>
        <source>A 1 kg ball swings on a very stiff spring (k = 100 000 N/m, so ω = √(k/m) = 316 rad/s) at the frame step dt = 1/60 s: ω·dt = 5.3, far past the stability limits of the explicit methods (ω·dt &lt; 2 for symplectic Euler and Verlet, 2.83 for RK4). Implicit Euler stays stable, but pays with numerical damping: watch the swing die away and the drift fall in the energy plot. Switch to symplectic Euler and the spring explodes within a few frames and is stopped as diverging; implicit midpoint is stable and keeps the energy.</source>
        <extracomment>scenes/stiff-spring-blowup.phasebox.json: description</extracomment>
        <translation>Ein 1-kg-Ball schwingt an einer sehr steifen Feder (k = 100 000 N/m, also ω = √(k/m) = 316 rad/s) beim Bildschritt dt = 1/60 s: ω·dt = 5,3, weit jenseits der Stabilitätsgrenzen der expliziten Verfahren (ω·dt &lt; 2 für symplektisches Euler und Verlet, 2,83 für RK4). Implizites Euler bleibt stabil, bezahlt aber mit numerischer Dämpfung: sehen Sie die Schwingung abklingen und die Drift im Energiediagramm fallen. Wechseln Sie zu symplektischem Euler, und die Feder explodiert innerhalb weniger Bilder und wird als divergierend gestoppt; die implizite Mittelpunktregel ist stabil und erhält die Energie.</translation>
    </message>
    <message>
        <source>Lesson: the Atwood machine</source>
        <extracomment>lessons/atwood-machine.phasebox.json: name</extracomment>
        <translation>Lektion: die Atwoodsche Fallmaschine</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: two Atwood machines, each a pair of weights on a massless rope over two fixed pulleys, 3 kg against 1 kg on the left and 1.1 kg against 0.9 kg on the right; each heavy weight starts 3 m above the floor. 2) Read each heavy weight&apos;s acceleration off the graph of its vy in the Instruments dock (left_heavy.vy, right_heavy.vy): while it falls the line is straight and its slope is −a; or time the fall with the stopwatch (Instruments, Timer) and work out a = 2·h/t². 3) Select a weight, change its mass, Reset and read the new slope. What to watch: the left pair accelerates at g/2 = 4.905 m/s² and lands after 1.11 s at 5.4 m/s; the right pair accelerates at g/10 = 0.981 m/s² and lands after 2.47 s at 2.4 m/s. When a heavy weight lands its partner stops too, because Phasebox&apos;s pulley rope never goes slack (a real light weight would coast on upwards for a moment). Why: the rope does not stretch, so the two weights move at the same speed, one up and one down, and it pulls each of them up with the same tension T. Newton&apos;s second law for each weight, m1·a = m1·g − T and m2·a = T − m2·g, added together gives a = g·(m1 − m2)/(m1 + m2): gravity pulls on the difference of the masses but has to accelerate their sum. Then T = 2·m1·m2·g/(m1 + m2), which is 14.7 N on the left, between the light weight&apos;s 9.8 N and the heavy one&apos;s 29.4 N, and 9.71 N on the right. George Atwood described the machine in 1784 to slow free fall down enough to time it by hand: with nearly equal masses a is a small fraction of g. The mass does not cancel here as it does for a pendulum, because the two weights share one acceleration.</source>
        <extracomment>lessons/atwood-machine.phasebox.json: description</extracomment>
        <translation>Probieren Sie: 1) Drücken Sie Start: zwei Atwoodsche Fallmaschinen, jede ein Paar Gewichte an einem masselosen Seil über zwei festen Rollen, 3 kg gegen 1 kg links und 1,1 kg gegen 0,9 kg rechts; jedes schwere Gewicht startet 3 m über dem Boden. 2) Lesen Sie die Beschleunigung jedes schweren Gewichts am Graphen seines vy im Instrumente-Dock ab (left_heavy.vy, right_heavy.vy): während es fällt, ist die Linie gerade und ihre Steigung ist −a; oder messen Sie die Fallzeit mit der Stoppuhr (Instrumente, Zeitmesser) und rechnen Sie a = 2·h/t². 3) Wählen Sie ein Gewicht, ändern Sie seine Masse, setzen Sie zurück und lesen Sie die neue Steigung ab. Worauf zu achten ist: das linke Paar beschleunigt mit g/2 = 4,905 m/s² und landet nach 1,11 s mit 5,4 m/s; das rechte Paar beschleunigt mit g/10 = 0,981 m/s² und landet nach 2,47 s mit 2,4 m/s. Wenn ein schweres Gewicht landet, bleibt auch sein Partner stehen, weil das Rollenseil von Phasebox nie erschlafft (ein echtes leichtes Gewicht würde noch einen Moment nach oben weiterfliegen). Warum: das Seil dehnt sich nicht, also bewegen sich die beiden Gewichte gleich schnell, eines nach oben und eines nach unten, und es zieht jedes mit derselben Seilkraft T nach oben. Newtons zweites Gesetz für jedes Gewicht, m1·a = m1·g − T und m2·a = T − m2·g, addiert ergibt a = g·(m1 − m2)/(m1 + m2): die Schwerkraft zieht an der Differenz der Massen, muss aber ihre Summe beschleunigen. Dann ist T = 2·m1·m2·g/(m1 + m2), links 14,7 N, zwischen den 9,8 N des leichten und den 29,4 N des schweren Gewichts, und rechts 9,71 N. George Atwood beschrieb die Maschine 1784, um den freien Fall so zu verlangsamen, dass man ihn von Hand messen kann: bei fast gleichen Massen ist a ein kleiner Bruchteil von g. Die Masse kürzt sich hier nicht heraus wie beim Pendel, weil die beiden Gewichte eine gemeinsame Beschleunigung haben.</translation>
    </message>
    <message>
        <source>Lesson: a bead on a hoop</source>
        <extracomment>lessons/bead-on-hoop.phasebox.json: name</extracomment>
        <translation>Lektion: eine Perle auf einem Ring</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: a 1 kg bead slides without friction on a circular wire of radius 1 m, released from rest level with the centre of the hoop, 90° from the bottom. 2) Read the period off the period timer in the Instruments dock, which times bead.x, or click the bead and watch its loop in the Phase space plot. 3) Reset, switch the integrator to explicit Euler and then to RK4, and compare the swings and the energy plot. What to watch: the bead swings up to the same height on the other side and back with a period of 2.3678 s, the period of a 1 m pendulum released at 90°; at the bottom it passes at √(2·g·R) = 4.43 m/s. Under explicit Euler each swing climbs higher than the last until Phasebox stops the run as diverging; under RK4 the energy stays put. Why: the wire can push only at right angles to itself, so like the pendulum&apos;s rod it does no work, and the bead moves exactly as a pendulum bob on a massless rod to the centre, T = 4·√(R/g)·K(sin(θ0/2)). Phasebox treats the wire as a constraint C(x) = ‖x − c‖ − R = 0, Witkin and Baraff&apos;s bead on a wire: at every force evaluation it solves for the force that keeps C from changing, the part of gravity that would pull the bead off the wire plus the centripetal force m·v²/R that bends its path. That force is the wire&apos;s normal force: at the bottom it is m·g + m·v²/R = 3·m·g = 29.4 N, three times the bead&apos;s weight, whatever the radius. The little drift off the wire that a finite step leaves is projected away after each step, and any energy that takes shows in the plot as correction. The same machinery holds the rods, hinges and pulleys of the other joint lessons.</source>
        <extracomment>lessons/bead-on-hoop.phasebox.json: description</extracomment>
        <translation>Probieren Sie: 1) Drücken Sie Start: eine 1-kg-Perle gleitet reibungsfrei auf einem kreisförmigen Draht mit 1 m Radius, aus der Ruhe auf Höhe des Ringmittelpunkts losgelassen, 90° vom tiefsten Punkt. 2) Lesen Sie die Periode am Periodenmesser im Instrumente-Dock ab, der bead.x misst, oder klicken Sie die Perle an und beobachten Sie ihre Schleife im Phasenraum-Diagramm. 3) Setzen Sie zurück, wechseln Sie den Integrator zu explizitem Euler und dann zu RK4 und vergleichen Sie die Schwingungen und das Energiediagramm. Worauf zu achten ist: die Perle schwingt auf der anderen Seite bis zur selben Höhe und zurück, mit einer Periode von 2,3678 s, der Periode eines 1-m-Pendels, das bei 90° losgelassen wird; unten kommt sie mit √(2·g·R) = 4,43 m/s vorbei. Unter explizitem Euler steigt jede Schwingung höher als die vorige, bis Phasebox den Lauf als divergierend stoppt; unter RK4 bleibt die Energie erhalten. Warum: der Draht kann nur senkrecht zu sich selbst drücken, also verrichtet er wie die Pendelstange keine Arbeit, und die Perle bewegt sich genau wie ein Pendelkörper an einer masselosen Stange zum Mittelpunkt, T = 4·√(R/g)·K(sin(θ0/2)). Phasebox behandelt den Draht als Zwangsbedingung C(x) = ‖x − c‖ − R = 0, die Perle auf dem Draht von Witkin und Baraff: bei jeder Kraftauswertung löst es nach der Kraft, die C unverändert hält, dem Teil der Schwerkraft, der die Perle vom Draht ziehen würde, plus der Zentripetalkraft m·v²/R, die ihre Bahn krümmt. Diese Kraft ist die Normalkraft des Drahts: unten beträgt sie m·g + m·v²/R = 3·m·g = 29,4 N, das Dreifache der Gewichtskraft der Perle, unabhängig vom Radius. Die kleine Abweichung vom Draht, die ein endlicher Schritt hinterlässt, wird nach jedem Schritt wegprojiziert, und die Energie, die das kostet, erscheint im Diagramm als Korrektur. Dieselbe Technik hält die Stangen, Scharniere und Rollen der anderen Gelenk-Lektionen.</translation>
    </message>
    <message>
        <source>Lesson: the three kinds of spring in a cloth</source>
        <extracomment>lessons/cloth-springs.phasebox.json: name</extracomment>
        <translation>Lektion: die drei Federarten in einem Tuch</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: three cloths, 1.2 m square, hang under implicit Euler from two nodes of their top edge, a quarter of the way in from each side. The left one has structural, shear and bend springs; the middle one has no shear springs; the right one has neither shear nor bend springs. 2) Select a cloth and change its stiffness, then Reset and play again: give the right one its bend springs back (bend 20), or take the bend springs away from the left one. What to watch: the full cloth hangs as a flat sheet and even its top corners outside the pins stay up; without shear springs the squares of the mesh fold into diamonds, the corners swing down and the cloth narrows to about 0.7 m; without bend springs as well it narrows further, to about 0.55 m, and its folds become sharp creases where the middle one&apos;s are rounded. Why: structural springs keep each thread from stretching, but a square of four of them folds like a hinge at no cost, so they alone cannot hold a shape. Shear springs across both diagonals cut every square into triangles, which cannot fold: with them the cloth keeps its shape and the bend springs have nothing left to do (the left cloth without them looks the same). Bend springs join each node to the node two places along a thread and stretch only when the thread kinks, so where the mesh does fold they spread each fold over several nodes instead of one sharp crease. In this flat world a cloth can fold only within its own plane; in 3D, where a sheet bends out of its plane without stretching anything, bend springs are what give cloth its drape. Stiff structural springs are also why cloth wants an implicit integrator: at k = 2 000 N/m on nodes of 7 g the threads vibrate far too fast for an explicit method at dt = 1/60 s.</source>
        <extracomment>lessons/cloth-springs.phasebox.json: description</extracomment>
        <translation>Probieren Sie: 1) Drücken Sie Start: drei Tücher, 1,2 m im Quadrat, hängen unter implizitem Euler an zwei Knoten ihrer Oberkante, jeweils ein Viertel von jeder Seite entfernt. Das linke hat Struktur-, Scher- und Biegefedern; das mittlere hat keine Scherfedern; das rechte hat weder Scher- noch Biegefedern. 2) Wählen Sie ein Tuch, ändern Sie seine Steifigkeit, setzen Sie zurück und starten Sie erneut: geben Sie dem rechten seine Biegefedern zurück (bend 20), oder nehmen Sie dem linken die Biegefedern weg. Worauf zu achten ist: das vollständige Tuch hängt als flache Fläche, und sogar seine oberen Ecken außerhalb der Befestigungen bleiben oben; ohne Scherfedern falten sich die Quadrate des Netzes zu Rauten, die Ecken schwingen herab, und das Tuch wird auf etwa 0,7 m schmaler; ohne auch die Biegefedern wird es noch schmaler, etwa 0,55 m, und seine Falten werden zu scharfen Knicken, wo die des mittleren abgerundet sind. Warum: Strukturfedern verhindern, dass sich ein Faden dehnt, aber ein Quadrat aus vier von ihnen faltet sich wie ein Scharnier ohne Kosten, also können sie allein keine Form halten. Scherfedern über beide Diagonalen zerlegen jedes Quadrat in Dreiecke, die sich nicht falten können: mit ihnen behält das Tuch seine Form, und die Biegefedern haben nichts mehr zu tun (das linke Tuch sieht ohne sie genauso aus). Biegefedern verbinden jeden Knoten mit dem Knoten zwei Plätze weiter entlang eines Fadens und dehnen sich nur, wenn der Faden knickt, also verteilen sie dort, wo sich das Netz faltet, jede Falte auf mehrere Knoten statt eines scharfen Knicks. In dieser flachen Welt kann sich ein Tuch nur in seiner eigenen Ebene falten; in 3D, wo sich eine Fläche aus ihrer Ebene biegt, ohne etwas zu dehnen, geben die Biegefedern dem Tuch seinen Fall. Steife Strukturfedern sind auch der Grund, warum ein Tuch einen impliziten Integrator will: bei k = 2 000 N/m an Knoten von 7 g schwingen die Fäden viel zu schnell für ein explizites Verfahren bei dt = 1/60 s.</translation>
    </message>
    <message>
        <source>Lesson: the double pendulum is chaotic</source>
        <extracomment>lessons/double-pendulum.phasebox.json: name</extracomment>
        <translation>Lektion: das Doppelpendel ist chaotisch</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: two identical double pendulums, 1 kg bobs on massless rods 1 m long, start from rest nearly upside down, both rods at 170° from the vertical; the right one&apos;s lower rod is turned a billionth of a radian (1e-9 rad) further than the left one&apos;s, a millionth of a millimetre at its bob. 2) Watch them swing in step and note the time when the graphs in the Instruments dock first differ: a2.x and b2.x, the lower bobs&apos; x, and distance(a2,b2), which stays at 4.5 m while they move as one. 3) Reset, set dt to 1/1200 s and play again. What to watch: for about 8 s the two move as one; by 12 s the lower bobs are visibly apart and by 14 s they swing quite differently, although both keep their energy (under RK4 the total in the energy plot stays flat to a few microjoules). At dt = 1/1200 s they part at about the same time, but after 12 s both move differently from the run at 1/600 s. Why: the two bobs pull on each other through the lower rod, and the equations of their motion are nonlinear, so the motion is chaotic: two starts a tiny distance d apart separate roughly as d·e^(λt), here with λ ≈ 1.3 per second, ten times further every 2 s or so. That is why a billionth of a radian becomes a visible gap in about 12 s, and a start a thousand times closer would part only about 5 s later. The integrator&apos;s own error grows at the same rate: RK4 at dt = 1/600 s is a few millionths of a metre off after 5 s, millimetres off after 10 s, and after 15 s no run predicts where the real pendulum is. Both pendulums make nearly the same error at each step, which is why their difference still follows the physics. Chaos is not randomness: the motion is fully determined by its start, and a run repeated with the same numbers gives exactly the same motion.</source>
        <extracomment>lessons/double-pendulum.phasebox.json: description</extracomment>
        <translation>Probieren Sie: 1) Drücken Sie Start: zwei gleiche Doppelpendel, 1-kg-Pendelkörper an masselosen Stangen von 1 m Länge, starten aus der Ruhe fast auf dem Kopf stehend, beide Stangen bei 170° von der Senkrechten; die untere Stange des rechten ist um ein Milliardstel Radiant (1e-9 rad) weiter gedreht als die des linken, ein Millionstel Millimeter an ihrem Pendelkörper. 2) Beobachten Sie, wie sie im Gleichtakt schwingen, und notieren Sie die Zeit, zu der sich die Graphen im Instrumente-Dock erstmals unterscheiden: a2.x und b2.x, das x der unteren Pendelkörper, und distance(a2,b2), das bei 4,5 m bleibt, solange sie sich wie eines bewegen. 3) Setzen Sie zurück, stellen Sie dt auf 1/1200 s und starten Sie erneut. Worauf zu achten ist: etwa 8 s lang bewegen sich die beiden wie eines; nach 12 s sind die unteren Pendelkörper sichtbar getrennt, und nach 14 s schwingen sie ganz verschieden, obwohl beide ihre Energie behalten (unter RK4 bleibt die Gesamtenergie im Energiediagramm auf wenige Mikrojoule flach). Bei dt = 1/1200 s trennen sie sich etwa zur selben Zeit, aber nach 12 s bewegen sich beide anders als im Lauf mit 1/600 s. Warum: die beiden Pendelkörper ziehen über die untere Stange aneinander, und ihre Bewegungsgleichungen sind nichtlinear, also ist die Bewegung chaotisch: zwei Starts im winzigen Abstand d entfernen sich ungefähr wie d·e^(λt), hier mit λ ≈ 1,3 pro Sekunde, etwa alle 2 s zehnmal weiter. Deshalb wird ein Milliardstel Radiant in etwa 12 s zu einer sichtbaren Lücke, und ein tausendmal näherer Start würde sich nur etwa 5 s später trennen. Der eigene Fehler des Integrators wächst mit derselben Rate: RK4 bei dt = 1/600 s liegt nach 5 s wenige Millionstel Meter daneben, nach 10 s Millimeter, und nach 15 s sagt kein Lauf vorher, wo das echte Pendel ist. Beide Pendel machen bei jedem Schritt fast denselben Fehler, deshalb folgt ihr Unterschied weiterhin der Physik. Chaos ist kein Zufall: die Bewegung ist durch ihren Start vollständig bestimmt, und ein mit denselben Zahlen wiederholter Lauf ergibt genau dieselbe Bewegung.</translation>
    </message>
    <message>
        <source>Lesson: explicit Euler spirals out of an orbit</source>
        <extracomment>lessons/euler-orbit-spiral.phasebox.json: name</extracomment>
        <translation>Lektion: explizites Euler spiralt aus der Umlaufbahn</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play and watch two planets on circular orbits (r = 3 m and 5 m) round a star of G·M = 100 under explicit Euler at dt = 1/60 s. 2) Open the energy plot: the total climbs step after step; the graphs in the Instruments dock show each planet&apos;s distance from the star, distance(star,inner) and distance(star,outer). 3) Reset, switch the integrator to symplectic Euler and play again, then to RK4. What to watch: under explicit Euler both orbits spiral outwards, the inner one faster (after 20 s it has doubled in size, its distance from the star has passed 6 m, and the outer one has grown by more than a third, past 6.7 m); symplectic Euler keeps both closed with a wobble of about two percent; RK4 keeps them circular. Why: explicit Euler moves the planet along the tangent with the old velocity, and a tangent always leads outside a circle, so every step lifts the planet a little. On a circular orbit of angular speed ω each step raises the energy by about 2·(ω·dt)² of its size, a growth that never stops and is more than four and a half times larger for the faster inner orbit. Symplectic Euler uses the new velocity to move, and that small change makes it preserve a slightly perturbed energy, so the error stays bounded instead of piling up. RK4 is simply accurate: its error per lap is about (ω·dt)⁴ smaller. Halve dt and the energy climbs half as fast: explicit Euler is a first-order method, so its error shrinks only in proportion to the step.</source>
        <extracomment>lessons/euler-orbit-spiral.phasebox.json: description</extracomment>
        <translation>Probieren Sie: 1) Drücken Sie Start und beobachten Sie zwei Planeten auf Kreisbahnen (r = 3 m und 5 m) um einen Stern mit G·M = 100 unter explizitem Euler bei dt = 1/60 s. 2) Öffnen Sie das Energiediagramm: die Gesamtenergie steigt Schritt für Schritt; die Graphen im Instrumente-Dock zeigen den Abstand jedes Planeten vom Stern, distance(star,inner) und distance(star,outer). 3) Setzen Sie zurück, wechseln Sie den Integrator zu symplektischem Euler und starten Sie erneut, dann zu RK4. Worauf zu achten ist: unter explizitem Euler spiralen beide Bahnen nach außen, die innere schneller (nach 20 s hat sie ihre Größe verdoppelt, ihr Abstand vom Stern hat 6 m überschritten, und die äußere ist um mehr als ein Drittel gewachsen, über 6,7 m); symplektisches Euler hält beide geschlossen mit einem Wackeln von etwa zwei Prozent; RK4 hält sie kreisförmig. Warum: explizites Euler bewegt den Planeten mit der alten Geschwindigkeit entlang der Tangente, und eine Tangente führt immer aus einem Kreis hinaus, also hebt jeder Schritt den Planeten ein wenig an. Auf einer Kreisbahn mit Winkelgeschwindigkeit ω erhöht jeder Schritt die Energie um etwa 2·(ω·dt)² ihres Betrags, ein Wachstum, das nie aufhört und für die schnellere innere Bahn mehr als viereinhalbmal größer ist. Symplektisches Euler bewegt mit der neuen Geschwindigkeit, und diese kleine Änderung lässt es eine leicht gestörte Energie erhalten, sodass der Fehler beschränkt bleibt, statt sich anzuhäufen. RK4 ist einfach genau: sein Fehler pro Umlauf ist etwa um (ω·dt)⁴ kleiner. Halbieren Sie dt, und die Energie steigt halb so schnell: explizites Euler ist ein Verfahren erster Ordnung, also schrumpft sein Fehler nur proportional zum Schritt.</translation>
    </message>
    <message>
        <source>Lesson: an impulse sets a box spinning</source>
        <extracomment>lessons/impulse-spin.phasebox.json: name</extracomment>
        <translation>Lektion: ein Kraftstoß versetzt einen Quader in Drehung</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: in empty space (no gravity) a 100 g pellet flies at 20 m/s into the left face of a 2 kg box, 0.15 m above the box&apos;s centre. 2) Read the box&apos;s speed and spin after the hit in the table in the Instruments dock (box.speed, and box.omega, negative when it turns clockwise), then Reset, drag the pellet up or down (or set its position y to 0) and play again. What to watch: the box drifts off at 1.41 m/s and turns clockwise at about 2 rad/s; a pellet aimed at the centre line pushes it without any spin, one aimed below the centre spins it the other way. Why: the contact pushes with one short, large force, an impulse J along the face&apos;s normal, and the same J changes the box&apos;s momentum by J and its angular momentum by r × J, where r runs from the centre of mass to the contact point: an off-centre push always turns. With restitution e = 0.5 and no friction, J = (1 + e)·m·v/(1 + m/M + m·d²/I) for an offset d, so the box moves at J/M and turns at J·d/I with I = M·(w² + h²)/12. Nothing outside the pellet and the box acts on them, so their total momentum and their angular momentum about any fixed point, the point of impact for instance, are the same after the hit as before, which is how the numbers above were worked out. The kinetic energy is not kept: the inelastic part of the bounce appears in work_nc. The dashed outline is that closed form (View → Exact Solution): with no force between the impacts, every integrator follows it to rounding.</source>
        <extracomment>lessons/impulse-spin.phasebox.json: description</extracomment>
        <translation>Probieren Sie: 1) Drücken Sie Start: im leeren Raum (ohne Schwerkraft) fliegt ein 100-g-Geschoss mit 20 m/s auf die linke Seite eines 2-kg-Quaders, 0,15 m über dessen Mittelpunkt. 2) Lesen Sie die Geschwindigkeit und Drehung des Quaders nach dem Treffer in der Tabelle im Instrumente-Dock ab (box.speed, und box.omega, negativ bei Drehung im Uhrzeigersinn), setzen Sie dann zurück, ziehen Sie das Geschoss nach oben oder unten (oder setzen Sie seine Position y auf 0) und starten Sie erneut. Worauf zu achten ist: der Quader driftet mit 1,41 m/s davon und dreht sich mit etwa 2 rad/s im Uhrzeigersinn; ein auf die Mittellinie gezieltes Geschoss schiebt ihn ohne jede Drehung, eines unterhalb der Mitte dreht ihn andersherum. Warum: der Kontakt drückt mit einer kurzen, großen Kraft, einem Kraftstoß J entlang der Normalen der Fläche, und dasselbe J ändert den Impuls des Quaders um J und seinen Drehimpuls um r × J, wobei r vom Schwerpunkt zum Kontaktpunkt zeigt: ein außermittiger Stoß dreht immer. Mit Stoßzahl e = 0,5 und ohne Reibung ist J = (1 + e)·m·v/(1 + m/M + m·d²/I) für einen Versatz d, also bewegt sich der Quader mit J/M und dreht sich mit J·d/I, wobei I = M·(w² + h²)/12. Nichts außer Geschoss und Quader wirkt auf sie, also sind ihr Gesamtimpuls und ihr Drehimpuls um jeden festen Punkt, etwa den Auftreffpunkt, nach dem Treffer dieselben wie vorher; so wurden die Zahlen oben berechnet. Die kinetische Energie bleibt nicht erhalten: der unelastische Teil des Stoßes erscheint in work_nc. Der gestrichelte Umriss ist diese geschlossene Lösung (Ansicht → Exakte Lösung): ohne Kraft zwischen den Stößen folgt ihr jeder Integrator bis auf Rundungsfehler.</translation>
    </message>
    <message>
        <source>Lesson: midpoint against RK4</source>
        <extracomment>lessons/midpoint-vs-rk4.phasebox.json: name</extracomment>
        <translation>Lektion: Mittelpunktregel gegen RK4</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: a ball on a spring (k = 4 N/m, m = 1 kg, so ω = 2 rad/s and the period is π s) swings under the midpoint method at a coarse dt = 0.1 s, next to its exact solution x = cos 2t. 2) Watch the graph of ball.vx against ball.x in the Instruments dock, the phase portrait: the exact motion is a closed ellipse. 3) Reset and switch to RK4 at the same dt; then try midpoint at dt = 0.05 s, which costs as many force evaluations per second as RK4 at 0.1 s. What to watch: midpoint&apos;s ellipse slowly grows and its swing runs ahead of the exact one (after 20 s by about a quarter of a radian); RK4&apos;s stays on the exact curve to four decimals. Why: both methods sample the force inside the step, midpoint once and RK4 three times, and the weights of RK4 cancel the error terms up to the fourth power of ω·dt, midpoint&apos;s only up to the second. Halving dt divides midpoint&apos;s error by 4 and RK4&apos;s by 16, so at equal cost RK4 still wins by a wide margin on a smooth problem like this one. Midpoint&apos;s amplification per step is √(1 + (ω·dt)⁴/4), slightly above 1, which is why its energy creeps up. The command phasebox-cli accuracy on this file draws the work-precision diagram that shows it across many step sizes.</source>
        <extracomment>lessons/midpoint-vs-rk4.phasebox.json: description</extracomment>
        <translation>Probieren Sie: 1) Drücken Sie Start: ein Ball an einer Feder (k = 4 N/m, m = 1 kg, also ω = 2 rad/s und die Periode π s) schwingt unter der Mittelpunktregel bei grobem dt = 0,1 s neben seiner exakten Lösung x = cos 2t. 2) Beobachten Sie den Graphen von ball.vx gegen ball.x im Instrumente-Dock, das Phasenporträt: die exakte Bewegung ist eine geschlossene Ellipse. 3) Setzen Sie zurück und wechseln Sie beim selben dt zu RK4; probieren Sie dann die Mittelpunktregel bei dt = 0,05 s, die pro Sekunde so viele Kraftauswertungen kostet wie RK4 bei 0,1 s. Worauf zu achten ist: die Ellipse der Mittelpunktregel wächst langsam, und ihre Schwingung läuft der exakten voraus (nach 20 s um etwa ein Viertel Radiant); die von RK4 bleibt auf vier Dezimalstellen auf der exakten Kurve. Warum: beide Verfahren werten die Kraft innerhalb des Schritts aus, die Mittelpunktregel einmal und RK4 dreimal, und die Gewichte von RK4 heben die Fehlerterme bis zur vierten Potenz von ω·dt auf, die der Mittelpunktregel nur bis zur zweiten. Halbieren von dt teilt den Fehler der Mittelpunktregel durch 4 und den von RK4 durch 16, also gewinnt RK4 bei gleichen Kosten bei einem glatten Problem wie diesem immer noch deutlich. Der Verstärkungsfaktor der Mittelpunktregel pro Schritt ist √(1 + (ω·dt)⁴/4), etwas über 1, deshalb kriecht ihre Energie nach oben. Der Befehl phasebox-cli accuracy auf diese Datei zeichnet das Arbeits-Genauigkeits-Diagramm, das es über viele Schrittweiten zeigt.</translation>
    </message>
    <message>
        <source>Lesson: restitution and friction</source>
        <extracomment>lessons/restitution-friction.phasebox.json: name</extracomment>
        <translation>Lektion: Stoßzahl und Reibung</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play. On the left three balls fall 2 m onto a floor; on the right three crates slide at 4 m/s along strips of ice, wood and rubber. 2) Read each ball&apos;s rebound off the graphs in the Instruments dock, e090.y, e060.y and e030.y (each ball&apos;s centre, 0.15 m above its lowest point), and where each crate stops off the table of on_ice.x, on_wood.x and on_rubber.x (each starts at x = 0.5 m). 3) Select a ball and change its restitution, or a crate and its strip and change their friction, then Reset and play again. What to watch: each ball climbs back to e²·h, 1.62 m, 0.72 m and 0.18 m for e = 0.9, 0.6 and 0.3; each crate stops after v²/(2·μ·g), 8.2 m on ice (μ = 0.1), 2.0 m on wood (μ = 0.4) and 1.0 m on rubber (μ = 0.8); the energy the bounces and the sliding lose appears in work_nc. Why: restitution e is the ratio of the speeds just after and just before a bounce, and since the height a ball reaches goes with the square of its speed, it rebounds to e² of its drop. Kinetic friction opposes sliding with a force μ times the normal force, here μ·m·g, so the crate decelerates uniformly at μ·g whatever its mass. A pair of materials combines as max(e₁, e₂) and √(μ₁·μ₂): the floor has e = 0, so each ball&apos;s own e counts, and each crate has the same μ as its strip. A bounce is an impulse the solver applies at the moment of impact, while a steady slide&apos;s friction, like the floor&apos;s push under a resting body, acts as a force inside the integrator&apos;s step; a bounce slower than the restitution threshold (1 m/s times 1 − e) is treated as inelastic, which is why small hops end in rest instead of going on for ever; with e = 1 every bounce is elastic.</source>
        <extracomment>lessons/restitution-friction.phasebox.json: description</extracomment>
        <translation>Probieren Sie: 1) Drücken Sie Start. Links fallen drei Bälle aus 2 m auf einen Boden; rechts gleiten drei Kisten mit 4 m/s über Streifen aus Eis, Holz und Gummi. 2) Lesen Sie den Rücksprung jedes Balls an den Graphen im Instrumente-Dock ab, e090.y, e060.y und e030.y (der Mittelpunkt jedes Balls, 0,15 m über seinem tiefsten Punkt), und wo jede Kiste stehen bleibt an der Tabelle von on_ice.x, on_wood.x und on_rubber.x (jede startet bei x = 0,5 m). 3) Wählen Sie einen Ball und ändern Sie seine Stoßzahl, oder eine Kiste und ihren Streifen und ändern Sie deren Reibung, setzen Sie dann zurück und starten Sie erneut. Worauf zu achten ist: jeder Ball steigt wieder auf e²·h, 1,62 m, 0,72 m und 0,18 m für e = 0,9, 0,6 und 0,3; jede Kiste bleibt nach v²/(2·μ·g) stehen, 8,2 m auf Eis (μ = 0,1), 2,0 m auf Holz (μ = 0,4) und 1,0 m auf Gummi (μ = 0,8); die Energie, die die Aufpralle und das Gleiten verlieren, erscheint in work_nc. Warum: die Stoßzahl e ist das Verhältnis der Geschwindigkeiten direkt nach und direkt vor einem Aufprall, und da die Höhe, die ein Ball erreicht, mit dem Quadrat seiner Geschwindigkeit geht, springt er auf e² seiner Fallhöhe zurück. Gleitreibung wirkt dem Gleiten mit einer Kraft μ mal der Normalkraft entgegen, hier μ·m·g, also bremst die Kiste gleichmäßig mit μ·g, unabhängig von ihrer Masse. Ein Materialpaar kombiniert sich als max(e₁, e₂) und √(μ₁·μ₂): der Boden hat e = 0, also zählt das eigene e jedes Balls, und jede Kiste hat dasselbe μ wie ihr Streifen. Ein Aufprall ist ein Kraftstoß, den der Löser im Moment des Aufpralls anwendet, während die Reibung eines gleichmäßigen Gleitens, wie der Druck des Bodens unter einem ruhenden Körper, als Kraft im Schritt des Integrators wirkt; ein Aufprall langsamer als die Stoßschwelle (1 m/s mal 1 − e) wird als unelastisch behandelt, deshalb enden kleine Hüpfer in Ruhe, statt ewig weiterzugehen; mit e = 1 ist jeder Aufprall elastisch.</translation>
    </message>
    <message>
        <source>Lesson: the rolling race</source>
        <extracomment>lessons/rolling-race.phasebox.json: name</extracomment>
        <translation>Lektion: das Rollrennen</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play and watch the three start together from rest on the same 20° slope, each 5 m (along the slope) from its finish. The ramps run on past the finish, so all three are still on them when the race ends at 3 s. 2) Guess the order first, then read it off the race: the graphs in the Instruments dock show slider.speed, disk.speed and box.speed, each a straight line whose slope is the body&apos;s acceleration. 3) Select the box or a ramp and change its friction, Reset, and race again. What to watch: the frictionless disk slides at g·sin θ = 3.36 m/s² and finishes 5 m in 1.73 s; the rolling disk (μ = 0.5) turns as it goes and accelerates at ⅔·g·sin θ = 2.24 m/s², finishing in 2.11 s; the box (μ = 0.2) slides at g·(sin θ − μ·cos θ) = 1.51 m/s², finishing in 2.57 s. The rolling disk loses no energy: work_nc stays at zero for it while the box&apos;s friction takes energy out. Why: a disk that rolls without slipping must spin up as it speeds up, so part of the work gravity does goes into ½·I·ω², with I = ½·m·r² and ω = v/r. Its kinetic energy is then ¾·m·v² instead of ½·m·v², so its acceleration is ⅔ of the frictionless g·sin θ, whatever its mass or radius. Static friction makes it roll but does no work, because the point of contact does not move. It needs only μ ≥ ⅓·tan θ = 0.12 to roll on this slope; with less, the disk slides and spins up more slowly. The box&apos;s kinetic friction does work, μ·m·g·cos θ per metre, which is why it comes last.</source>
        <extracomment>lessons/rolling-race.phasebox.json: description</extracomment>
        <translation>Probieren Sie: 1) Drücken Sie Start und beobachten Sie, wie die drei zusammen aus der Ruhe auf derselben 20°-Schräge starten, jeder 5 m (entlang der Schräge) vom Ziel entfernt. Die Rampen gehen hinter dem Ziel weiter, also sind alle drei noch darauf, wenn das Rennen bei 3 s endet. 2) Raten Sie zuerst die Reihenfolge und lesen Sie sie dann am Rennen ab: die Graphen im Instrumente-Dock zeigen slider.speed, disk.speed und box.speed, jeweils eine Gerade, deren Steigung die Beschleunigung des Körpers ist. 3) Wählen Sie den Quader oder eine Rampe, ändern Sie deren Reibung, setzen Sie zurück und starten Sie das Rennen erneut. Worauf zu achten ist: die reibungsfreie Scheibe gleitet mit g·sin θ = 3,36 m/s² und schafft die 5 m in 1,73 s; die rollende Scheibe (μ = 0,5) dreht sich dabei und beschleunigt mit ⅔·g·sin θ = 2,24 m/s², im Ziel nach 2,11 s; der Quader (μ = 0,2) gleitet mit g·(sin θ − μ·cos θ) = 1,51 m/s², im Ziel nach 2,57 s. Die rollende Scheibe verliert keine Energie: work_nc bleibt für sie bei null, während die Reibung des Quaders Energie entnimmt. Warum: eine Scheibe, die ohne Schlupf rollt, muss sich schneller drehen, während sie schneller wird, also geht ein Teil der Arbeit der Schwerkraft in ½·I·ω², mit I = ½·m·r² und ω = v/r. Ihre kinetische Energie ist dann ¾·m·v² statt ½·m·v², also ist ihre Beschleunigung ⅔ des reibungsfreien g·sin θ, unabhängig von Masse und Radius. Haftreibung lässt sie rollen, verrichtet aber keine Arbeit, weil sich der Kontaktpunkt nicht bewegt. Sie braucht nur μ ≥ ⅓·tan θ = 0,12, um auf dieser Schräge zu rollen; mit weniger gleitet die Scheibe und dreht sich langsamer hoch. Die Gleitreibung des Quaders verrichtet Arbeit, μ·m·g·cos θ pro Meter, deshalb kommt er als Letzter an.</translation>
    </message>
    <message>
        <source>Lesson: the simple pendulum</source>
        <extracomment>lessons/simple-pendulum.phasebox.json: name</extracomment>
        <translation>Lektion: das Fadenpendel</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: two 1 kg bobs hang on massless rigid rods 1 m long, the left one released from rest at 90° from the vertical (level with its pivot), the right one at 10°. 2) Read each period off the period timer in the Instruments dock: it times rod90.angle, the 90° pendulum&apos;s swing from straight down, as the mean interval between its upward crossings; choose rod10.angle as its probe to time the 10° one from then on (or click a bob and watch its loop in the Phase space plot close). 3) Reset and switch the integrator to explicit Euler, then RK4, and watch the swings and the energy plot; then try a smaller dt. What to watch: the 10° pendulum swings with a period of 2.0099 s, hardly more than the small-angle 2π·√(L/g) = 2.006 s; the 90° one takes 2.3678 s, 18% longer, so it falls further and further behind. Under symplectic Euler the energy wobbles a little but stays put; under explicit Euler the swings grow every period until Phasebox stops the run as diverging; RK4 keeps the energy to many decimals. Why: the rod holds the bob on a circle, so only gravity&apos;s component along the circle, −m·g·sin θ, speeds it up or slows it down, and the mass cancels. For small angles sin θ ≈ θ, the motion is simple harmonic and T = 2π·√(L/g) whatever the amplitude. Farther out sin θ &lt; θ, the pull back is weaker than the linear one, and the swing takes longer: the exact period is T = 4·√(L/g)·K(sin(θ0/2)), with K the complete elliptic integral of the first kind. With L = 1 m and g = 9.81 m/s² this gives 2.0099 s at 10° and 2.3678 s at 90°. The rod&apos;s pull does no work, because it is always at right angles to the motion: the energy plot&apos;s total is the integrator&apos;s doing.</source>
        <extracomment>lessons/simple-pendulum.phasebox.json: description</extracomment>
        <translation>Probieren Sie: 1) Drücken Sie Start: zwei 1-kg-Pendelkörper hängen an masselosen starren Stangen von 1 m Länge, der linke aus der Ruhe bei 90° von der Senkrechten losgelassen (auf Höhe seines Drehpunkts), der rechte bei 10°. 2) Lesen Sie jede Periode am Periodenmesser im Instrumente-Dock ab: er misst rod90.angle, die Auslenkung des 90°-Pendels aus der Senkrechten, als mittleren Abstand zwischen ihren Aufwärtsdurchgängen; wählen Sie rod10.angle als Messgröße, um von da an das 10°-Pendel zu messen (oder klicken Sie einen Pendelkörper an und sehen Sie seine Schleife im Phasenraum-Diagramm sich schließen). 3) Setzen Sie zurück, wechseln Sie den Integrator zu explizitem Euler, dann zu RK4, und beobachten Sie die Schwingungen und das Energiediagramm; probieren Sie dann ein kleineres dt. Worauf zu achten ist: das 10°-Pendel schwingt mit einer Periode von 2,0099 s, kaum mehr als das 2π·√(L/g) = 2,006 s für kleine Winkel; das 90°-Pendel braucht 2,3678 s, 18 % länger, also fällt es immer weiter zurück. Unter symplektischem Euler schwankt die Energie etwas, bleibt aber, wo sie ist; unter explizitem Euler wachsen die Schwingungen jede Periode, bis Phasebox den Lauf als divergierend stoppt; RK4 hält die Energie auf viele Dezimalstellen. Warum: die Stange hält den Pendelkörper auf einem Kreis, also beschleunigt oder bremst ihn nur die Komponente der Schwerkraft entlang des Kreises, −m·g·sin θ, und die Masse kürzt sich heraus. Für kleine Winkel ist sin θ ≈ θ, die Bewegung ist harmonisch und T = 2π·√(L/g), unabhängig von der Amplitude. Weiter außen ist sin θ &lt; θ, die Rückstellkraft ist schwächer als die lineare, und die Schwingung dauert länger: die exakte Periode ist T = 4·√(L/g)·K(sin(θ0/2)), mit K dem vollständigen elliptischen Integral erster Art. Mit L = 1 m und g = 9,81 m/s² ergibt das 2,0099 s bei 10° und 2,3678 s bei 90°. Der Zug der Stange verrichtet keine Arbeit, weil er immer senkrecht zur Bewegung steht: die Gesamtenergie im Energiediagramm ist das Werk des Integrators.</translation>
    </message>
    <message>
        <source>Lesson: a stiff spring, explicit against implicit</source>
        <extracomment>lessons/stiff-spring-implicit.phasebox.json: name</extracomment>
        <translation>Lektion: eine steife Feder, explizit gegen implizit</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: a 1 kg bob swings on a soft spring (k = 10 N/m) with a 10 g bead fastened to it by a very stiff spring (k = 10 000 N/m), under implicit Euler at dt = 1/60 s. 2) Reset, switch to symplectic Euler and play; then try RK4. 3) Go back to implicit Euler and compare with implicit midpoint. What to watch: the explicit methods blow up within a few frames and the world stops them as diverging, although the motion you see is the slow 2-second swing of the soft spring; implicit Euler runs, but the swing dies away, to half its size in 10 s (look at the drift in the energy plot); implicit midpoint runs and keeps the swing. Why: the bead on its stiff spring vibrates at ω = √(k·(1/m₁ + 1/m₂)) ≈ 1 000 rad/s, so ω·dt ≈ 17, far past the explicit methods&apos; stability limits (ω·dt &lt; 2 for symplectic Euler, 2.8 for RK4): the stiffest spring sets the step for the whole scene, even when its own motion is invisible. An implicit method evaluates the force at the end of the step and solves for it, which is stable at any step. Backward Euler pays with numerical damping of every motion, about (ω·dt)²/2 of the amplitude per step, while implicit midpoint keeps the energy of the slow swing. Symplectic Euler needs ω·h &lt; 2 here: 9 sub-steps per frame (RK4, stable to 2.8, needs 6), for a motion you cannot even see.</source>
        <extracomment>lessons/stiff-spring-implicit.phasebox.json: description</extracomment>
        <translation>Probieren Sie: 1) Drücken Sie Start: ein 1-kg-Pendelkörper schwingt an einer weichen Feder (k = 10 N/m), mit einer 10-g-Perle, die über eine sehr steife Feder (k = 10 000 N/m) an ihm befestigt ist, unter implizitem Euler bei dt = 1/60 s. 2) Setzen Sie zurück, wechseln Sie zu symplektischem Euler und starten Sie; probieren Sie dann RK4. 3) Gehen Sie zurück zu implizitem Euler und vergleichen Sie mit der impliziten Mittelpunktregel. Worauf zu achten ist: die expliziten Verfahren explodieren innerhalb weniger Bilder, und die Welt stoppt sie als divergierend, obwohl die Bewegung, die Sie sehen, die langsame 2-Sekunden-Schwingung der weichen Feder ist; implizites Euler läuft, aber die Schwingung klingt ab, in 10 s auf die Hälfte (achten Sie auf die Drift im Energiediagramm); die implizite Mittelpunktregel läuft und erhält die Schwingung. Warum: die Perle an ihrer steifen Feder schwingt mit ω = √(k·(1/m₁ + 1/m₂)) ≈ 1 000 rad/s, also ω·dt ≈ 17, weit jenseits der Stabilitätsgrenzen der expliziten Verfahren (ω·dt &lt; 2 für symplektisches Euler, 2,8 für RK4): die steifste Feder bestimmt den Schritt für die ganze Szene, auch wenn ihre eigene Bewegung unsichtbar ist. Ein implizites Verfahren wertet die Kraft am Ende des Schritts aus und löst nach ihr, was bei jedem Schritt stabil ist. Das Rückwärts-Euler-Verfahren bezahlt mit numerischer Dämpfung jeder Bewegung, etwa (ω·dt)²/2 der Amplitude pro Schritt, während die implizite Mittelpunktregel die Energie der langsamen Schwingung erhält. Symplektisches Euler braucht hier ω·h &lt; 2: 9 Teilschritte pro Bild (RK4, stabil bis 2,8, braucht 6), für eine Bewegung, die man nicht einmal sieht.</translation>
    </message>
    <message>
        <source>Lesson: three ways to collide</source>
        <extracomment>lessons/three-ways-to-collide.phasebox.json: name</extracomment>
        <translation>Lektion: drei Arten zu stoßen</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: a 1 kg ball with restitution 0.8 drops 2 m onto the ground, four 1 kg boxes stand in a stack and a Newton&apos;s cradle of five 1 kg balls on 2 m rods is released from 40°, all under impulse contacts (Parameters, Contacts); read the ball&apos;s bounces off the graph of ball.y in the Instruments dock (its centre: it touches the ground at ball.y = 0.25 m). 2) Reset, choose Penalty in Contacts and play again; watch the energy plot and click the dropped ball to see its phase plot. 3) Reset, choose Kinematic and play once more; each time, compare the step cost in the Effects panel. What to watch: under impulses the ball rebounds to 1.26 m (e²·h = 1.28 m), the stack stands still and the cradle hands the swing down the row to the last ball, which rises as high as the first one fell. Under penalty the dashed ghost beside the ball is the closed form of its bounces (free fall, then the damped contact spring; View → Exact Solution), and the phase plot of the ball draws it as a dashed curve. The ball sinks 4.6 cm into the ground and stays in contact for 0.026 s, half an oscillation of the contact spring, π·√(m/k)/√(1 − ζ²) with k = 14,400 N/m (the automatic choice, ω·h = 0.5 at dt = 1/240 s); it leaves at 0.80 of its speed, e = exp(−ζπ/√(1 − ζ²)) with ζ = c/(2·√(k·m)) = 0.071 from the contact damping c = 17 N·s/m. The stack sags a few millimetres, and in the cradle every ball swings: the momentum spreads along the row. Under kinematic the ball rebounds to 1.27 m as under impulses, but the energy plot&apos;s correction line climbs, about 0.8 J a second, while the drift line falls about as fast and work_nc falls with each bounce: every push out of an overlap adds energy, and the resting bodies&apos; fall back into the next overlap takes it out again. Why: kinematic response is geometry first: it moves overlapping bodies apart and flips the approaching velocity, exact for one isolated bounce, but it knows no forces, so a resting body is lifted and dropped again at every step. The penalty method makes contact a force, a stiff damped spring at each overlapping point, so the integrator treats it like any spring: ½·k·d² is in the potential energy, a bounce is half an oscillation, and a stiffer spring needs a smaller step (the stability advisor asks ω·h ≤ 1 of explicit methods). In a row of touching balls those springs form a chain that carries waves, so the cradle&apos;s momentum disperses instead of passing on whole. Impulses solve for the velocity changes that stop each approach at once, with restitution and friction as rules on those changes, which is why stacks rest and the cradle works, at the price of an iterative solver after every step. Penalty costs least per step but needs small steps when stiff; impulses cost most per step but hold a stack at any step.</source>
        <extracomment>lessons/three-ways-to-collide.phasebox.json: description</extracomment>
        <translation>Probieren Sie: 1) Drücken Sie Start: ein 1-kg-Ball mit Stoßzahl 0,8 fällt 2 m auf den Boden, vier 1-kg-Quader stehen als Stapel, und ein Newton-Pendel aus fünf 1-kg-Kugeln an 2-m-Stangen wird aus 40° losgelassen, alles unter Impulskontakten (Parameter, Kontakte); lesen Sie die Aufpralle des Balls am Graphen von ball.y im Instrumente-Dock ab (sein Mittelpunkt: er berührt den Boden bei ball.y = 0,25 m). 2) Setzen Sie zurück, wählen Sie unter Kontakte „Penalty-Federn“ und starten Sie erneut; beobachten Sie das Energiediagramm und klicken Sie den fallenden Ball an, um sein Phasendiagramm zu sehen. 3) Setzen Sie zurück, wählen Sie „Kinematisch“ und starten Sie noch einmal; vergleichen Sie jedes Mal die Schrittkosten im Effekte-Bereich. Worauf zu achten ist: unter Impulsen springt der Ball auf 1,26 m zurück (e²·h = 1,28 m), der Stapel steht still, und das Newton-Pendel gibt die Schwingung die Reihe entlang an die letzte Kugel weiter, die so hoch steigt, wie die erste fiel. Mit Penalty-Federn ist der gestrichelte Geist neben dem Ball die geschlossene Lösung seiner Aufpralle (freier Fall, dann die gedämpfte Kontaktfeder; Ansicht → Exakte Lösung), und das Phasendiagramm des Balls zeichnet sie als gestrichelte Kurve. Der Ball sinkt 4,6 cm in den Boden ein und bleibt 0,026 s in Kontakt, eine halbe Schwingung der Kontaktfeder, π·√(m/k)/√(1 − ζ²) mit k = 14 400 N/m (die automatische Wahl, ω·h = 0,5 bei dt = 1/240 s); er verlässt den Boden mit 0,80 seiner Geschwindigkeit, e = exp(−ζπ/√(1 − ζ²)) mit ζ = c/(2·√(k·m)) = 0,071 aus der Kontaktdämpfung c = 17 N·s/m. Der Stapel sackt ein paar Millimeter ein, und im Newton-Pendel schwingt jede Kugel: der Impuls verteilt sich über die Reihe. Mit „Kinematisch“ springt der Ball wie unter Impulsen auf 1,27 m zurück, aber die Korrekturlinie im Energiediagramm steigt, um etwa 0,8 J pro Sekunde, während die Driftlinie etwa ebenso schnell fällt und work_nc mit jedem Aufprall fällt: jedes Herausschieben aus einer Überlappung fügt Energie hinzu, und das Zurückfallen der ruhenden Körper in die nächste Überlappung nimmt sie wieder weg. Warum: die kinematische Antwort ist zuerst Geometrie: sie schiebt überlappende Körper auseinander und kehrt die Annäherungsgeschwindigkeit um, exakt für einen einzelnen Aufprall, aber sie kennt keine Kräfte, also wird ein ruhender Körper bei jedem Schritt angehoben und wieder fallen gelassen. Die Penalty-Methode macht den Kontakt zu einer Kraft, einer steifen gedämpften Feder an jedem überlappenden Punkt, also behandelt der Integrator sie wie jede Feder: ½·k·d² steckt in der potentiellen Energie, ein Aufprall ist eine halbe Schwingung, und eine steifere Feder braucht einen kleineren Schritt (der Stabilitätsberater verlangt von expliziten Verfahren ω·h ≤ 1). In einer Reihe sich berührender Kugeln bilden diese Federn eine Kette, die Wellen trägt, also zerstreut sich der Impuls des Newton-Pendels, statt ganz weitergegeben zu werden. Impulse lösen nach den Geschwindigkeitsänderungen, die jede Annäherung sofort stoppen, mit Stoßzahl und Reibung als Regeln für diese Änderungen, deshalb ruhen Stapel und das Newton-Pendel funktioniert, zum Preis eines iterativen Lösers nach jedem Schritt. Penalty kostet pro Schritt am wenigsten, braucht aber kleine Schritte, wenn es steif ist; Impulse kosten pro Schritt am meisten, halten aber einen Stapel bei jedem Schritt.</translation>
    </message>
</context>
<context>
    <name>Schema</name>
    <message>
        <source>Width</source>
        <translation>Breite</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Höhe</translation>
    </message>
    <message>
        <source>Columns</source>
        <translation>Spalten</translation>
    </message>
    <message>
        <source>Rows</source>
        <translation>Zeilen</translation>
    </message>
    <message>
        <source>%1 lower</source>
        <translation>%1 unten</translation>
    </message>
    <message>
        <source>%1 upper</source>
        <translation>%1 oben</translation>
    </message>
    <message>
        <source>%1 x</source>
        <translation>%1 x</translation>
    </message>
    <message>
        <source>%1 y</source>
        <translation>%1 y</translation>
    </message>
    <message>
        <source>how time advances</source>
        <extracomment>schema: simulation</extracomment>
        <translation>wie die Zeit voranschreitet</translation>
    </message>
    <message>
        <source>Integrator</source>
        <extracomment>schema: simulation.integrator</extracomment>
        <translation>Integrator</translation>
    </message>
    <message>
        <source>Time step</source>
        <extracomment>schema: simulation.dt</extracomment>
        <translation>Zeitschritt</translation>
    </message>
    <message>
        <source>Sub-steps</source>
        <extracomment>schema: simulation.substeps</extracomment>
        <translation>Teilschritte</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <extracomment>schema: simulation.tolerance</extracomment>
        <translation>Toleranz</translation>
    </message>
    <message>
        <source>Newton iterations</source>
        <extracomment>schema: simulation.newton_iterations</extracomment>
        <translation>Newton-Iterationen</translation>
    </message>
    <message>
        <source>Duration</source>
        <extracomment>schema: simulation.duration</extracomment>
        <translation>Dauer</translation>
    </message>
    <message>
        <source>Contact solver</source>
        <extracomment>schema: simulation.solver</extracomment>
        <translation>Kontaktlöser</translation>
    </message>
    <message>
        <source>Contact model</source>
        <extracomment>schema: simulation.contact_model</extracomment>
        <translation>Kontaktmodell</translation>
    </message>
    <message>
        <source>Contact stiffness</source>
        <extracomment>schema: simulation.contact_stiffness</extracomment>
        <translation>Kontaktsteifigkeit</translation>
    </message>
    <message>
        <source>Contact damping</source>
        <extracomment>schema: simulation.contact_damping</extracomment>
        <translation>Kontaktdämpfung</translation>
    </message>
    <message>
        <source>Uniform gravity: F = m·g on every dynamic body</source>
        <extracomment>schema: gravity</extracomment>
        <translation>Homogene Schwerkraft: F = m·g auf jeden dynamischen Körper</translation>
    </message>
    <message>
        <source>g</source>
        <extracomment>schema: gravity.g</extracomment>
        <translation>g</translation>
    </message>
    <message>
        <source>Air drag: F = −b·v − c·‖v‖·v, torque −β·ω</source>
        <extracomment>schema: drag</extracomment>
        <translation>Luftwiderstand: F = −b·v − c·‖v‖·v, Drehmoment −β·ω</translation>
    </message>
    <message>
        <source>Linear b</source>
        <extracomment>schema: drag.linear</extracomment>
        <translation>Linear b</translation>
    </message>
    <message>
        <source>Quadratic c</source>
        <extracomment>schema: drag.quadratic</extracomment>
        <translation>Quadratisch c</translation>
    </message>
    <message>
        <source>Angular β</source>
        <extracomment>schema: drag.angular</extracomment>
        <translation>Drehung β</translation>
    </message>
    <message>
        <source>Newtonian gravity toward attractors (and between particles if mutual)</source>
        <extracomment>schema: newtonian_gravity</extracomment>
        <translation>Newtonsche Gravitation zu Anziehungszentren hin (und zwischen Teilchen, falls gegenseitig)</translation>
    </message>
    <message>
        <source>G</source>
        <extracomment>schema: newtonian_gravity.G</extracomment>
        <translation>G</translation>
    </message>
    <message>
        <source>Attractors</source>
        <extracomment>schema: newtonian_gravity.attractors</extracomment>
        <translation>Anziehungszentren</translation>
    </message>
    <message>
        <source>Mutual</source>
        <extracomment>schema: newtonian_gravity.mutual</extracomment>
        <translation>Gegenseitig</translation>
    </message>
    <message>
        <source>Softening ε</source>
        <extracomment>schema: newtonian_gravity.softening</extracomment>
        <translation>Glättung ε</translation>
    </message>
    <message>
        <source>Buoyancy ρ·A_sub·‖g‖ on the submerged part below the surface</source>
        <extracomment>schema: buoyancy</extracomment>
        <translation>Auftrieb ρ·A_sub·‖g‖ auf den eingetauchten Teil unter der Oberfläche</translation>
    </message>
    <message>
        <source>Fluid density ρ</source>
        <extracomment>schema: buoyancy.fluid_density</extracomment>
        <translation>Dichte der Flüssigkeit ρ</translation>
    </message>
    <message>
        <source>Surface y</source>
        <extracomment>schema: buoyancy.surface_y</extracomment>
        <translation>Oberfläche y</translation>
    </message>
    <message>
        <source>Drag b_f</source>
        <extracomment>schema: buoyancy.drag</extracomment>
        <translation>Widerstand b_f</translation>
    </message>
    <message>
        <source>Wind: F = b·(w − v) on particles</source>
        <extracomment>schema: wind</extracomment>
        <translation>Wind: F = b·(w − v) auf Teilchen</translation>
    </message>
    <message>
        <source>Velocity w</source>
        <extracomment>schema: wind.velocity</extracomment>
        <translation>Geschwindigkeit w</translation>
    </message>
    <message>
        <source>Drag b</source>
        <extracomment>schema: wind.drag</extracomment>
        <translation>Widerstand b</translation>
    </message>
    <message>
        <source>Boids steering: separation, alignment, cohesion (Reynolds 1987)</source>
        <extracomment>schema: flocking</extracomment>
        <translation>Schwarmsteuerung: Trennung, Ausrichtung, Zusammenhalt (Reynolds 1987)</translation>
    </message>
    <message>
        <source>Radius</source>
        <extracomment>schema: flocking.radius</extracomment>
        <translation>Radius</translation>
    </message>
    <message>
        <source>Separation</source>
        <extracomment>schema: flocking.separation</extracomment>
        <translation>Trennung</translation>
    </message>
    <message>
        <source>Alignment</source>
        <extracomment>schema: flocking.alignment</extracomment>
        <translation>Ausrichtung</translation>
    </message>
    <message>
        <source>Cohesion</source>
        <extracomment>schema: flocking.cohesion</extracomment>
        <translation>Zusammenhalt</translation>
    </message>
    <message>
        <source>Maximum speed</source>
        <extracomment>schema: flocking.max_speed</extracomment>
        <translation>Höchstgeschwindigkeit</translation>
    </message>
    <message>
        <source>Particle–particle disk contacts</source>
        <extracomment>schema: particle_collisions</extracomment>
        <translation>Scheibenkontakte zwischen Teilchen</translation>
    </message>
    <message>
        <source>Restitution e</source>
        <extracomment>schema: particle_collisions.restitution</extracomment>
        <translation>Stoßzahl e</translation>
    </message>
    <message>
        <source>Coulomb&apos;s law between charged particles</source>
        <extracomment>schema: coulomb</extracomment>
        <translation>Coulombsches Gesetz zwischen geladenen Teilchen</translation>
    </message>
    <message>
        <source>k</source>
        <extracomment>schema: coulomb.k</extracomment>
        <translation>k</translation>
    </message>
    <message>
        <source>fixed points of newtonian_gravity</source>
        <extracomment>schema: attractors</extracomment>
        <translation>feste Punkte von newtonian_gravity</translation>
    </message>
    <message>
        <source>Position</source>
        <extracomment>schema: attractors.position</extracomment>
        <translation>Position</translation>
    </message>
    <message>
        <source>Mass</source>
        <extracomment>schema: attractors.mass</extracomment>
        <translation>Masse</translation>
    </message>
    <message>
        <source>point masses, drawn as disks</source>
        <extracomment>schema: particles</extracomment>
        <translation>Punktmassen, als Scheiben gezeichnet</translation>
    </message>
    <message>
        <source>Id</source>
        <extracomment>schema: particles.id</extracomment>
        <translation>Kennung</translation>
    </message>
    <message>
        <source>Velocity</source>
        <extracomment>schema: particles.velocity</extracomment>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Pinned</source>
        <extracomment>schema: particles.pinned</extracomment>
        <translation>Fixiert</translation>
    </message>
    <message>
        <source>Restitution</source>
        <extracomment>schema: particles.restitution</extracomment>
        <translation>Stoßzahl</translation>
    </message>
    <message>
        <source>Friction</source>
        <extracomment>schema: particles.friction</extracomment>
        <translation>Reibung</translation>
    </message>
    <message>
        <source>Charge</source>
        <extracomment>schema: particles.charge</extracomment>
        <translation>Ladung</translation>
    </message>
    <message>
        <source>rigid rectangles</source>
        <extracomment>schema: boxes</extracomment>
        <translation>starre Rechtecke</translation>
    </message>
    <message>
        <source>Size</source>
        <extracomment>schema: boxes.size</extracomment>
        <translation>Größe</translation>
    </message>
    <message>
        <source>Angle</source>
        <extracomment>schema: boxes.angle</extracomment>
        <translation>Winkel</translation>
    </message>
    <message>
        <source>Angular velocity ω</source>
        <extracomment>schema: boxes.angular_velocity</extracomment>
        <translation>Winkelgeschwindigkeit ω</translation>
    </message>
    <message>
        <source>Density</source>
        <extracomment>schema: boxes.density</extracomment>
        <translation>Dichte</translation>
    </message>
    <message>
        <source>Static</source>
        <extracomment>schema: boxes.static</extracomment>
        <translation>Statisch</translation>
    </message>
    <message>
        <source>rigid disks: they turn, so they roll</source>
        <extracomment>schema: disks</extracomment>
        <translation>starre Scheiben: sie drehen sich, also rollen sie</translation>
    </message>
    <message>
        <source>rigid convex polygons</source>
        <extracomment>schema: polygons</extracomment>
        <translation>starre konvexe Vielecke</translation>
    </message>
    <message>
        <source>Vertices</source>
        <extracomment>schema: polygons.vertices</extracomment>
        <translation>Ecken</translation>
    </message>
    <message>
        <source>static half-planes, solid opposite the normal</source>
        <extracomment>schema: planes</extracomment>
        <translation>statische Halbebenen, fest auf der Seite gegenüber der Normalen</translation>
    </message>
    <message>
        <source>Point</source>
        <extracomment>schema: planes.point</extracomment>
        <translation>Punkt</translation>
    </message>
    <message>
        <source>Normal</source>
        <extracomment>schema: planes.normal</extracomment>
        <translation>Normale</translation>
    </message>
    <message>
        <source>damped springs between two objects or an anchor</source>
        <extracomment>schema: springs</extracomment>
        <translation>gedämpfte Federn zwischen zwei Objekten oder einem Aufhängepunkt</translation>
    </message>
    <message>
        <source>End a</source>
        <extracomment>schema: springs.a</extracomment>
        <translation>Ende a</translation>
    </message>
    <message>
        <source>End b</source>
        <extracomment>schema: springs.b</extracomment>
        <translation>Ende b</translation>
    </message>
    <message>
        <source>Anchor</source>
        <extracomment>schema: springs.anchor</extracomment>
        <translation>Aufhängepunkt</translation>
    </message>
    <message>
        <source>Point on a</source>
        <extracomment>schema: springs.a_point</extracomment>
        <translation>Punkt auf a</translation>
    </message>
    <message>
        <source>Point on b</source>
        <extracomment>schema: springs.b_point</extracomment>
        <translation>Punkt auf b</translation>
    </message>
    <message>
        <source>Stiffness k</source>
        <extracomment>schema: springs.stiffness</extracomment>
        <translation>Federkonstante k</translation>
    </message>
    <message>
        <source>Damping c</source>
        <extracomment>schema: springs.damping</extracomment>
        <translation>Dämpfung c</translation>
    </message>
    <message>
        <source>Rest length</source>
        <extracomment>schema: springs.rest_length</extracomment>
        <translation>Ruhelänge</translation>
    </message>
    <message>
        <source>grids of particles joined by springs</source>
        <extracomment>schema: cloths</extracomment>
        <translation>Gitter aus Teilchen, durch Federn verbunden</translation>
    </message>
    <message>
        <source>Origin</source>
        <extracomment>schema: cloths.origin</extracomment>
        <translation>Ursprung</translation>
    </message>
    <message>
        <source>Resolution</source>
        <extracomment>schema: cloths.resolution</extracomment>
        <translation>Auflösung</translation>
    </message>
    <message>
        <source>Mass (total)</source>
        <extracomment>schema: cloths.mass</extracomment>
        <translation>Masse (gesamt)</translation>
    </message>
    <message>
        <source>Stiffness</source>
        <extracomment>schema: cloths.stiffness</extracomment>
        <translation>Steifigkeit</translation>
    </message>
    <message>
        <source>Damping</source>
        <extracomment>schema: cloths.damping</extracomment>
        <translation>Dämpfung</translation>
    </message>
    <message>
        <source>Node radius</source>
        <extracomment>schema: cloths.radius</extracomment>
        <translation>Knotenradius</translation>
    </message>
    <message>
        <source>joints holding bodies together: hinges, rods, ropes, welds, pulleys, tracks</source>
        <extracomment>schema: joints</extracomment>
        <translation>Gelenke, die Körper zusammenhalten: Scharniere, Stangen, Seile, Schweißungen, Rollen, Bahnen</translation>
    </message>
    <message>
        <source>Type</source>
        <extracomment>schema: joints.type</extracomment>
        <translation>Art</translation>
    </message>
    <message>
        <source>Body a</source>
        <extracomment>schema: joints.a</extracomment>
        <translation>Körper a</translation>
    </message>
    <message>
        <source>Body b</source>
        <extracomment>schema: joints.b</extracomment>
        <translation>Körper b</translation>
    </message>
    <message>
        <source>Length</source>
        <extracomment>schema: joints.length</extracomment>
        <translation>Länge</translation>
    </message>
    <message>
        <source>Limits</source>
        <extracomment>schema: joints.limits</extracomment>
        <translation>Grenzen</translation>
    </message>
    <message>
        <source>Motor</source>
        <extracomment>schema: joints.motor</extracomment>
        <translation>Motor</translation>
    </message>
    <message>
        <source>Ground a</source>
        <extracomment>schema: joints.ground_a</extracomment>
        <translation>Festpunkt a</translation>
    </message>
    <message>
        <source>Ground b</source>
        <extracomment>schema: joints.ground_b</extracomment>
        <translation>Festpunkt b</translation>
    </message>
    <message>
        <source>Ratio</source>
        <extracomment>schema: joints.ratio</extracomment>
        <translation>Übersetzung</translation>
    </message>
    <message>
        <source>Circle</source>
        <extracomment>schema: joints.circle</extracomment>
        <translation>Kreis</translation>
    </message>
    <message>
        <source>Line</source>
        <extracomment>schema: joints.line</extracomment>
        <translation>Gerade</translation>
    </message>
    <message>
        <source>a cloth&apos;s spring stiffnesses</source>
        <extracomment>schema: stiffness</extracomment>
        <translation>die Federsteifigkeiten eines Tuchs</translation>
    </message>
    <message>
        <source>Structural stiffness</source>
        <extracomment>schema: stiffness.structural</extracomment>
        <translation>Struktursteifigkeit</translation>
    </message>
    <message>
        <source>Shear stiffness</source>
        <extracomment>schema: stiffness.shear</extracomment>
        <translation>Schersteifigkeit</translation>
    </message>
    <message>
        <source>Bend stiffness</source>
        <extracomment>schema: stiffness.bend</extracomment>
        <translation>Biegesteifigkeit</translation>
    </message>
    <message>
        <source>a hinge&apos;s motor</source>
        <extracomment>schema: motor</extracomment>
        <translation>der Motor eines Scharniers</translation>
    </message>
    <message>
        <source>Speed</source>
        <extracomment>schema: motor.speed</extracomment>
        <translation>Drehzahl</translation>
    </message>
    <message>
        <source>Maximum torque</source>
        <extracomment>schema: motor.max_torque</extracomment>
        <translation>Höchstes Drehmoment</translation>
    </message>
    <message>
        <source>the circle of a track</source>
        <extracomment>schema: circle</extracomment>
        <translation>der Kreis einer Bahn</translation>
    </message>
    <message>
        <source>Centre</source>
        <extracomment>schema: circle.center</extracomment>
        <translation>Mittelpunkt</translation>
    </message>
    <message>
        <source>the line of a track</source>
        <extracomment>schema: line</extracomment>
        <translation>die Gerade einer Bahn</translation>
    </message>
    <message>
        <source>Direction</source>
        <extracomment>schema: line.direction</extracomment>
        <translation>Richtung</translation>
    </message>
    <message>
        <source>Sleep</source>
        <extracomment>schema: simulation.sleep</extracomment>
        <translation>Schlafen</translation>
    </message>
</context>
<context>
    <name>StabilityText</name>
    <message>
        <source>%1 (stable below %2 s)</source>
        <translation>%1 (stabil unter %2 s)</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3 (below the linear limit %4 but above %5, the margin for penalty contacts): a contact that begins within a step can gain energy at every touch. Use dt/substeps below %6 s (%7 sub-steps).</source>
        <translation>%1 hat bei einem Teilschritt von %2 s ω·h = %3 (unter der linearen Grenze %4, aber über %5, dem Spielraum für Strafkontakte): Ein Kontakt, der innerhalb eines Schritts beginnt, kann bei jeder Berührung Energie gewinnen. Wählen Sie dt/Teilschritte unter %6 s (%7 Teilschritte).</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3 (below the linear limit %4 but above %5, the margin for penalty contacts): a contact that begins within a step can gain energy at every touch. Use dt/substeps below %6 s (%7 sub-steps), or a method stable at this step: %8.</source>
        <translation>%1 hat bei einem Teilschritt von %2 s ω·h = %3 (unter der linearen Grenze %4, aber über %5, dem Spielraum für Strafkontakte): Ein Kontakt, der innerhalb eines Schritts beginnt, kann bei jeder Berührung Energie gewinnen. Wählen Sie dt/Teilschritte unter %6 s (%7 Teilschritte) oder ein bei diesem Schritt stabiles Verfahren: %8.</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3 (stable below %4): it will blow up. Use dt/substeps below %5 s (%6 sub-steps, more for a margin).</source>
        <translation>%1 hat bei einem Teilschritt von %2 s ω·h = %3 (stabil unter %4): Die Simulation wird explodieren. Wählen Sie dt/Teilschritte unter %5 s (%6 Teilschritte, mehr für einen Spielraum).</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3 (stable below %4): it will blow up. Use dt/substeps below %5 s (%6 sub-steps, more for a margin), or a method stable at this step: %7.</source>
        <translation>%1 hat bei einem Teilschritt von %2 s ω·h = %3 (stabil unter %4): Die Simulation wird explodieren. Wählen Sie dt/Teilschritte unter %5 s (%6 Teilschritte, mehr für einen Spielraum) oder ein bei diesem Schritt stabiles Verfahren: %7.</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3: it gains energy at every step (its stiffest mode by a factor of about %4 per sub-step).</source>
        <translation>%1 hat bei einem Teilschritt von %2 s ω·h = %3: Es gewinnt bei jedem Schritt Energie (seine steifste Schwingung um etwa den Faktor %4 je Teilschritt).</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3: it gains energy at every step (its stiffest mode by a factor of about %4 per sub-step). Use a method stable at this step: %5.</source>
        <translation>%1 hat bei einem Teilschritt von %2 s ω·h = %3: Es gewinnt bei jedem Schritt Energie (seine steifste Schwingung um etwa den Faktor %4 je Teilschritt). Wählen Sie ein bei diesem Schritt stabiles Verfahren: %5.</translation>
    </message>
    <message>
        <source>nothing in the scene oscillates</source>
        <translation>nichts in der Szene schwingt</translation>
    </message>
    <message>
        <source>%1 is stable at this step (ω·h = %2)</source>
        <translation>%1 ist bei diesem Schritt stabil (ω·h = %2)</translation>
    </message>
    <message>
        <source>Kinematic contacts cannot hold a stack (&quot;%1&quot; rests on &quot;%2&quot;): they only stop bodies moving into each other and push them apart, so the stack sinks into the floor. Use impulse contacts for stacks.</source>
        <translation>Kinematische Kontakte können keinen Stapel tragen („%1“ liegt auf „%2“): Sie halten Körper nur davon ab, sich ineinander zu bewegen, und schieben sie auseinander, daher sinkt der Stapel in den Boden. Verwenden Sie für Stapel Impulskontakte.</translation>
    </message>
</context>
<context>
    <name>phasebox</name>
    <message>
        <source>the clip</source>
        <translation>der Clip</translation>
    </message>
</context>
<context>
    <name>phasebox::AccuracyDialog</name>
    <message>
        <source>Accuracy Lab — what accuracy costs in time</source>
        <translation>Genauigkeitslabor – was Genauigkeit an Zeit kostet</translation>
    </message>
    <message>
        <source>Integrators to study</source>
        <translation>Zu untersuchende Integratoren</translation>
    </message>
    <message>
        <source>Step sizes, separated by commas; fractions such as 1/120 are fine. The adaptive methods sweep tolerances at the first dt instead.</source>
        <translation>Schrittweiten, durch Kommas getrennt; Brüche wie 1/120 sind erlaubt. Die adaptiven Verfahren durchlaufen stattdessen Toleranzen beim ersten dt.</translation>
    </message>
    <message>
        <source>Simulated seconds each run lasts; errors are measured at the end.</source>
        <translation>Simulierte Sekunden pro Lauf; die Fehler werden am Ende gemessen.</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Starten</translation>
    </message>
    <message>
        <source>&amp;Cancel</source>
        <translation>&amp;Abbrechen</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <source>&amp;dt list:</source>
        <translation>&amp;dt-Liste:</translation>
    </message>
    <message>
        <source>D&amp;uration [s]:</source>
        <translation>&amp;Dauer [s]:</translation>
    </message>
    <message>
        <source>&amp;Integrators:</source>
        <translation>&amp;Integratoren:</translation>
    </message>
    <message>
        <source>The largest position error you accept at the end time, in metres</source>
        <translation>Der größte Positionsfehler, den Sie zur Endzeit akzeptieren, in Metern</translation>
    </message>
    <message>
        <source>&amp;Apply to the scene</source>
        <translation>Auf die Szene &amp;anwenden</translation>
    </message>
    <message>
        <source>Cheapest settings for an error of</source>
        <translation>Günstigste Einstellungen für einen Fehler von</translation>
    </message>
    <message>
        <source>m:</source>
        <translation>m:</translation>
    </message>
    <message>
        <source>Work-precision diagram</source>
        <translation>Arbeits-Genauigkeits-Diagramm</translation>
    </message>
    <message>
        <source>Each point is one run, labelled with its step dt. &lt;b&gt;Lower is better&lt;/b&gt; (a smaller error) and &lt;b&gt;left is faster&lt;/b&gt; (less CPU time): the best methods sit at the lower left. A steeper line is a higher order: halving dt divides the error by 2&lt;sup&gt;p&lt;/sup&gt;.</source>
        <translation>Jeder Punkt ist ein Lauf, beschriftet mit seinem Schritt dt. &lt;b&gt;Tiefer ist besser&lt;/b&gt; (ein kleinerer Fehler) und &lt;b&gt;weiter links ist schneller&lt;/b&gt; (weniger CPU-Zeit): die besten Verfahren liegen unten links. Eine steilere Linie bedeutet eine höhere Ordnung: Halbieren von dt teilt den Fehler durch 2&lt;sup&gt;p&lt;/sup&gt;.</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>Integrator</translation>
    </message>
    <message>
        <source>dt</source>
        <translation>dt</translation>
    </message>
    <message>
        <source>tolerance</source>
        <translation>Toleranz</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source>force evals</source>
        <translation>Kraftauswertungen</translation>
    </message>
    <message>
        <source>CPU [s]</source>
        <translation>CPU [s]</translation>
    </message>
    <message>
        <source>position error [m]</source>
        <translation>Positionsfehler [m]</translation>
    </message>
    <message>
        <source>energy drift [J]</source>
        <translation>Energiedrift [J]</translation>
    </message>
    <message>
        <source>order</source>
        <translation>Ordnung</translation>
    </message>
    <message>
        <source>measured order</source>
        <translation>gemessene Ordnung</translation>
    </message>
    <message>
        <source>theory</source>
        <translation>Theorie</translation>
    </message>
    <message>
        <source>what it means</source>
        <translation>Bedeutung</translation>
    </message>
    <message>
        <source>Rest the mouse on a row for the whole explanation</source>
        <translation>Zeigen Sie mit der Maus auf eine Zeile für die ganze Erklärung</translation>
    </message>
    <message>
        <source>&amp;Orders</source>
        <translation>&amp;Ordnungen</translation>
    </message>
    <message>
        <source>A&amp;ll runs</source>
        <translation>A&amp;lle Läufe</translation>
    </message>
    <message>
        <source>Scene: %1. Press Run: every checked method runs the scene at every dt on a copy; the open scene is not touched.</source>
        <translation>Szene: %1. Drücken Sie „Starten“: jedes angehakte Verfahren rechnet die Szene bei jedem dt auf einer Kopie; die offene Szene bleibt unberührt.</translation>
    </message>
    <message>
        <source>Check at least one integrator.</source>
        <translation>Haken Sie mindestens einen Integrator an.</translation>
    </message>
    <message>
        <source>dt list: &quot;%1&quot; is not a step in (0, 1] s.</source>
        <translation>dt-Liste: „%1“ ist kein Schritt in (0, 1] s.</translation>
    </message>
    <message>
        <source>Duration: a number of seconds &gt; 0, please.</source>
        <translation>Dauer: bitte eine Anzahl Sekunden &gt; 0.</translation>
    </message>
    <message>
        <source>Running…</source>
        <translation>Läuft…</translation>
    </message>
    <message>
        <source>The study could not run: %1</source>
        <translation>Die Untersuchung konnte nicht laufen: %1</translation>
    </message>
    <message>
        <source>%1: error at t = %2 s against CPU time</source>
        <translation>%1: Fehler bei t = %2 s gegen CPU-Zeit</translation>
    </message>
    <message>
        <source>Reference: %1. %2 runs%3.</source>
        <translation>Referenz: %1. %2 Läufe%3.</translation>
    </message>
    <message>
        <source> (cancelled)</source>
        <translation> (abgebrochen)</translation>
    </message>
    <message>
        <source>This scene has contacts: </source>
        <translation>Diese Szene hat Kontakte: </translation>
    </message>
    <message>
        <source>The end time was moved to %1 s, where the motion is fastest: at a turning point every method looks better than it is.</source>
        <translation>Die Endzeit wurde auf %1 s verschoben, wo die Bewegung am schnellsten ist: an einem Umkehrpunkt sieht jedes Verfahren besser aus, als es ist.</translation>
    </message>
    <message>
        <source>diverged: unstable at this dt</source>
        <translation>divergiert: instabil bei diesem dt</translation>
    </message>
    <message>
        <source>unstable at this dt</source>
        <translation>instabil bei diesem dt</translation>
    </message>
    <message>
        <source>The error does not shrink as the step is halved here: the method is unstable at this step, so this number is not its order.</source>
        <translation>Der Fehler sinkt hier nicht, wenn der Schritt halbiert wird: das Verfahren ist bei diesem Schritt instabil, also ist diese Zahl nicht seine Ordnung.</translation>
    </message>
    <message>
        <source>round-off floor reached</source>
        <translation>Rundungsgrenze erreicht</translation>
    </message>
    <message>
        <source>reference&apos;s accuracy reached</source>
        <translation>Genauigkeit der Referenz erreicht</translation>
    </message>
    <message>
        <source>The error is already as small as rounding (or the reference) allows: smaller steps no longer improve it, so this number is not the method&apos;s order.</source>
        <translation>Der Fehler ist schon so klein, wie es die Rundung (oder die Referenz) zulässt: kleinere Schritte verbessern ihn nicht mehr, also ist diese Zahl nicht die Ordnung des Verfahrens.</translation>
    </message>
    <message>
        <source>type an error such as 1e-4</source>
        <translation>geben Sie einen Fehler wie 1e-4 ein</translation>
    </message>
    <message>
        <source>run the study first</source>
        <translation>zuerst die Untersuchung starten</translation>
    </message>
    <message>
        <source>no run reached it: try smaller steps or a higher-order method</source>
        <translation>kein Lauf hat ihn erreicht: versuchen Sie kleinere Schritte oder ein Verfahren höherer Ordnung</translation>
    </message>
    <message>
        <source>the scene has changed since this study: run it again to apply</source>
        <translation>die Szene hat sich seit dieser Untersuchung geändert: starten Sie sie erneut, um anzuwenden</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; at dt %2%3: error %4 m in %5 s of CPU</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; bei dt %2%3: Fehler %4 m in %5 s CPU-Zeit</translation>
    </message>
    <message>
        <source>, tolerance %1</source>
        <translation>, Toleranz %1</translation>
    </message>
    <message>
        <source>the CSV file</source>
        <translation>die CSV-Datei</translation>
    </message>
    <message>
        <source>%1: error against CPU time</source>
        <translation>%1: Fehler gegen CPU-Zeit</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <source>Step sizes, separated by semicolons; fractions such as 1/120 are fine. The adaptive methods sweep tolerances at the first dt instead.</source>
        <translation>Schrittweiten, durch Semikolons getrennt; Brüche wie 1/120 sind erlaubt. Die adaptiven Verfahren durchlaufen stattdessen Toleranzen beim ersten dt.</translation>
    </message>
</context>
<context>
    <name>phasebox::AnimationExport</name>
    <message>
        <source>%1: unknown clip format; known: %2</source>
        <translation>%1: unbekanntes Clip-Format; bekannt: %2</translation>
    </message>
    <message>
        <source>Exporting %1…</source>
        <translation>%1 wird exportiert…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Wrote %1 (%2 frames)</source>
        <translation>%1 geschrieben (%2 Bilder)</translation>
    </message>
    <message>
        <source>Wrote %1; the run diverged: %2</source>
        <translation>%1 geschrieben; die Simulation divergierte: %2</translation>
    </message>
    <message>
        <source>Export cancelled; nothing was written</source>
        <translation>Export abgebrochen; nichts wurde geschrieben</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
</context>
<context>
    <name>phasebox::AnimationExportDialog</name>
    <message>
        <source>Export Animation</source>
        <translation>Animation exportieren</translation>
    </message>
    <message>
        <source>Clip file</source>
        <translation>Clip-Datei</translation>
    </message>
    <message>
        <source>A .mp4 file (H.264 video) or a .gif file (animated GIF)</source>
        <translation>Eine .mp4-Datei (H.264-Video) oder eine .gif-Datei (animiertes GIF)</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>&amp;Durchsuchen…</translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation>&amp;Datei:</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Start time</source>
        <translation>Startzeit</translation>
    </message>
    <message>
        <source>Simulated time of the first frame</source>
        <translation>Simulierte Zeit des ersten Bildes</translation>
    </message>
    <message>
        <source>Fro&amp;m:</source>
        <translation>&amp;Ab:</translation>
    </message>
    <message>
        <source>Duration</source>
        <translation>Dauer</translation>
    </message>
    <message>
        <source>Simulated seconds the clip shows</source>
        <translation>Simulierte Sekunden, die der Clip zeigt</translation>
    </message>
    <message>
        <source>&amp;Duration:</source>
        <translation>D&amp;auer:</translation>
    </message>
    <message>
        <source>Frames per second</source>
        <translation>Bilder pro Sekunde</translation>
    </message>
    <message>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <source>Frame &amp;rate:</source>
        <translation>Bild&amp;rate:</translation>
    </message>
    <message>
        <source>Width in pixels</source>
        <translation>Breite in Pixeln</translation>
    </message>
    <message>
        <source>Height in pixels</source>
        <translation>Höhe in Pixeln</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>&amp;Size:</source>
        <translation>&amp;Größe:</translation>
    </message>
    <message>
        <source>&amp;Plots beside the canvas (energy and phase space)</source>
        <translation>&amp;Diagramme neben der Zeichenfläche (Energie und Phasenraum)</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <source>MP4 video (*.mp4);;Animated GIF (*.gif)</source>
        <translation>MP4-Video (*.mp4);;Animiertes GIF (*.gif)</translation>
    </message>
</context>
<context>
    <name>phasebox::AppearancePresenter</name>
    <message>
        <source>High &amp;Contrast</source>
        <translation>&amp;Hoher Kontrast</translation>
    </message>
    <message>
        <source>White on black, with a yellow selection and focus: for a projector or for low vision</source>
        <translation>Weiß auf Schwarz, mit gelber Auswahl und gelbem Fokus: für Beamer oder bei Sehschwäche</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Line &amp;Width</source>
        <translation>&amp;Linienbreite</translation>
    </message>
    <message>
        <source>Te&amp;xt Size</source>
        <translation>Te&amp;xtgröße</translation>
    </message>
</context>
<context>
    <name>phasebox::CanvasPresenter</name>
    <message>
        <source> sides</source>
        <translation> Ecken</translation>
    </message>
    <message>
        <source>Sides of the regular polygon the Add polygon tool draws</source>
        <translation>Eckenzahl des regelmäßigen Vielecks, das das Werkzeug „Vieleck hinzufügen“ zeichnet</translation>
    </message>
    <message>
        <source>The kind of joint the Add joint tool makes</source>
        <translation>Die Art von Gelenk, die das Werkzeug „Gelenk hinzufügen“ erzeugt</translation>
    </message>
    <message>
        <source>&amp;Fit Scene</source>
        <translation>Szene &amp;einpassen</translation>
    </message>
    <message>
        <source>F&amp;ollow</source>
        <translation>&amp;Folgen</translation>
    </message>
    <message>
        <source>Keep the selection, or every moving object, in view while it runs</source>
        <translation>Die Auswahl oder jedes bewegte Objekt während des Laufs im Blick behalten</translation>
    </message>
    <message>
        <source>Export &amp;Canvas as PNG…</source>
        <translation>&amp;Zeichenfläche als PNG exportieren…</translation>
    </message>
    <message>
        <source>&amp;Trails</source>
        <translation>&amp;Spuren</translation>
    </message>
    <message>
        <source>&amp;Velocity Arrows</source>
        <translation>&amp;Geschwindigkeitspfeile</translation>
    </message>
    <message>
        <source>&amp;Force Arrows (springs, joints)</source>
        <translation>&amp;Kraftpfeile (Federn, Gelenke)</translation>
    </message>
    <message>
        <source>Object &amp;Labels</source>
        <translation>Objekt&amp;namen</translation>
    </message>
    <message>
        <source>Metre &amp;Grid</source>
        <translation>Meter&amp;gitter</translation>
    </message>
    <message>
        <source>%1: cannot draw the picture</source>
        <translation>%1: das Bild kann nicht gezeichnet werden</translation>
    </message>
    <message>
        <source>the picture</source>
        <translation>das Bild</translation>
    </message>
    <message>
        <source>Export Canvas</source>
        <translation>Zeichenfläche exportieren</translation>
    </message>
    <message>
        <source>PNG (*.png)</source>
        <translation>PNG (*.png)</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <source>Nothing selected. Tab walks the objects; with a drawing tool, the arrow keys move the cursor and Enter places the object there.</source>
        <translation>Nichts ausgewählt. Tab geht die Objekte durch; mit einem Zeichenwerkzeug bewegen die Pfeiltasten den Cursor, und Eingabe setzt das Objekt dorthin.</translation>
    </message>
    <message>
        <source>Selected: %1 %2.</source>
        <translation>Ausgewählt: %1 %2.</translation>
    </message>
    <message>
        <source>Position %1, %2 m; velocity %3, %4 m/s.</source>
        <translation>Position %1; %2 m; Geschwindigkeit %3; %4 m/s.</translation>
    </message>
    <message>
        <source>Arrows move it (Shift: finely), Enter opens its properties.</source>
        <translation>Pfeiltasten verschieben es (Umschalt: fein), Eingabe öffnet seine Eigenschaften.</translation>
    </message>
    <message>
        <source>hinge</source>
        <translation>Scharnier</translation>
    </message>
    <message>
        <source>rod</source>
        <translation>Stange</translation>
    </message>
    <message>
        <source>rope</source>
        <translation>Seil</translation>
    </message>
    <message>
        <source>weld</source>
        <translation>Schweißung</translation>
    </message>
    <message>
        <source>pulley</source>
        <translation>Rolle</translation>
    </message>
    <message>
        <source>track</source>
        <translation>Bahn</translation>
    </message>
    <message>
        <source>t = %L1 s   %2, dt %L3 s</source>
        <translation>t = %L1 s   %2, dt %L3 s</translation>
    </message>
</context>
<context>
    <name>phasebox::CanvasTools</name>
    <message>
        <source>That corner would make the polygon non-convex; polygons must be convex (build a concave shape from convex pieces).</source>
        <translation>Diese Ecke würde das Vieleck nicht-konvex machen; Vielecke müssen konvex sein (bauen Sie eine konkave Form aus konvexen Teilen).</translation>
    </message>
    <message>
        <source>That corner is in a line with two others: move it off the line.</source>
        <translation>Diese Ecke liegt mit zwei anderen auf einer Linie: rücken Sie sie von der Linie weg.</translation>
    </message>
    <message>
        <source>That corner is on top of another one.</source>
        <translation>Diese Ecke liegt auf einer anderen.</translation>
    </message>
    <message>
        <source>That corner is refused: %1</source>
        <translation>Diese Ecke wird abgelehnt: %1</translation>
    </message>
    <message>
        <source>Select / move</source>
        <translation>Auswählen / verschieben</translation>
    </message>
    <message>
        <source>Add particle</source>
        <translation>Teilchen hinzufügen</translation>
    </message>
    <message>
        <source>Add spring</source>
        <translation>Feder hinzufügen</translation>
    </message>
    <message>
        <source>Add cloth</source>
        <translation>Tuch hinzufügen</translation>
    </message>
    <message>
        <source>Add box</source>
        <translation>Quader hinzufügen</translation>
    </message>
    <message>
        <source>Add disk</source>
        <translation>Scheibe hinzufügen</translation>
    </message>
    <message>
        <source>Add polygon</source>
        <translation>Vieleck hinzufügen</translation>
    </message>
    <message>
        <source>Add plane</source>
        <translation>Ebene hinzufügen</translation>
    </message>
    <message>
        <source>Pin / unpin</source>
        <translation>Fixieren / lösen</translation>
    </message>
    <message>
        <source>Add joint</source>
        <translation>Gelenk hinzufügen</translation>
    </message>
    <message>
        <source>Ruler</source>
        <translation>Lineal</translation>
    </message>
    <message>
        <source>Protractor</source>
        <translation>Winkelmesser</translation>
    </message>
    <message>
        <source>Click to select (Shift adds), drag to move; while running, drag an object to pull it with a mouse spring.</source>
        <translation>Klicken zum Auswählen (Umschalt fügt hinzu), ziehen zum Verschieben; während des Laufs ein Objekt ziehen, um es mit einer Mausfeder zu ziehen.</translation>
    </message>
    <message>
        <source>Click to drop a particle; drag to give it a velocity.</source>
        <translation>Klicken, um ein Teilchen abzusetzen; ziehen, um ihm eine Geschwindigkeit zu geben.</translation>
    </message>
    <message>
        <source>Drag from an object to another, or to empty space for a fixed anchor.</source>
        <translation>Von einem Objekt zu einem anderen ziehen, oder ins Leere für einen festen Aufhängepunkt.</translation>
    </message>
    <message>
        <source>Drag a rectangle: a cloth hung from its top corners.</source>
        <translation>Ein Rechteck ziehen: ein Tuch, an seinen oberen Ecken aufgehängt.</translation>
    </message>
    <message>
        <source>Drag a rectangle: a box of that size.</source>
        <translation>Ein Rechteck ziehen: ein Quader dieser Größe.</translation>
    </message>
    <message>
        <source>Drag from the centre to the rim: a disk that rolls; click for one of 0.5 m.</source>
        <translation>Von der Mitte zum Rand ziehen: eine Scheibe, die rollt; klicken für eine von 0,5 m.</translation>
    </message>
    <message>
        <source>Drag from the centre to a corner: a regular polygon, flat side down; or click the corners and close on the first (double click or Enter closes, Backspace undoes a corner, Esc drops the outline).</source>
        <translation>Von der Mitte zu einer Ecke ziehen: ein regelmäßiges Vieleck, flache Seite unten; oder die Ecken anklicken und auf der ersten schließen (Doppelklick oder Eingabe schließt, Rücktaste nimmt eine Ecke zurück, Esc verwirft den Umriss).</translation>
    </message>
    <message>
        <source>Drag a line along the surface; the solid side is to the right of the drag.</source>
        <translation>Eine Linie entlang der Oberfläche ziehen; die feste Seite liegt rechts der Zugrichtung.</translation>
    </message>
    <message>
        <source>Click a particle to pin or unpin it, a box or disk to make it static.</source>
        <translation>Ein Teilchen anklicken, um es zu fixieren oder zu lösen, einen Quader oder eine Scheibe, um sie statisch zu machen.</translation>
    </message>
    <message>
        <source>Drag from a body to another, or to empty space for the fixed world: a hinge pivots where the drag starts; a rod or rope joins the two points; a weld holds two bodies together; a pulley hangs two bodies over two wheels a metre above; a track puts a particle on a hoop centred where the drag ends.</source>
        <translation>Von einem Körper zu einem anderen ziehen, oder ins Leere für die feste Welt: ein Scharnier dreht sich dort, wo das Ziehen beginnt; eine Stange oder ein Seil verbindet die zwei Punkte; eine Schweißung hält zwei Körper zusammen; eine Rolle hängt zwei Körper über zwei Räder einen Meter darüber; eine Bahn setzt ein Teilchen auf einen Ring mit Mittelpunkt am Ende des Ziehens.</translation>
    </message>
    <message>
        <source>Drag from one point to another to measure the distance; an end dropped on an object follows it. Click a ruler to select it, Esc or Delete removes it.</source>
        <translation>Von einem Punkt zu einem anderen ziehen, um den Abstand zu messen; ein auf ein Objekt gesetztes Ende folgt ihm. Ein Lineal anklicken, um es auszuwählen; Esc oder Entf entfernt es.</translation>
    </message>
    <message>
        <source>Drag from the vertex along the first arm, then click the second arm: the angle between them. Ends dropped on objects follow them; Esc or Delete removes the selected one.</source>
        <translation>Vom Scheitel entlang des ersten Schenkels ziehen, dann den zweiten Schenkel anklicken: der Winkel zwischen ihnen. Auf Objekte gesetzte Enden folgen ihnen; Esc oder Entf entfernt das ausgewählte.</translation>
    </message>
    <message>
        <source>Pulling %1 with a mouse spring</source>
        <translation>%1 wird mit einer Mausfeder gezogen</translation>
    </message>
    <message>
        <source>pulling %1</source>
        <translation>zieht %1</translation>
    </message>
    <message>
        <source>v = %1 m/s</source>
        <translation>v = %1 m/s</translation>
    </message>
    <message>
        <source>anchor, %1</source>
        <translation>Aufhängepunkt, %1</translation>
    </message>
    <message>
        <source>r = %1</source>
        <translation>r = %1</translation>
    </message>
    <message>
        <source>A spring starts on an object: drag from a particle or box.</source>
        <translation>Eine Feder beginnt an einem Objekt: von einem Teilchen oder Quader ziehen.</translation>
    </message>
    <message>
        <source>A joint starts on a body: drag from a particle, box, disk or polygon.</source>
        <translation>Ein Gelenk beginnt an einem Körper: von einem Teilchen, Quader, einer Scheibe oder einem Vieleck ziehen.</translation>
    </message>
    <message>
        <source>Only particles can be pinned and boxes and disks made static.</source>
        <translation>Nur Teilchen können fixiert und Quader und Scheiben statisch gemacht werden.</translation>
    </message>
    <message>
        <source>A polygon needs at least three corners.</source>
        <translation>Ein Vieleck braucht mindestens drei Ecken.</translation>
    </message>
    <message>
        <source>Corner %1: click the next corner.</source>
        <translation>Ecke %1: die nächste Ecke anklicken.</translation>
    </message>
    <message>
        <source>Corner %1: click the next, or the first corner (or Enter) to close.</source>
        <translation>Ecke %1: die nächste oder die erste Ecke anklicken (oder Eingabe), um zu schließen.</translation>
    </message>
    <message numerus="yes">
        <source>%n corner(s)</source>
        <translation>
            <numerusform>%n Ecke</numerusform>
            <numerusform>%n Ecken</numerusform>
        </translation>
    </message>
    <message>
        <source>Outline dropped.</source>
        <translation>Umriss verworfen.</translation>
    </message>
    <message>
        <source>Drag to where the %1 ends: another body or a fixed point.</source>
        <translation>Zum Endpunkt (%1) ziehen: ein anderer Körper oder ein fester Punkt.</translation>
    </message>
    <message>
        <source>rod</source>
        <translation>Stange</translation>
    </message>
    <message>
        <source>rope</source>
        <translation>Seil</translation>
    </message>
    <message>
        <source>A weld holds two bodies: drag from one onto the other.</source>
        <translation>Eine Schweißung hält zwei Körper: von einem auf den anderen ziehen.</translation>
    </message>
    <message>
        <source>A pulley hangs two bodies: drag from one to the other.</source>
        <translation>Eine Rolle hängt zwei Körper auf: von einem zum anderen ziehen.</translation>
    </message>
    <message>
        <source>Drag from a particle to the centre of its hoop.</source>
        <translation>Von einem Teilchen zum Mittelpunkt seines Rings ziehen.</translation>
    </message>
</context>
<context>
    <name>phasebox::CompareDialog</name>
    <message>
        <source>Compare from Here</source>
        <translation>Von hier vergleichen</translation>
    </message>
    <message>
        <source>From t = %L1 s the run goes on with the settings below, while the recorded run (%2, dt %L3 s) is drawn beside it as a ghost.</source>
        <translation>Ab t = %L1 s läuft die Simulation mit den Einstellungen unten weiter, während der aufgezeichnete Lauf (%2, dt %L3 s) als Geist daneben gezeichnet wird.</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>&amp;Integrator:</source>
        <translation>&amp;Integrator:</translation>
    </message>
    <message>
        <source>&amp;dt:</source>
        <translation>&amp;dt:</translation>
    </message>
    <message>
        <source>&amp;Contacts:</source>
        <translation>&amp;Kontakte:</translation>
    </message>
    <message>
        <source>Co&amp;mpare</source>
        <translation>&amp;Vergleichen</translation>
    </message>
</context>
<context>
    <name>phasebox::ComparePresenter</name>
    <message>
        <source>&amp;Compare from Here…</source>
        <translation>Von hier &amp;vergleichen…</translation>
    </message>
    <message>
        <source>Run on from the timeline&apos;s moment with another integrator, dt or contact model, with the recorded run beside it as a ghost</source>
        <translation>Vom Moment der Zeitleiste an mit einem anderen Integrator, dt oder Kontaktmodell weiterlaufen, den aufgezeichneten Lauf als Geist daneben</translation>
    </message>
    <message>
        <source>Compare…</source>
        <translation>Vergleichen…</translation>
    </message>
    <message>
        <source>&amp;Leave Compare</source>
        <translation>Vergleich &amp;beenden</translation>
    </message>
    <message>
        <source>Remove the recorded run&apos;s ghost from the canvas and the plots</source>
        <translation>Den Geist des aufgezeichneten Laufs von der Zeichenfläche und aus den Diagrammen entfernen</translation>
    </message>
    <message>
        <source>Leave compare</source>
        <translation>Vergleich aus</translation>
    </message>
    <message>
        <source>Comparing from t = %L1 s: %2 against the recorded run (dashed).</source>
        <translation>Vergleich ab t = %L1 s: %2 gegen den aufgezeichneten Lauf (gestrichelt).</translation>
    </message>
    <message>
        <source>Drag the timeline to an earlier moment first: the run is compared from there.</source>
        <translation>Ziehen Sie die Zeitleiste zuerst auf einen früheren Moment: Von dort aus wird der Lauf verglichen.</translation>
    </message>
    <message>
        <source>Left Compare: the recorded run&apos;s ghost is gone.</source>
        <translation>Vergleich beendet: Der Geist des aufgezeichneten Laufs ist entfernt.</translation>
    </message>
    <message>
        <source>recorded: %1</source>
        <translation>aufgezeichnet: %1</translation>
    </message>
    <message>
        <source>, dt %L1 s</source>
        <translation>, dt %L1 s</translation>
    </message>
    <message>
        <source>Ghost: the recorded run ended at t = %L1 s</source>
        <translation>Geist: Der aufgezeichnete Lauf endete bei t = %L1 s</translation>
    </message>
    <message>
        <source>Ghost: the recorded run, %1</source>
        <translation>Geist: der aufgezeichnete Lauf, %1</translation>
    </message>
</context>
<context>
    <name>phasebox::DivergenceNotice</name>
    <message>
        <source>The simulation became unstable</source>
        <translation>Die Simulation wurde instabil</translation>
    </message>
</context>
<context>
    <name>phasebox::Document</name>
    <message>
        <source>Switched to %1 so the %2 stays stable; Undo to go back to %3</source>
        <translation>Zu %1 gewechselt, damit %2 stabil bleibt; Rückgängig führt zurück zu %3</translation>
    </message>
    <message>
        <source>unknown effect &quot;%1&quot;; known: %2</source>
        <translation>unbekannter Effekt „%1“; bekannt: %2</translation>
    </message>
    <message>
        <source>Switch on %1</source>
        <translation>%1 einschalten</translation>
    </message>
    <message>
        <source>Switch off %1</source>
        <translation>%1 ausschalten</translation>
    </message>
    <message>
        <source>Change effects</source>
        <translation>Effekte ändern</translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation>%1 ändern</translation>
    </message>
</context>
<context>
    <name>phasebox::EffectsPresenter</name>
    <message>
        <source>Runs because the scene has springs</source>
        <translation>Läuft, weil die Szene Federn hat</translation>
    </message>
    <message>
        <source>Runs because the scene holds things that can touch</source>
        <translation>Läuft, weil die Szene Dinge enthält, die sich berühren können</translation>
    </message>
    <message>
        <source>The integrator&apos;s own arithmetic</source>
        <translation>Die eigene Rechenarbeit des Integrators</translation>
    </message>
    <message>
        <source>Costs per step of the whole run: a recorded frame keeps no timing of its own.</source>
        <translation>Kosten pro Schritt über den ganzen Lauf: ein aufgezeichnetes Bild hat keine eigene Zeitmessung.</translation>
    </message>
</context>
<context>
    <name>phasebox::ExactPresenter</name>
    <message>
        <source>E&amp;xact Solution</source>
        <translation>E&amp;xakte Lösung</translation>
    </message>
    <message>
        <source>Draw the exact (closed-form) motion beside the simulation, dashed, when the scene has one: oscillators, free fall, orbits, pendulums, Atwood machines, rolling and sliding on ramps (until a contact begins or ends)</source>
        <translation>Die exakte (geschlossene) Bewegung gestrichelt neben der Simulation zeichnen, wenn die Szene eine hat: Schwinger, freier Fall, Umlaufbahnen, Pendel, Atwoodsche Fallmaschinen, Rollen und Gleiten auf Rampen (bis ein Kontakt beginnt oder endet)</translation>
    </message>
    <message>
        <source>exact</source>
        <translation>exakt</translation>
    </message>
    <message>
        <source>dashed: exact solution (%1)</source>
        <translation>gestrichelt: exakte Lösung (%1)</translation>
    </message>
    <message>
        <source>dashed: exact solution (%1) until t = %2 s, where a contact begins or ends</source>
        <translation>gestrichelt: exakte Lösung (%1) bis t = %2 s, wo ein Kontakt beginnt oder endet</translation>
    </message>
</context>
<context>
    <name>phasebox::FramePainter</name>
    <message>
        <source>%1, dt %2 s</source>
        <translation>%1, dt %2 s</translation>
    </message>
    <message>
        <source>t = %1 s   %2</source>
        <translation>t = %1 s   %2</translation>
    </message>
    <message>
        <source>Energy (%1)</source>
        <translation>Energie (%1)</translation>
    </message>
    <message>
        <source>Phase space</source>
        <translation>Phasenraum</translation>
    </message>
    <message>
        <source>Phase space of %1</source>
        <translation>Phasenraum von %1</translation>
    </message>
</context>
<context>
    <name>phasebox::HelpWindows</name>
    <message>
        <source>About Phasebox</source>
        <translation>Über Phasebox</translation>
    </message>
    <message>
        <source>&lt;b&gt;Phasebox %1&lt;/b&gt;&lt;p&gt;A 2D physics sandbox for the classroom: drop particles, springs, cloth and boxes into a scene, switch the integrator while it runs, and watch what accuracy costs.&lt;/p&gt;</source>
        <translation>&lt;b&gt;Phasebox %1&lt;/b&gt;&lt;p&gt;Ein 2D-Physik-Sandkasten für den Unterricht: Teilchen, Federn, Tücher und Quader in eine Szene setzen, den Integrator während des Laufs wechseln und sehen, was Genauigkeit kostet.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>phasebox::InstrumentsPresenter</name>
    <message>
        <source>&amp;Instruments</source>
        <translation>&amp;Instrumente</translation>
    </message>
    <message>
        <source>Start/Stop S&amp;topwatch</source>
        <translation>S&amp;toppuhr starten/anhalten</translation>
    </message>
    <message>
        <source>The stopwatch on simulated time (Instruments → Timer)</source>
        <translation>Die Stoppuhr in simulierter Zeit (Instrumente → Zeitmesser)</translation>
    </message>
    <message>
        <source>Stopwatch &amp;Lap</source>
        <translation>Stoppuhr-&amp;Runde</translation>
    </message>
    <message>
        <source>Probe Table as CSV…</source>
        <translation>Messwerttabelle als CSV…</translation>
    </message>
</context>
<context>
    <name>phasebox::LanguageMenu</name>
    <message>
        <source>&amp;System Language</source>
        <translation>&amp;Systemsprache</translation>
    </message>
    <message>
        <source>Phasebox will speak %1 from its next start.</source>
        <translation>Phasebox spricht ab dem nächsten Start %1.</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
</context>
<context>
    <name>phasebox::MainWindow</name>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Automatisches Speichern fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Re&amp;vert</source>
        <translation>Gespeicherte &amp;Version laden</translation>
    </message>
    <message>
        <source>Reopen the scene&apos;s file as it was last saved, dropping the edits</source>
        <translation>Die Datei der Szene so wieder öffnen, wie sie zuletzt gespeichert wurde, und die Änderungen verwerfen</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Kopieren</translation>
    </message>
    <message>
        <source>Cu&amp;t</source>
        <translation>&amp;Ausschneiden</translation>
    </message>
    <message>
        <source>&amp;Paste</source>
        <translation>&amp;Einfügen</translation>
    </message>
    <message>
        <source>&amp;Accuracy Lab…</source>
        <translation>&amp;Genauigkeitslabor…</translation>
    </message>
    <message>
        <source>Error against CPU time for every integrator, on this scene</source>
        <translation>Fehler gegen CPU-Zeit für jeden Integrator, an dieser Szene</translation>
    </message>
    <message>
        <source>&amp;Presentation Mode</source>
        <translation>&amp;Präsentationsmodus</translation>
    </message>
    <message>
        <source>Live &amp;Error Estimate</source>
        <translation>Live-&amp;Fehlerschätzung</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Benutzerhandbuch</translation>
    </message>
    <message>
        <source>How to use Phasebox: the window, building scenes, measuring, files</source>
        <translation>Wie man Phasebox benutzt: das Fenster, Szenen bauen, messen, Dateien</translation>
    </message>
    <message>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>&amp;Tastenkürzel</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Examples</source>
        <translation>&amp;Beispiele</translation>
    </message>
    <message>
        <source>&amp;Lessons</source>
        <translation>&amp;Lektionen</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About Phasebox</source>
        <translation>&amp;Über Phasebox</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Haupt</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Effects</source>
        <translation>Effekte</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <source>Plots</source>
        <translation>Diagramme</translation>
    </message>
    <message>
        <source>Instruments</source>
        <translation>Instrumente</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Notizen</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Drop your changes and reopen %1 as it was last saved?</source>
        <translation>Ihre Änderungen verwerfen und %1 so wieder öffnen, wie es zuletzt gespeichert wurde?</translation>
    </message>
    <message>
        <source>Phasebox</source>
        <translation>Phasebox</translation>
    </message>
    <message>
        <source>The scene has unsaved changes. Save them?</source>
        <translation>Die Szene hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>Scene canvas</source>
        <translation>Zeichenfläche der Szene</translation>
    </message>
    <message>
        <source>Export &amp;Animation…</source>
        <translation>&amp;Animation exportieren…</translation>
    </message>
    <message>
        <source>The run as an MP4 or animated GIF clip, optionally with the plots</source>
        <translation>Der Lauf als MP4- oder animierter GIF-Clip, wahlweise mit den Diagrammen</translation>
    </message>
    <message>
        <source>&amp;Worker Threads</source>
        <translation>&amp;Arbeits-Threads</translation>
    </message>
</context>
<context>
    <name>phasebox::MeasureTools</name>
    <message>
        <source>Free-&amp;Body View</source>
        <translation>&amp;Freikörperbild</translation>
    </message>
    <message>
        <source>Draw the forces on the selected body by source, its momentum and the system&apos;s centre of mass</source>
        <translation>Die Kräfte auf den ausgewählten Körper nach Quelle zeichnen, seinen Impuls und den Schwerpunkt des Systems</translation>
    </message>
    <message>
        <source>&amp;Clear Measurements</source>
        <translation>Messungen &amp;löschen</translation>
    </message>
    <message>
        <source>--ruler &quot;%1&quot;: expected A,B with each an object id or X:Y</source>
        <translation>--ruler &quot;%1&quot;: erwartet A,B, jeweils eine Objektkennung oder X:Y</translation>
    </message>
    <message>
        <source>--protractor &quot;%1&quot;: expected A,B,C (the vertex B in the middle, as in angle(A,B,C)) with each an object id or X:Y</source>
        <translation>--protractor &quot;%1&quot;: erwartet A,B,C (der Scheitel B in der Mitte, wie in angle(A,B,C)), jeweils eine Objektkennung oder X:Y</translation>
    </message>
    <message>
        <source>%1 m
dx %2  dy %3</source>
        <translation>%1 m
dx %2  dy %3</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>Angle %1</source>
        <translation>Winkel %1</translation>
    </message>
    <message>
        <source>Drag from one point to the other to measure.</source>
        <translation>Von einem Punkt zum anderen ziehen, um zu messen.</translation>
    </message>
    <message>
        <source>Drag from the vertex along the first arm.</source>
        <translation>Vom Scheitel entlang des ersten Schenkels ziehen.</translation>
    </message>
    <message>
        <source>Distance %1</source>
        <translation>Abstand %1</translation>
    </message>
    <message>
        <source>Now click the second arm (Esc cancels).</source>
        <translation>Jetzt den zweiten Schenkel anklicken (Esc bricht ab).</translation>
    </message>
</context>
<context>
    <name>phasebox::ParametersPresenter</name>
    <message>
        <source>&amp;Play</source>
        <translation>&amp;Start</translation>
    </message>
    <message>
        <source>Play or pause the simulation (Space)</source>
        <translation>Simulation starten oder anhalten (Leertaste)</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>S&amp;tep</source>
        <translation>Sch&amp;ritt</translation>
    </message>
    <message>
        <source>Advance one step (S)</source>
        <translation>Einen Schritt weiter (S)</translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <source>Back to the setup (Ctrl+R)</source>
        <translation>Zurück zum Anfangszustand (Strg+R)</translation>
    </message>
    <message>
        <source>Next Integrator</source>
        <translation>Nächster Integrator</translation>
    </message>
    <message>
        <source>Previous Integrator</source>
        <translation>Vorheriger Integrator</translation>
    </message>
    <message>
        <source>Double dt</source>
        <translation>dt verdoppeln</translation>
    </message>
    <message>
        <source>Halve dt</source>
        <translation>dt halbieren</translation>
    </message>
    <message>
        <source>More Sub-steps</source>
        <translation>Mehr Teilschritte</translation>
    </message>
    <message>
        <source>Fewer Sub-steps</source>
        <translation>Weniger Teilschritte</translation>
    </message>
    <message>
        <source>Faster</source>
        <translation>Schneller</translation>
    </message>
    <message>
        <source>Slower</source>
        <translation>Langsamer</translation>
    </message>
    <message>
        <source>Largest stable sub-step (stiffest mode ω = %1 rad/s):</source>
        <translation>Größter stabiler Teilschritt (steifste Mode ω = %1 rad/s):</translation>
    </message>
    <message>
        <source>any</source>
        <translation>beliebig</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keiner</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Integrator: %1</source>
        <translation>Integrator: %1</translation>
    </message>
    <message>
        <source>dt = %1 s</source>
        <translation>dt = %1 s</translation>
    </message>
    <message>
        <source>%1 sub-steps</source>
        <translation>%1 Teilschritte</translation>
    </message>
    <message>
        <source>Applied %1 at dt %2 s</source>
        <translation>%1 bei dt %2 s angewendet</translation>
    </message>
</context>
<context>
    <name>phasebox::PeriodTimerPresenter</name>
    <message>
        <source>Pick a probe (an object&apos;s x for a swing), then press Play: the period is the mean interval between its upward crossings of the middle of its range.</source>
        <translation>Wählen Sie eine Messgröße (das x eines Objekts für eine Schwingung) und drücken Sie dann Start: die Periode ist der mittlere Abstand zwischen ihren Aufwärtsdurchgängen durch die Mitte ihres Bereichs.</translation>
    </message>
    <message>
        <source>%1 cannot be read in this scene.</source>
        <translation>%1 kann in dieser Szene nicht gelesen werden.</translation>
    </message>
    <message numerus="yes">
        <source>Waiting for two upward crossings of the middle of the range of %1 (%n so far).</source>
        <translation>
            <numerusform>Warte auf zwei Aufwärtsdurchgänge durch die Mitte des Bereichs von %1 (bisher %n).</numerusform>
            <numerusform>Warte auf zwei Aufwärtsdurchgänge durch die Mitte des Bereichs von %1 (bisher %n).</numerusform>
        </translation>
    </message>
    <message>
        <source>Mean interval between the upward crossings of %1 through %2 %3, the middle of its range [%4, %5] %3, each interpolated within its step.</source>
        <translation>Mittlerer Abstand zwischen den Aufwärtsdurchgängen von %1 durch %2 %3, die Mitte seines Bereichs [%4, %5] %3, jeweils innerhalb des Schritts interpoliert.</translation>
    </message>
</context>
<context>
    <name>phasebox::PlotsPresenter</name>
    <message>
        <source>The live error estimate is off (View menu).</source>
        <translation>Die Live-Fehlerschätzung ist aus (Menü Ansicht).</translation>
    </message>
    <message>
        <source>No live error estimate: a step takes %1 ms, and the estimate would cost three more.</source>
        <translation>Keine Live-Fehlerschätzung: ein Schritt dauert %1 ms, und die Schätzung würde drei weitere kosten.</translation>
    </message>
    <message>
        <source>Press Play: the error one step makes is estimated as the simulation runs.</source>
        <translation>Drücken Sie Start: der Fehler, den ein Schritt macht, wird während der Simulation geschätzt.</translation>
    </message>
    <message>
        <source>Phase space</source>
        <translation>Phasenraum</translation>
    </message>
    <message>
        <source>Phase space of %1</source>
        <translation>Phasenraum von %1</translation>
    </message>
    <message>
        <source>Click an object first.</source>
        <translation>Klicken Sie zuerst ein Objekt an.</translation>
    </message>
    <message>
        <source>Only rigid bodies have an angle.</source>
        <translation>Nur starre Körper haben einen Winkel.</translation>
    </message>
    <message>
        <source>no object chosen for the phase plot: click one on the canvas</source>
        <translation>kein Objekt für das Phasendiagramm gewählt: klicken Sie eines auf der Zeichenfläche an</translation>
    </message>
    <message>
        <source>Phase space of %1 (%2)</source>
        <translation>Phasenraum von %1 (%2)</translation>
    </message>
    <message>
        <source>Energy Plot</source>
        <translation>Energiediagramm</translation>
    </message>
    <message>
        <source>Phase Plot</source>
        <translation>Phasendiagramm</translation>
    </message>
    <message>
        <source>Error Plot</source>
        <translation>Fehlerdiagramm</translation>
    </message>
    <message>
        <source>%1 as %2…</source>
        <translation>%1 als %2…</translation>
    </message>
    <message>
        <source>Export Plot</source>
        <translation>Diagramm exportieren</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>%1 geschrieben</translation>
    </message>
    <message>
        <source>Energy&lt;br&gt;%1, dt %L2 s</source>
        <translation>Energie&lt;br&gt;%1, dt %L2 s</translation>
    </message>
    <message>
        <source>Local error per step&lt;br&gt;%1, dt %L2 s</source>
        <translation>Lokaler Fehler pro Schritt&lt;br&gt;%1, dt %L2 s</translation>
    </message>
</context>
<context>
    <name>phasebox::ProbeGraphsPresenter</name>
    <message>
        <source>no graph %1</source>
        <translation>kein Graph %1</translation>
    </message>
    <message>
        <source>All %1 graphs are in use: close one first.</source>
        <translation>Alle %1 Graphen sind belegt: schließen Sie zuerst einen.</translation>
    </message>
    <message>
        <source>time [s]</source>
        <translation>Zeit [s]</translation>
    </message>
    <message>
        <source>Pick a probe to plot, or type one (p0.x, system.total, distance(A,B), …).</source>
        <translation>Wählen Sie eine Messgröße zum Plotten oder tippen Sie eine ein (p0.x, system.total, distance(A,B), …).</translation>
    </message>
    <message>
        <source>%1 cannot be read in this scene (was its object deleted or renamed?)</source>
        <translation>%1 kann in dieser Szene nicht gelesen werden (wurde sein Objekt gelöscht oder umbenannt?)</translation>
    </message>
    <message>
        <source>Press Play: %1 is recorded at every step.</source>
        <translation>Drücken Sie Start: %1 wird bei jedem Schritt aufgezeichnet.</translation>
    </message>
    <message>
        <source>Recorded since t = %1 s, when it was chosen.</source>
        <translation>Aufgezeichnet seit t = %1 s, als es gewählt wurde.</translation>
    </message>
    <message>
        <source>graph %1 plots nothing: pick a probe first</source>
        <translation>Graph %1 zeigt nichts: wählen Sie zuerst eine Messgröße</translation>
    </message>
    <message>
        <source>%1 against %2 — %3 (%4, dt %5 s)</source>
        <translation>%1 gegen %2 – %3 (%4, dt %5 s)</translation>
    </message>
    <message>
        <source>time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>Export Graph</source>
        <translation>Graph exportieren</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>%1 geschrieben</translation>
    </message>
</context>
<context>
    <name>phasebox::ProbeRecorder</name>
    <message>
        <source>the CSV file</source>
        <translation>die CSV-Datei</translation>
    </message>
</context>
<context>
    <name>phasebox::ProbeTablePresenter</name>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>%1 (invalid)</source>
        <translation>%1 (ungültig)</translation>
    </message>
    <message>
        <source>Export Probe Table</source>
        <translation>Messwerttabelle exportieren</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>%1 geschrieben</translation>
    </message>
</context>
<context>
    <name>phasebox::PropertiesPresenter</name>
    <message>
        <source>Live at t = %1 s; Reset shows the setup</source>
        <translation>Live bei t = %1 s; Zurücksetzen zeigt den Anfangszustand</translation>
    </message>
    <message>
        <source>The setup&apos;s numbers (the run is at t = %1 s)</source>
        <translation>Die Zahlen des Anfangszustands (der Lauf steht bei t = %1 s)</translation>
    </message>
    <message>
        <source>Setup: the state at t = 0, what Reset returns to</source>
        <translation>Anfangszustand: der Zustand bei t = 0, zu dem Zurücksetzen zurückkehrt</translation>
    </message>
    <message>
        <source>Recorded at t = %1 s; Reset shows the setup</source>
        <translation>Aufgezeichnet bei t = %1 s; Zurücksetzen zeigt den Anfangszustand</translation>
    </message>
</context>
<context>
    <name>phasebox::ReadoutsPresenter</name>
    <message>
        <source>cloth node</source>
        <translation>Tuchknoten</translation>
    </message>
    <message>
        <source>pinned particle</source>
        <translation>fixiertes Teilchen</translation>
    </message>
    <message>
        <source>particle</source>
        <translation>Teilchen</translation>
    </message>
    <message>
        <source>disk</source>
        <translation>Scheibe</translation>
    </message>
    <message>
        <source>polygon</source>
        <translation>Vieleck</translation>
    </message>
    <message>
        <source>box</source>
        <translation>Quader</translation>
    </message>
    <message>
        <source>static %1</source>
        <translation>%1 (statisch)</translation>
    </message>
    <message>
        <source>Click an object on the canvas to read its position, velocity, energy and momentum; Shift-click a second and a third for the distance and the angle between them.</source>
        <translation>Klicken Sie ein Objekt auf der Zeichenfläche an, um Position, Geschwindigkeit, Energie und Impuls abzulesen; Umschalt-Klick auf ein zweites und drittes zeigt Abstand und Winkel zwischen ihnen.</translation>
    </message>
    <message>
        <source>position (x, y)</source>
        <translation>Position (x, y)</translation>
    </message>
    <message>
        <source>velocity (vx, vy)</source>
        <translation>Geschwindigkeit (vx, vy)</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>Betrag der Geschwindigkeit</translation>
    </message>
    <message>
        <source>angle</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <source>angular velocity ω</source>
        <translation>Winkelgeschwindigkeit ω</translation>
    </message>
    <message>
        <source>kinetic energy</source>
        <translation>kinetische Energie</translation>
    </message>
    <message>
        <source>momentum (px, py)</source>
        <translation>Impuls (px, py)</translation>
    </message>
    <message>
        <source>angular momentum L</source>
        <translation>Drehimpuls L</translation>
    </message>
    <message>
        <source>contact force</source>
        <translation>Kontaktkraft</translation>
    </message>
    <message>
        <source>distance %1–%2</source>
        <translation>Abstand %1–%2</translation>
    </message>
    <message>
        <source>angle %1–%2–%3</source>
        <translation>Winkel %1–%2–%3</translation>
    </message>
    <message>
        <source>%1 (joint)</source>
        <translation>%1 (Gelenk)</translation>
    </message>
    <message>
        <source>constraint force of %1</source>
        <translation>Zwangskraft von %1</translation>
    </message>
    <message>
        <source>angle of %1</source>
        <translation>Winkel von %1</translation>
    </message>
    <message>
        <source>live, t = %1 s</source>
        <translation>live, t = %1 s</translation>
    </message>
    <message>
        <source>setup</source>
        <translation>Anfangszustand</translation>
    </message>
    <message>
        <source>recorded, t = %1 s</source>
        <translation>aufgezeichnet, t = %1 s</translation>
    </message>
</context>
<context>
    <name>phasebox::SceneBrowserPresenter</name>
    <message>
        <source>Nothing to copy: select objects first (a spring goes along with the objects it joins).</source>
        <translation>Nichts zu kopieren: wählen Sie zuerst Objekte aus (eine Feder kommt mit den Objekten mit, die sie verbindet).</translation>
    </message>
    <message numerus="yes">
        <source>Copied %n object(s)</source>
        <translation>
            <numerusform>%n Objekt kopiert</numerusform>
            <numerusform>%n Objekte kopiert</numerusform>
        </translation>
    </message>
    <message>
        <source>Nothing to paste: copy objects first.</source>
        <translation>Nichts einzufügen: kopieren Sie zuerst Objekte.</translation>
    </message>
    <message>
        <source>the clipboard</source>
        <translation>die Zwischenablage</translation>
    </message>
    <message>
        <source>The clipboard holds no Phasebox objects: %1</source>
        <translation>Die Zwischenablage enthält keine Phasebox-Objekte: %1</translation>
    </message>
    <message>
        <source>Nothing to paste: the clipboard&apos;s scene is empty.</source>
        <translation>Nichts einzufügen: die Szene in der Zwischenablage ist leer.</translation>
    </message>
</context>
<context>
    <name>phasebox::SceneFiles</name>
    <message>
        <source>Could not open %1</source>
        <translation>%1 konnte nicht geöffnet werden</translation>
    </message>
    <message>
        <source>Could not open the scene</source>
        <translation>Die Szene konnte nicht geöffnet werden</translation>
    </message>
    <message>
        <source>%1

The open scene is unchanged.</source>
        <translation>%1

Die offene Szene ist unverändert.</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <source>Open Scene</source>
        <translation>Szene öffnen</translation>
    </message>
    <message>
        <source>Save Scene As</source>
        <translation>Szene speichern unter</translation>
    </message>
    <message>
        <source>Could not save</source>
        <translation>Speichern nicht möglich</translation>
    </message>
    <message>
        <source>%1

The file on disk (if any) is unchanged.</source>
        <translation>%1

Die Datei auf der Festplatte (falls vorhanden) ist unverändert.</translation>
    </message>
    <message>
        <source>Saving failed: %1</source>
        <translation>Speichern fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>an unsaved scene</source>
        <translation>eine ungespeicherte Szene</translation>
    </message>
    <message>
        <source>Recover the last scene?</source>
        <translation>Die letzte Szene wiederherstellen?</translation>
    </message>
    <message>
        <source>Phasebox did not close properly last time. An autosave of %1 from %2 is available. Open it?</source>
        <translation>Phasebox wurde letztes Mal nicht richtig beendet. Eine automatische Sicherung von %1 vom %2 ist vorhanden. Öffnen?</translation>
    </message>
    <message>
        <source>Recovered from the autosave: save it to keep it.</source>
        <translation>Aus der automatischen Sicherung wiederhergestellt: speichern Sie sie, um sie zu behalten.</translation>
    </message>
    <message>
        <source>Could not recover</source>
        <translation>Wiederherstellung nicht möglich</translation>
    </message>
</context>
<context>
    <name>phasebox::StatusPresenter</name>
    <message>
        <source>Step doubling at the current state: the error one step of this method makes now. Raise dt and watch it grow.</source>
        <translation>Schrittverdopplung im aktuellen Zustand: der Fehler, den ein Schritt dieses Verfahrens jetzt macht. Erhöhen Sie dt und sehen Sie ihn wachsen.</translation>
    </message>
    <message>
        <source>Not simulated yet by this version: %1</source>
        <translation>Von dieser Version noch nicht simuliert: %1</translation>
    </message>
    <message>
        <source>local error ≈ %L1 m</source>
        <translation>lokaler Fehler ≈ %L1 m</translation>
    </message>
    <message>
        <source>t = %L1 s</source>
        <translation>t = %L1 s</translation>
    </message>
    <message>
        <source>real-time factor %L1 (speed %L2×)</source>
        <translation>Echtzeitfaktor %L1 (Tempo %L2×)</translation>
    </message>
    <message>
        <source>paused (speed %L1×)</source>
        <translation>angehalten (Tempo %L1×)</translation>
    </message>
    <message>
        <source>%L1 ms per step</source>
        <translation>%L1 ms pro Schritt</translation>
    </message>
    <message>
        <source>%L1 ms per step (live run)</source>
        <translation>%L1 ms pro Schritt (aktueller Lauf)</translation>
    </message>
</context>
<context>
    <name>phasebox::TimelinePresenter</name>
    <message>
        <source>One Frame Back</source>
        <translation>Ein Bild zurück</translation>
    </message>
    <message>
        <source>One Frame Forward</source>
        <translation>Ein Bild vor</translation>
    </message>
    <message>
        <source>Jump to Start</source>
        <translation>Zum Anfang springen</translation>
    </message>
</context>
<context>
    <name>phasebox::WorkerMenu</name>
    <message numerus="yes">
        <source>&amp;Every Core (%n threads)</source>
        <translation>
            <numerusform>&amp;Alle Kerne (%n Thread)</numerusform>
            <numerusform>&amp;Alle Kerne (%n Threads)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n Thread(s)</source>
        <translation>
            <numerusform>%n Thread</numerusform>
            <numerusform>%n Threads</numerusform>
        </translation>
    </message>
    <message>
        <source>The step shares its work among every core.</source>
        <translation>Der Schritt verteilt seine Arbeit auf alle Kerne.</translation>
    </message>
    <message numerus="yes">
        <source>The step runs on %n thread(s).</source>
        <translation>
            <numerusform>Der Schritt läuft auf %n Thread.</numerusform>
            <numerusform>Der Schritt läuft auf %n Threads.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>phasebox::ui::EffectsPanel</name>
    <message>
        <source>Spring forces; runs because the scene holds springs</source>
        <translation>Federkräfte; läuft, weil die Szene Federn enthält</translation>
    </message>
    <message>
        <source>Collision detection and contact impulses; runs because the scene holds things that can touch</source>
        <translation>Kollisionserkennung und Kontaktstöße; läuft, weil die Szene Dinge enthält, die sich berühren können</translation>
    </message>
    <message>
        <source>The integrator&apos;s own arithmetic: the step minus its effects and contacts</source>
        <translation>Die eigene Rechenarbeit des Integrators: der Schritt ohne seine Effekte und Kontakte</translation>
    </message>
    <message>
        <source>Newtonian gravity</source>
        <translation>Newtonsche Gravitation</translation>
    </message>
    <message>
        <source>0 µs/step</source>
        <translation>0 µs/Schritt</translation>
    </message>
    <message>
        <source>%1/step</source>
        <translation>%1/Schritt</translation>
    </message>
    <message>
        <source>Effect</source>
        <translation>Effekt</translation>
    </message>
    <message>
        <source>CPU time</source>
        <translation>CPU-Zeit</translation>
    </message>
    <message>
        <source>CPU time per step, over the last frames</source>
        <translation>CPU-Zeit pro Schritt, über die letzten Bilder</translation>
    </message>
    <message>
        <source>&amp;Add effect</source>
        <translation>Effekt &amp;hinzufügen</translation>
    </message>
    <message>
        <source>Add an effect the scene does not simulate yet</source>
        <translation>Einen Effekt hinzufügen, den die Szene noch nicht simuliert</translation>
    </message>
    <message>
        <source>Time of one whole step: integrator, effects and contacts</source>
        <translation>Zeit eines ganzen Schritts: Integrator, Effekte und Kontakte</translation>
    </message>
    <message>
        <source>total: %1 per step</source>
        <translation>gesamt: %1 pro Schritt</translation>
    </message>
    <message>
        <source>Stage of the step</source>
        <translation>Phase des Schritts</translation>
    </message>
    <message>
        <source>per step</source>
        <translation>pro Schritt</translation>
    </message>
    <message>
        <source>Where a step&apos;s time goes, stage by stage, in the order they run</source>
        <translation>Wohin die Zeit eines Schritts geht, Phase für Phase, in der Reihenfolge ihres Ablaufs</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Gewichtskraft</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>Luftwiderstand</translation>
    </message>
    <message>
        <source>Buoyancy</source>
        <translation>Auftrieb</translation>
    </message>
    <message>
        <source>Wind</source>
        <translation>Wind</translation>
    </message>
    <message>
        <source>Flocking</source>
        <translation>Schwarmverhalten</translation>
    </message>
    <message>
        <source>Particle collisions</source>
        <translation>Teilchenstöße</translation>
    </message>
    <message>
        <source>Coulomb</source>
        <translation>Coulomb</translation>
    </message>
    <message>
        <source>Springs</source>
        <translation>Federn</translation>
    </message>
    <message>
        <source>Contacts</source>
        <translation>Kontakte</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>Integrator</translation>
    </message>
    <message>
        <source>Integrate</source>
        <translation>Integrieren</translation>
    </message>
    <message>
        <source>Collide</source>
        <translation>Kollisionen finden</translation>
    </message>
    <message>
        <source>Solve contacts</source>
        <translation>Kontakte lösen</translation>
    </message>
    <message>
        <source>Solve joints</source>
        <translation>Gelenke lösen</translation>
    </message>
    <message>
        <source>Ledger</source>
        <translation>Energiebilanz</translation>
    </message>
    <message>
        <source>Guard</source>
        <translation>Wächter</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::GraphsView</name>
    <message>
        <source>+ Add graph</source>
        <translation>+ Graph hinzufügen</translation>
    </message>
    <message>
        <source>Another graph below, up to %1</source>
        <translation>Ein weiterer Graph darunter, bis zu %1</translation>
    </message>
    <message>
        <source>Any probe against time or another probe.</source>
        <translation>Jede Messgröße gegen die Zeit oder eine andere Messgröße.</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::InstrumentsPanel</name>
    <message>
        <source>Rea&amp;douts</source>
        <translation>&amp;Anzeigen</translation>
    </message>
    <message>
        <source>&amp;Graphs</source>
        <translation>&amp;Graphen</translation>
    </message>
    <message>
        <source>&amp;Timer</source>
        <translation>&amp;Zeitmesser</translation>
    </message>
    <message>
        <source>Ta&amp;ble</source>
        <translation>Ta&amp;belle</translation>
    </message>
    <message>
        <source>The selected object&apos;s state, live or as set up</source>
        <translation>Der Zustand des ausgewählten Objekts, live oder im Anfangszustand</translation>
    </message>
    <message>
        <source>Any probe against time or against another</source>
        <translation>Jede Messgröße gegen die Zeit oder gegen eine andere</translation>
    </message>
    <message>
        <source>The period of any probe, and a stopwatch</source>
        <translation>Die Periode jeder Messgröße und eine Stoppuhr</translation>
    </message>
    <message>
        <source>The recorded probes, for CSV and spreadsheets</source>
        <translation>Die aufgezeichneten Messgrößen, für CSV und Tabellenkalkulation</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::ParametersPanel</name>
    <message>
        <source>implicit</source>
        <translation>implizit</translation>
    </message>
    <message>
        <source>explicit</source>
        <translation>explizit</translation>
    </message>
    <message>
        <source>symplectic</source>
        <translation>symplektisch</translation>
    </message>
    <message>
        <source>not symplectic</source>
        <translation>nicht symplektisch</translation>
    </message>
    <message>
        <source>order %1 · %2 · %3</source>
        <translation>Ordnung %1 · %2 · %3</translation>
    </message>
    <message>
        <source> · adaptive step</source>
        <translation> · adaptive Schrittweite</translation>
    </message>
    <message>
        <source>%1 (%2)
%3
force evaluations per step: %4
%5</source>
        <translation>%1 (%2)
%3
Kraftauswertungen pro Schritt: %4
%5</translation>
    </message>
    <message>
        <source>1/%1 s  (%2 s)</source>
        <translation>1/%1 s  (%2 s)</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Play or pause (Space)</source>
        <translation>Starten oder anhalten (Leertaste)</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>Advance one step (S or Right)</source>
        <translation>Einen Schritt weiter (S oder Pfeil rechts)</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Back to the scene&apos;s setup (R or Ctrl+R)</source>
        <translation>Zurück zum Anfangszustand der Szene (R oder Strg+R)</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>The frame step: the time one step advances (%1 … %2 s).
The arrows halve or double it; 2e-4 style entry is accepted.</source>
        <translation>Der Zeitschritt: die Zeit, um die ein Schritt vorrückt (%1 … %2 s).
Die Pfeile halbieren oder verdoppeln ihn; Eingaben wie 2e-4 sind erlaubt.</translation>
    </message>
    <message>
        <source>1/n</source>
        <translation>1/n</translation>
    </message>
    <message>
        <source>Common frame steps</source>
        <translation>Übliche Zeitschritte</translation>
    </message>
    <message>
        <source>dt presets</source>
        <translation>dt-Vorgaben</translation>
    </message>
    <message>
        <source>Each step is split into this many equal sub-steps</source>
        <translation>Jeder Schritt wird in so viele gleiche Teilschritte geteilt</translation>
    </message>
    <message>
        <source>Local error tolerance of the adaptive methods (%1);
the arrows move it by a factor of ten</source>
        <translation>Lokale Fehlertoleranz der adaptiven Verfahren (%1);
die Pfeile ändern sie um den Faktor zehn</translation>
    </message>
    <message>
        <source>Newton iterations of implicit Euler per step
(1 = the linearised step of Baraff &amp; Witkin)</source>
        <translation>Newton-Iterationen des impliziten Euler-Verfahrens pro Schritt
(1 = der linearisierte Schritt von Baraff &amp; Witkin)</translation>
    </message>
    <message>
        <source>Impulses after the step, with friction and restitution: stacks rest</source>
        <translation>Kraftstöße nach dem Schritt, mit Reibung und Stoßzahl: Stapel bleiben liegen</translation>
    </message>
    <message>
        <source>A stiff damped spring in each overlap, F = k·d + c·ḋ: a smooth force the integrator sees, with its potential ½·k·d² in the energy</source>
        <translation>Eine steife gedämpfte Feder in jeder Überlappung, F = k·d + c·ḋ: eine glatte Kraft, die der Integrator sieht, mit ihrer potentiellen Energie ½·k·d² in der Energie</translation>
    </message>
    <message>
        <source>Move the bodies apart and reflect the approaching velocity by e; no forces</source>
        <translation>Die Körper auseinanderschieben und die annähernde Geschwindigkeit mit e reflektieren; keine Kräfte</translation>
    </message>
    <message>
        <source> N/m</source>
        <translation> N/m</translation>
    </message>
    <message>
        <source>none yet</source>
        <translation>noch keine</translation>
    </message>
    <message>
        <source>Penalty stiffness k per contact point; the arrows move it by a factor of ten</source>
        <translation>Strafsteifigkeit k pro Kontaktpunkt; die Pfeile ändern sie um den Faktor zehn</translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>Auto</translation>
    </message>
    <message>
        <source>Automatic stiffness: the lightest body gets ω·h = 0.5 at the step</source>
        <translation>Automatische Steifigkeit: der leichteste Körper erhält ω·h = 0,5 beim Schritt</translation>
    </message>
    <message>
        <source> N·s/m</source>
        <translation> N·s/m</translation>
    </message>
    <message>
        <source>Penalty damping c per contact point</source>
        <translation>Strafdämpfung c pro Kontaktpunkt</translation>
    </message>
    <message>
        <source>Simulated seconds per second of wall time (slow motion below 1×)</source>
        <translation>Simulierte Sekunden pro Sekunde Echtzeit (Zeitlupe unter 1×)</translation>
    </message>
    <message>
        <source>&amp;Integrator:</source>
        <translation>&amp;Integrator:</translation>
    </message>
    <message>
        <source>&amp;dt:</source>
        <translation>&amp;dt:</translation>
    </message>
    <message>
        <source>S&amp;ub-steps:</source>
        <translation>T&amp;eilschritte:</translation>
    </message>
    <message>
        <source>&amp;Tolerance:</source>
        <translation>&amp;Toleranz:</translation>
    </message>
    <message>
        <source>&amp;Newton iter.:</source>
        <translation>&amp;Newton-Iter.:</translation>
    </message>
    <message>
        <source>Newton iterations (implicit Euler only)</source>
        <translation>Newton-Iterationen (nur implizites Euler-Verfahren)</translation>
    </message>
    <message>
        <source>&amp;Contacts:</source>
        <translation>&amp;Kontakte:</translation>
    </message>
    <message>
        <source>Sti&amp;ffness:</source>
        <translation>Stei&amp;figkeit:</translation>
    </message>
    <message>
        <source>Dam&amp;ping:</source>
        <translation>Dä&amp;mpfung:</translation>
    </message>
    <message>
        <source>Sp&amp;eed:</source>
        <translation>Tem&amp;po:</translation>
    </message>
    <message>
        <source>dt</source>
        <translation>dt</translation>
    </message>
    <message>
        <source>tolerance</source>
        <translation>Toleranz</translation>
    </message>
    <message>
        <source> or </source>
        <translation> oder </translation>
    </message>
    <message>
        <source>Impulse</source>
        <translation>Kraftstöße</translation>
    </message>
    <message>
        <source>Penalty</source>
        <translation>Penalty-Federn</translation>
    </message>
    <message>
        <source>Kinematic</source>
        <translation>Kinematisch</translation>
    </message>
    <message>
        <source>Let resting &amp;bodies sleep</source>
        <translation>Ruhende Körper &amp;schlafen lassen</translation>
    </message>
    <message>
        <source>Bodies that have stayed at rest for half a second are no longer simulated, and are drawn dimmed, until something touches them, drags them or an edit wakes them: large resting piles cost almost nothing</source>
        <translation>Körper, die eine halbe Sekunde lang in Ruhe waren, werden nicht mehr simuliert und blass gezeichnet, bis etwas sie berührt, sie gezogen werden oder eine Änderung sie weckt: große ruhende Stapel kosten dann fast nichts</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::PlotsPanel</name>
    <message>
        <source>&amp;Pause plots</source>
        <translation>Diagramme &amp;anhalten</translation>
    </message>
    <message>
        <source>Freeze the plots while the simulation goes on</source>
        <translation>Die Diagramme einfrieren, während die Simulation weiterläuft</translation>
    </message>
    <message>
        <source>C&amp;lear</source>
        <translation>&amp;Leeren</translation>
    </message>
    <message>
        <source>Forget the recorded samples; the plots start again from now</source>
        <translation>Die aufgezeichneten Werte vergessen; die Diagramme beginnen ab jetzt neu</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <source>Energy</source>
        <translation>Energie</translation>
    </message>
    <message>
        <source>Phase space</source>
        <translation>Phasenraum</translation>
    </message>
    <message>
        <source>Local error</source>
        <translation>Lokaler Fehler</translation>
    </message>
    <message>
        <source>%1 as %2…</source>
        <translation>%1 als %2…</translation>
    </message>
    <message>
        <source>Click an object on the canvas to plot its phase space.</source>
        <translation>Klicken Sie ein Objekt auf der Zeichenfläche an, um seinen Phasenraum zu zeigen.</translation>
    </message>
    <message>
        <source>The coordinate plotted against its velocity</source>
        <translation>Die Koordinate gegen ihre Geschwindigkeit aufgetragen</translation>
    </message>
    <message>
        <source>x against vx</source>
        <translation>x gegen vx</translation>
    </message>
    <message>
        <source>y against vy</source>
        <translation>y gegen vy</translation>
    </message>
    <message>
        <source>angle against ω (boxes)</source>
        <translation>Winkel gegen ω (Quader)</translation>
    </message>
    <message>
        <source>Local error estimate</source>
        <translation>Lokale Fehlerschätzung</translation>
    </message>
    <message>
        <source>P&amp;hase space</source>
        <translation>P&amp;hasenraum</translation>
    </message>
    <message>
        <source>Local e&amp;rror</source>
        <translation>Lokaler &amp;Fehler</translation>
    </message>
    <message>
        <source>Resume &amp;plots</source>
        <translation>Diagramme &amp;fortsetzen</translation>
    </message>
    <message>
        <source>Energy plot</source>
        <translation>Energiediagramm</translation>
    </message>
    <message>
        <source>Phase space plot</source>
        <translation>Phasenraumdiagramm</translation>
    </message>
    <message>
        <source>Local error plot</source>
        <translation>Diagramm des lokalen Fehlers</translation>
    </message>
    <message>
        <source>At t = %1 s: kinetic %2 J, potential %3 J, total %4 J, work_nc %5 J, drift %6 J</source>
        <translation>Bei t = %1 s: kinetisch %2 J, potentiell %3 J, gesamt %4 J, Arbeit_nk %5 J, Drift %6 J</translation>
    </message>
    <message>
        <source>Latest: %1 = %2, %3 = %4</source>
        <translation>Zuletzt: %1 = %2, %3 = %4</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::ProbeGraphView</name>
    <message>
        <source>probe to plot</source>
        <translation>Messgröße zum Plotten</translation>
    </message>
    <message>
        <source>time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>vs</source>
        <translation>gegen</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <source>Save this graph as a picture or its samples as CSV</source>
        <translation>Diesen Graphen als Bild oder seine Werte als CSV speichern</translation>
    </message>
    <message>
        <source>As %1…</source>
        <translation>Als %1…</translation>
    </message>
    <message>
        <source>Close this graph</source>
        <translation>Diesen Graphen schließen</translation>
    </message>
    <message>
        <source>time [s]</source>
        <translation>Zeit [s]</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::ProbePicker</name>
    <message>
        <source>Pick a probe, or type one (CONTRACT §7: ID.x, system.total, distance(A,B), …) and press Enter</source>
        <translation>Wählen Sie eine Messgröße oder tippen Sie eine ein (CONTRACT §7: ID.x, system.total, distance(A,B), …) und drücken Sie Eingabe</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::ProbeTableView</name>
    <message>
        <source>add a column</source>
        <translation>Spalte hinzufügen</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Remove a column added here</source>
        <translation>Eine hier hinzugefügte Spalte entfernen</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Kopieren</translation>
    </message>
    <message>
        <source>Copy the selected rows (or all) as tab-separated text</source>
        <translation>Die ausgewählten Zeilen (oder alle) als tabulatorgetrennten Text kopieren</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>CSV exportieren…</translation>
    </message>
    <message>
        <source>No probes recorded yet: graph or time one, or add a column above.</source>
        <translation>Noch keine Messgrößen aufgezeichnet: eine plotten oder zeitmessen oder oben eine Spalte hinzufügen.</translation>
    </message>
    <message numerus="yes">
        <source>%n sample(s)</source>
        <translation>
            <numerusform>%n Messwert</numerusform>
            <numerusform>%n Messwerte</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>phasebox::ui::PropertiesPanel</name>
    <message>
        <source>Select an object on the canvas or in the scene list</source>
        <translation>Wählen Sie ein Objekt auf der Zeichenfläche oder in der Szenenliste aus</translation>
    </message>
    <message>
        <source>%1: %2 … %3 %4 (scientific notation such as 1e6 is accepted)</source>
        <translation>%1: %2 … %3 %4 (wissenschaftliche Schreibweise wie 1e6 ist erlaubt)</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::ReadoutView</name>
    <message>
        <source>quantity</source>
        <translation>Größe</translation>
    </message>
    <message>
        <source>value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>Right-click a row to graph it or time its period</source>
        <translation>Rechtsklick auf eine Zeile, um sie zu plotten oder ihre Periode zu messen</translation>
    </message>
    <message>
        <source>Click an object on the canvas to read its state.</source>
        <translation>Klicken Sie ein Objekt auf der Zeichenfläche an, um seinen Zustand abzulesen.</translation>
    </message>
    <message>
        <source>Graph %1 against time</source>
        <translation>%1 gegen die Zeit plotten</translation>
    </message>
    <message>
        <source>Time the period of %1</source>
        <translation>Die Periode von %1 messen</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::SceneBrowser</name>
    <message>
        <source>m %1 kg, r %2 m</source>
        <translation>m %1 kg, r %2 m</translation>
    </message>
    <message>
        <source>, pinned</source>
        <translation>, fixiert</translation>
    </message>
    <message>
        <source>, q %1 C</source>
        <translation>, q %1 C</translation>
    </message>
    <message>
        <source>%1 × %2 m</source>
        <translation>%1 × %2 m</translation>
    </message>
    <message>
        <source>%1, static</source>
        <translation>%1, statisch</translation>
    </message>
    <message>
        <source>%1, m %2 kg</source>
        <translation>%1, m %2 kg</translation>
    </message>
    <message>
        <source>through %1, normal %2</source>
        <translation>durch %1, Normale %2</translation>
    </message>
    <message>
        <source>anchor %1</source>
        <translation>Aufhängepunkt %1</translation>
    </message>
    <message>
        <source>?</source>
        <translation>?</translation>
    </message>
    <message>
        <source>%1 – %2, k %3 N/m</source>
        <translation>%1 – %2, k %3 N/m</translation>
    </message>
    <message>
        <source>, c %1 N·s/m</source>
        <translation>, c %1 N·s/m</translation>
    </message>
    <message>
        <source>the world</source>
        <translation>die Welt</translation>
    </message>
    <message>
        <source>%1 of %2 on a %3</source>
        <translation>%1 von %2 (%3)</translation>
    </message>
    <message>
        <source>circle</source>
        <translation>Kreis</translation>
    </message>
    <message>
        <source>line</source>
        <translation>Gerade</translation>
    </message>
    <message>
        <source>%1: %2 – %3</source>
        <translation>%1: %2 – %3</translation>
    </message>
    <message>
        <source>, %1 m</source>
        <translation>, %1 m</translation>
    </message>
    <message>
        <source>, motor %1 rad/s</source>
        <translation>, Motor %1 rad/s</translation>
    </message>
    <message numerus="yes">
        <source>%n node(s)</source>
        <translation>
            <numerusform>%n Knoten</numerusform>
            <numerusform>%n Knoten</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 × %2 nodes, %3 kg, pinned %4</source>
        <translation>%1 × %2 Knoten, %3 kg, fixiert %4</translation>
    </message>
    <message>
        <source>Filter by id or summary</source>
        <translation>Kennung oder Zusammenfassung</translation>
    </message>
    <message>
        <source>Filter objects</source>
        <translation>Objekte filtern</translation>
    </message>
    <message>
        <source>Id</source>
        <translation>Kennung</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>Zusammenfassung</translation>
    </message>
    <message>
        <source>… and %1 more</source>
        <translation>… und %1 weitere</translation>
    </message>
    <message>
        <source>Particles</source>
        <translation>Teilchen</translation>
    </message>
    <message>
        <source>Boxes</source>
        <translation>Quader</translation>
    </message>
    <message>
        <source>Planes</source>
        <translation>Ebenen</translation>
    </message>
    <message>
        <source>Springs</source>
        <translation>Federn</translation>
    </message>
    <message>
        <source>Cloths</source>
        <translation>Tücher</translation>
    </message>
    <message>
        <source>Joints</source>
        <translation>Gelenke</translation>
    </message>
    <message>
        <source>r %1 m</source>
        <translation>r %1 m</translation>
    </message>
    <message numerus="yes">
        <source>%n vertices</source>
        <translation>
            <numerusform>%n Ecke</numerusform>
            <numerusform>%n Ecken</numerusform>
        </translation>
    </message>
    <message>
        <source>Disks</source>
        <translation>Scheiben</translation>
    </message>
    <message>
        <source>Polygons</source>
        <translation>Polygone</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::ScientificSpinBox</name>
    <message>
        <source>a number is needed</source>
        <translation>eine Zahl wird benötigt</translation>
    </message>
    <message>
        <source>“%1” is not a number</source>
        <translation>„%1“ ist keine Zahl</translation>
    </message>
    <message>
        <source>must be ≥ %1</source>
        <translation>muss ≥ %1 sein</translation>
    </message>
    <message>
        <source>must be ≤ %1</source>
        <translation>muss ≤ %1 sein</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::TimelineBar</name>
    <message>
        <source>Jump to the start (Home)</source>
        <translation>Zum Anfang springen (Pos1)</translation>
    </message>
    <message>
        <source>One frame back (,)</source>
        <translation>Ein Bild zurück (,)</translation>
    </message>
    <message>
        <source>One frame forward (.)</source>
        <translation>Ein Bild vor (.)</translation>
    </message>
    <message>
        <source>Recorded time</source>
        <translation>Aufgezeichnete Zeit</translation>
    </message>
    <message>
        <source>Drag to any recorded moment; Play goes on from there</source>
        <translation>Zu jedem aufgezeichneten Moment ziehen; Start macht von dort weiter</translation>
    </message>
    <message>
        <source>Memory the recording holds, of its budget</source>
        <translation>Speicher der Aufzeichnung, von ihrem Budget</translation>
    </message>
    <message>
        <source>Recording budget</source>
        <translation>Aufzeichnungsbudget</translation>
    </message>
    <message>
        <source>The recording&apos;s memory budget: beyond it older frames are thinned</source>
        <translation>Das Speicherbudget der Aufzeichnung: darüber hinaus werden ältere Bilder ausgedünnt</translation>
    </message>
    <message>
        <source> MB</source>
        <translation> MB</translation>
    </message>
    <message>
        <source>%1 / %2 s</source>
        <translation>%1 / %2 s</translation>
    </message>
    <message>
        <source>%1 MB of</source>
        <translation>%1 MB von</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::TimerView</name>
    <message>
        <source>Period timer</source>
        <translation>Periodenmesser</translation>
    </message>
    <message>
        <source>probe to time, e.g. p0.x</source>
        <translation>Messgröße zum Zeitmessen, z. B. p0.x</translation>
    </message>
    <message>
        <source>Probe:</source>
        <translation>Messgröße:</translation>
    </message>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>crossing t [s]</source>
        <translation>Durchgang t [s]</translation>
    </message>
    <message>
        <source>interval [s]</source>
        <translation>Intervall [s]</translation>
    </message>
    <message>
        <source>Stopwatch (simulated time)</source>
        <translation>Stoppuhr (simulierte Zeit)</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Lap</source>
        <translation>Runde</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>split [s]</source>
        <translation>Zwischenzeit [s]</translation>
    </message>
    <message>
        <source>lap [s]</source>
        <translation>Runde [s]</translation>
    </message>
    <message>
        <source>Pick a probe, then press Play: the period is measured from its upward crossings of the middle of its range.</source>
        <translation>Wählen Sie eine Messgröße und drücken Sie dann Start: die Periode wird aus ihren Aufwärtsdurchgängen durch die Mitte ihres Bereichs gemessen.</translation>
    </message>
    <message>
        <source>T = %1 s</source>
        <translation>T = %1 s</translation>
    </message>
    <message>
        <source>f = %1 Hz
ω = %2 rad/s</source>
        <translation>f = %1 Hz
ω = %2 rad/s</translation>
    </message>
    <message>
        <source>T = —</source>
        <translation>T = —</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
</context>
</TS>
