<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr" sourcelanguage="en">
<context>
    <name>Charts</name>
    <message>
        <source>kinetic</source>
        <translation>cinétique</translation>
    </message>
    <message>
        <source>potential</source>
        <translation>potentielle</translation>
    </message>
    <message>
        <source>total</source>
        <translation>totale</translation>
    </message>
    <message>
        <source>work_nc</source>
        <translation>travail_nc</translation>
    </message>
    <message>
        <source>drift</source>
        <translation>dérive</translation>
    </message>
    <message>
        <source>correction</source>
        <translation>correction</translation>
    </message>
    <message>
        <source>time [s]</source>
        <translation>temps [s]</translation>
    </message>
    <message>
        <source>energy [J]</source>
        <translation>énergie [J]</translation>
    </message>
    <message>
        <source>local error per step</source>
        <translation>erreur locale par pas</translation>
    </message>
    <message>
        <source>error [m]</source>
        <translation>erreur [m]</translation>
    </message>
    <message>
        <source>simulation</source>
        <translation>simulation</translation>
    </message>
    <message>
        <source>start</source>
        <translation>départ</translation>
    </message>
</context>
<context>
    <name>CompareRun</name>
    <message>
        <source>Drag the timeline to an earlier moment first: the run is compared from there.</source>
        <translation>Faites d&apos;abord glisser la frise chronologique vers un moment antérieur : la simulation est comparée à partir de là.</translation>
    </message>
    <message>
        <source>The recording holds no state before this moment.</source>
        <translation>L&apos;enregistrement ne contient aucun état avant ce moment.</translation>
    </message>
    <message>
        <source>The scene cannot be built for the ghost.</source>
        <translation>La scène ne peut pas être construite pour le fantôme.</translation>
    </message>
    <message>
        <source>The recorded frames are of other objects than the scene&apos;s.</source>
        <translation>Les images enregistrées portent sur d&apos;autres objets que ceux de la scène.</translation>
    </message>
    <message>
        <source>Compare from here</source>
        <translation>Comparer à partir d&apos;ici</translation>
    </message>
</context>
<context>
    <name>DivergenceText</name>
    <message>
        <source>a position or speed grew so large that it is no longer a number</source>
        <translation>une position ou une vitesse est devenue si grande qu’elle n’est plus un nombre</translation>
    </message>
    <message>
        <source>its energy grew without bound</source>
        <translation>son énergie a crû sans limite</translation>
    </message>
    <message>
        <source>the adaptive method could not keep its error small enough</source>
        <translation>la méthode adaptative n’a pas pu garder son erreur assez petite</translation>
    </message>
    <message>
        <source>cloth &apos;%1&apos;, the node in row %2 from the top, column %3 from the left</source>
        <translation>tissu « %1 », le nœud de la ligne %2 depuis le haut, colonne %3 depuis la gauche</translation>
    </message>
    <message>
        <source>particle &apos;%1&apos;</source>
        <translation>particule « %1 »</translation>
    </message>
    <message>
        <source>disk &apos;%1&apos;</source>
        <translation>disque « %1 »</translation>
    </message>
    <message>
        <source>polygon &apos;%1&apos;</source>
        <translation>polygone « %1 »</translation>
    </message>
    <message>
        <source>box &apos;%1&apos;</source>
        <translation>boîte « %1 »</translation>
    </message>
    <message>
        <source>The simulation became unstable. Try a smaller time step, more sub-steps or Implicit Euler.</source>
        <translation>La simulation est devenue instable. Essayez un pas de temps plus petit, plus de sous-pas ou Euler implicite.</translation>
    </message>
    <message>
        <source>The simulation became unstable at t = %1: %2. It was paused and put back to t = %3.</source>
        <translation>La simulation est devenue instable à t = %1 : %2. Elle a été mise en pause et ramenée à t = %3.</translation>
    </message>
    <message>
        <source>It started at %1.</source>
        <translation>Cela a commencé à %1.</translation>
    </message>
    <message>
        <source>a smaller time step: dt below %1</source>
        <translation>un pas de temps plus petit : dt sous %1</translation>
    </message>
    <message>
        <source>%1 sub-steps per step (same dt, each step cut into %1 pieces)</source>
        <translation>%1 sous-pas par pas (même dt, chaque pas coupé en %1 morceaux)</translation>
    </message>
    <message>
        <source>a smaller time step (half of dt = %1)</source>
        <translation>un pas de temps plus petit (la moitié de dt = %1)</translation>
    </message>
    <message>
        <source>%1 sub-steps per step</source>
        <translation>%1 sous-pas par pas</translation>
    </message>
    <message>
        <source>%1, which stays stable at any time step (it damps fast motion)</source>
        <translation>%1, qui reste stable à tout pas de temps (il amortit les mouvements rapides)</translation>
    </message>
    <message>
        <source>start the chain from joint &apos;%1&apos; to joint &apos;%2&apos; with some sag: it is pulled straight between two fixed points, where it cannot sag without stretching, and the forces that keep it straight grow without bound as it moves</source>
        <translation>commencer la chaîne de l’articulation « %1 » à l’articulation « %2 » avec un peu de flèche : elle est tendue en ligne droite entre deux points fixes, où elle ne peut fléchir sans s’allonger, et les forces qui la maintiennent droite croissent sans limite dès qu’elle bouge</translation>
    </message>
    <message>
        <source>or free one end of that chain</source>
        <translation>ou libérer une extrémité de cette chaîne</translation>
    </message>
    <message>
        <source>softer springs or cloth (a lower stiffness)</source>
        <translation>des ressorts ou des tissus plus souples (une raideur plus faible)</translation>
    </message>
    <message>
        <source>impulse contacts instead of penalty contacts</source>
        <translation>des contacts par impulsions au lieu de contacts par pénalité</translation>
    </message>
    <message>
        <source>What to try:</source>
        <translation>Que tenter :</translation>
    </message>
    <message>
        <source>Stability advisor: %1</source>
        <translation>Conseiller de stabilité : %1</translation>
    </message>
</context>
<context>
    <name>Integrators</name>
    <message>
        <source>Explicit Euler</source>
        <extracomment>integrator: explicit_euler</extracomment>
        <translation>Euler explicite</translation>
    </message>
    <message>
        <source>1</source>
        <extracomment>integrator: explicit_euler evaluations</extracomment>
        <translation>1</translation>
    </message>
    <message>
        <source>Forward Euler on (x, v): first order, gains energy on every oscillation.</source>
        <extracomment>integrator: explicit_euler summary</extracomment>
        <translation>Euler progressif sur (x, v) : premier ordre, gagne de l’énergie à chaque oscillation.</translation>
    </message>
    <message>
        <source>Symplectic Euler</source>
        <extracomment>integrator: symplectic_euler</extracomment>
        <translation>Euler symplect.</translation>
    </message>
    <message>
        <source>Semi-implicit Euler: velocity first, then position with the new velocity; bounded energy.</source>
        <extracomment>integrator: symplectic_euler summary</extracomment>
        <translation>Euler semi-implicite : d’abord la vitesse, puis la position avec la nouvelle vitesse ; énergie bornée.</translation>
    </message>
    <message>
        <source>Midpoint (RK2)</source>
        <extracomment>integrator: midpoint</extracomment>
        <translation>P. milieu (RK2)</translation>
    </message>
    <message>
        <source>2</source>
        <extracomment>integrator: midpoint evaluations</extracomment>
        <translation>2</translation>
    </message>
    <message>
        <source>Explicit midpoint: a half step to estimate the slope, then a full step with it.</source>
        <extracomment>integrator: midpoint summary</extracomment>
        <translation>Point milieu explicite : un demi-pas pour estimer la pente, puis un pas entier avec elle.</translation>
    </message>
    <message>
        <source>Heun (explicit trapezoid)</source>
        <extracomment>integrator: heun</extracomment>
        <translation>Heun (trapèze expl.)</translation>
    </message>
    <message>
        <source>Average of the slopes at the start and at an Euler-predicted end point.</source>
        <extracomment>integrator: heun summary</extracomment>
        <translation>Moyenne des pentes au début et en un point final prédit par Euler.</translation>
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
        <translation>Runge-Kutta classique d’ordre quatre : quatre pentes pondérées 1/6, 1/3, 1/3, 1/6.</translation>
    </message>
    <message>
        <source>Velocity Verlet</source>
        <extracomment>integrator: velocity_verlet</extracomment>
        <translation>Verlet vitesse</translation>
    </message>
    <message>
        <source>Position from the current acceleration, velocity from the average of old and new ones.</source>
        <extracomment>integrator: velocity_verlet summary</extracomment>
        <translation>Position à partir de l’accélération actuelle, vitesse à partir de la moyenne de l’ancienne et de la nouvelle.</translation>
    </message>
    <message>
        <source>Implicit Euler</source>
        <extracomment>integrator: implicit_euler</extracomment>
        <translation>Euler implicite</translation>
    </message>
    <message>
        <source>1 + Jacobian per Newton iteration</source>
        <extracomment>integrator: implicit_euler evaluations</extracomment>
        <translation>1 + jacobienne par itération de Newton</translation>
    </message>
    <message>
        <source>Backward Euler, Newton-linearised (Baraff &amp; Witkin): unconditionally stable, dissipative.</source>
        <extracomment>integrator: implicit_euler summary</extracomment>
        <translation>Euler rétrograde, linéarisé par Newton (Baraff &amp; Witkin) : inconditionnellement stable, dissipatif.</translation>
    </message>
    <message>
        <source>Implicit midpoint</source>
        <extracomment>integrator: implicit_midpoint</extracomment>
        <translation>P. milieu implicite</translation>
    </message>
    <message>
        <source>1 + Jacobian per Newton iteration (to convergence)</source>
        <extracomment>integrator: implicit_midpoint evaluations</extracomment>
        <translation>1 + jacobienne par itération de Newton (jusqu’à convergence)</translation>
    </message>
    <message>
        <source>Implicit midpoint rule: symplectic, second order, conserves a linear spring&apos;s energy.</source>
        <extracomment>integrator: implicit_midpoint summary</extracomment>
        <translation>Règle du point milieu implicite : symplectique, d’ordre deux, conserve l’énergie d’un ressort linéaire.</translation>
    </message>
    <message>
        <source>Adaptive Euler (step doubling)</source>
        <extracomment>integrator: adaptive_euler</extracomment>
        <translation>Euler adaptatif (doublement)</translation>
    </message>
    <message>
        <source>2 per attempt</source>
        <extracomment>integrator: adaptive_euler evaluations</extracomment>
        <translation>2 par essai</translation>
    </message>
    <message>
        <source>Explicit Euler whose step size follows the error of one step against two half steps.</source>
        <extracomment>integrator: adaptive_euler summary</extracomment>
        <translation>Euler explicite dont le pas suit l’erreur d’un pas comparé à deux demi-pas.</translation>
    </message>
    <message>
        <source>Dormand–Prince 5(4)</source>
        <extracomment>integrator: rk45</extracomment>
        <translation>Dormand-Prince 5(4)</translation>
    </message>
    <message>
        <source>6 per attempt (+1 per call)</source>
        <extracomment>integrator: rk45 evaluations</extracomment>
        <translation>6 par essai (+1 par appel)</translation>
    </message>
    <message>
        <source>Embedded Runge–Kutta pair with error control; the reference for the accuracy lab.</source>
        <extracomment>integrator: rk45 summary</extracomment>
        <translation>Paire de Runge-Kutta emboîtée avec contrôle d’erreur ; la référence du labo de précision.</translation>
    </message>
</context>
<context>
    <name>MeasureOverlay</name>
    <message>
        <source>gravity</source>
        <translation>poids</translation>
    </message>
    <message>
        <source>drag</source>
        <translation>frottement de l’air</translation>
    </message>
    <message>
        <source>newtonian gravity</source>
        <translation>gravitation newtonienne</translation>
    </message>
    <message>
        <source>buoyancy</source>
        <translation>poussée d’Archimède</translation>
    </message>
    <message>
        <source>wind</source>
        <translation>vent</translation>
    </message>
    <message>
        <source>flocking</source>
        <translation>nuée</translation>
    </message>
    <message>
        <source>coulomb</source>
        <translation>Coulomb</translation>
    </message>
    <message>
        <source>penalty contacts</source>
        <translation>contacts par pénalité</translation>
    </message>
    <message>
        <source>spring %1</source>
        <translation>ressort %1</translation>
    </message>
    <message>
        <source>contact</source>
        <translation>contact</translation>
    </message>
    <message>
        <source>joint %1</source>
        <translation>liaison %1</translation>
    </message>
    <message>
        <source>Free body: %1, m = %2 kg</source>
        <translation>Corps isolé : %1, m = %2 kg</translation>
    </message>
    <message>
        <source>forces: 1 px = %1 N, net %2 N</source>
        <translation>forces : 1 px = %1 N, résultante %2 N</translation>
    </message>
    <message>
        <source>momentum 0</source>
        <translation>quantité de mouvement 0</translation>
    </message>
    <message>
        <source>momentum: 1 px = %1 kg·m/s</source>
        <translation>quantité de mouvement : 1 px = %1 kg·m/s</translation>
    </message>
    <message>
        <source>Free body: select a moving body</source>
        <translation>Corps isolé : sélectionnez un corps en mouvement</translation>
    </message>
    <message>
        <source>system: p = (%1, %2) kg·m/s, CM ◑</source>
        <translation>système : p = (%1, %2) kg·m/s, CM ◑</translation>
    </message>
</context>
<context>
    <name>ObjectKind</name>
    <message>
        <source>particle</source>
        <extracomment>kind: particle</extracomment>
        <translation>particule</translation>
    </message>
    <message>
        <source>box</source>
        <extracomment>kind: box</extracomment>
        <translation>boîte</translation>
    </message>
    <message>
        <source>disk</source>
        <extracomment>kind: disk</extracomment>
        <translation>disque</translation>
    </message>
    <message>
        <source>polygon</source>
        <extracomment>kind: polygon</extracomment>
        <translation>polygone</translation>
    </message>
    <message>
        <source>plane</source>
        <extracomment>kind: plane</extracomment>
        <translation>plan</translation>
    </message>
    <message>
        <source>spring</source>
        <extracomment>kind: spring</extracomment>
        <translation>ressort</translation>
    </message>
    <message>
        <source>cloth</source>
        <extracomment>kind: cloth</extracomment>
        <translation>tissu</translation>
    </message>
    <message>
        <source>joint</source>
        <extracomment>kind: joint</extracomment>
        <translation>liaison</translation>
    </message>
    <message>
        <source>object</source>
        <extracomment>kind: object</extracomment>
        <translation>objet</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>diverged</source>
        <translation>divergé</translation>
    </message>
    <message>
        <source>Phasebox User Guide</source>
        <translation>Guide d’utilisation de Phasebox</translation>
    </message>
    <message>
        <source>User guide</source>
        <translation>Guide d’utilisation</translation>
    </message>
    <message>
        <source>The user guide is missing from this build.</source>
        <translation>Le guide d’utilisation manque dans cette version.</translation>
    </message>
    <message>
        <source>Keyboard Shortcuts</source>
        <translation>Raccourcis clavier</translation>
    </message>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>Raccourcis clavier</translation>
    </message>
    <message>
        <source>action</source>
        <translation>action</translation>
    </message>
    <message>
        <source>keys</source>
        <translation>touches</translation>
    </message>
    <message>
        <source>Every menu command that has a key, as this window has them now.</source>
        <translation>Chaque commande de menu qui a une touche, telle que cette fenêtre les a maintenant.</translation>
    </message>
    <message>
        <source>Phasebox scenes (*.phasebox.json *.json);;All files (*)</source>
        <translation>Scènes Phasebox (*.phasebox.json *.json);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Add %1 %2</source>
        <translation>Ajouter %1 %2</translation>
    </message>
    <message numerus="yes">
        <source>Paste %n objects</source>
        <translation>
            <numerusform>Coller %n objet</numerusform>
            <numerusform>Coller %n objets</numerusform>
        </translation>
    </message>
    <message>
        <source>nothing to add</source>
        <translation>rien à ajouter</translation>
    </message>
    <message>
        <source>nothing to delete: no object has the id %1</source>
        <translation>rien à supprimer : aucun objet n’a l’identifiant %1</translation>
    </message>
    <message>
        <source>Delete %1</source>
        <translation>Supprimer %1</translation>
    </message>
    <message numerus="yes">
        <source>Delete %n objects</source>
        <translation>
            <numerusform>Supprimer %n objet</numerusform>
            <numerusform>Supprimer %n objets</numerusform>
        </translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>Déplacer %1</translation>
    </message>
    <message>
        <source>unknown object id %1</source>
        <translation>identifiant d’objet inconnu %1</translation>
    </message>
    <message>
        <source>the position of %1 must be finite</source>
        <translation>la position de %1 doit être finie</translation>
    </message>
    <message>
        <source>the position of %1 must lie within ±%2 m</source>
        <translation>la position de %1 doit rester dans ±%2 m</translation>
    </message>
    <message>
        <source>%1 %2 has no property &quot;%3&quot;</source>
        <translation>%1 %2 n’a pas de propriété « %3 »</translation>
    </message>
    <message>
        <source>Set %1 of %2</source>
        <translation>Modifier %1 de %2</translation>
    </message>
    <message>
        <source>Pin %1</source>
        <translation>Fixer %1</translation>
    </message>
    <message>
        <source>Unpin %1</source>
        <translation>Libérer %1</translation>
    </message>
    <message>
        <source>Make %1 static</source>
        <translation>Rendre %1 immobile</translation>
    </message>
    <message>
        <source>Make %1 dynamic</source>
        <translation>Rendre %1 mobile</translation>
    </message>
    <message>
        <source>only particles and rigid bodies can be pinned</source>
        <translation>seules les particules et les solides peuvent être fixés</translation>
    </message>
    <message>
        <source>Change simulation settings</source>
        <translation>Modifier les réglages de la simulation</translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation>Modifier %1</translation>
    </message>
    <message>
        <source>the CSV file</source>
        <translation>le fichier CSV</translation>
    </message>
    <message>
        <source>position error [m], lower is better</source>
        <translation>erreur de position [m], plus bas est mieux</translation>
    </message>
    <message>
        <source>CPU time [s], left is faster</source>
        <translation>temps CPU [s], plus à gauche est plus rapide</translation>
    </message>
    <message>
        <source>%1 %2 hangs between two bodies; move them instead</source>
        <translation>%1 %2 est tendu entre deux corps ; déplacez plutôt les corps</translation>
    </message>
    <message>
        <source>%1 %2 moves with its bodies; move them instead</source>
        <translation>%1 %2 se déplace avec ses corps ; déplacez plutôt les corps</translation>
    </message>
</context>
<context>
    <name>RewindCommand</name>
    <message>
        <source>Play from t = %1 s</source>
        <translation>Lecture depuis t = %1 s</translation>
    </message>
</context>
<context>
    <name>SceneTexts</name>
    <message>
        <source>Bouncing balls: restitution</source>
        <extracomment>scenes/bouncing-balls.phasebox.json: name</extracomment>
        <translation>Balles rebondissantes : restitution</translation>
    </message>
    <message>
        <source>Four balls fall from 2 m onto a hard floor. The coefficient of restitution e is the ratio of the speeds after and before the bounce, so each ball climbs back to e²·h: 2 m, 1.28 m, 0.5 m and 0.08 m for e = 1, 0.8, 0.5 and 0.2. Watch the kinetic and potential energy trade places, and each bounce of the lossy balls move energy into work_nc.</source>
        <extracomment>scenes/bouncing-balls.phasebox.json: description</extracomment>
        <translation>Quatre balles tombent de 2 m sur un sol dur. Le coefficient de restitution e est le rapport des vitesses après et avant le rebond, donc chaque balle remonte à e²·h : 2 m, 1,28 m, 0,5 m et 0,08 m pour e = 1, 0,8, 0,5 et 0,2. Regardez l’énergie cinétique et l’énergie potentielle échanger leurs places, et chaque rebond des balles qui perdent de l’énergie la faire passer dans work_nc.</translation>
    </message>
    <message>
        <source>Box on an incline: stick or slide</source>
        <extracomment>scenes/box-incline.phasebox.json: name</extracomment>
        <translation>Boîte sur un plan incliné : adhérer ou glisser</translation>
    </message>
    <message>
        <source>Two boxes sit on two ramps, both at θ = 30° (tan θ = 0.58). On the left the friction coefficient is μ = 0.7 &gt; tan θ, so static friction holds the box still; on the right μ = 0.4 &lt; tan θ, so the box slides down with a = g(sin θ − μ cos θ) = 1.5 m/s². The rule: a box sticks when tan θ ≤ μ. Change the friction of a box and of its ramp to find the tipping point (their contact takes √(μ₁·μ₂) of the two).</source>
        <extracomment>scenes/box-incline.phasebox.json: description</extracomment>
        <translation>Deux boîtes sont posées sur deux rampes, toutes deux à θ = 30° (tan θ = 0,58). À gauche le coefficient de frottement est μ = 0,7 &gt; tan θ, donc le frottement statique retient la boîte ; à droite μ = 0,4 &lt; tan θ, donc la boîte glisse avec a = g(sin θ − μ cos θ) = 1,5 m/s². La règle : une boîte adhère quand tan θ ≤ μ. Changez le frottement d’une boîte et de sa rampe pour trouver le point de bascule (leur contact prend √(μ₁·μ₂) des deux).</translation>
    </message>
    <message>
        <source>Pyramid of boxes</source>
        <extracomment>scenes/box-pyramid.phasebox.json: name</extracomment>
        <translation>Pyramide de boîtes</translation>
    </message>
    <message>
        <source>Fifty-five 1 m boxes stacked in 10 rows on the ground, friction 0.6. A good contact solver keeps the pyramid standing still, with no creeping or jitter. It runs velocity Verlet, which is exact under constant gravity, so the drift stays at zero; switch to symplectic Euler and the drift stays flat too once the stack has settled in its first second (about −0.15 J): the contacts&apos; forces act inside the method&apos;s step, so a box at rest leaves the method nothing to get wrong. The contact solver takes the inner sub-steps a stack needs by itself: the scene runs at the format&apos;s defaults, one step per frame.</source>
        <extracomment>scenes/box-pyramid.phasebox.json: description</extracomment>
        <translation>Cinquante-cinq boîtes de 1 m empilées en 10 rangées sur le sol, frottement 0,6. Un bon solveur de contacts garde la pyramide immobile, sans glissement lent ni tremblement. Elle tourne avec Verlet vitesse, exact sous une pesanteur constante, donc la dérive reste à zéro ; passez à Euler symplectique : la dérive reste plate elle aussi une fois la pile tassée, dans sa première seconde (environ −0,15 J) : les forces des contacts agissent dans le pas de la méthode, donc une boîte au repos ne laisse à la méthode rien sur quoi se tromper. Le solveur de contacts choisit seul les sous-pas internes dont une pile a besoin : la scène tourne avec les valeurs par défaut du format, un pas par image.</translation>
    </message>
    <message>
        <source>Motor car climbing a ramp</source>
        <extracomment>scenes/car.phasebox.json: name</extracomment>
        <translation>Voiture à moteur montant une rampe</translation>
    </message>
    <message>
        <source>A toy car climbs a ramp: a 4 kg box body rides on two rigid disk wheels (radius 0.3 m, 2 kg, friction 1) hinged at their axles, and each axle has a motor that turns its wheel at −3 rad/s relative to the body with at most 40 N·m. The joint angle is the wheel&apos;s angle minus the body&apos;s, so a negative speed turns the wheels clockwise and drives the car towards +x at about 0.9 m/s. It rolls along the ground, climbs the 15° ramp and drives on along the 1 m high plateau. The motors&apos; work ends up as the car&apos;s potential energy (78 J by the plateau) and its motion: the energy plot books it in work_nc (82 J in 10 s, the motors&apos; push less what friction takes) while correction stays near zero, because the motors push inside the method&apos;s step, as the contacts do; the hinges hold the wheels to well under a millimetre.</source>
        <extracomment>scenes/car.phasebox.json: description</extracomment>
        <translation>Une voiture jouet monte une rampe : une boîte de 4 kg comme carrosserie roule sur deux roues-disques rigides (rayon 0,3 m, 2 kg, frottement 1) articulées à leurs essieux, et chaque essieu a un moteur qui fait tourner sa roue à −3 rad/s par rapport à la carrosserie avec au plus 40 N·m. L’angle de la liaison est l’angle de la roue moins celui de la carrosserie, donc une vitesse négative fait tourner les roues dans le sens horaire et pousse la voiture vers +x à environ 0,9 m/s. Elle roule sur le sol, monte la rampe de 15° et continue sur le plateau de 1 m de haut. Le travail des moteurs finit en énergie potentielle de la voiture (78 J sur le plateau) et en mouvement : le graphique d’énergie le compte dans work_nc (82 J en 10 s, la poussée des moteurs moins ce que prend le frottement) tandis que la correction reste proche de zéro, car les moteurs poussent à l’intérieur du pas de la méthode, comme les contacts ; les charnières tiennent les roues à bien moins d’un millimètre près.</translation>
    </message>
    <message>
        <source>Chain bridge</source>
        <extracomment>scenes/chain-bridge.phasebox.json: name</extracomment>
        <translation>Pont de chaîne</translation>
    </message>
    <message>
        <source>A bridge of ten wooden planks, 0.6 m by 0.12 m and 2 kg each, hinged end to end and hinged to the world at both ends, hangs between two pillars, and a 4 kg crate falls onto it from 2 m. Frictionless hinges pass forces but no turning moments, so the bridge hangs like a chain: the horizontal pull is the same all along it and each plank is steeper than its inner neighbour by the same step in slope, a discrete catenary, which is the shape it starts in. Watch the crate land, the bridge bounce and sway and the dip settle under the crate; drag the crate along the bridge, or drop more boxes on it. The hinges hold the planks together to well under a millimetre.</source>
        <extracomment>scenes/chain-bridge.phasebox.json: description</extracomment>
        <translation>Un pont de dix planches de bois, de 0,6 m sur 0,12 m et 2 kg chacune, articulées bout à bout et au monde aux deux extrémités, pend entre deux piliers, et une caisse de 4 kg tombe dessus de 2 m. Des charnières sans frottement transmettent des forces mais aucun moment, donc le pont pend comme une chaîne : la traction horizontale est la même sur toute sa longueur et chaque planche est plus pentue que sa voisine intérieure d’un même pas de pente, une chaînette discrète, qui est la forme dans laquelle il démarre. Regardez la caisse atterrir, le pont rebondir et se balancer, puis le creux se stabiliser sous la caisse ; faites glisser la caisse le long du pont, ou lâchez d’autres boîtes dessus. Les charnières tiennent les planches ensemble à bien moins d’un millimètre près.</translation>
    </message>
    <message>
        <source>Flag in the wind</source>
        <extracomment>scenes/cloth-flag.phasebox.json: name</extracomment>
        <translation>Drapeau au vent</translation>
    </message>
    <message>
        <source>A 2 m × 1.2 m cloth of 20 × 12 nodes (0.5 kg) is held along its left edge by a pole and released level. Each node feels its weight m·g and the wind&apos;s drag b·(w − v), so the flag swings down and settles where they balance, at tan α = m·g/(b·w) = 0.51, α = 27° below level. The cloth springs are stiff, so it runs implicit Euler at the frame step: switch to symplectic Euler and watch it blow up and be stopped as diverging.</source>
        <extracomment>scenes/cloth-flag.phasebox.json: description</extracomment>
        <translation>Un tissu de 2 m × 1,2 m de 20 × 12 nœuds (0,5 kg) est tenu par son bord gauche à un mât et lâché à l’horizontale. Chaque nœud subit son poids m·g et la traînée du vent b·(w − v), donc le drapeau retombe et se stabilise là où elles s’équilibrent, à tan α = m·g/(b·w) = 0,51, α = 27° sous l’horizontale. Les ressorts du tissu sont raides, donc il tourne avec Euler implicite au pas de l’image : passez à Euler symplectique et regardez-le exploser et être arrêté pour divergence.</translation>
    </message>
    <message>
        <source>Damped oscillators</source>
        <extracomment>scenes/damped-oscillators.phasebox.json: name</extracomment>
        <translation>Oscillateurs amortis</translation>
    </message>
    <message>
        <source>Three 1 kg balls hang on springs of k = 20 N/m and rest length 1 m, with damping c = 1, 8.944 and 25 N·s/m: under-damped, critically damped and over-damped (ζ = c/(2·√(k·m)) = 0.11, 1 and 2.8). Each is released at the spring&apos;s rest length and falls toward its equilibrium m·g/k = 0.49 m lower. What to watch: the under-damped ball overshoots and rings down with the envelope e^(−ζωt) at ω = √(k/m) = 4.47 rad/s; the critically damped one gets there fastest without overshooting; the over-damped one creeps in slowly, held back by its own damper. View → Exact Solution draws the closed form of each (dashed), and the energy plot shows work_nc taking the energy the dampers turn into heat.</source>
        <extracomment>scenes/damped-oscillators.phasebox.json: description</extracomment>
        <translation>Trois balles de 1 kg pendent à des ressorts de k = 20 N/m et de longueur à vide 1 m, avec un amortissement c = 1, 8,944 et 25 N·s/m : pseudo-périodique, critique et apériodique (ζ = c/(2·√(k·m)) = 0,11, 1 et 2,8). Chacune est lâchée à la longueur à vide de son ressort et tombe vers son équilibre m·g/k = 0,49 m plus bas. Ce qu’il faut regarder : la balle pseudo-périodique dépasse et oscille de moins en moins avec l’enveloppe e^(−ζωt) pour ω = √(k/m) = 4,47 rad/s ; la critique arrive le plus vite sans dépasser ; l’apériodique approche lentement, freinée par son propre amortisseur. Affichage → Solution exacte dessine la forme fermée de chacune (en tirets), et le graphique d’énergie montre work_nc recueillir l’énergie que les amortisseurs changent en chaleur.</translation>
    </message>
    <message>
        <source>Springs, a pendulum and a swinging box</source>
        <extracomment>scenes/demo.phasebox.json: name</extracomment>
        <translation>Ressorts, un pendule et une boîte qui se balance</translation>
    </message>
    <message>
        <source>A ball on a spring, a two-ball spring pendulum and a box hung from one corner. Switch the integrator while it runs and watch the drift line in the energy plot: explicit Euler gains energy so fast that the run is stopped as diverging within a second and a half; symplectic Euler and Verlet keep the drift small, swinging about zero; implicit Euler steadily loses energy. The total falls a little under every method because the box&apos;s spring has a damper: that loss is work_nc, not drift.</source>
        <extracomment>scenes/demo.phasebox.json: description</extracomment>
        <translation>Une balle sur un ressort, un pendule à ressort à deux balles et une boîte suspendue par un coin. Changez d’intégrateur pendant le calcul et regardez la ligne de dérive du graphique d’énergie : Euler explicite gagne de l’énergie si vite que le calcul est arrêté pour divergence en moins d’une seconde et demie ; Euler symplectique et Verlet gardent la dérive petite, oscillant autour de zéro ; Euler implicite perd de l’énergie régulièrement. Le total baisse un peu avec toutes les méthodes parce que le ressort de la boîte a un amortisseur : cette perte est du work_nc, pas de la dérive.</translation>
    </message>
    <message>
        <source>Dominoes</source>
        <extracomment>scenes/dominoes.phasebox.json: name</extracomment>
        <translation>Dominos</translation>
    </message>
    <message>
        <source>Twenty dominoes (0.1 m × 1 m) stand 0.5 m apart and the first is given a push. Each one tips the next, and the wave of falling dominoes runs down the row at a steady speed. Watch the potential energy fall steadily while the wave passes (several dominoes are falling at any moment), and the contacts&apos; work_nc take it away: about 7 J in all.</source>
        <extracomment>scenes/dominoes.phasebox.json: description</extracomment>
        <translation>Vingt dominos (0,1 m × 1 m) sont debout à 0,5 m l’un de l’autre et le premier reçoit une poussée. Chacun fait tomber le suivant, et la vague de dominos qui tombent parcourt la rangée à vitesse constante. Regardez l’énergie potentielle baisser régulièrement pendant le passage de la vague (plusieurs dominos tombent à tout moment), et le work_nc des contacts l’emporter : environ 7 J en tout.</translation>
    </message>
    <message>
        <source>Elastic gas</source>
        <extracomment>scenes/elastic-gas.phasebox.json: name</extracomment>
        <translation>Gaz élastique</translation>
    </message>
    <message>
        <source>212 disks bounce in a closed 6 m box with restitution 1, no friction and no gravity; all start at nearly the same speed (1.3 to 1.7 m/s) in random directions. Collisions share the energy out into a spread of speeds (the Maxwell–Boltzmann distribution) while the total kinetic energy stays constant: watch the flat line in the energy plot. The big heavy disk in the middle jiggles under the random kicks: Brownian motion.</source>
        <extracomment>scenes/elastic-gas.phasebox.json: description</extracomment>
        <translation>212 disques rebondissent dans une boîte fermée de 6 m avec une restitution de 1, sans frottement ni pesanteur ; tous partent presque à la même vitesse (1,3 à 1,7 m/s) dans des directions aléatoires. Les chocs répartissent l’énergie en un éventail de vitesses (la distribution de Maxwell-Boltzmann) tandis que l’énergie cinétique totale reste constante : regardez la ligne plate du graphique d’énergie. Le gros disque lourd au milieu s’agite sous les coups aléatoires : le mouvement brownien.</translation>
    </message>
    <message>
        <source>Galton board</source>
        <extracomment>scenes/galton-board.phasebox.json: name</extracomment>
        <translation>Planche de Galton</translation>
    </message>
    <message>
        <source>A Galton board: sixty balls fall in a column onto nine staggered rows of pegs and pile up in the bins below. At each row a ball goes left or right about equally often, so where it lands counts its rights against its lefts: for many balls and rows the piles would approach the binomial distribution, which looks like the bell curve. These sixty make a rough mound under the drop, wider than the binomial, because the balls bounce and knock each other across more than one peg at a time. The pegs are static rigid disks; the balls are particles that collide with each other (particle_collisions) and with the pegs, walls and floor. The pegs and the bin walls are frictionless: a ball is a particle, which slides rather than rolls, and friction would hold one that lands near a peg&apos;s top there for good, while in a real board it rolls off.</source>
        <extracomment>scenes/galton-board.phasebox.json: description</extracomment>
        <translation>Une planche de Galton : soixante billes tombent en colonne sur neuf rangées de clous en quinconce et s’empilent dans les cases du bas. À chaque rangée une bille va à gauche ou à droite à peu près aussi souvent, donc là où elle atterrit compte ses droites contre ses gauches : avec beaucoup de billes et de rangées les piles approcheraient la loi binomiale, qui ressemble à la courbe en cloche. Ces soixante forment un tas irrégulier sous le point de lâcher, plus large que la loi binomiale, parce que les billes rebondissent et se poussent les unes les autres par-dessus plus d’un clou à la fois. Les clous sont des disques rigides immobiles ; les billes sont des particules qui se heurtent entre elles (particle_collisions) et heurtent les clous, les parois et le sol. Les clous et les parois des cases sont sans frottement : une bille est une particule, qui glisse au lieu de rouler, et le frottement retiendrait pour toujours une bille tombée près du sommet d’un clou, alors que sur une vraie planche elle roule et tombe.</translation>
    </message>
    <message>
        <source>Newton&apos;s cradle</source>
        <extracomment>scenes/newtons-cradle.phasebox.json: name</extracomment>
        <translation>Pendule de Newton</translation>
    </message>
    <message>
        <source>Five steel balls hang on stiff strings, touching; the left ball is pulled out and let go. With restitution 1 the collision passes momentum and energy down the row, so the last ball flies out at the speed the first came in, and the middle balls hardly move. Count the balls that swing out, and watch the kinetic and potential energy trade places.</source>
        <extracomment>scenes/newtons-cradle.phasebox.json: description</extracomment>
        <translation>Cinq billes d’acier pendent à des fils raides et se touchent ; la bille de gauche est écartée puis lâchée. Avec une restitution de 1, le choc transmet la quantité de mouvement et l’énergie le long de la rangée, donc la dernière bille part à la vitesse à laquelle la première est arrivée, et les billes du milieu bougent à peine. Comptez les billes qui partent, et regardez l’énergie cinétique et l’énergie potentielle échanger leurs places.</translation>
    </message>
    <message>
        <source>Orbit around a star</source>
        <extracomment>scenes/orbit.phasebox.json: name</extracomment>
        <translation>Orbite autour d’une étoile</translation>
    </message>
    <message>
        <source>A ship on a circular orbit (r = 4 m, v = √(GM/r) = 5 m/s, one lap in 5.0 s) and a comet on an ellipse go round a star of GM = 100 (G = 1, so the numbers stay classroom-sized). RK4 keeps both orbits closed and the energy flat. Switch to explicit Euler and watch the orbits spiral outwards as the total energy climbs; symplectic Euler keeps them closed.</source>
        <extracomment>scenes/orbit.phasebox.json: description</extracomment>
        <translation>Un vaisseau sur une orbite circulaire (r = 4 m, v = √(GM/r) = 5 m/s, un tour en 5,0 s) et une comète sur une ellipse tournent autour d’une étoile de GM = 100 (G = 1, pour que les nombres restent à l’échelle de la classe). RK4 garde les deux orbites fermées et l’énergie plate. Passez à Euler explicite et regardez les orbites s’ouvrir en spirale pendant que l’énergie totale monte ; Euler symplectique les garde fermées.</translation>
    </message>
    <message>
        <source>Pendulum on a stiff spring</source>
        <extracomment>scenes/pendulum-stiff-spring.phasebox.json: name</extracomment>
        <translation>Pendule sur un ressort raide</translation>
    </message>
    <message>
        <source>A 1 kg bob swings on a 2 m rod that is really a stiff spring (k = 10 000 N/m). The swing is slow (T ≈ 2π√(L/g) = 2.8 s, about 7% longer at this 60° amplitude) but the rod&apos;s stretching mode is fast (ω = √(k/m) = 100 rad/s), and that fast mode is what limits the time step. Try explicit Euler and watch it blow up; implicit Euler is stable but visibly damps the swing; symplectic Euler with sub-steps keeps the energy bounded.</source>
        <extracomment>scenes/pendulum-stiff-spring.phasebox.json: description</extracomment>
        <translation>Une masse de 1 kg oscille au bout d’une tige de 2 m qui est en fait un ressort raide (k = 10 000 N/m). L’oscillation est lente (T ≈ 2π√(L/g) = 2,8 s, environ 7 % de plus à cette amplitude de 60°) mais le mode d’allongement de la tige est rapide (ω = √(k/m) = 100 rad/s), et c’est ce mode rapide qui limite le pas de temps. Essayez Euler explicite et regardez-le exploser ; Euler implicite est stable mais amortit visiblement l’oscillation ; Euler symplectique avec des sous-pas garde l’énergie bornée.</translation>
    </message>
    <message>
        <source>Pendulum wave</source>
        <extracomment>scenes/pendulum-wave.phasebox.json: name</extracomment>
        <translation>Vague de pendules</translation>
    </message>
    <message>
        <source>Twelve pendulums hang side by side, their lengths chosen so that in 60 s the longest makes 51 swings, the next 52, and so on to 62 for the shortest (T = 60/(51 + n) s, L = g·(T/2π)²). Released together from 10°, they drift out of step: after 15 s they form a travelling snake, after 30 s two rows swinging against each other, and at 60 s they all line up again. Each one is a simple pendulum, so View → Exact Solution draws where the closed form puts it (dashed): at 10° the period is 0.19% longer than the small-angle 2π·√(L/g) the lengths were chosen for, so the real line-up comes about 0.1 s late. Try RK4 or a smaller dt and watch the bobs stay on their ghosts; explicit Euler lets every swing grow until, after about 8 s, the run is stopped as diverging.</source>
        <extracomment>scenes/pendulum-wave.phasebox.json: description</extracomment>
        <translation>Douze pendules pendent côte à côte, leurs longueurs choisies pour qu’en 60 s le plus long fasse 51 oscillations, le suivant 52, et ainsi de suite jusqu’à 62 pour le plus court (T = 60/(51 + n) s, L = g·(T/2π)²). Lâchés ensemble depuis 10°, ils se déphasent : après 15 s ils forment un serpent qui avance, après 30 s deux rangées qui oscillent l’une contre l’autre, et à 60 s ils sont de nouveau tous alignés. Chacun est un pendule simple, donc Affichage → Solution exacte dessine où la forme fermée le place (en tirets) : à 10° la période est 0,19 % plus longue que le 2π·√(L/g) des petits angles pour lequel les longueurs ont été choisies, donc le vrai alignement arrive environ 0,1 s en retard. Essayez RK4 ou un dt plus petit et regardez les masses rester sur leurs fantômes ; Euler explicite fait croître chaque oscillation jusqu’à ce que, après environ 8 s, le calcul soit arrêté pour divergence.</translation>
    </message>
    <message>
        <source>Polygon pile</source>
        <extracomment>scenes/polygon-pile.phasebox.json: name</extracomment>
        <translation>Tas de polygones</translation>
    </message>
    <message>
        <source>A pile of polygons: triangles to heptagons of several sizes dropped into a bin. Each is a rigid convex polygon whose mass and moment of inertia come from its vertices; they collide face to face and corner to face, tumble, and settle into a heap that stands. Select one to see its properties, or add more with the Add polygon tool and watch the heap take them.</source>
        <extracomment>scenes/polygon-pile.phasebox.json: description</extracomment>
        <translation>Un tas de polygones : des triangles aux heptagones de plusieurs tailles, lâchés dans un bac. Chacun est un polygone convexe rigide dont la masse et le moment d’inertie viennent de ses sommets ; ils se heurtent face contre face et coin contre face, culbutent et se stabilisent en un tas qui tient debout. Sélectionnez-en un pour voir ses propriétés, ou ajoutez-en avec l’outil Ajouter un polygone et regardez le tas les recevoir.</translation>
    </message>
    <message>
        <source>Projectiles with air drag</source>
        <extracomment>scenes/projectile-drag.phasebox.json: name</extracomment>
        <translation>Projectiles avec frottement de l’air</translation>
    </message>
    <message>
        <source>Four balls of the same size are launched together at 10 m/s and 45° through air with quadratic drag F = −c‖v‖v (c = 0.004 kg/m). The drag force is the same on all, so the light balls slow down far more: the terminal speed √(mg/c) is 7 m/s for 20 g, 16 m/s for 0.1 kg, 35 m/s for 0.5 kg and 157 m/s for 10 kg. Without drag all would land 10.2 m away: compare the ranges and the lopsided paths. In the energy plot work_nc slopes gently down in flight as drag takes its share (most of the 20 g ball&apos;s energy, a hundredth of the 10 kg ball&apos;s), then drops as each ball lands dead in the ground, which work_nc counts too.</source>
        <extracomment>scenes/projectile-drag.phasebox.json: description</extracomment>
        <translation>Quatre balles de même taille sont lancées ensemble à 10 m/s et 45° dans l’air avec une traînée quadratique F = −c‖v‖v (c = 0,004 kg/m). La force de traînée est la même pour toutes, donc les balles légères sont bien plus freinées : la vitesse limite √(mg/c) est de 7 m/s pour 20 g, 16 m/s pour 0,1 kg, 35 m/s pour 0,5 kg et 157 m/s pour 10 kg. Sans traînée toutes atterriraient à 10,2 m : comparez les portées et les trajectoires dissymétriques. Dans le graphique d’énergie, work_nc descend doucement en vol tandis que la traînée prend sa part (la plus grande partie de l’énergie de la balle de 20 g, un centième de celle de la balle de 10 kg), puis chute quand chaque balle atterrit sans rebond dans le sol, ce que work_nc compte aussi.</translation>
    </message>
    <message>
        <source>Ragdoll on the stairs</source>
        <extracomment>scenes/ragdoll.phasebox.json: name</extracomment>
        <translation>Pantin dans l’escalier</translation>
    </message>
    <message>
        <source>A ragdoll of ten boxes (torso, head, upper and lower arms, thighs and shins; 32 kg in all) joined by nine hinges with limits: the neck turns half a radian either way, elbows and knees bend one way only, shoulders and hips swing outwards but not across the body. It is pushed off the top of a flight of stairs and tumbles down them. Where it ends is chaotic: a nanometre&apos;s nudge to the torso changes the whole tumble, and it may end up on the bottom step, on the floor or against the low wall at the foot of the stairs. Hinged neighbours do not collide with each other, but every other pair of limbs does, and so do the limbs and the steps. Watch the hinges hold (well under a millimetre) while the limits stop the joints at their ends.</source>
        <extracomment>scenes/ragdoll.phasebox.json: description</extracomment>
        <translation>Un pantin de dix boîtes (torse, tête, bras et avant-bras, cuisses et tibias ; 32 kg en tout) reliées par neuf charnières avec butées : le cou tourne d’un demi-radian de chaque côté, coudes et genoux ne plient que dans un sens, épaules et hanches s’écartent vers l’extérieur mais ne croisent pas le corps. Il est poussé du haut d’un escalier et le dévale. L’endroit où il finit est chaotique : une poussée d’un nanomètre sur le torse change toute la chute, et il peut finir sur la dernière marche, sur le sol ou contre le muret au pied de l’escalier. Les voisins articulés ne se heurtent pas, mais toutes les autres paires de membres si, et les membres heurtent aussi les marches. Regardez les charnières tenir (à bien moins d’un millimètre) pendant que les butées arrêtent les articulations à leurs extrémités.</translation>
    </message>
    <message>
        <source>Chain of springs</source>
        <extracomment>scenes/spring-chain.phasebox.json: name</extracomment>
        <translation>Chaîne de ressorts</translation>
    </message>
    <message>
        <source>Ten 0.1 kg beads joined by springs hang from a fixed hook and are released from a horizontal line. Watch the chain whip down and swing like a rope, and notice that the top spring stretches most: it carries the weight of every bead below it. The spring damping turns the swing&apos;s energy into work_nc in the energy plot, so the total slowly falls while the drift stays near zero.</source>
        <extracomment>scenes/spring-chain.phasebox.json: description</extracomment>
        <translation>Dix perles de 0,1 kg reliées par des ressorts pendent à un crochet fixe et sont lâchées depuis une ligne horizontale. Regardez la chaîne fouetter vers le bas et se balancer comme une corde, et remarquez que le ressort du haut s’allonge le plus : il porte le poids de toutes les perles en dessous. L’amortissement des ressorts change l’énergie de l’oscillation en work_nc dans le graphique d’énergie, donc le total baisse lentement tandis que la dérive reste proche de zéro.</translation>
    </message>
    <message>
        <source>Spring oscillator: T = 2π√(m/k)</source>
        <extracomment>scenes/spring-oscillator.phasebox.json: name</extracomment>
        <translation>Oscillateur à ressort : T = 2π√(m/k)</translation>
    </message>
    <message>
        <source>Two balls bounce on identical springs (k = 39.48 N/m); the right one is 4 times heavier. The period T = 2π√(m/k) is exactly 1 s for the 1 kg ball and 2 s for the 4 kg ball, and gravity only moves the equilibrium down by mg/k without changing the period. Switch to explicit Euler and watch the bounce grow and the total energy climb in the energy plot; symplectic Euler and Verlet keep it bounded.</source>
        <extracomment>scenes/spring-oscillator.phasebox.json: description</extracomment>
        <translation>Deux balles oscillent sur des ressorts identiques (k = 39,48 N/m) ; celle de droite est 4 fois plus lourde. La période T = 2π√(m/k) vaut exactement 1 s pour la balle de 1 kg et 2 s pour celle de 4 kg, et la pesanteur ne fait que descendre l’équilibre de mg/k sans changer la période. Passez à Euler explicite et regardez l’oscillation grandir et l’énergie totale monter dans le graphique d’énergie ; Euler symplectique et Verlet la gardent bornée.</translation>
    </message>
    <message>
        <source>Stiff spring: explicit methods blow up</source>
        <extracomment>scenes/stiff-spring-blowup.phasebox.json: name</extracomment>
        <translation>Ressort raide : les méthodes explicites explosent</translation>
    </message>
    <message>
        <source>A 1 kg ball swings on a very stiff spring (k = 100 000 N/m, so ω = √(k/m) = 316 rad/s) at the frame step dt = 1/60 s: ω·dt = 5.3, far past the stability limits of the explicit methods (ω·dt &lt; 2 for symplectic Euler and Verlet, 2.83 for RK4). Implicit Euler stays stable, but pays with numerical damping: watch the swing die away and the drift fall in the energy plot. Switch to symplectic Euler and the spring explodes within a few frames and is stopped as diverging; implicit midpoint is stable and keeps the energy.</source>
        <extracomment>scenes/stiff-spring-blowup.phasebox.json: description</extracomment>
        <translation>Une balle de 1 kg oscille sur un ressort très raide (k = 100 000 N/m, donc ω = √(k/m) = 316 rad/s) au pas de l’image dt = 1/60 s : ω·dt = 5,3, bien au-delà des limites de stabilité des méthodes explicites (ω·dt &lt; 2 pour Euler symplectique et Verlet, 2,83 pour RK4). Euler implicite reste stable, mais le paie par un amortissement numérique : regardez l’oscillation s’éteindre et la dérive baisser dans le graphique d’énergie. Passez à Euler symplectique et le ressort explose en quelques images et est arrêté pour divergence ; le point milieu implicite est stable et conserve l’énergie.</translation>
    </message>
    <message>
        <source>Lesson: the Atwood machine</source>
        <extracomment>lessons/atwood-machine.phasebox.json: name</extracomment>
        <translation>Leçon : la machine d’Atwood</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: two Atwood machines, each a pair of weights on a massless rope over two fixed pulleys, 3 kg against 1 kg on the left and 1.1 kg against 0.9 kg on the right; each heavy weight starts 3 m above the floor. 2) Read each heavy weight&apos;s acceleration off the graph of its vy in the Instruments dock (left_heavy.vy, right_heavy.vy): while it falls the line is straight and its slope is −a; or time the fall with the stopwatch (Instruments, Timer) and work out a = 2·h/t². 3) Select a weight, change its mass, Reset and read the new slope. What to watch: the left pair accelerates at g/2 = 4.905 m/s² and lands after 1.11 s at 5.4 m/s; the right pair accelerates at g/10 = 0.981 m/s² and lands after 2.47 s at 2.4 m/s. When a heavy weight lands its partner stops too, because Phasebox&apos;s pulley rope never goes slack (a real light weight would coast on upwards for a moment). Why: the rope does not stretch, so the two weights move at the same speed, one up and one down, and it pulls each of them up with the same tension T. Newton&apos;s second law for each weight, m1·a = m1·g − T and m2·a = T − m2·g, added together gives a = g·(m1 − m2)/(m1 + m2): gravity pulls on the difference of the masses but has to accelerate their sum. Then T = 2·m1·m2·g/(m1 + m2), which is 14.7 N on the left, between the light weight&apos;s 9.8 N and the heavy one&apos;s 29.4 N, and 9.71 N on the right. George Atwood described the machine in 1784 to slow free fall down enough to time it by hand: with nearly equal masses a is a small fraction of g. The mass does not cancel here as it does for a pendulum, because the two weights share one acceleration.</source>
        <extracomment>lessons/atwood-machine.phasebox.json: description</extracomment>
        <translation>Essayez : 1) Appuyez sur Lecture : deux machines d’Atwood, chacune une paire de masses sur une corde sans masse passant sur deux poulies fixes, 3 kg contre 1 kg à gauche et 1,1 kg contre 0,9 kg à droite ; chaque masse lourde part à 3 m au-dessus du sol. 2) Lisez l’accélération de chaque masse lourde sur le graphique de son vy dans le panneau Instruments (left_heavy.vy, right_heavy.vy) : pendant la chute la ligne est droite et sa pente vaut −a ; ou chronométrez la chute (Instruments, Minuteur) et calculez a = 2·h/t². 3) Sélectionnez une masse, changez-la, réinitialisez et lisez la nouvelle pente. Ce qu’il faut regarder : la paire de gauche accélère à g/2 = 4,905 m/s² et touche le sol après 1,11 s à 5,4 m/s ; celle de droite accélère à g/10 = 0,981 m/s² et touche le sol après 2,47 s à 2,4 m/s. Quand une masse lourde touche le sol, sa partenaire s’arrête aussi, parce que la corde de poulie de Phasebox ne se détend jamais (une vraie masse légère continuerait à monter un instant). Pourquoi : la corde ne s’allonge pas, donc les deux masses vont à la même vitesse, l’une vers le haut et l’autre vers le bas, et elle tire chacune vers le haut avec la même tension T. La deuxième loi de Newton pour chaque masse, m1·a = m1·g − T et m2·a = T − m2·g, additionnées donnent a = g·(m1 − m2)/(m1 + m2) : la pesanteur tire sur la différence des masses mais doit accélérer leur somme. Alors T = 2·m1·m2·g/(m1 + m2), soit 14,7 N à gauche, entre les 9,8 N de la masse légère et les 29,4 N de la lourde, et 9,71 N à droite. George Atwood a décrit la machine en 1784 pour ralentir assez la chute libre pour la chronométrer à la main : avec des masses presque égales, a est une petite fraction de g. La masse ne se simplifie pas ici comme pour un pendule, parce que les deux masses partagent une même accélération.</translation>
    </message>
    <message>
        <source>Lesson: a bead on a hoop</source>
        <extracomment>lessons/bead-on-hoop.phasebox.json: name</extracomment>
        <translation>Leçon : une perle sur un cerceau</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: a 1 kg bead slides without friction on a circular wire of radius 1 m, released from rest level with the centre of the hoop, 90° from the bottom. 2) Read the period off the period timer in the Instruments dock, which times bead.x, or click the bead and watch its loop in the Phase space plot. 3) Reset, switch the integrator to explicit Euler and then to RK4, and compare the swings and the energy plot. What to watch: the bead swings up to the same height on the other side and back with a period of 2.3678 s, the period of a 1 m pendulum released at 90°; at the bottom it passes at √(2·g·R) = 4.43 m/s. Under explicit Euler each swing climbs higher than the last until Phasebox stops the run as diverging; under RK4 the energy stays put. Why: the wire can push only at right angles to itself, so like the pendulum&apos;s rod it does no work, and the bead moves exactly as a pendulum bob on a massless rod to the centre, T = 4·√(R/g)·K(sin(θ0/2)). Phasebox treats the wire as a constraint C(x) = ‖x − c‖ − R = 0, Witkin and Baraff&apos;s bead on a wire: at every force evaluation it solves for the force that keeps C from changing, the part of gravity that would pull the bead off the wire plus the centripetal force m·v²/R that bends its path. That force is the wire&apos;s normal force: at the bottom it is m·g + m·v²/R = 3·m·g = 29.4 N, three times the bead&apos;s weight, whatever the radius. The little drift off the wire that a finite step leaves is projected away after each step, and any energy that takes shows in the plot as correction. The same machinery holds the rods, hinges and pulleys of the other joint lessons.</source>
        <extracomment>lessons/bead-on-hoop.phasebox.json: description</extracomment>
        <translation>Essayez : 1) Appuyez sur Lecture : une perle de 1 kg glisse sans frottement sur un fil circulaire de 1 m de rayon, lâchée au repos à la hauteur du centre du cerceau, à 90° du bas. 2) Lisez la période sur la mesure de période du panneau Instruments, qui chronomètre bead.x, ou cliquez la perle et regardez sa boucle dans l’espace des phases. 3) Réinitialisez, passez à Euler explicite puis à RK4, et comparez les oscillations et le graphique d’énergie. Ce qu’il faut regarder : la perle remonte à la même hauteur de l’autre côté et revient avec une période de 2,3678 s, celle d’un pendule de 1 m lâché à 90° ; en bas elle passe à √(2·g·R) = 4,43 m/s. Avec Euler explicite chaque oscillation monte plus haut que la précédente jusqu’à ce que Phasebox arrête le calcul pour divergence ; avec RK4 l’énergie reste en place. Pourquoi : le fil ne peut pousser que perpendiculairement à lui-même, donc, comme la tige d’un pendule, il ne travaille pas, et la perle se déplace exactement comme la masse d’un pendule sur une tige sans masse reliée au centre, T = 4·√(R/g)·K(sin(θ0/2)). Phasebox traite le fil comme une contrainte C(x) = ‖x − c‖ − R = 0, la perle sur un fil de Witkin et Baraff : à chaque évaluation de force il calcule la force qui empêche C de changer, la part de la pesanteur qui arracherait la perle du fil plus la force centripète m·v²/R qui courbe sa trajectoire. Cette force est la réaction normale du fil : en bas elle vaut m·g + m·v²/R = 3·m·g = 29,4 N, trois fois le poids de la perle, quel que soit le rayon. Le petit écart au fil qu’un pas fini laisse est projeté après chaque pas, et l’énergie que cela coûte apparaît dans le graphique comme correction. La même mécanique tient les tiges, charnières et poulies des autres leçons de liaisons.</translation>
    </message>
    <message>
        <source>Lesson: the three kinds of spring in a cloth</source>
        <extracomment>lessons/cloth-springs.phasebox.json: name</extracomment>
        <translation>Leçon : les trois sortes de ressorts d’un tissu</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: three cloths, 1.2 m square, hang under implicit Euler from two nodes of their top edge, a quarter of the way in from each side. The left one has structural, shear and bend springs; the middle one has no shear springs; the right one has neither shear nor bend springs. 2) Select a cloth and change its stiffness, then Reset and play again: give the right one its bend springs back (bend 20), or take the bend springs away from the left one. What to watch: the full cloth hangs as a flat sheet and even its top corners outside the pins stay up; without shear springs the squares of the mesh fold into diamonds, the corners swing down and the cloth narrows to about 0.7 m; without bend springs as well it narrows further, to about 0.55 m, and its folds become sharp creases where the middle one&apos;s are rounded. Why: structural springs keep each thread from stretching, but a square of four of them folds like a hinge at no cost, so they alone cannot hold a shape. Shear springs across both diagonals cut every square into triangles, which cannot fold: with them the cloth keeps its shape and the bend springs have nothing left to do (the left cloth without them looks the same). Bend springs join each node to the node two places along a thread and stretch only when the thread kinks, so where the mesh does fold they spread each fold over several nodes instead of one sharp crease. In this flat world a cloth can fold only within its own plane; in 3D, where a sheet bends out of its plane without stretching anything, bend springs are what give cloth its drape. Stiff structural springs are also why cloth wants an implicit integrator: at k = 2 000 N/m on nodes of 7 g the threads vibrate far too fast for an explicit method at dt = 1/60 s.</source>
        <extracomment>lessons/cloth-springs.phasebox.json: description</extracomment>
        <translation>Essayez : 1) Appuyez sur Lecture : trois tissus de 1,2 m de côté pendent sous Euler implicite à deux nœuds de leur bord supérieur, au quart de chaque côté. Celui de gauche a des ressorts de structure, de cisaillement et de flexion ; celui du milieu n’a pas de ressorts de cisaillement ; celui de droite n’a ni ressorts de cisaillement ni de flexion. 2) Sélectionnez un tissu et changez sa raideur, puis réinitialisez et relancez : rendez à celui de droite ses ressorts de flexion (bend 20), ou retirez-les à celui de gauche. Ce qu’il faut regarder : le tissu complet pend comme une feuille plane et même ses coins supérieurs à l’extérieur des attaches restent en haut ; sans ressorts de cisaillement les carrés du maillage se plient en losanges, les coins retombent et le tissu se rétrécit à environ 0,7 m ; sans ressorts de flexion non plus, il se rétrécit encore, à environ 0,55 m, et ses plis deviennent des cassures nettes là où ceux du milieu sont arrondis. Pourquoi : les ressorts de structure empêchent chaque fil de s’allonger, mais un carré de quatre d’entre eux se plie comme une charnière sans effort, donc seuls ils ne tiennent aucune forme. Les ressorts de cisaillement sur les deux diagonales coupent chaque carré en triangles, qui ne peuvent pas se plier : avec eux le tissu garde sa forme et les ressorts de flexion n’ont plus rien à faire (le tissu de gauche sans eux a le même aspect). Les ressorts de flexion relient chaque nœud au nœud situé deux places plus loin le long d’un fil et ne s’allongent que quand le fil se coude, donc là où le maillage se plie ils répartissent chaque pli sur plusieurs nœuds au lieu d’une cassure nette. Dans ce monde plat un tissu ne peut se plier que dans son propre plan ; en 3D, où une feuille se courbe hors de son plan sans rien allonger, ce sont les ressorts de flexion qui donnent au tissu son tombé. Des ressorts de structure raides sont aussi la raison pour laquelle un tissu veut un intégrateur implicite : à k = 2 000 N/m sur des nœuds de 7 g, les fils vibrent bien trop vite pour une méthode explicite à dt = 1/60 s.</translation>
    </message>
    <message>
        <source>Lesson: the double pendulum is chaotic</source>
        <extracomment>lessons/double-pendulum.phasebox.json: name</extracomment>
        <translation>Leçon : le pendule double est chaotique</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: two identical double pendulums, 1 kg bobs on massless rods 1 m long, start from rest nearly upside down, both rods at 170° from the vertical; the right one&apos;s lower rod is turned a billionth of a radian (1e-9 rad) further than the left one&apos;s, a millionth of a millimetre at its bob. 2) Watch them swing in step and note the time when the graphs in the Instruments dock first differ: a2.x and b2.x, the lower bobs&apos; x, and distance(a2,b2), which stays at 4.5 m while they move as one. 3) Reset, set dt to 1/1200 s and play again. What to watch: for about 8 s the two move as one; by 12 s the lower bobs are visibly apart and by 14 s they swing quite differently, although both keep their energy (under RK4 the total in the energy plot stays flat to a few microjoules). At dt = 1/1200 s they part at about the same time, but after 12 s both move differently from the run at 1/600 s. Why: the two bobs pull on each other through the lower rod, and the equations of their motion are nonlinear, so the motion is chaotic: two starts a tiny distance d apart separate roughly as d·e^(λt), here with λ ≈ 1.3 per second, ten times further every 2 s or so. That is why a billionth of a radian becomes a visible gap in about 12 s, and a start a thousand times closer would part only about 5 s later. The integrator&apos;s own error grows at the same rate: RK4 at dt = 1/600 s is a few millionths of a metre off after 5 s, millimetres off after 10 s, and after 15 s no run predicts where the real pendulum is. Both pendulums make nearly the same error at each step, which is why their difference still follows the physics. Chaos is not randomness: the motion is fully determined by its start, and a run repeated with the same numbers gives exactly the same motion.</source>
        <extracomment>lessons/double-pendulum.phasebox.json: description</extracomment>
        <translation>Essayez : 1) Appuyez sur Lecture : deux pendules doubles identiques, masses de 1 kg sur des tiges sans masse de 1 m, partent du repos presque à l’envers, les deux tiges à 170° de la verticale ; la tige inférieure de celui de droite est tournée d’un milliardième de radian (1e-9 rad) de plus que celle de gauche, un millionième de millimètre à sa masse. 2) Regardez-les osciller ensemble et notez l’instant où les graphiques du panneau Instruments diffèrent pour la première fois : a2.x et b2.x, le x des masses inférieures, et distance(a2,b2), qui reste à 4,5 m tant qu’ils bougent comme un seul. 3) Réinitialisez, réglez dt à 1/1200 s et relancez. Ce qu’il faut regarder : pendant environ 8 s les deux bougent comme un seul ; à 12 s les masses inférieures sont visiblement séparées et à 14 s elles oscillent tout autrement, bien que les deux gardent leur énergie (avec RK4 le total du graphique d’énergie reste plat à quelques microjoules près). À dt = 1/1200 s ils se séparent à peu près au même instant, mais après 12 s tous deux bougent autrement que dans le calcul à 1/600 s. Pourquoi : les deux masses se tirent l’une l’autre par la tige inférieure, et leurs équations du mouvement sont non linéaires, donc le mouvement est chaotique : deux départs distants d’un minuscule d s’écartent à peu près comme d·e^(λt), ici avec λ ≈ 1,3 par seconde, dix fois plus toutes les 2 s environ. C’est pourquoi un milliardième de radian devient un écart visible en environ 12 s, et un départ mille fois plus proche ne se séparerait qu’environ 5 s plus tard. L’erreur propre de l’intégrateur croît au même rythme : RK4 à dt = 1/600 s est décalé de quelques millionièmes de mètre après 5 s, de millimètres après 10 s, et après 15 s aucun calcul ne prédit où est le vrai pendule. Les deux pendules font presque la même erreur à chaque pas, c’est pourquoi leur différence suit toujours la physique. Le chaos n’est pas le hasard : le mouvement est entièrement déterminé par son départ, et un calcul répété avec les mêmes nombres donne exactement le même mouvement.</translation>
    </message>
    <message>
        <source>Lesson: explicit Euler spirals out of an orbit</source>
        <extracomment>lessons/euler-orbit-spiral.phasebox.json: name</extracomment>
        <translation>Leçon : Euler explicite sort de l’orbite en spirale</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play and watch two planets on circular orbits (r = 3 m and 5 m) round a star of G·M = 100 under explicit Euler at dt = 1/60 s. 2) Open the energy plot: the total climbs step after step; the graphs in the Instruments dock show each planet&apos;s distance from the star, distance(star,inner) and distance(star,outer). 3) Reset, switch the integrator to symplectic Euler and play again, then to RK4. What to watch: under explicit Euler both orbits spiral outwards, the inner one faster (after 20 s it has doubled in size, its distance from the star has passed 6 m, and the outer one has grown by more than a third, past 6.7 m); symplectic Euler keeps both closed with a wobble of about two percent; RK4 keeps them circular. Why: explicit Euler moves the planet along the tangent with the old velocity, and a tangent always leads outside a circle, so every step lifts the planet a little. On a circular orbit of angular speed ω each step raises the energy by about 2·(ω·dt)² of its size, a growth that never stops and is more than four and a half times larger for the faster inner orbit. Symplectic Euler uses the new velocity to move, and that small change makes it preserve a slightly perturbed energy, so the error stays bounded instead of piling up. RK4 is simply accurate: its error per lap is about (ω·dt)⁴ smaller. Halve dt and the energy climbs half as fast: explicit Euler is a first-order method, so its error shrinks only in proportion to the step.</source>
        <extracomment>lessons/euler-orbit-spiral.phasebox.json: description</extracomment>
        <translation>Essayez : 1) Appuyez sur Lecture et regardez deux planètes sur des orbites circulaires (r = 3 m et 5 m) autour d’une étoile de G·M = 100 sous Euler explicite à dt = 1/60 s. 2) Ouvrez le graphique d’énergie : le total monte pas après pas ; les graphiques du panneau Instruments montrent la distance de chaque planète à l’étoile, distance(star,inner) et distance(star,outer). 3) Réinitialisez, passez à Euler symplectique et relancez, puis à RK4. Ce qu’il faut regarder : sous Euler explicite les deux orbites s’ouvrent en spirale, l’intérieure plus vite (après 20 s elle a doublé de taille, sa distance à l’étoile a dépassé 6 m, et l’extérieure a grandi de plus d’un tiers, au-delà de 6,7 m) ; Euler symplectique les garde fermées avec une oscillation d’environ deux pour cent ; RK4 les garde circulaires. Pourquoi : Euler explicite déplace la planète le long de la tangente avec l’ancienne vitesse, et une tangente mène toujours hors d’un cercle, donc chaque pas soulève un peu la planète. Sur une orbite circulaire de vitesse angulaire ω, chaque pas augmente l’énergie d’environ 2·(ω·dt)² de sa valeur, une croissance qui ne s’arrête jamais et qui est plus de quatre fois et demie plus grande pour l’orbite intérieure, plus rapide. Euler symplectique utilise la nouvelle vitesse pour déplacer, et ce petit changement lui fait conserver une énergie légèrement perturbée, donc l’erreur reste bornée au lieu de s’accumuler. RK4 est simplement précis : son erreur par tour est environ (ω·dt)⁴ fois plus petite. Divisez dt par deux et l’énergie monte deux fois moins vite : Euler explicite est une méthode du premier ordre, donc son erreur ne diminue qu’en proportion du pas.</translation>
    </message>
    <message>
        <source>Lesson: an impulse sets a box spinning</source>
        <extracomment>lessons/impulse-spin.phasebox.json: name</extracomment>
        <translation>Leçon : une percussion met une boîte en rotation</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: in empty space (no gravity) a 100 g pellet flies at 20 m/s into the left face of a 2 kg box, 0.15 m above the box&apos;s centre. 2) Read the box&apos;s speed and spin after the hit in the table in the Instruments dock (box.speed, and box.omega, negative when it turns clockwise), then Reset, drag the pellet up or down (or set its position y to 0) and play again. What to watch: the box drifts off at 1.41 m/s and turns clockwise at about 2 rad/s; a pellet aimed at the centre line pushes it without any spin, one aimed below the centre spins it the other way. Why: the contact pushes with one short, large force, an impulse J along the face&apos;s normal, and the same J changes the box&apos;s momentum by J and its angular momentum by r × J, where r runs from the centre of mass to the contact point: an off-centre push always turns. With restitution e = 0.5 and no friction, J = (1 + e)·m·v/(1 + m/M + m·d²/I) for an offset d, so the box moves at J/M and turns at J·d/I with I = M·(w² + h²)/12. Nothing outside the pellet and the box acts on them, so their total momentum and their angular momentum about any fixed point, the point of impact for instance, are the same after the hit as before, which is how the numbers above were worked out. The kinetic energy is not kept: the inelastic part of the bounce appears in work_nc. The dashed outline is that closed form (View → Exact Solution): with no force between the impacts, every integrator follows it to rounding.</source>
        <extracomment>lessons/impulse-spin.phasebox.json: description</extracomment>
        <translation>Essayez : 1) Appuyez sur Lecture : dans l’espace vide (sans pesanteur) un plomb de 100 g vole à 20 m/s vers la face gauche d’une boîte de 2 kg, 0,15 m au-dessus du centre de la boîte. 2) Lisez la vitesse et la rotation de la boîte après le choc dans le tableau du panneau Instruments (box.speed, et box.omega, négatif quand elle tourne dans le sens horaire), puis réinitialisez, déplacez le plomb vers le haut ou vers le bas (ou mettez sa position y à 0) et relancez. Ce qu’il faut regarder : la boîte part à 1,41 m/s et tourne dans le sens horaire à environ 2 rad/s ; un plomb visant la ligne médiane la pousse sans aucune rotation, un plomb visant sous le centre la fait tourner dans l’autre sens. Pourquoi : le contact pousse avec une force brève et grande, une percussion J selon la normale de la face, et ce même J change la quantité de mouvement de la boîte de J et son moment cinétique de r × J, où r va du centre de masse au point de contact : une poussée décentrée fait toujours tourner. Avec une restitution e = 0,5 et sans frottement, J = (1 + e)·m·v/(1 + m/M + m·d²/I) pour un décalage d, donc la boîte se déplace à J/M et tourne à J·d/I avec I = M·(w² + h²)/12. Rien d’extérieur au plomb et à la boîte n’agit sur eux, donc leur quantité de mouvement totale et leur moment cinétique par rapport à tout point fixe, le point d’impact par exemple, sont les mêmes après le choc qu’avant, et c’est ainsi que les nombres ci-dessus ont été calculés. L’énergie cinétique n’est pas conservée : la part inélastique du rebond apparaît dans work_nc. Le contour en tirets est cette forme fermée (Affichage → Solution exacte) : sans force entre les impacts, chaque intégrateur la suit à l’arrondi près.</translation>
    </message>
    <message>
        <source>Lesson: midpoint against RK4</source>
        <extracomment>lessons/midpoint-vs-rk4.phasebox.json: name</extracomment>
        <translation>Leçon : point milieu contre RK4</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: a ball on a spring (k = 4 N/m, m = 1 kg, so ω = 2 rad/s and the period is π s) swings under the midpoint method at a coarse dt = 0.1 s, next to its exact solution x = cos 2t. 2) Watch the graph of ball.vx against ball.x in the Instruments dock, the phase portrait: the exact motion is a closed ellipse. 3) Reset and switch to RK4 at the same dt; then try midpoint at dt = 0.05 s, which costs as many force evaluations per second as RK4 at 0.1 s. What to watch: midpoint&apos;s ellipse slowly grows and its swing runs ahead of the exact one (after 20 s by about a quarter of a radian); RK4&apos;s stays on the exact curve to four decimals. Why: both methods sample the force inside the step, midpoint once and RK4 three times, and the weights of RK4 cancel the error terms up to the fourth power of ω·dt, midpoint&apos;s only up to the second. Halving dt divides midpoint&apos;s error by 4 and RK4&apos;s by 16, so at equal cost RK4 still wins by a wide margin on a smooth problem like this one. Midpoint&apos;s amplification per step is √(1 + (ω·dt)⁴/4), slightly above 1, which is why its energy creeps up. The command phasebox-cli accuracy on this file draws the work-precision diagram that shows it across many step sizes.</source>
        <extracomment>lessons/midpoint-vs-rk4.phasebox.json: description</extracomment>
        <translation>Essayez : 1) Appuyez sur Lecture : une balle sur un ressort (k = 4 N/m, m = 1 kg, donc ω = 2 rad/s et la période est π s) oscille avec la méthode du point milieu à un dt grossier de 0,1 s, à côté de sa solution exacte x = cos 2t. 2) Regardez le graphique de ball.vx en fonction de ball.x dans le panneau Instruments, le portrait de phase : le mouvement exact est une ellipse fermée. 3) Réinitialisez et passez à RK4 au même dt ; essayez ensuite le point milieu à dt = 0,05 s, qui coûte autant d’évaluations de force par seconde que RK4 à 0,1 s. Ce qu’il faut regarder : l’ellipse du point milieu grandit lentement et son oscillation prend de l’avance sur l’exacte (après 20 s d’environ un quart de radian) ; celle de RK4 reste sur la courbe exacte à quatre décimales. Pourquoi : les deux méthodes échantillonnent la force à l’intérieur du pas, le point milieu une fois et RK4 trois fois, et les poids de RK4 annulent les termes d’erreur jusqu’à la puissance quatre de ω·dt, ceux du point milieu seulement jusqu’à la deuxième. Diviser dt par deux divise l’erreur du point milieu par 4 et celle de RK4 par 16, donc à coût égal RK4 gagne encore largement sur un problème régulier comme celui-ci. L’amplification par pas du point milieu est √(1 + (ω·dt)⁴/4), un peu plus de 1, c’est pourquoi son énergie monte lentement. La commande phasebox-cli accuracy sur ce fichier trace le diagramme travail-précision qui le montre pour de nombreux pas.</translation>
    </message>
    <message>
        <source>Lesson: restitution and friction</source>
        <extracomment>lessons/restitution-friction.phasebox.json: name</extracomment>
        <translation>Leçon : restitution et frottement</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play. On the left three balls fall 2 m onto a floor; on the right three crates slide at 4 m/s along strips of ice, wood and rubber. 2) Read each ball&apos;s rebound off the graphs in the Instruments dock, e090.y, e060.y and e030.y (each ball&apos;s centre, 0.15 m above its lowest point), and where each crate stops off the table of on_ice.x, on_wood.x and on_rubber.x (each starts at x = 0.5 m). 3) Select a ball and change its restitution, or a crate and its strip and change their friction, then Reset and play again. What to watch: each ball climbs back to e²·h, 1.62 m, 0.72 m and 0.18 m for e = 0.9, 0.6 and 0.3; each crate stops after v²/(2·μ·g), 8.2 m on ice (μ = 0.1), 2.0 m on wood (μ = 0.4) and 1.0 m on rubber (μ = 0.8); the energy the bounces and the sliding lose appears in work_nc. Why: restitution e is the ratio of the speeds just after and just before a bounce, and since the height a ball reaches goes with the square of its speed, it rebounds to e² of its drop. Kinetic friction opposes sliding with a force μ times the normal force, here μ·m·g, so the crate decelerates uniformly at μ·g whatever its mass. A pair of materials combines as max(e₁, e₂) and √(μ₁·μ₂): the floor has e = 0, so each ball&apos;s own e counts, and each crate has the same μ as its strip. A bounce is an impulse the solver applies at the moment of impact, while a steady slide&apos;s friction, like the floor&apos;s push under a resting body, acts as a force inside the integrator&apos;s step; a bounce slower than the restitution threshold (1 m/s times 1 − e) is treated as inelastic, which is why small hops end in rest instead of going on for ever; with e = 1 every bounce is elastic.</source>
        <extracomment>lessons/restitution-friction.phasebox.json: description</extracomment>
        <translation>Essayez : 1) Appuyez sur Lecture. À gauche trois balles tombent de 2 m sur un sol ; à droite trois caisses glissent à 4 m/s sur des bandes de glace, de bois et de caoutchouc. 2) Lisez le rebond de chaque balle sur les graphiques du panneau Instruments, e090.y, e060.y et e030.y (le centre de chaque balle, 0,15 m au-dessus de son point le plus bas), et l’endroit où chaque caisse s’arrête dans le tableau de on_ice.x, on_wood.x et on_rubber.x (chacune part de x = 0,5 m). 3) Sélectionnez une balle et changez sa restitution, ou une caisse et sa bande et changez leur frottement, puis réinitialisez et relancez. Ce qu’il faut regarder : chaque balle remonte à e²·h, 1,62 m, 0,72 m et 0,18 m pour e = 0,9, 0,6 et 0,3 ; chaque caisse s’arrête après v²/(2·μ·g), 8,2 m sur la glace (μ = 0,1), 2,0 m sur le bois (μ = 0,4) et 1,0 m sur le caoutchouc (μ = 0,8) ; l’énergie que perdent les rebonds et le glissement apparaît dans work_nc. Pourquoi : la restitution e est le rapport des vitesses juste après et juste avant un rebond, et comme la hauteur qu’atteint une balle varie comme le carré de sa vitesse, elle remonte à e² de sa chute. Le frottement de glissement s’oppose au glissement avec une force égale à μ fois la réaction normale, ici μ·m·g, donc la caisse décélère uniformément à μ·g quelle que soit sa masse. Une paire de matériaux se combine en max(e₁, e₂) et √(μ₁·μ₂) : le sol a e = 0, donc c’est le e de chaque balle qui compte, et chaque caisse a le même μ que sa bande. Un rebond est une impulsion que le solveur applique au moment de l’impact, tandis que le frottement d’un glissement régulier, comme la poussée du sol sous un corps au repos, agit comme une force dans le pas de l’intégrateur ; un rebond plus lent que le seuil de restitution (1 m/s fois 1 − e) est traité comme inélastique, c’est pourquoi les petits sauts finissent au repos au lieu de continuer à jamais ; avec e = 1 chaque rebond est élastique.</translation>
    </message>
    <message>
        <source>Lesson: the rolling race</source>
        <extracomment>lessons/rolling-race.phasebox.json: name</extracomment>
        <translation>Leçon : la course en roulant</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play and watch the three start together from rest on the same 20° slope, each 5 m (along the slope) from its finish. The ramps run on past the finish, so all three are still on them when the race ends at 3 s. 2) Guess the order first, then read it off the race: the graphs in the Instruments dock show slider.speed, disk.speed and box.speed, each a straight line whose slope is the body&apos;s acceleration. 3) Select the box or a ramp and change its friction, Reset, and race again. What to watch: the frictionless disk slides at g·sin θ = 3.36 m/s² and finishes 5 m in 1.73 s; the rolling disk (μ = 0.5) turns as it goes and accelerates at ⅔·g·sin θ = 2.24 m/s², finishing in 2.11 s; the box (μ = 0.2) slides at g·(sin θ − μ·cos θ) = 1.51 m/s², finishing in 2.57 s. The rolling disk loses no energy: work_nc stays at zero for it while the box&apos;s friction takes energy out. Why: a disk that rolls without slipping must spin up as it speeds up, so part of the work gravity does goes into ½·I·ω², with I = ½·m·r² and ω = v/r. Its kinetic energy is then ¾·m·v² instead of ½·m·v², so its acceleration is ⅔ of the frictionless g·sin θ, whatever its mass or radius. Static friction makes it roll but does no work, because the point of contact does not move. It needs only μ ≥ ⅓·tan θ = 0.12 to roll on this slope; with less, the disk slides and spins up more slowly. The box&apos;s kinetic friction does work, μ·m·g·cos θ per metre, which is why it comes last.</source>
        <extracomment>lessons/rolling-race.phasebox.json: description</extracomment>
        <translation>Essayez : 1) Appuyez sur Lecture et regardez les trois partir ensemble du repos sur la même pente de 20°, chacun à 5 m (le long de la pente) de son arrivée. Les rampes continuent au-delà de l’arrivée, donc les trois y sont encore quand la course finit à 3 s. 2) Devinez d’abord l’ordre, puis lisez-le dans la course : les graphiques du panneau Instruments montrent slider.speed, disk.speed et box.speed, chacun une droite dont la pente est l’accélération du corps. 3) Sélectionnez la boîte ou une rampe et changez son frottement, réinitialisez, et relancez la course. Ce qu’il faut regarder : le disque sans frottement glisse à g·sin θ = 3,36 m/s² et parcourt les 5 m en 1,73 s ; le disque qui roule (μ = 0,5) tourne en avançant et accélère à ⅔·g·sin θ = 2,24 m/s², arrivant en 2,11 s ; la boîte (μ = 0,2) glisse à g·(sin θ − μ·cos θ) = 1,51 m/s², arrivant en 2,57 s. Le disque qui roule ne perd aucune énergie : son work_nc reste à zéro tandis que le frottement de la boîte lui retire de l’énergie. Pourquoi : un disque qui roule sans glisser doit tourner plus vite à mesure qu’il accélère, donc une partie du travail de la pesanteur va dans ½·I·ω², avec I = ½·m·r² et ω = v/r. Son énergie cinétique est alors ¾·m·v² au lieu de ½·m·v², donc son accélération vaut ⅔ du g·sin θ sans frottement, quels que soient sa masse et son rayon. Le frottement statique le fait rouler mais ne travaille pas, car le point de contact ne bouge pas. Il lui suffit de μ ≥ ⅓·tan θ = 0,12 pour rouler sur cette pente ; avec moins, le disque glisse et prend sa rotation plus lentement. Le frottement de glissement de la boîte travaille, μ·m·g·cos θ par mètre, c’est pourquoi elle arrive la dernière.</translation>
    </message>
    <message>
        <source>Lesson: the simple pendulum</source>
        <extracomment>lessons/simple-pendulum.phasebox.json: name</extracomment>
        <translation>Leçon : le pendule simple</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: two 1 kg bobs hang on massless rigid rods 1 m long, the left one released from rest at 90° from the vertical (level with its pivot), the right one at 10°. 2) Read each period off the period timer in the Instruments dock: it times rod90.angle, the 90° pendulum&apos;s swing from straight down, as the mean interval between its upward crossings; choose rod10.angle as its probe to time the 10° one from then on (or click a bob and watch its loop in the Phase space plot close). 3) Reset and switch the integrator to explicit Euler, then RK4, and watch the swings and the energy plot; then try a smaller dt. What to watch: the 10° pendulum swings with a period of 2.0099 s, hardly more than the small-angle 2π·√(L/g) = 2.006 s; the 90° one takes 2.3678 s, 18% longer, so it falls further and further behind. Under symplectic Euler the energy wobbles a little but stays put; under explicit Euler the swings grow every period until Phasebox stops the run as diverging; RK4 keeps the energy to many decimals. Why: the rod holds the bob on a circle, so only gravity&apos;s component along the circle, −m·g·sin θ, speeds it up or slows it down, and the mass cancels. For small angles sin θ ≈ θ, the motion is simple harmonic and T = 2π·√(L/g) whatever the amplitude. Farther out sin θ &lt; θ, the pull back is weaker than the linear one, and the swing takes longer: the exact period is T = 4·√(L/g)·K(sin(θ0/2)), with K the complete elliptic integral of the first kind. With L = 1 m and g = 9.81 m/s² this gives 2.0099 s at 10° and 2.3678 s at 90°. The rod&apos;s pull does no work, because it is always at right angles to the motion: the energy plot&apos;s total is the integrator&apos;s doing.</source>
        <extracomment>lessons/simple-pendulum.phasebox.json: description</extracomment>
        <translation>Essayez : 1) Appuyez sur Lecture : deux masses de 1 kg pendent à des tiges rigides sans masse de 1 m, celle de gauche lâchée au repos à 90° de la verticale (à la hauteur de son pivot), celle de droite à 10°. 2) Lisez chaque période sur la mesure de période du panneau Instruments : elle chronomètre rod90.angle, l’écart du pendule de 90° à la verticale, comme l’intervalle moyen entre ses passages montants ; choisissez rod10.angle comme sonde pour chronométrer ensuite celui de 10° (ou cliquez une masse et regardez sa boucle se fermer dans l’espace des phases). 3) Réinitialisez et passez à Euler explicite, puis à RK4, et regardez les oscillations et le graphique d’énergie ; essayez ensuite un dt plus petit. Ce qu’il faut regarder : le pendule de 10° oscille avec une période de 2,0099 s, à peine plus que le 2π·√(L/g) = 2,006 s des petits angles ; celui de 90° met 2,3678 s, 18 % de plus, donc il prend de plus en plus de retard. Sous Euler symplectique l’énergie fluctue un peu mais reste en place ; sous Euler explicite les oscillations grandissent à chaque période jusqu’à ce que Phasebox arrête le calcul pour divergence ; RK4 garde l’énergie à de nombreuses décimales. Pourquoi : la tige tient la masse sur un cercle, donc seule la composante de la pesanteur le long du cercle, −m·g·sin θ, l’accélère ou la freine, et la masse se simplifie. Pour de petits angles sin θ ≈ θ, le mouvement est harmonique et T = 2π·√(L/g) quelle que soit l’amplitude. Plus loin sin θ &lt; θ, le rappel est plus faible que le rappel linéaire, et l’oscillation dure plus longtemps : la période exacte est T = 4·√(L/g)·K(sin(θ0/2)), avec K l’intégrale elliptique complète de première espèce. Avec L = 1 m et g = 9,81 m/s², cela donne 2,0099 s à 10° et 2,3678 s à 90°. La traction de la tige ne travaille pas, car elle est toujours perpendiculaire au mouvement : le total du graphique d’énergie est l’œuvre de l’intégrateur.</translation>
    </message>
    <message>
        <source>Lesson: a stiff spring, explicit against implicit</source>
        <extracomment>lessons/stiff-spring-implicit.phasebox.json: name</extracomment>
        <translation>Leçon : un ressort raide, explicite contre implicite</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: a 1 kg bob swings on a soft spring (k = 10 N/m) with a 10 g bead fastened to it by a very stiff spring (k = 10 000 N/m), under implicit Euler at dt = 1/60 s. 2) Reset, switch to symplectic Euler and play; then try RK4. 3) Go back to implicit Euler and compare with implicit midpoint. What to watch: the explicit methods blow up within a few frames and the world stops them as diverging, although the motion you see is the slow 2-second swing of the soft spring; implicit Euler runs, but the swing dies away, to half its size in 10 s (look at the drift in the energy plot); implicit midpoint runs and keeps the swing. Why: the bead on its stiff spring vibrates at ω = √(k·(1/m₁ + 1/m₂)) ≈ 1 000 rad/s, so ω·dt ≈ 17, far past the explicit methods&apos; stability limits (ω·dt &lt; 2 for symplectic Euler, 2.8 for RK4): the stiffest spring sets the step for the whole scene, even when its own motion is invisible. An implicit method evaluates the force at the end of the step and solves for it, which is stable at any step. Backward Euler pays with numerical damping of every motion, about (ω·dt)²/2 of the amplitude per step, while implicit midpoint keeps the energy of the slow swing. Symplectic Euler needs ω·h &lt; 2 here: 9 sub-steps per frame (RK4, stable to 2.8, needs 6), for a motion you cannot even see.</source>
        <extracomment>lessons/stiff-spring-implicit.phasebox.json: description</extracomment>
        <translation>Essayez : 1) Appuyez sur Lecture : une masse de 1 kg oscille sur un ressort souple (k = 10 N/m) avec une perle de 10 g fixée à elle par un ressort très raide (k = 10 000 N/m), sous Euler implicite à dt = 1/60 s. 2) Réinitialisez, passez à Euler symplectique et lancez ; essayez ensuite RK4. 3) Revenez à Euler implicite et comparez avec le point milieu implicite. Ce qu’il faut regarder : les méthodes explicites explosent en quelques images et le monde les arrête pour divergence, bien que le mouvement que l’on voit soit la lente oscillation de 2 secondes du ressort souple ; Euler implicite tourne, mais l’oscillation s’éteint, de moitié en 10 s (regardez la dérive dans le graphique d’énergie) ; le point milieu implicite tourne et garde l’oscillation. Pourquoi : la perle sur son ressort raide vibre à ω = √(k·(1/m₁ + 1/m₂)) ≈ 1 000 rad/s, donc ω·dt ≈ 17, bien au-delà des limites de stabilité des méthodes explicites (ω·dt &lt; 2 pour Euler symplectique, 2,8 pour RK4) : le ressort le plus raide fixe le pas de toute la scène, même quand son propre mouvement est invisible. Une méthode implicite évalue la force à la fin du pas et la résout, ce qui est stable à tout pas. Euler rétrograde le paie par un amortissement numérique de tout mouvement, environ (ω·dt)²/2 de l’amplitude par pas, tandis que le point milieu implicite conserve l’énergie de l’oscillation lente. Euler symplectique demande ici ω·h &lt; 2 : 9 sous-pas par image (RK4, stable jusqu’à 2,8, en demande 6), pour un mouvement que l’on ne voit même pas.</translation>
    </message>
    <message>
        <source>Lesson: three ways to collide</source>
        <extracomment>lessons/three-ways-to-collide.phasebox.json: name</extracomment>
        <translation>Leçon : trois façons de se heurter</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: a 1 kg ball with restitution 0.8 drops 2 m onto the ground, four 1 kg boxes stand in a stack and a Newton&apos;s cradle of five 1 kg balls on 2 m rods is released from 40°, all under impulse contacts (Parameters, Contacts); read the ball&apos;s bounces off the graph of ball.y in the Instruments dock (its centre: it touches the ground at ball.y = 0.25 m). 2) Reset, choose Penalty in Contacts and play again; watch the energy plot and click the dropped ball to see its phase plot. 3) Reset, choose Kinematic and play once more; each time, compare the step cost in the Effects panel. What to watch: under impulses the ball rebounds to 1.26 m (e²·h = 1.28 m), the stack stands still and the cradle hands the swing down the row to the last ball, which rises as high as the first one fell. Under penalty the dashed ghost beside the ball is the closed form of its bounces (free fall, then the damped contact spring; View → Exact Solution), and the phase plot of the ball draws it as a dashed curve. The ball sinks 4.6 cm into the ground and stays in contact for 0.026 s, half an oscillation of the contact spring, π·√(m/k)/√(1 − ζ²) with k = 14,400 N/m (the automatic choice, ω·h = 0.5 at dt = 1/240 s); it leaves at 0.80 of its speed, e = exp(−ζπ/√(1 − ζ²)) with ζ = c/(2·√(k·m)) = 0.071 from the contact damping c = 17 N·s/m. The stack sags a few millimetres, and in the cradle every ball swings: the momentum spreads along the row. Under kinematic the ball rebounds to 1.27 m as under impulses, but the energy plot&apos;s correction line climbs, about 0.8 J a second, while the drift line falls about as fast and work_nc falls with each bounce: every push out of an overlap adds energy, and the resting bodies&apos; fall back into the next overlap takes it out again. Why: kinematic response is geometry first: it moves overlapping bodies apart and flips the approaching velocity, exact for one isolated bounce, but it knows no forces, so a resting body is lifted and dropped again at every step. The penalty method makes contact a force, a stiff damped spring at each overlapping point, so the integrator treats it like any spring: ½·k·d² is in the potential energy, a bounce is half an oscillation, and a stiffer spring needs a smaller step (the stability advisor asks ω·h ≤ 1 of explicit methods). In a row of touching balls those springs form a chain that carries waves, so the cradle&apos;s momentum disperses instead of passing on whole. Impulses solve for the velocity changes that stop each approach at once, with restitution and friction as rules on those changes, which is why stacks rest and the cradle works, at the price of an iterative solver after every step. Penalty costs least per step but needs small steps when stiff; impulses cost most per step but hold a stack at any step.</source>
        <extracomment>lessons/three-ways-to-collide.phasebox.json: description</extracomment>
        <translation>Essayez : 1) Appuyez sur Lecture : une balle de 1 kg de restitution 0,8 tombe de 2 m sur le sol, quatre boîtes de 1 kg forment une pile et un pendule de Newton de cinq billes de 1 kg sur des tiges de 2 m est lâché depuis 40°, le tout avec des contacts par impulsions (Paramètres, Contacts) ; lisez les rebonds de la balle sur le graphique de ball.y du panneau Instruments (son centre : elle touche le sol à ball.y = 0,25 m). 2) Réinitialisez, choisissez Pénalité dans Contacts et relancez ; regardez le graphique d’énergie et cliquez la balle qui tombe pour voir son portrait de phase. 3) Réinitialisez, choisissez Cinématique et relancez encore ; à chaque fois, comparez le coût du pas dans le panneau Effets. Ce qu’il faut regarder : avec les impulsions la balle remonte à 1,26 m (e²·h = 1,28 m), la pile reste immobile et le pendule de Newton transmet l’oscillation le long de la rangée jusqu’à la dernière bille, qui monte aussi haut que la première est tombée. Avec la pénalité, le fantôme en tirets à côté de la balle est la forme fermée de ses rebonds (chute libre, puis le ressort de contact amorti ; Affichage → Solution exacte), et le portrait de phase de la balle la trace en courbe en tirets. La balle s’enfonce de 4,6 cm dans le sol et reste en contact 0,026 s, une demi-oscillation du ressort de contact, π·√(m/k)/√(1 − ζ²) avec k = 14 400 N/m (le choix automatique, ω·h = 0,5 à dt = 1/240 s) ; elle repart à 0,80 de sa vitesse, e = exp(−ζπ/√(1 − ζ²)) avec ζ = c/(2·√(k·m)) = 0,071 d’après l’amortissement de contact c = 17 N·s/m. La pile s’affaisse de quelques millimètres, et dans le pendule de Newton chaque bille oscille : la quantité de mouvement se répartit le long de la rangée. Avec la réponse cinématique la balle remonte à 1,27 m comme avec les impulsions, mais la ligne de correction du graphique d’énergie monte, d’environ 0,8 J par seconde, tandis que la ligne de dérive baisse à peu près aussi vite et que work_nc baisse à chaque rebond : chaque poussée hors d’un recouvrement ajoute de l’énergie, et la retombée des corps au repos dans le recouvrement suivant la retire de nouveau. Pourquoi : la réponse cinématique est d’abord de la géométrie : elle écarte les corps qui se recouvrent et retourne la vitesse d’approche, exacte pour un rebond isolé, mais elle ne connaît pas de forces, donc un corps au repos est soulevé puis relâché à chaque pas. La méthode de pénalité fait du contact une force, un ressort raide amorti en chaque point de recouvrement, donc l’intégrateur la traite comme tout ressort : ½·k·d² est dans l’énergie potentielle, un rebond est une demi-oscillation, et un ressort plus raide demande un pas plus petit (le conseiller de stabilité exige ω·h ≤ 1 des méthodes explicites). Dans une rangée de billes qui se touchent, ces ressorts forment une chaîne qui porte des ondes, donc la quantité de mouvement du pendule de Newton se disperse au lieu de passer entière. Les impulsions calculent les changements de vitesse qui arrêtent chaque approche d’un coup, avec la restitution et le frottement comme règles sur ces changements, c’est pourquoi les piles restent au repos et le pendule de Newton fonctionne, au prix d’un solveur itératif après chaque pas. La pénalité coûte le moins par pas mais demande de petits pas quand elle est raide ; les impulsions coûtent le plus par pas mais tiennent une pile à tout pas.</translation>
    </message>
</context>
<context>
    <name>Schema</name>
    <message>
        <source>Width</source>
        <translation>Largeur</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Hauteur</translation>
    </message>
    <message>
        <source>Columns</source>
        <translation>Colonnes</translation>
    </message>
    <message>
        <source>Rows</source>
        <translation>Lignes</translation>
    </message>
    <message>
        <source>%1 lower</source>
        <translation>%1 min</translation>
    </message>
    <message>
        <source>%1 upper</source>
        <translation>%1 max</translation>
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
        <translation>comment avance le temps</translation>
    </message>
    <message>
        <source>Integrator</source>
        <extracomment>schema: simulation.integrator</extracomment>
        <translation>Intégrateur</translation>
    </message>
    <message>
        <source>Time step</source>
        <extracomment>schema: simulation.dt</extracomment>
        <translation>Pas de temps</translation>
    </message>
    <message>
        <source>Sub-steps</source>
        <extracomment>schema: simulation.substeps</extracomment>
        <translation>Sous-pas</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <extracomment>schema: simulation.tolerance</extracomment>
        <translation>Tolérance</translation>
    </message>
    <message>
        <source>Newton iterations</source>
        <extracomment>schema: simulation.newton_iterations</extracomment>
        <translation>Itérations de Newton</translation>
    </message>
    <message>
        <source>Duration</source>
        <extracomment>schema: simulation.duration</extracomment>
        <translation>Durée</translation>
    </message>
    <message>
        <source>Contact solver</source>
        <extracomment>schema: simulation.solver</extracomment>
        <translation>Solveur de contacts</translation>
    </message>
    <message>
        <source>Contact model</source>
        <extracomment>schema: simulation.contact_model</extracomment>
        <translation>Modèle de contact</translation>
    </message>
    <message>
        <source>Contact stiffness</source>
        <extracomment>schema: simulation.contact_stiffness</extracomment>
        <translation>Raideur de contact</translation>
    </message>
    <message>
        <source>Contact damping</source>
        <extracomment>schema: simulation.contact_damping</extracomment>
        <translation>Amortissement de contact</translation>
    </message>
    <message>
        <source>Uniform gravity: F = m·g on every dynamic body</source>
        <extracomment>schema: gravity</extracomment>
        <translation>Pesanteur uniforme : F = m·g sur chaque corps mobile</translation>
    </message>
    <message>
        <source>g</source>
        <extracomment>schema: gravity.g</extracomment>
        <translation>g</translation>
    </message>
    <message>
        <source>Air drag: F = −b·v − c·‖v‖·v, torque −β·ω</source>
        <extracomment>schema: drag</extracomment>
        <translation>Frottement de l’air : F = −b·v − c·‖v‖·v, couple −β·ω</translation>
    </message>
    <message>
        <source>Linear b</source>
        <extracomment>schema: drag.linear</extracomment>
        <translation>Linéaire b</translation>
    </message>
    <message>
        <source>Quadratic c</source>
        <extracomment>schema: drag.quadratic</extracomment>
        <translation>Quadratique c</translation>
    </message>
    <message>
        <source>Angular β</source>
        <extracomment>schema: drag.angular</extracomment>
        <translation>Angulaire β</translation>
    </message>
    <message>
        <source>Newtonian gravity toward attractors (and between particles if mutual)</source>
        <extracomment>schema: newtonian_gravity</extracomment>
        <translation>Gravitation newtonienne vers les attracteurs (et entre particules si mutuelle)</translation>
    </message>
    <message>
        <source>G</source>
        <extracomment>schema: newtonian_gravity.G</extracomment>
        <translation>G</translation>
    </message>
    <message>
        <source>Attractors</source>
        <extracomment>schema: newtonian_gravity.attractors</extracomment>
        <translation>Attracteurs</translation>
    </message>
    <message>
        <source>Mutual</source>
        <extracomment>schema: newtonian_gravity.mutual</extracomment>
        <translation>Mutuelle</translation>
    </message>
    <message>
        <source>Softening ε</source>
        <extracomment>schema: newtonian_gravity.softening</extracomment>
        <translation>Adoucissement ε</translation>
    </message>
    <message>
        <source>Buoyancy ρ·A_sub·‖g‖ on the submerged part below the surface</source>
        <extracomment>schema: buoyancy</extracomment>
        <translation>Poussée d’Archimède ρ·A_sub·‖g‖ sur la partie immergée sous la surface</translation>
    </message>
    <message>
        <source>Fluid density ρ</source>
        <extracomment>schema: buoyancy.fluid_density</extracomment>
        <translation>Masse volumique du fluide ρ</translation>
    </message>
    <message>
        <source>Surface y</source>
        <extracomment>schema: buoyancy.surface_y</extracomment>
        <translation>Surface y</translation>
    </message>
    <message>
        <source>Drag b_f</source>
        <extracomment>schema: buoyancy.drag</extracomment>
        <translation>Traînée b_f</translation>
    </message>
    <message>
        <source>Wind: F = b·(w − v) on particles</source>
        <extracomment>schema: wind</extracomment>
        <translation>Vent : F = b·(w − v) sur les particules</translation>
    </message>
    <message>
        <source>Velocity w</source>
        <extracomment>schema: wind.velocity</extracomment>
        <translation>Vitesse w</translation>
    </message>
    <message>
        <source>Drag b</source>
        <extracomment>schema: wind.drag</extracomment>
        <translation>Traînée b</translation>
    </message>
    <message>
        <source>Boids steering: separation, alignment, cohesion (Reynolds 1987)</source>
        <extracomment>schema: flocking</extracomment>
        <translation>Pilotage de nuée : séparation, alignement, cohésion (Reynolds 1987)</translation>
    </message>
    <message>
        <source>Radius</source>
        <extracomment>schema: flocking.radius</extracomment>
        <translation>Rayon</translation>
    </message>
    <message>
        <source>Separation</source>
        <extracomment>schema: flocking.separation</extracomment>
        <translation>Séparation</translation>
    </message>
    <message>
        <source>Alignment</source>
        <extracomment>schema: flocking.alignment</extracomment>
        <translation>Alignement</translation>
    </message>
    <message>
        <source>Cohesion</source>
        <extracomment>schema: flocking.cohesion</extracomment>
        <translation>Cohésion</translation>
    </message>
    <message>
        <source>Maximum speed</source>
        <extracomment>schema: flocking.max_speed</extracomment>
        <translation>Vitesse maximale</translation>
    </message>
    <message>
        <source>Particle–particle disk contacts</source>
        <extracomment>schema: particle_collisions</extracomment>
        <translation>Contacts de disques entre particules</translation>
    </message>
    <message>
        <source>Restitution e</source>
        <extracomment>schema: particle_collisions.restitution</extracomment>
        <translation>Restitution e</translation>
    </message>
    <message>
        <source>Coulomb&apos;s law between charged particles</source>
        <extracomment>schema: coulomb</extracomment>
        <translation>Loi de Coulomb entre particules chargées</translation>
    </message>
    <message>
        <source>k</source>
        <extracomment>schema: coulomb.k</extracomment>
        <translation>k</translation>
    </message>
    <message>
        <source>fixed points of newtonian_gravity</source>
        <extracomment>schema: attractors</extracomment>
        <translation>points fixes de newtonian_gravity</translation>
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
        <translation>masses ponctuelles, dessinées comme des disques</translation>
    </message>
    <message>
        <source>Id</source>
        <extracomment>schema: particles.id</extracomment>
        <translation>Identifiant</translation>
    </message>
    <message>
        <source>Velocity</source>
        <extracomment>schema: particles.velocity</extracomment>
        <translation>Vitesse</translation>
    </message>
    <message>
        <source>Pinned</source>
        <extracomment>schema: particles.pinned</extracomment>
        <translation>Fixée</translation>
    </message>
    <message>
        <source>Restitution</source>
        <extracomment>schema: particles.restitution</extracomment>
        <translation>Restitution</translation>
    </message>
    <message>
        <source>Friction</source>
        <extracomment>schema: particles.friction</extracomment>
        <translation>Frottement</translation>
    </message>
    <message>
        <source>Charge</source>
        <extracomment>schema: particles.charge</extracomment>
        <translation>Charge</translation>
    </message>
    <message>
        <source>rigid rectangles</source>
        <extracomment>schema: boxes</extracomment>
        <translation>rectangles rigides</translation>
    </message>
    <message>
        <source>Size</source>
        <extracomment>schema: boxes.size</extracomment>
        <translation>Taille</translation>
    </message>
    <message>
        <source>Angle</source>
        <extracomment>schema: boxes.angle</extracomment>
        <translation>Angle</translation>
    </message>
    <message>
        <source>Angular velocity ω</source>
        <extracomment>schema: boxes.angular_velocity</extracomment>
        <translation>Vitesse angulaire ω</translation>
    </message>
    <message>
        <source>Density</source>
        <extracomment>schema: boxes.density</extracomment>
        <translation>Masse surfacique</translation>
    </message>
    <message>
        <source>Static</source>
        <extracomment>schema: boxes.static</extracomment>
        <translation>Immobile</translation>
    </message>
    <message>
        <source>rigid disks: they turn, so they roll</source>
        <extracomment>schema: disks</extracomment>
        <translation>disques rigides : ils tournent, donc ils roulent</translation>
    </message>
    <message>
        <source>rigid convex polygons</source>
        <extracomment>schema: polygons</extracomment>
        <translation>polygones convexes rigides</translation>
    </message>
    <message>
        <source>Vertices</source>
        <extracomment>schema: polygons.vertices</extracomment>
        <translation>Sommets</translation>
    </message>
    <message>
        <source>static half-planes, solid opposite the normal</source>
        <extracomment>schema: planes</extracomment>
        <translation>demi-plans immobiles, pleins du côté opposé à la normale</translation>
    </message>
    <message>
        <source>Point</source>
        <extracomment>schema: planes.point</extracomment>
        <translation>Point</translation>
    </message>
    <message>
        <source>Normal</source>
        <extracomment>schema: planes.normal</extracomment>
        <translation>Normale</translation>
    </message>
    <message>
        <source>damped springs between two objects or an anchor</source>
        <extracomment>schema: springs</extracomment>
        <translation>ressorts amortis entre deux objets ou un point d’attache</translation>
    </message>
    <message>
        <source>End a</source>
        <extracomment>schema: springs.a</extracomment>
        <translation>Extrémité a</translation>
    </message>
    <message>
        <source>End b</source>
        <extracomment>schema: springs.b</extracomment>
        <translation>Extrémité b</translation>
    </message>
    <message>
        <source>Anchor</source>
        <extracomment>schema: springs.anchor</extracomment>
        <translation>Point d’attache</translation>
    </message>
    <message>
        <source>Point on a</source>
        <extracomment>schema: springs.a_point</extracomment>
        <translation>Point sur a</translation>
    </message>
    <message>
        <source>Point on b</source>
        <extracomment>schema: springs.b_point</extracomment>
        <translation>Point sur b</translation>
    </message>
    <message>
        <source>Stiffness k</source>
        <extracomment>schema: springs.stiffness</extracomment>
        <translation>Raideur k</translation>
    </message>
    <message>
        <source>Damping c</source>
        <extracomment>schema: springs.damping</extracomment>
        <translation>Amortissement c</translation>
    </message>
    <message>
        <source>Rest length</source>
        <extracomment>schema: springs.rest_length</extracomment>
        <translation>Longueur à vide</translation>
    </message>
    <message>
        <source>grids of particles joined by springs</source>
        <extracomment>schema: cloths</extracomment>
        <translation>grilles de particules reliées par des ressorts</translation>
    </message>
    <message>
        <source>Origin</source>
        <extracomment>schema: cloths.origin</extracomment>
        <translation>Origine</translation>
    </message>
    <message>
        <source>Resolution</source>
        <extracomment>schema: cloths.resolution</extracomment>
        <translation>Résolution</translation>
    </message>
    <message>
        <source>Mass (total)</source>
        <extracomment>schema: cloths.mass</extracomment>
        <translation>Masse (totale)</translation>
    </message>
    <message>
        <source>Stiffness</source>
        <extracomment>schema: cloths.stiffness</extracomment>
        <translation>Raideur</translation>
    </message>
    <message>
        <source>Damping</source>
        <extracomment>schema: cloths.damping</extracomment>
        <translation>Amortissement</translation>
    </message>
    <message>
        <source>Node radius</source>
        <extracomment>schema: cloths.radius</extracomment>
        <translation>Rayon des nœuds</translation>
    </message>
    <message>
        <source>joints holding bodies together: hinges, rods, ropes, welds, pulleys, tracks</source>
        <extracomment>schema: joints</extracomment>
        <translation>liaisons qui tiennent des corps : charnières, tiges, cordes, soudures, poulies, rails</translation>
    </message>
    <message>
        <source>Type</source>
        <extracomment>schema: joints.type</extracomment>
        <translation>Type</translation>
    </message>
    <message>
        <source>Body a</source>
        <extracomment>schema: joints.a</extracomment>
        <translation>Corps a</translation>
    </message>
    <message>
        <source>Body b</source>
        <extracomment>schema: joints.b</extracomment>
        <translation>Corps b</translation>
    </message>
    <message>
        <source>Length</source>
        <extracomment>schema: joints.length</extracomment>
        <translation>Longueur</translation>
    </message>
    <message>
        <source>Limits</source>
        <extracomment>schema: joints.limits</extracomment>
        <translation>Butées</translation>
    </message>
    <message>
        <source>Motor</source>
        <extracomment>schema: joints.motor</extracomment>
        <translation>Moteur</translation>
    </message>
    <message>
        <source>Ground a</source>
        <extracomment>schema: joints.ground_a</extracomment>
        <translation>Point fixe a</translation>
    </message>
    <message>
        <source>Ground b</source>
        <extracomment>schema: joints.ground_b</extracomment>
        <translation>Point fixe b</translation>
    </message>
    <message>
        <source>Ratio</source>
        <extracomment>schema: joints.ratio</extracomment>
        <translation>Rapport</translation>
    </message>
    <message>
        <source>Circle</source>
        <extracomment>schema: joints.circle</extracomment>
        <translation>Cercle</translation>
    </message>
    <message>
        <source>Line</source>
        <extracomment>schema: joints.line</extracomment>
        <translation>Droite</translation>
    </message>
    <message>
        <source>a cloth&apos;s spring stiffnesses</source>
        <extracomment>schema: stiffness</extracomment>
        <translation>les raideurs des ressorts d’un tissu</translation>
    </message>
    <message>
        <source>Structural stiffness</source>
        <extracomment>schema: stiffness.structural</extracomment>
        <translation>Raideur de structure</translation>
    </message>
    <message>
        <source>Shear stiffness</source>
        <extracomment>schema: stiffness.shear</extracomment>
        <translation>Raideur de cisaillement</translation>
    </message>
    <message>
        <source>Bend stiffness</source>
        <extracomment>schema: stiffness.bend</extracomment>
        <translation>Raideur de flexion</translation>
    </message>
    <message>
        <source>a hinge&apos;s motor</source>
        <extracomment>schema: motor</extracomment>
        <translation>le moteur d’une charnière</translation>
    </message>
    <message>
        <source>Speed</source>
        <extracomment>schema: motor.speed</extracomment>
        <translation>Vitesse</translation>
    </message>
    <message>
        <source>Maximum torque</source>
        <extracomment>schema: motor.max_torque</extracomment>
        <translation>Couple maximal</translation>
    </message>
    <message>
        <source>the circle of a track</source>
        <extracomment>schema: circle</extracomment>
        <translation>le cercle d’un rail</translation>
    </message>
    <message>
        <source>Centre</source>
        <extracomment>schema: circle.center</extracomment>
        <translation>Centre</translation>
    </message>
    <message>
        <source>the line of a track</source>
        <extracomment>schema: line</extracomment>
        <translation>la droite d’un rail</translation>
    </message>
    <message>
        <source>Direction</source>
        <extracomment>schema: line.direction</extracomment>
        <translation>Direction</translation>
    </message>
    <message>
        <source>Sleep</source>
        <extracomment>schema: simulation.sleep</extracomment>
        <translation>Sommeil</translation>
    </message>
</context>
<context>
    <name>StabilityText</name>
    <message>
        <source>%1 (stable below %2 s)</source>
        <translation>%1 (stable en dessous de %2 s)</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3 (below the linear limit %4 but above %5, the margin for penalty contacts): a contact that begins within a step can gain energy at every touch. Use dt/substeps below %6 s (%7 sub-steps).</source>
        <translation>%1 avec un sous-pas de %2 s a ω·h = %3 (sous la limite linéaire %4 mais au-dessus de %5, la marge pour les contacts par pénalité) : un contact qui commence au cours d&apos;un pas peut gagner de l&apos;énergie à chaque contact. Prenez dt/sous-pas en dessous de %6 s (%7 sous-pas).</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3 (below the linear limit %4 but above %5, the margin for penalty contacts): a contact that begins within a step can gain energy at every touch. Use dt/substeps below %6 s (%7 sub-steps), or a method stable at this step: %8.</source>
        <translation>%1 avec un sous-pas de %2 s a ω·h = %3 (sous la limite linéaire %4 mais au-dessus de %5, la marge pour les contacts par pénalité) : un contact qui commence au cours d&apos;un pas peut gagner de l&apos;énergie à chaque contact. Prenez dt/sous-pas en dessous de %6 s (%7 sous-pas) ou une méthode stable à ce pas : %8.</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3 (stable below %4): it will blow up. Use dt/substeps below %5 s (%6 sub-steps, more for a margin).</source>
        <translation>%1 avec un sous-pas de %2 s a ω·h = %3 (stable en dessous de %4) : la simulation va exploser. Prenez dt/sous-pas en dessous de %5 s (%6 sous-pas, davantage pour une marge).</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3 (stable below %4): it will blow up. Use dt/substeps below %5 s (%6 sub-steps, more for a margin), or a method stable at this step: %7.</source>
        <translation>%1 avec un sous-pas de %2 s a ω·h = %3 (stable en dessous de %4) : la simulation va exploser. Prenez dt/sous-pas en dessous de %5 s (%6 sous-pas, davantage pour une marge) ou une méthode stable à ce pas : %7.</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3: it gains energy at every step (its stiffest mode by a factor of about %4 per sub-step).</source>
        <translation>%1 avec un sous-pas de %2 s a ω·h = %3 : elle gagne de l&apos;énergie à chaque pas (son mode le plus raide, d&apos;un facteur d&apos;environ %4 par sous-pas).</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3: it gains energy at every step (its stiffest mode by a factor of about %4 per sub-step). Use a method stable at this step: %5.</source>
        <translation>%1 avec un sous-pas de %2 s a ω·h = %3 : elle gagne de l&apos;énergie à chaque pas (son mode le plus raide, d&apos;un facteur d&apos;environ %4 par sous-pas). Prenez une méthode stable à ce pas : %5.</translation>
    </message>
    <message>
        <source>nothing in the scene oscillates</source>
        <translation>rien n&apos;oscille dans la scène</translation>
    </message>
    <message>
        <source>%1 is stable at this step (ω·h = %2)</source>
        <translation>%1 est stable à ce pas (ω·h = %2)</translation>
    </message>
    <message>
        <source>Kinematic contacts cannot hold a stack (&quot;%1&quot; rests on &quot;%2&quot;): they only stop bodies moving into each other and push them apart, so the stack sinks into the floor. Use impulse contacts for stacks.</source>
        <translation>Les contacts cinématiques ne peuvent pas porter une pile (« %1 » repose sur « %2 ») : ils empêchent seulement les corps d&apos;entrer l&apos;un dans l&apos;autre et les écartent, donc la pile s&apos;enfonce dans le sol. Utilisez des contacts par impulsions pour les piles.</translation>
    </message>
</context>
<context>
    <name>phasebox</name>
    <message>
        <source>the clip</source>
        <translation>le clip</translation>
    </message>
</context>
<context>
    <name>phasebox::AccuracyDialog</name>
    <message>
        <source>Accuracy Lab — what accuracy costs in time</source>
        <translation>Labo de précision – ce que coûte la précision en temps</translation>
    </message>
    <message>
        <source>Integrators to study</source>
        <translation>Intégrateurs à étudier</translation>
    </message>
    <message>
        <source>Step sizes, separated by commas; fractions such as 1/120 are fine. The adaptive methods sweep tolerances at the first dt instead.</source>
        <translation>Pas séparés par des virgules ; les fractions comme 1/120 sont acceptées. Les méthodes adaptatives parcourent plutôt des tolérances au premier dt.</translation>
    </message>
    <message>
        <source>Simulated seconds each run lasts; errors are measured at the end.</source>
        <translation>Secondes simulées par calcul ; les erreurs sont mesurées à la fin.</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Lancer</translation>
    </message>
    <message>
        <source>&amp;Cancel</source>
        <translation>&amp;Annuler</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exporter</translation>
    </message>
    <message>
        <source>&amp;dt list:</source>
        <translation>Liste des &amp;dt :</translation>
    </message>
    <message>
        <source>D&amp;uration [s]:</source>
        <translation>D&amp;urée [s] :</translation>
    </message>
    <message>
        <source>&amp;Integrators:</source>
        <translation>&amp;Intégrateurs :</translation>
    </message>
    <message>
        <source>The largest position error you accept at the end time, in metres</source>
        <translation>La plus grande erreur de position acceptée à l’instant final, en mètres</translation>
    </message>
    <message>
        <source>&amp;Apply to the scene</source>
        <translation>Appli&amp;quer à la scène</translation>
    </message>
    <message>
        <source>Cheapest settings for an error of</source>
        <translation>Réglages les moins coûteux pour une erreur de</translation>
    </message>
    <message>
        <source>m:</source>
        <translation>m :</translation>
    </message>
    <message>
        <source>Work-precision diagram</source>
        <translation>Diagramme travail-précision</translation>
    </message>
    <message>
        <source>Each point is one run, labelled with its step dt. &lt;b&gt;Lower is better&lt;/b&gt; (a smaller error) and &lt;b&gt;left is faster&lt;/b&gt; (less CPU time): the best methods sit at the lower left. A steeper line is a higher order: halving dt divides the error by 2&lt;sup&gt;p&lt;/sup&gt;.</source>
        <translation>Chaque point est un calcul, étiqueté par son pas dt. &lt;b&gt;Plus bas est mieux&lt;/b&gt; (une erreur plus petite) et &lt;b&gt;plus à gauche est plus rapide&lt;/b&gt; (moins de temps CPU) : les meilleures méthodes sont en bas à gauche. Une droite plus raide est un ordre plus élevé : diviser dt par deux divise l’erreur par 2&lt;sup&gt;p&lt;/sup&gt;.</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>intégrateur</translation>
    </message>
    <message>
        <source>dt</source>
        <translation>dt</translation>
    </message>
    <message>
        <source>tolerance</source>
        <translation>tolérance</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>pas</translation>
    </message>
    <message>
        <source>force evals</source>
        <translation>évaluations de force</translation>
    </message>
    <message>
        <source>CPU [s]</source>
        <translation>CPU [s]</translation>
    </message>
    <message>
        <source>position error [m]</source>
        <translation>erreur de position [m]</translation>
    </message>
    <message>
        <source>energy drift [J]</source>
        <translation>dérive d’énergie [J]</translation>
    </message>
    <message>
        <source>order</source>
        <translation>ordre</translation>
    </message>
    <message>
        <source>measured order</source>
        <translation>ordre mesuré</translation>
    </message>
    <message>
        <source>theory</source>
        <translation>théorie</translation>
    </message>
    <message>
        <source>what it means</source>
        <translation>ce que cela signifie</translation>
    </message>
    <message>
        <source>Rest the mouse on a row for the whole explanation</source>
        <translation>Laissez la souris sur une ligne pour l’explication complète</translation>
    </message>
    <message>
        <source>&amp;Orders</source>
        <translation>&amp;Ordres</translation>
    </message>
    <message>
        <source>A&amp;ll runs</source>
        <translation>&amp;Tous les calculs</translation>
    </message>
    <message>
        <source>Scene: %1. Press Run: every checked method runs the scene at every dt on a copy; the open scene is not touched.</source>
        <translation>Scène : %1. Appuyez sur Lancer : chaque méthode cochée calcule la scène à chaque dt sur une copie ; la scène ouverte n’est pas touchée.</translation>
    </message>
    <message>
        <source>Check at least one integrator.</source>
        <translation>Cochez au moins un intégrateur.</translation>
    </message>
    <message>
        <source>dt list: &quot;%1&quot; is not a step in (0, 1] s.</source>
        <translation>Liste des dt : « %1 » n’est pas un pas dans (0, 1] s.</translation>
    </message>
    <message>
        <source>Duration: a number of seconds &gt; 0, please.</source>
        <translation>Durée : un nombre de secondes &gt; 0, s’il vous plaît.</translation>
    </message>
    <message>
        <source>Running…</source>
        <translation>Calcul en cours…</translation>
    </message>
    <message>
        <source>The study could not run: %1</source>
        <translation>L’étude n’a pas pu être lancée : %1</translation>
    </message>
    <message>
        <source>%1: error at t = %2 s against CPU time</source>
        <translation>%1 : erreur à t = %2 s en fonction du temps CPU</translation>
    </message>
    <message>
        <source>Reference: %1. %2 runs%3.</source>
        <translation>Référence : %1. %2 calculs%3.</translation>
    </message>
    <message>
        <source> (cancelled)</source>
        <translation> (annulé)</translation>
    </message>
    <message>
        <source>This scene has contacts: </source>
        <translation>Cette scène a des contacts : </translation>
    </message>
    <message>
        <source>The end time was moved to %1 s, where the motion is fastest: at a turning point every method looks better than it is.</source>
        <translation>L’instant final a été déplacé à %1 s, là où le mouvement est le plus rapide : à un point de rebroussement, toute méthode paraît meilleure qu’elle n’est.</translation>
    </message>
    <message>
        <source>diverged: unstable at this dt</source>
        <translation>divergé : instable à ce dt</translation>
    </message>
    <message>
        <source>unstable at this dt</source>
        <translation>instable à ce dt</translation>
    </message>
    <message>
        <source>The error does not shrink as the step is halved here: the method is unstable at this step, so this number is not its order.</source>
        <translation>L’erreur ne diminue pas ici quand le pas est divisé par deux : la méthode est instable à ce pas, donc ce nombre n’est pas son ordre.</translation>
    </message>
    <message>
        <source>round-off floor reached</source>
        <translation>plancher d’arrondi atteint</translation>
    </message>
    <message>
        <source>reference&apos;s accuracy reached</source>
        <translation>précision de la référence atteinte</translation>
    </message>
    <message>
        <source>The error is already as small as rounding (or the reference) allows: smaller steps no longer improve it, so this number is not the method&apos;s order.</source>
        <translation>L’erreur est déjà aussi petite que l’arrondi (ou la référence) le permet : des pas plus petits ne l’améliorent plus, donc ce nombre n’est pas l’ordre de la méthode.</translation>
    </message>
    <message>
        <source>type an error such as 1e-4</source>
        <translation>tapez une erreur comme 1e-4</translation>
    </message>
    <message>
        <source>run the study first</source>
        <translation>lancez d’abord l’étude</translation>
    </message>
    <message>
        <source>no run reached it: try smaller steps or a higher-order method</source>
        <translation>aucun calcul ne l’a atteinte : essayez des pas plus petits ou une méthode d’ordre plus élevé</translation>
    </message>
    <message>
        <source>the scene has changed since this study: run it again to apply</source>
        <translation>la scène a changé depuis cette étude : relancez-la pour appliquer</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; at dt %2%3: error %4 m in %5 s of CPU</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; à dt %2%3 : erreur %4 m en %5 s de CPU</translation>
    </message>
    <message>
        <source>, tolerance %1</source>
        <translation>, tolérance %1</translation>
    </message>
    <message>
        <source>the CSV file</source>
        <translation>le fichier CSV</translation>
    </message>
    <message>
        <source>%1: error against CPU time</source>
        <translation>%1 : erreur en fonction du temps CPU</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exporter</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Échec de l’export</translation>
    </message>
    <message>
        <source>Step sizes, separated by semicolons; fractions such as 1/120 are fine. The adaptive methods sweep tolerances at the first dt instead.</source>
        <translation>Pas séparés par des points-virgules ; les fractions comme 1/120 sont acceptées. Les méthodes adaptatives parcourent plutôt des tolérances au premier dt.</translation>
    </message>
</context>
<context>
    <name>phasebox::AnimationExport</name>
    <message>
        <source>%1: unknown clip format; known: %2</source>
        <translation>%1 : format de clip inconnu ; connus : %2</translation>
    </message>
    <message>
        <source>Exporting %1…</source>
        <translation>Exportation de %1…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Wrote %1 (%2 frames)</source>
        <translation>%1 écrit (%2 images)</translation>
    </message>
    <message>
        <source>Wrote %1; the run diverged: %2</source>
        <translation>%1 écrit ; la simulation a divergé : %2</translation>
    </message>
    <message>
        <source>Export cancelled; nothing was written</source>
        <translation>Exportation annulée ; rien n’a été écrit</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Échec de l’exportation</translation>
    </message>
</context>
<context>
    <name>phasebox::AnimationExportDialog</name>
    <message>
        <source>Export Animation</source>
        <translation>Exporter l’animation</translation>
    </message>
    <message>
        <source>Clip file</source>
        <translation>Fichier du clip</translation>
    </message>
    <message>
        <source>A .mp4 file (H.264 video) or a .gif file (animated GIF)</source>
        <translation>Un fichier .mp4 (vidéo H.264) ou .gif (GIF animé)</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>&amp;Parcourir…</translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation>&amp;Fichier :</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Start time</source>
        <translation>Instant de début</translation>
    </message>
    <message>
        <source>Simulated time of the first frame</source>
        <translation>Temps simulé de la première image</translation>
    </message>
    <message>
        <source>Fro&amp;m:</source>
        <translation>&amp;De :</translation>
    </message>
    <message>
        <source>Duration</source>
        <translation>Durée</translation>
    </message>
    <message>
        <source>Simulated seconds the clip shows</source>
        <translation>Secondes simulées que montre le clip</translation>
    </message>
    <message>
        <source>&amp;Duration:</source>
        <translation>D&amp;urée :</translation>
    </message>
    <message>
        <source>Frames per second</source>
        <translation>Images par seconde</translation>
    </message>
    <message>
        <source> fps</source>
        <translation> i/s</translation>
    </message>
    <message>
        <source>Frame &amp;rate:</source>
        <translation>&amp;Fréquence d’images :</translation>
    </message>
    <message>
        <source>Width in pixels</source>
        <translation>Largeur en pixels</translation>
    </message>
    <message>
        <source>Height in pixels</source>
        <translation>Hauteur en pixels</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>&amp;Size:</source>
        <translation>&amp;Taille :</translation>
    </message>
    <message>
        <source>&amp;Plots beside the canvas (energy and phase space)</source>
        <translation>&amp;Graphiques à côté du canevas (énergie et espace des phases)</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exporter</translation>
    </message>
    <message>
        <source>MP4 video (*.mp4);;Animated GIF (*.gif)</source>
        <translation>Vidéo MP4 (*.mp4);;GIF animé (*.gif)</translation>
    </message>
</context>
<context>
    <name>phasebox::AppearancePresenter</name>
    <message>
        <source>High &amp;Contrast</source>
        <translation>&amp;Contraste élevé</translation>
    </message>
    <message>
        <source>White on black, with a yellow selection and focus: for a projector or for low vision</source>
        <translation>Blanc sur noir, avec sélection et focus jaunes : pour un vidéoprojecteur ou une basse vision</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Line &amp;Width</source>
        <translation>É&amp;paisseur des traits</translation>
    </message>
    <message>
        <source>Te&amp;xt Size</source>
        <translation>&amp;Taille du texte</translation>
    </message>
</context>
<context>
    <name>phasebox::CanvasPresenter</name>
    <message>
        <source> sides</source>
        <translation> côtés</translation>
    </message>
    <message>
        <source>Sides of the regular polygon the Add polygon tool draws</source>
        <translation>Côtés du polygone régulier que trace l’outil Ajouter un polygone</translation>
    </message>
    <message>
        <source>The kind of joint the Add joint tool makes</source>
        <translation>Le type de liaison que crée l’outil Ajouter une liaison</translation>
    </message>
    <message>
        <source>&amp;Fit Scene</source>
        <translation>&amp;Cadrer la scène</translation>
    </message>
    <message>
        <source>F&amp;ollow</source>
        <translation>&amp;Suivre</translation>
    </message>
    <message>
        <source>Keep the selection, or every moving object, in view while it runs</source>
        <translation>Garder la sélection, ou chaque objet en mouvement, en vue pendant le calcul</translation>
    </message>
    <message>
        <source>Export &amp;Canvas as PNG…</source>
        <translation>Exporter le &amp;canevas en PNG…</translation>
    </message>
    <message>
        <source>&amp;Trails</source>
        <translation>&amp;Traces</translation>
    </message>
    <message>
        <source>&amp;Velocity Arrows</source>
        <translation>Flèches de &amp;vitesse</translation>
    </message>
    <message>
        <source>&amp;Force Arrows (springs, joints)</source>
        <translation>Flèches de &amp;force (ressorts, liaisons)</translation>
    </message>
    <message>
        <source>Object &amp;Labels</source>
        <translation>É&amp;tiquettes des objets</translation>
    </message>
    <message>
        <source>Metre &amp;Grid</source>
        <translation>&amp;Grille métrique</translation>
    </message>
    <message>
        <source>%1: cannot draw the picture</source>
        <translation>%1 : impossible de dessiner l’image</translation>
    </message>
    <message>
        <source>the picture</source>
        <translation>l’image</translation>
    </message>
    <message>
        <source>Export Canvas</source>
        <translation>Exporter le canevas</translation>
    </message>
    <message>
        <source>PNG (*.png)</source>
        <translation>PNG (*.png)</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Échec de l’export</translation>
    </message>
    <message>
        <source>Nothing selected. Tab walks the objects; with a drawing tool, the arrow keys move the cursor and Enter places the object there.</source>
        <translation>Rien de sélectionné. Tab parcourt les objets ; avec un outil de dessin, les flèches déplacent le curseur et Entrée y pose l’objet.</translation>
    </message>
    <message>
        <source>Selected: %1 %2.</source>
        <translation>Sélection : %1 %2.</translation>
    </message>
    <message>
        <source>Position %1, %2 m; velocity %3, %4 m/s.</source>
        <translation>Position %1 ; %2 m ; vitesse %3 ; %4 m/s.</translation>
    </message>
    <message>
        <source>Arrows move it (Shift: finely), Enter opens its properties.</source>
        <translation>Les flèches le déplacent (Maj : finement), Entrée ouvre ses propriétés.</translation>
    </message>
    <message>
        <source>hinge</source>
        <translation>charnière</translation>
    </message>
    <message>
        <source>rod</source>
        <translation>tige</translation>
    </message>
    <message>
        <source>rope</source>
        <translation>corde</translation>
    </message>
    <message>
        <source>weld</source>
        <translation>soudure</translation>
    </message>
    <message>
        <source>pulley</source>
        <translation>poulie</translation>
    </message>
    <message>
        <source>track</source>
        <translation>rail</translation>
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
        <translation>Ce coin rendrait le polygone non convexe ; les polygones doivent être convexes (construisez une forme concave avec des pièces convexes).</translation>
    </message>
    <message>
        <source>That corner is in a line with two others: move it off the line.</source>
        <translation>Ce coin est aligné avec deux autres : écartez-le de la ligne.</translation>
    </message>
    <message>
        <source>That corner is on top of another one.</source>
        <translation>Ce coin est sur un autre.</translation>
    </message>
    <message>
        <source>That corner is refused: %1</source>
        <translation>Ce coin est refusé : %1</translation>
    </message>
    <message>
        <source>Select / move</source>
        <translation>Sélectionner / déplacer</translation>
    </message>
    <message>
        <source>Add particle</source>
        <translation>Ajouter une particule</translation>
    </message>
    <message>
        <source>Add spring</source>
        <translation>Ajouter un ressort</translation>
    </message>
    <message>
        <source>Add cloth</source>
        <translation>Ajouter un tissu</translation>
    </message>
    <message>
        <source>Add box</source>
        <translation>Ajouter une boîte</translation>
    </message>
    <message>
        <source>Add disk</source>
        <translation>Ajouter un disque</translation>
    </message>
    <message>
        <source>Add polygon</source>
        <translation>Ajouter un polygone</translation>
    </message>
    <message>
        <source>Add plane</source>
        <translation>Ajouter un plan</translation>
    </message>
    <message>
        <source>Pin / unpin</source>
        <translation>Fixer / libérer</translation>
    </message>
    <message>
        <source>Add joint</source>
        <translation>Ajouter une liaison</translation>
    </message>
    <message>
        <source>Ruler</source>
        <translation>Règle</translation>
    </message>
    <message>
        <source>Protractor</source>
        <translation>Rapporteur</translation>
    </message>
    <message>
        <source>Click to select (Shift adds), drag to move; while running, drag an object to pull it with a mouse spring.</source>
        <translation>Cliquez pour sélectionner (Maj ajoute), glissez pour déplacer ; pendant le calcul, glissez un objet pour le tirer avec un ressort de souris.</translation>
    </message>
    <message>
        <source>Click to drop a particle; drag to give it a velocity.</source>
        <translation>Cliquez pour poser une particule ; glissez pour lui donner une vitesse.</translation>
    </message>
    <message>
        <source>Drag from an object to another, or to empty space for a fixed anchor.</source>
        <translation>Glissez d’un objet à un autre, ou vers le vide pour un point d’attache fixe.</translation>
    </message>
    <message>
        <source>Drag a rectangle: a cloth hung from its top corners.</source>
        <translation>Glissez un rectangle : un tissu suspendu par ses coins supérieurs.</translation>
    </message>
    <message>
        <source>Drag a rectangle: a box of that size.</source>
        <translation>Glissez un rectangle : une boîte de cette taille.</translation>
    </message>
    <message>
        <source>Drag from the centre to the rim: a disk that rolls; click for one of 0.5 m.</source>
        <translation>Glissez du centre au bord : un disque qui roule ; cliquez pour un disque de 0,5 m.</translation>
    </message>
    <message>
        <source>Drag from the centre to a corner: a regular polygon, flat side down; or click the corners and close on the first (double click or Enter closes, Backspace undoes a corner, Esc drops the outline).</source>
        <translation>Glissez du centre vers un coin : un polygone régulier, côté plat en bas ; ou cliquez les coins et fermez sur le premier (double clic ou Entrée ferme, Retour arrière annule un coin, Échap abandonne le contour).</translation>
    </message>
    <message>
        <source>Drag a line along the surface; the solid side is to the right of the drag.</source>
        <translation>Glissez une ligne le long de la surface ; le côté solide est à droite du glissement.</translation>
    </message>
    <message>
        <source>Click a particle to pin or unpin it, a box or disk to make it static.</source>
        <translation>Cliquez une particule pour la fixer ou la libérer, une boîte ou un disque pour le rendre immobile.</translation>
    </message>
    <message>
        <source>Drag from a body to another, or to empty space for the fixed world: a hinge pivots where the drag starts; a rod or rope joins the two points; a weld holds two bodies together; a pulley hangs two bodies over two wheels a metre above; a track puts a particle on a hoop centred where the drag ends.</source>
        <translation>Glissez d’un corps à un autre, ou vers le vide pour le monde fixe : une charnière pivote là où le glissement commence ; une tige ou une corde relie les deux points ; une soudure tient deux corps ensemble ; une poulie suspend deux corps à deux roues un mètre au-dessus ; un rail met une particule sur un cerceau centré là où le glissement finit.</translation>
    </message>
    <message>
        <source>Drag from one point to another to measure the distance; an end dropped on an object follows it. Click a ruler to select it, Esc or Delete removes it.</source>
        <translation>Glissez d’un point à un autre pour mesurer la distance ; une extrémité posée sur un objet le suit. Cliquez une règle pour la sélectionner ; Échap ou Suppr la retire.</translation>
    </message>
    <message>
        <source>Drag from the vertex along the first arm, then click the second arm: the angle between them. Ends dropped on objects follow them; Esc or Delete removes the selected one.</source>
        <translation>Glissez depuis le sommet le long du premier côté, puis cliquez le second côté : l’angle entre eux. Les extrémités posées sur des objets les suivent ; Échap ou Suppr retire celui sélectionné.</translation>
    </message>
    <message>
        <source>Pulling %1 with a mouse spring</source>
        <translation>%1 tiré par un ressort de souris</translation>
    </message>
    <message>
        <source>pulling %1</source>
        <translation>tire %1</translation>
    </message>
    <message>
        <source>v = %1 m/s</source>
        <translation>v = %1 m/s</translation>
    </message>
    <message>
        <source>anchor, %1</source>
        <translation>point d’attache, %1</translation>
    </message>
    <message>
        <source>r = %1</source>
        <translation>r = %1</translation>
    </message>
    <message>
        <source>A spring starts on an object: drag from a particle or box.</source>
        <translation>Un ressort part d’un objet : glissez depuis une particule ou une boîte.</translation>
    </message>
    <message>
        <source>A joint starts on a body: drag from a particle, box, disk or polygon.</source>
        <translation>Une liaison part d’un corps : glissez depuis une particule, une boîte, un disque ou un polygone.</translation>
    </message>
    <message>
        <source>Only particles can be pinned and boxes and disks made static.</source>
        <translation>Seules les particules peuvent être fixées, et les boîtes et disques rendus immobiles.</translation>
    </message>
    <message>
        <source>A polygon needs at least three corners.</source>
        <translation>Un polygone a besoin d’au moins trois coins.</translation>
    </message>
    <message>
        <source>Corner %1: click the next corner.</source>
        <translation>Coin %1 : cliquez le coin suivant.</translation>
    </message>
    <message>
        <source>Corner %1: click the next, or the first corner (or Enter) to close.</source>
        <translation>Coin %1 : cliquez le suivant, ou le premier coin (ou Entrée) pour fermer.</translation>
    </message>
    <message numerus="yes">
        <source>%n corner(s)</source>
        <translation>
            <numerusform>%n coin</numerusform>
            <numerusform>%n coins</numerusform>
        </translation>
    </message>
    <message>
        <source>Outline dropped.</source>
        <translation>Contour abandonné.</translation>
    </message>
    <message>
        <source>Drag to where the %1 ends: another body or a fixed point.</source>
        <translation>Glissez jusqu’à l’autre extrémité (%1) : un autre corps ou un point fixe.</translation>
    </message>
    <message>
        <source>rod</source>
        <translation>tige</translation>
    </message>
    <message>
        <source>rope</source>
        <translation>corde</translation>
    </message>
    <message>
        <source>A weld holds two bodies: drag from one onto the other.</source>
        <translation>Une soudure tient deux corps : glissez de l’un sur l’autre.</translation>
    </message>
    <message>
        <source>A pulley hangs two bodies: drag from one to the other.</source>
        <translation>Une poulie suspend deux corps : glissez de l’un à l’autre.</translation>
    </message>
    <message>
        <source>Drag from a particle to the centre of its hoop.</source>
        <translation>Glissez d’une particule au centre de son cerceau.</translation>
    </message>
</context>
<context>
    <name>phasebox::CompareDialog</name>
    <message>
        <source>Compare from Here</source>
        <translation>Comparer à partir d&apos;ici</translation>
    </message>
    <message>
        <source>From t = %L1 s the run goes on with the settings below, while the recorded run (%2, dt %L3 s) is drawn beside it as a ghost.</source>
        <translation>À partir de t = %L1 s, la simulation continue avec les réglages ci-dessous, tandis que la simulation enregistrée (%2, dt %L3 s) est dessinée à côté comme un fantôme.</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>&amp;Integrator:</source>
        <translation>&amp;Intégrateur :</translation>
    </message>
    <message>
        <source>&amp;dt:</source>
        <translation>&amp;dt :</translation>
    </message>
    <message>
        <source>&amp;Contacts:</source>
        <translation>&amp;Contacts :</translation>
    </message>
    <message>
        <source>Co&amp;mpare</source>
        <translation>Co&amp;mparer</translation>
    </message>
</context>
<context>
    <name>phasebox::ComparePresenter</name>
    <message>
        <source>&amp;Compare from Here…</source>
        <translation>&amp;Comparer à partir d&apos;ici…</translation>
    </message>
    <message>
        <source>Run on from the timeline&apos;s moment with another integrator, dt or contact model, with the recorded run beside it as a ghost</source>
        <translation>Repartir du moment de la frise avec un autre intégrateur, dt ou modèle de contact, la simulation enregistrée à côté comme un fantôme</translation>
    </message>
    <message>
        <source>Compare…</source>
        <translation>Comparer…</translation>
    </message>
    <message>
        <source>&amp;Leave Compare</source>
        <translation>&amp;Quitter la comparaison</translation>
    </message>
    <message>
        <source>Remove the recorded run&apos;s ghost from the canvas and the plots</source>
        <translation>Retirer le fantôme de la simulation enregistrée du canevas et des graphiques</translation>
    </message>
    <message>
        <source>Leave compare</source>
        <translation>Fin comparaison</translation>
    </message>
    <message>
        <source>Comparing from t = %L1 s: %2 against the recorded run (dashed).</source>
        <translation>Comparaison à partir de t = %L1 s : %2 contre la simulation enregistrée (en pointillés).</translation>
    </message>
    <message>
        <source>Drag the timeline to an earlier moment first: the run is compared from there.</source>
        <translation>Faites d&apos;abord glisser la frise chronologique vers un moment antérieur : la simulation est comparée à partir de là.</translation>
    </message>
    <message>
        <source>Left Compare: the recorded run&apos;s ghost is gone.</source>
        <translation>Comparaison quittée : le fantôme de la simulation enregistrée a disparu.</translation>
    </message>
    <message>
        <source>recorded: %1</source>
        <translation>enregistré : %1</translation>
    </message>
    <message>
        <source>, dt %L1 s</source>
        <translation>, dt %L1 s</translation>
    </message>
    <message>
        <source>Ghost: the recorded run ended at t = %L1 s</source>
        <translation>Fantôme : la simulation enregistrée s&apos;est arrêtée à t = %L1 s</translation>
    </message>
    <message>
        <source>Ghost: the recorded run, %1</source>
        <translation>Fantôme : la simulation enregistrée, %1</translation>
    </message>
</context>
<context>
    <name>phasebox::DivergenceNotice</name>
    <message>
        <source>The simulation became unstable</source>
        <translation>La simulation est devenue instable</translation>
    </message>
</context>
<context>
    <name>phasebox::Document</name>
    <message>
        <source>Switched to %1 so the %2 stays stable; Undo to go back to %3</source>
        <translation>Passé à %1 pour que %2 reste stable ; Annuler revient à %3</translation>
    </message>
    <message>
        <source>unknown effect &quot;%1&quot;; known: %2</source>
        <translation>effet inconnu « %1 » ; connus : %2</translation>
    </message>
    <message>
        <source>Switch on %1</source>
        <translation>Activer %1</translation>
    </message>
    <message>
        <source>Switch off %1</source>
        <translation>Désactiver %1</translation>
    </message>
    <message>
        <source>Change effects</source>
        <translation>Modifier les effets</translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation>Modifier %1</translation>
    </message>
</context>
<context>
    <name>phasebox::EffectsPresenter</name>
    <message>
        <source>Runs because the scene has springs</source>
        <translation>Tourne parce que la scène a des ressorts</translation>
    </message>
    <message>
        <source>Runs because the scene holds things that can touch</source>
        <translation>Tourne parce que la scène contient des choses qui peuvent se toucher</translation>
    </message>
    <message>
        <source>The integrator&apos;s own arithmetic</source>
        <translation>L’arithmétique propre de l’intégrateur</translation>
    </message>
    <message>
        <source>Costs per step of the whole run: a recorded frame keeps no timing of its own.</source>
        <translation>Coûts par pas sur toute la simulation : une image enregistrée ne garde pas de mesure de temps propre.</translation>
    </message>
</context>
<context>
    <name>phasebox::ExactPresenter</name>
    <message>
        <source>E&amp;xact Solution</source>
        <translation>Solution e&amp;xacte</translation>
    </message>
    <message>
        <source>Draw the exact (closed-form) motion beside the simulation, dashed, when the scene has one: oscillators, free fall, orbits, pendulums, Atwood machines, rolling and sliding on ramps (until a contact begins or ends)</source>
        <translation>Dessiner le mouvement exact (formule fermée) à côté de la simulation, en tirets, quand la scène en a un : oscillateurs, chute libre, orbites, pendules, machines d’Atwood, roulement et glissement sur des rampes (jusqu’au début ou à la fin d’un contact)</translation>
    </message>
    <message>
        <source>exact</source>
        <translation>exacte</translation>
    </message>
    <message>
        <source>dashed: exact solution (%1)</source>
        <translation>tirets : solution exacte (%1)</translation>
    </message>
    <message>
        <source>dashed: exact solution (%1) until t = %2 s, where a contact begins or ends</source>
        <translation>tirets : solution exacte (%1) jusqu’à t = %2 s, où un contact commence ou finit</translation>
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
        <translation>Énergie (%1)</translation>
    </message>
    <message>
        <source>Phase space</source>
        <translation>Espace des phases</translation>
    </message>
    <message>
        <source>Phase space of %1</source>
        <translation>Espace des phases de %1</translation>
    </message>
</context>
<context>
    <name>phasebox::HelpWindows</name>
    <message>
        <source>About Phasebox</source>
        <translation>À propos de Phasebox</translation>
    </message>
    <message>
        <source>&lt;b&gt;Phasebox %1&lt;/b&gt;&lt;p&gt;A 2D physics sandbox for the classroom: drop particles, springs, cloth and boxes into a scene, switch the integrator while it runs, and watch what accuracy costs.&lt;/p&gt;</source>
        <translation>&lt;b&gt;Phasebox %1&lt;/b&gt;&lt;p&gt;Un bac à sable de physique 2D pour la classe : posez des particules, des ressorts, des tissus et des boîtes dans une scène, changez d’intégrateur pendant le calcul et voyez ce que coûte la précision.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>phasebox::InstrumentsPresenter</name>
    <message>
        <source>&amp;Instruments</source>
        <translation>&amp;Instruments</translation>
    </message>
    <message>
        <source>Start/Stop S&amp;topwatch</source>
        <translation>Démarrer/arrêter le &amp;chronomètre</translation>
    </message>
    <message>
        <source>The stopwatch on simulated time (Instruments → Timer)</source>
        <translation>Le chronomètre en temps simulé (Instruments → Minuteur)</translation>
    </message>
    <message>
        <source>Stopwatch &amp;Lap</source>
        <translation>&amp;Tour du chronomètre</translation>
    </message>
    <message>
        <source>Probe Table as CSV…</source>
        <translation>Tableau des sondes en CSV…</translation>
    </message>
</context>
<context>
    <name>phasebox::LanguageMenu</name>
    <message>
        <source>&amp;System Language</source>
        <translation>Langue du &amp;système</translation>
    </message>
    <message>
        <source>Phasebox will speak %1 from its next start.</source>
        <translation>Phasebox parlera %1 à son prochain démarrage.</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Langue</translation>
    </message>
</context>
<context>
    <name>phasebox::MainWindow</name>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Échec de la sauvegarde automatique : %1</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Nouveau</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Ouvrir…</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Enregistrer</translation>
    </message>
    <message>
        <source>Re&amp;vert</source>
        <translation>&amp;Revenir à la version enregistrée</translation>
    </message>
    <message>
        <source>Reopen the scene&apos;s file as it was last saved, dropping the edits</source>
        <translation>Rouvrir le fichier de la scène tel qu’il a été enregistré, en abandonnant les modifications</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Enregistrer &amp;sous…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Annuler</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Rétablir</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Supprimer</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Copier</translation>
    </message>
    <message>
        <source>Cu&amp;t</source>
        <translation>Co&amp;uper</translation>
    </message>
    <message>
        <source>&amp;Paste</source>
        <translation>C&amp;oller</translation>
    </message>
    <message>
        <source>&amp;Accuracy Lab…</source>
        <translation>Labo de &amp;précision…</translation>
    </message>
    <message>
        <source>Error against CPU time for every integrator, on this scene</source>
        <translation>Erreur en fonction du temps CPU pour chaque intégrateur, sur cette scène</translation>
    </message>
    <message>
        <source>&amp;Presentation Mode</source>
        <translation>Mode &amp;présentation</translation>
    </message>
    <message>
        <source>Live &amp;Error Estimate</source>
        <translation>Estimation de l’&amp;erreur en direct</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Guide d’utilisation</translation>
    </message>
    <message>
        <source>How to use Phasebox: the window, building scenes, measuring, files</source>
        <translation>Comment utiliser Phasebox : la fenêtre, construire des scènes, mesurer, les fichiers</translation>
    </message>
    <message>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>&amp;Raccourcis clavier</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Fichiers &amp;récents</translation>
    </message>
    <message>
        <source>&amp;Examples</source>
        <translation>&amp;Exemples</translation>
    </message>
    <message>
        <source>&amp;Lessons</source>
        <translation>&amp;Leçons</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exporter</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>É&amp;dition</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Outils</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>Aid&amp;e</translation>
    </message>
    <message>
        <source>&amp;About Phasebox</source>
        <translation>À &amp;propos de Phasebox</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Principale</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Paramètres</translation>
    </message>
    <message>
        <source>Effects</source>
        <translation>Effets</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Scène</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Propriétés</translation>
    </message>
    <message>
        <source>Plots</source>
        <translation>Graphiques</translation>
    </message>
    <message>
        <source>Instruments</source>
        <translation>Instruments</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Notes</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Sans titre</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>Revenir</translation>
    </message>
    <message>
        <source>Drop your changes and reopen %1 as it was last saved?</source>
        <translation>Abandonner vos modifications et rouvrir %1 tel qu’il a été enregistré ?</translation>
    </message>
    <message>
        <source>Phasebox</source>
        <translation>Phasebox</translation>
    </message>
    <message>
        <source>The scene has unsaved changes. Save them?</source>
        <translation>La scène a des modifications non enregistrées. Les enregistrer ?</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Langue</translation>
    </message>
    <message>
        <source>Scene canvas</source>
        <translation>Canevas de la scène</translation>
    </message>
    <message>
        <source>Export &amp;Animation…</source>
        <translation>Exporter l’&amp;animation…</translation>
    </message>
    <message>
        <source>The run as an MP4 or animated GIF clip, optionally with the plots</source>
        <translation>La simulation en clip MP4 ou GIF animé, avec les graphiques si souhaité</translation>
    </message>
    <message>
        <source>&amp;Worker Threads</source>
        <translation>&amp;Fils d&apos;exécution</translation>
    </message>
</context>
<context>
    <name>phasebox::MeasureTools</name>
    <message>
        <source>Free-&amp;Body View</source>
        <translation>Vue du corps &amp;isolé</translation>
    </message>
    <message>
        <source>Draw the forces on the selected body by source, its momentum and the system&apos;s centre of mass</source>
        <translation>Dessiner les forces sur le corps sélectionné par origine, sa quantité de mouvement et le centre de masse du système</translation>
    </message>
    <message>
        <source>&amp;Clear Measurements</source>
        <translation>&amp;Effacer les mesures</translation>
    </message>
    <message>
        <source>--ruler &quot;%1&quot;: expected A,B with each an object id or X:Y</source>
        <translation>--ruler &quot;%1&quot; : A,B attendu, chacun un identifiant d’objet ou X:Y</translation>
    </message>
    <message>
        <source>--protractor &quot;%1&quot;: expected A,B,C (the vertex B in the middle, as in angle(A,B,C)) with each an object id or X:Y</source>
        <translation>--protractor &quot;%1&quot; : A,B,C attendu (le sommet B au milieu, comme dans angle(A,B,C)), chacun un identifiant d’objet ou X:Y</translation>
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
        <translation>Angle %1</translation>
    </message>
    <message>
        <source>Drag from one point to the other to measure.</source>
        <translation>Glissez d’un point à l’autre pour mesurer.</translation>
    </message>
    <message>
        <source>Drag from the vertex along the first arm.</source>
        <translation>Glissez depuis le sommet le long du premier côté.</translation>
    </message>
    <message>
        <source>Distance %1</source>
        <translation>Distance %1</translation>
    </message>
    <message>
        <source>Now click the second arm (Esc cancels).</source>
        <translation>Cliquez maintenant le second côté (Échap annule).</translation>
    </message>
</context>
<context>
    <name>phasebox::ParametersPresenter</name>
    <message>
        <source>&amp;Play</source>
        <translation>&amp;Lecture</translation>
    </message>
    <message>
        <source>Play or pause the simulation (Space)</source>
        <translation>Lancer ou mettre en pause la simulation (Espace)</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>S&amp;tep</source>
        <translation>&amp;Pas</translation>
    </message>
    <message>
        <source>Advance one step (S)</source>
        <translation>Avancer d’un pas (S)</translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation>&amp;Réinitialiser</translation>
    </message>
    <message>
        <source>Back to the setup (Ctrl+R)</source>
        <translation>Retour à l’état initial (Ctrl+R)</translation>
    </message>
    <message>
        <source>Next Integrator</source>
        <translation>Intégrateur suivant</translation>
    </message>
    <message>
        <source>Previous Integrator</source>
        <translation>Intégrateur précédent</translation>
    </message>
    <message>
        <source>Double dt</source>
        <translation>Doubler dt</translation>
    </message>
    <message>
        <source>Halve dt</source>
        <translation>Diviser dt par deux</translation>
    </message>
    <message>
        <source>More Sub-steps</source>
        <translation>Plus de sous-pas</translation>
    </message>
    <message>
        <source>Fewer Sub-steps</source>
        <translation>Moins de sous-pas</translation>
    </message>
    <message>
        <source>Faster</source>
        <translation>Plus vite</translation>
    </message>
    <message>
        <source>Slower</source>
        <translation>Plus lent</translation>
    </message>
    <message>
        <source>Largest stable sub-step (stiffest mode ω = %1 rad/s):</source>
        <translation>Plus grand sous-pas stable (mode le plus raide ω = %1 rad/s) :</translation>
    </message>
    <message>
        <source>any</source>
        <translation>tout</translation>
    </message>
    <message>
        <source>none</source>
        <translation>aucun</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Integrator: %1</source>
        <translation>Intégrateur : %1</translation>
    </message>
    <message>
        <source>dt = %1 s</source>
        <translation>dt = %1 s</translation>
    </message>
    <message>
        <source>%1 sub-steps</source>
        <translation>%1 sous-pas</translation>
    </message>
    <message>
        <source>Applied %1 at dt %2 s</source>
        <translation>%1 appliqué à dt %2 s</translation>
    </message>
</context>
<context>
    <name>phasebox::PeriodTimerPresenter</name>
    <message>
        <source>Pick a probe (an object&apos;s x for a swing), then press Play: the period is the mean interval between its upward crossings of the middle of its range.</source>
        <translation>Choisissez une sonde (le x d’un objet pour une oscillation), puis appuyez sur Lecture : la période est l’intervalle moyen entre ses passages montants par le milieu de sa plage.</translation>
    </message>
    <message>
        <source>%1 cannot be read in this scene.</source>
        <translation>%1 ne peut pas être lu dans cette scène.</translation>
    </message>
    <message numerus="yes">
        <source>Waiting for two upward crossings of the middle of the range of %1 (%n so far).</source>
        <translation>
            <numerusform>En attente de deux passages montants par le milieu de la plage de %1 (%n jusqu’ici).</numerusform>
            <numerusform>En attente de deux passages montants par le milieu de la plage de %1 (%n jusqu’ici).</numerusform>
        </translation>
    </message>
    <message>
        <source>Mean interval between the upward crossings of %1 through %2 %3, the middle of its range [%4, %5] %3, each interpolated within its step.</source>
        <translation>Intervalle moyen entre les passages montants de %1 par %2 %3, le milieu de sa plage [%4, %5] %3, chacun interpolé dans son pas.</translation>
    </message>
</context>
<context>
    <name>phasebox::PlotsPresenter</name>
    <message>
        <source>The live error estimate is off (View menu).</source>
        <translation>L’estimation de l’erreur en direct est désactivée (menu Affichage).</translation>
    </message>
    <message>
        <source>No live error estimate: a step takes %1 ms, and the estimate would cost three more.</source>
        <translation>Pas d’estimation de l’erreur en direct : un pas prend %1 ms, et l’estimation en coûterait trois de plus.</translation>
    </message>
    <message>
        <source>Press Play: the error one step makes is estimated as the simulation runs.</source>
        <translation>Appuyez sur Lecture : l’erreur d’un pas est estimée pendant la simulation.</translation>
    </message>
    <message>
        <source>Phase space</source>
        <translation>Espace des phases</translation>
    </message>
    <message>
        <source>Phase space of %1</source>
        <translation>Espace des phases de %1</translation>
    </message>
    <message>
        <source>Click an object first.</source>
        <translation>Cliquez d’abord un objet.</translation>
    </message>
    <message>
        <source>Only rigid bodies have an angle.</source>
        <translation>Seuls les solides ont un angle.</translation>
    </message>
    <message>
        <source>no object chosen for the phase plot: click one on the canvas</source>
        <translation>aucun objet choisi pour le portrait de phase : cliquez-en un sur le canevas</translation>
    </message>
    <message>
        <source>Phase space of %1 (%2)</source>
        <translation>Espace des phases de %1 (%2)</translation>
    </message>
    <message>
        <source>Energy Plot</source>
        <translation>Graphique d’énergie</translation>
    </message>
    <message>
        <source>Phase Plot</source>
        <translation>Portrait de phase</translation>
    </message>
    <message>
        <source>Error Plot</source>
        <translation>Graphique d’erreur</translation>
    </message>
    <message>
        <source>%1 as %2…</source>
        <translation>%1 en %2…</translation>
    </message>
    <message>
        <source>Export Plot</source>
        <translation>Exporter le graphique</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Échec de l’export</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>%1 écrit</translation>
    </message>
    <message>
        <source>Energy&lt;br&gt;%1, dt %L2 s</source>
        <translation>Énergie&lt;br&gt;%1, dt %L2 s</translation>
    </message>
    <message>
        <source>Local error per step&lt;br&gt;%1, dt %L2 s</source>
        <translation>Erreur locale par pas&lt;br&gt;%1, dt %L2 s</translation>
    </message>
</context>
<context>
    <name>phasebox::ProbeGraphsPresenter</name>
    <message>
        <source>no graph %1</source>
        <translation>pas de graphique %1</translation>
    </message>
    <message>
        <source>All %1 graphs are in use: close one first.</source>
        <translation>Les %1 graphiques sont utilisés : fermez-en un d’abord.</translation>
    </message>
    <message>
        <source>time [s]</source>
        <translation>temps [s]</translation>
    </message>
    <message>
        <source>Pick a probe to plot, or type one (p0.x, system.total, distance(A,B), …).</source>
        <translation>Choisissez une sonde à tracer, ou tapez-en une (p0.x, system.total, distance(A,B), …).</translation>
    </message>
    <message>
        <source>%1 cannot be read in this scene (was its object deleted or renamed?)</source>
        <translation>%1 ne peut pas être lu dans cette scène (son objet a-t-il été supprimé ou renommé ?)</translation>
    </message>
    <message>
        <source>Press Play: %1 is recorded at every step.</source>
        <translation>Appuyez sur Lecture : %1 est enregistré à chaque pas.</translation>
    </message>
    <message>
        <source>Recorded since t = %1 s, when it was chosen.</source>
        <translation>Enregistré depuis t = %1 s, quand il a été choisi.</translation>
    </message>
    <message>
        <source>graph %1 plots nothing: pick a probe first</source>
        <translation>le graphique %1 ne trace rien : choisissez d’abord une sonde</translation>
    </message>
    <message>
        <source>%1 against %2 — %3 (%4, dt %5 s)</source>
        <translation>%1 en fonction de %2 — %3 (%4, dt %5 s)</translation>
    </message>
    <message>
        <source>time</source>
        <translation>temps</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Sans titre</translation>
    </message>
    <message>
        <source>Export Graph</source>
        <translation>Exporter le graphique</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Échec de l’export</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>%1 écrit</translation>
    </message>
</context>
<context>
    <name>phasebox::ProbeRecorder</name>
    <message>
        <source>the CSV file</source>
        <translation>le fichier CSV</translation>
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
        <translation>%1 (invalide)</translation>
    </message>
    <message>
        <source>Export Probe Table</source>
        <translation>Exporter le tableau des sondes</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Échec de l’export</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>%1 écrit</translation>
    </message>
</context>
<context>
    <name>phasebox::PropertiesPresenter</name>
    <message>
        <source>Live at t = %1 s; Reset shows the setup</source>
        <translation>En direct à t = %1 s ; Réinitialiser montre l’état initial</translation>
    </message>
    <message>
        <source>The setup&apos;s numbers (the run is at t = %1 s)</source>
        <translation>Les nombres de l’état initial (le calcul est à t = %1 s)</translation>
    </message>
    <message>
        <source>Setup: the state at t = 0, what Reset returns to</source>
        <translation>État initial : l’état à t = 0, auquel Réinitialiser revient</translation>
    </message>
    <message>
        <source>Recorded at t = %1 s; Reset shows the setup</source>
        <translation>Enregistré à t = %1 s ; Réinitialiser montre l’état initial</translation>
    </message>
</context>
<context>
    <name>phasebox::ReadoutsPresenter</name>
    <message>
        <source>cloth node</source>
        <translation>nœud de tissu</translation>
    </message>
    <message>
        <source>pinned particle</source>
        <translation>particule fixée</translation>
    </message>
    <message>
        <source>particle</source>
        <translation>particule</translation>
    </message>
    <message>
        <source>disk</source>
        <translation>disque</translation>
    </message>
    <message>
        <source>polygon</source>
        <translation>polygone</translation>
    </message>
    <message>
        <source>box</source>
        <translation>boîte</translation>
    </message>
    <message>
        <source>static %1</source>
        <translation>%1 (immobile)</translation>
    </message>
    <message>
        <source>Click an object on the canvas to read its position, velocity, energy and momentum; Shift-click a second and a third for the distance and the angle between them.</source>
        <translation>Cliquez un objet sur le canevas pour lire sa position, sa vitesse, son énergie et sa quantité de mouvement ; Maj-clic sur un deuxième et un troisième pour la distance et l’angle entre eux.</translation>
    </message>
    <message>
        <source>position (x, y)</source>
        <translation>position (x, y)</translation>
    </message>
    <message>
        <source>velocity (vx, vy)</source>
        <translation>vitesse (vx, vy)</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>norme de la vitesse</translation>
    </message>
    <message>
        <source>angle</source>
        <translation>angle</translation>
    </message>
    <message>
        <source>angular velocity ω</source>
        <translation>vitesse angulaire ω</translation>
    </message>
    <message>
        <source>kinetic energy</source>
        <translation>énergie cinétique</translation>
    </message>
    <message>
        <source>momentum (px, py)</source>
        <translation>quantité de mouvement (px, py)</translation>
    </message>
    <message>
        <source>angular momentum L</source>
        <translation>moment cinétique L</translation>
    </message>
    <message>
        <source>contact force</source>
        <translation>force de contact</translation>
    </message>
    <message>
        <source>distance %1–%2</source>
        <translation>distance %1–%2</translation>
    </message>
    <message>
        <source>angle %1–%2–%3</source>
        <translation>angle %1–%2–%3</translation>
    </message>
    <message>
        <source>%1 (joint)</source>
        <translation>%1 (liaison)</translation>
    </message>
    <message>
        <source>constraint force of %1</source>
        <translation>force de liaison de %1</translation>
    </message>
    <message>
        <source>angle of %1</source>
        <translation>angle de %1</translation>
    </message>
    <message>
        <source>live, t = %1 s</source>
        <translation>en direct, t = %1 s</translation>
    </message>
    <message>
        <source>setup</source>
        <translation>état initial</translation>
    </message>
    <message>
        <source>recorded, t = %1 s</source>
        <translation>enregistré, t = %1 s</translation>
    </message>
</context>
<context>
    <name>phasebox::SceneBrowserPresenter</name>
    <message>
        <source>Nothing to copy: select objects first (a spring goes along with the objects it joins).</source>
        <translation>Rien à copier : sélectionnez d’abord des objets (un ressort suit les objets qu’il relie).</translation>
    </message>
    <message numerus="yes">
        <source>Copied %n object(s)</source>
        <translation>
            <numerusform>%n objet copié</numerusform>
            <numerusform>%n objets copiés</numerusform>
        </translation>
    </message>
    <message>
        <source>Nothing to paste: copy objects first.</source>
        <translation>Rien à coller : copiez d’abord des objets.</translation>
    </message>
    <message>
        <source>the clipboard</source>
        <translation>le presse-papiers</translation>
    </message>
    <message>
        <source>The clipboard holds no Phasebox objects: %1</source>
        <translation>Le presse-papiers ne contient pas d’objets Phasebox : %1</translation>
    </message>
    <message>
        <source>Nothing to paste: the clipboard&apos;s scene is empty.</source>
        <translation>Rien à coller : la scène du presse-papiers est vide.</translation>
    </message>
</context>
<context>
    <name>phasebox::SceneFiles</name>
    <message>
        <source>Could not open %1</source>
        <translation>Impossible d’ouvrir %1</translation>
    </message>
    <message>
        <source>Could not open the scene</source>
        <translation>Impossible d’ouvrir la scène</translation>
    </message>
    <message>
        <source>%1

The open scene is unchanged.</source>
        <translation>%1

La scène ouverte n’a pas changé.</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 ouvert</translation>
    </message>
    <message>
        <source>Open Scene</source>
        <translation>Ouvrir une scène</translation>
    </message>
    <message>
        <source>Save Scene As</source>
        <translation>Enregistrer la scène sous</translation>
    </message>
    <message>
        <source>Could not save</source>
        <translation>Impossible d’enregistrer</translation>
    </message>
    <message>
        <source>%1

The file on disk (if any) is unchanged.</source>
        <translation>%1

Le fichier sur le disque (s’il existe) n’a pas changé.</translation>
    </message>
    <message>
        <source>Saving failed: %1</source>
        <translation>Échec de l’enregistrement : %1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 enregistré</translation>
    </message>
    <message>
        <source>an unsaved scene</source>
        <translation>une scène non enregistrée</translation>
    </message>
    <message>
        <source>Recover the last scene?</source>
        <translation>Récupérer la dernière scène ?</translation>
    </message>
    <message>
        <source>Phasebox did not close properly last time. An autosave of %1 from %2 is available. Open it?</source>
        <translation>Phasebox ne s’est pas fermé correctement la dernière fois. Une sauvegarde automatique de %1 du %2 est disponible. L’ouvrir ?</translation>
    </message>
    <message>
        <source>Recovered from the autosave: save it to keep it.</source>
        <translation>Récupéré de la sauvegarde automatique : enregistrez-la pour la garder.</translation>
    </message>
    <message>
        <source>Could not recover</source>
        <translation>Récupération impossible</translation>
    </message>
</context>
<context>
    <name>phasebox::StatusPresenter</name>
    <message>
        <source>Step doubling at the current state: the error one step of this method makes now. Raise dt and watch it grow.</source>
        <translation>Doublement du pas dans l’état actuel : l’erreur que fait maintenant un pas de cette méthode. Augmentez dt et regardez-la croître.</translation>
    </message>
    <message>
        <source>Not simulated yet by this version: %1</source>
        <translation>Pas encore simulé par cette version : %1</translation>
    </message>
    <message>
        <source>local error ≈ %L1 m</source>
        <translation>erreur locale ≈ %L1 m</translation>
    </message>
    <message>
        <source>t = %L1 s</source>
        <translation>t = %L1 s</translation>
    </message>
    <message>
        <source>real-time factor %L1 (speed %L2×)</source>
        <translation>facteur temps réel %L1 (vitesse %L2×)</translation>
    </message>
    <message>
        <source>paused (speed %L1×)</source>
        <translation>en pause (vitesse %L1×)</translation>
    </message>
    <message>
        <source>%L1 ms per step</source>
        <translation>%L1 ms par pas</translation>
    </message>
    <message>
        <source>%L1 ms per step (live run)</source>
        <translation>%L1 ms par pas (simulation en cours)</translation>
    </message>
</context>
<context>
    <name>phasebox::TimelinePresenter</name>
    <message>
        <source>One Frame Back</source>
        <translation>Une image en arrière</translation>
    </message>
    <message>
        <source>One Frame Forward</source>
        <translation>Une image en avant</translation>
    </message>
    <message>
        <source>Jump to Start</source>
        <translation>Aller au début</translation>
    </message>
</context>
<context>
    <name>phasebox::WorkerMenu</name>
    <message numerus="yes">
        <source>&amp;Every Core (%n threads)</source>
        <translation>
            <numerusform>&amp;Tous les cœurs (%n fil)</numerusform>
            <numerusform>&amp;Tous les cœurs (%n fils)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n Thread(s)</source>
        <translation>
            <numerusform>%n fil</numerusform>
            <numerusform>%n fils</numerusform>
        </translation>
    </message>
    <message>
        <source>The step shares its work among every core.</source>
        <translation>Le pas répartit son travail sur tous les cœurs.</translation>
    </message>
    <message numerus="yes">
        <source>The step runs on %n thread(s).</source>
        <translation>
            <numerusform>Le pas s&apos;exécute sur %n fil.</numerusform>
            <numerusform>Le pas s&apos;exécute sur %n fils.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>phasebox::ui::EffectsPanel</name>
    <message>
        <source>Spring forces; runs because the scene holds springs</source>
        <translation>Forces des ressorts ; tourne parce que la scène contient des ressorts</translation>
    </message>
    <message>
        <source>Collision detection and contact impulses; runs because the scene holds things that can touch</source>
        <translation>Détection des collisions et impulsions de contact ; tourne parce que la scène contient des choses qui peuvent se toucher</translation>
    </message>
    <message>
        <source>The integrator&apos;s own arithmetic: the step minus its effects and contacts</source>
        <translation>L’arithmétique propre de l’intégrateur : le pas moins ses effets et contacts</translation>
    </message>
    <message>
        <source>Newtonian gravity</source>
        <translation>Gravitation newtonienne</translation>
    </message>
    <message>
        <source>0 µs/step</source>
        <translation>0 µs/pas</translation>
    </message>
    <message>
        <source>%1/step</source>
        <translation>%1/pas</translation>
    </message>
    <message>
        <source>Effect</source>
        <translation>Effet</translation>
    </message>
    <message>
        <source>CPU time</source>
        <translation>Temps CPU</translation>
    </message>
    <message>
        <source>CPU time per step, over the last frames</source>
        <translation>Temps CPU par pas, sur les dernières images</translation>
    </message>
    <message>
        <source>&amp;Add effect</source>
        <translation>&amp;Ajouter un effet</translation>
    </message>
    <message>
        <source>Add an effect the scene does not simulate yet</source>
        <translation>Ajouter un effet que la scène ne simule pas encore</translation>
    </message>
    <message>
        <source>Time of one whole step: integrator, effects and contacts</source>
        <translation>Durée d’un pas entier : intégrateur, effets et contacts</translation>
    </message>
    <message>
        <source>total: %1 per step</source>
        <translation>total : %1 par pas</translation>
    </message>
    <message>
        <source>Stage of the step</source>
        <translation>Étape du pas</translation>
    </message>
    <message>
        <source>per step</source>
        <translation>par pas</translation>
    </message>
    <message>
        <source>Where a step&apos;s time goes, stage by stage, in the order they run</source>
        <translation>Où passe le temps d’un pas, étape par étape, dans l’ordre où elles s’exécutent</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Poids</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>Frottement de l’air</translation>
    </message>
    <message>
        <source>Buoyancy</source>
        <translation>Poussée d’Archimède</translation>
    </message>
    <message>
        <source>Wind</source>
        <translation>Vent</translation>
    </message>
    <message>
        <source>Flocking</source>
        <translation>Nuée</translation>
    </message>
    <message>
        <source>Particle collisions</source>
        <translation>Chocs entre particules</translation>
    </message>
    <message>
        <source>Coulomb</source>
        <translation>Coulomb</translation>
    </message>
    <message>
        <source>Springs</source>
        <translation>Ressorts</translation>
    </message>
    <message>
        <source>Contacts</source>
        <translation>Contacts</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>Intégrateur</translation>
    </message>
    <message>
        <source>Integrate</source>
        <translation>Intégrer</translation>
    </message>
    <message>
        <source>Collide</source>
        <translation>Détecter les collisions</translation>
    </message>
    <message>
        <source>Solve contacts</source>
        <translation>Résoudre les contacts</translation>
    </message>
    <message>
        <source>Solve joints</source>
        <translation>Résoudre les liaisons</translation>
    </message>
    <message>
        <source>Ledger</source>
        <translation>Bilan d’énergie</translation>
    </message>
    <message>
        <source>Guard</source>
        <translation>Garde</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::GraphsView</name>
    <message>
        <source>+ Add graph</source>
        <translation>+ Ajouter un graphique</translation>
    </message>
    <message>
        <source>Another graph below, up to %1</source>
        <translation>Un autre graphique en dessous, jusqu’à %1</translation>
    </message>
    <message>
        <source>Any probe against time or another probe.</source>
        <translation>Toute sonde en fonction du temps ou d’une autre sonde.</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::InstrumentsPanel</name>
    <message>
        <source>Rea&amp;douts</source>
        <translation>&amp;Mesures</translation>
    </message>
    <message>
        <source>&amp;Graphs</source>
        <translation>&amp;Graphiques</translation>
    </message>
    <message>
        <source>&amp;Timer</source>
        <translation>&amp;Minuteur</translation>
    </message>
    <message>
        <source>Ta&amp;ble</source>
        <translation>Ta&amp;bleau</translation>
    </message>
    <message>
        <source>The selected object&apos;s state, live or as set up</source>
        <translation>L’état de l’objet sélectionné, en direct ou à l’état initial</translation>
    </message>
    <message>
        <source>Any probe against time or against another</source>
        <translation>Toute sonde en fonction du temps ou d’une autre</translation>
    </message>
    <message>
        <source>The period of any probe, and a stopwatch</source>
        <translation>La période de toute sonde, et un chronomètre</translation>
    </message>
    <message>
        <source>The recorded probes, for CSV and spreadsheets</source>
        <translation>Les sondes enregistrées, pour CSV et tableurs</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::ParametersPanel</name>
    <message>
        <source>implicit</source>
        <translation>implicite</translation>
    </message>
    <message>
        <source>explicit</source>
        <translation>explicite</translation>
    </message>
    <message>
        <source>symplectic</source>
        <translation>symplectique</translation>
    </message>
    <message>
        <source>not symplectic</source>
        <translation>non symplectique</translation>
    </message>
    <message>
        <source>order %1 · %2 · %3</source>
        <translation>ordre %1 · %2 · %3</translation>
    </message>
    <message>
        <source> · adaptive step</source>
        <translation> · pas adaptatif</translation>
    </message>
    <message>
        <source>%1 (%2)
%3
force evaluations per step: %4
%5</source>
        <translation>%1 (%2)
%3
évaluations de force par pas : %4
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
        <translation>Lecture</translation>
    </message>
    <message>
        <source>Play or pause (Space)</source>
        <translation>Lancer ou mettre en pause (Espace)</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Pas</translation>
    </message>
    <message>
        <source>Advance one step (S or Right)</source>
        <translation>Avancer d’un pas (S ou Droite)</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Réinitialiser</translation>
    </message>
    <message>
        <source>Back to the scene&apos;s setup (R or Ctrl+R)</source>
        <translation>Retour à l’état initial de la scène (R ou Ctrl+R)</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>The frame step: the time one step advances (%1 … %2 s).
The arrows halve or double it; 2e-4 style entry is accepted.</source>
        <translation>Le pas de temps : le temps dont avance un pas (%1 … %2 s).
Les flèches le divisent ou le multiplient par deux ; une saisie comme 2e-4 est acceptée.</translation>
    </message>
    <message>
        <source>1/n</source>
        <translation>1/n</translation>
    </message>
    <message>
        <source>Common frame steps</source>
        <translation>Pas de temps courants</translation>
    </message>
    <message>
        <source>dt presets</source>
        <translation>dt prédéfinis</translation>
    </message>
    <message>
        <source>Each step is split into this many equal sub-steps</source>
        <translation>Chaque pas est découpé en autant de sous-pas égaux</translation>
    </message>
    <message>
        <source>Local error tolerance of the adaptive methods (%1);
the arrows move it by a factor of ten</source>
        <translation>Tolérance d’erreur locale des méthodes adaptatives (%1) ;
les flèches la changent d’un facteur dix</translation>
    </message>
    <message>
        <source>Newton iterations of implicit Euler per step
(1 = the linearised step of Baraff &amp; Witkin)</source>
        <translation>Itérations de Newton d’Euler implicite par pas
(1 = le pas linéarisé de Baraff &amp; Witkin)</translation>
    </message>
    <message>
        <source>Impulses after the step, with friction and restitution: stacks rest</source>
        <translation>Impulsions après le pas, avec frottement et restitution : les piles restent au repos</translation>
    </message>
    <message>
        <source>A stiff damped spring in each overlap, F = k·d + c·ḋ: a smooth force the integrator sees, with its potential ½·k·d² in the energy</source>
        <translation>Un ressort raide amorti dans chaque recouvrement, F = k·d + c·ḋ : une force régulière que voit l’intégrateur, avec son énergie potentielle ½·k·d² dans l’énergie</translation>
    </message>
    <message>
        <source>Move the bodies apart and reflect the approaching velocity by e; no forces</source>
        <translation>Écarter les corps et réfléchir la vitesse d’approche avec e ; aucune force</translation>
    </message>
    <message>
        <source> N/m</source>
        <translation> N/m</translation>
    </message>
    <message>
        <source>none yet</source>
        <translation>aucune encore</translation>
    </message>
    <message>
        <source>Penalty stiffness k per contact point; the arrows move it by a factor of ten</source>
        <translation>Raideur de pénalité k par point de contact ; les flèches la changent d’un facteur dix</translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>Auto</translation>
    </message>
    <message>
        <source>Automatic stiffness: the lightest body gets ω·h = 0.5 at the step</source>
        <translation>Raideur automatique : le corps le plus léger reçoit ω·h = 0,5 au pas</translation>
    </message>
    <message>
        <source> N·s/m</source>
        <translation> N·s/m</translation>
    </message>
    <message>
        <source>Penalty damping c per contact point</source>
        <translation>Amortissement de pénalité c par point de contact</translation>
    </message>
    <message>
        <source>Simulated seconds per second of wall time (slow motion below 1×)</source>
        <translation>Secondes simulées par seconde réelle (ralenti sous 1×)</translation>
    </message>
    <message>
        <source>&amp;Integrator:</source>
        <translation>&amp;Intégrateur :</translation>
    </message>
    <message>
        <source>&amp;dt:</source>
        <translation>&amp;dt :</translation>
    </message>
    <message>
        <source>S&amp;ub-steps:</source>
        <translation>So&amp;us-pas :</translation>
    </message>
    <message>
        <source>&amp;Tolerance:</source>
        <translation>&amp;Tolérance :</translation>
    </message>
    <message>
        <source>&amp;Newton iter.:</source>
        <translation>Itér. &amp;Newton :</translation>
    </message>
    <message>
        <source>Newton iterations (implicit Euler only)</source>
        <translation>Itérations de Newton (Euler implicite seulement)</translation>
    </message>
    <message>
        <source>&amp;Contacts:</source>
        <translation>&amp;Contacts :</translation>
    </message>
    <message>
        <source>Sti&amp;ffness:</source>
        <translation>Rai&amp;deur :</translation>
    </message>
    <message>
        <source>Dam&amp;ping:</source>
        <translation>A&amp;mort. :</translation>
    </message>
    <message>
        <source>Sp&amp;eed:</source>
        <translation>&amp;Vitesse :</translation>
    </message>
    <message>
        <source>dt</source>
        <translation>dt</translation>
    </message>
    <message>
        <source>tolerance</source>
        <translation>tolérance</translation>
    </message>
    <message>
        <source> or </source>
        <translation> ou </translation>
    </message>
    <message>
        <source>Impulse</source>
        <translation>Impulsions</translation>
    </message>
    <message>
        <source>Penalty</source>
        <translation>Pénalité</translation>
    </message>
    <message>
        <source>Kinematic</source>
        <translation>Cinématique</translation>
    </message>
    <message>
        <source>Let resting &amp;bodies sleep</source>
        <translation>Endormir les corps au re&amp;pos</translation>
    </message>
    <message>
        <source>Bodies that have stayed at rest for half a second are no longer simulated, and are drawn dimmed, until something touches them, drags them or an edit wakes them: large resting piles cost almost nothing</source>
        <translation>Les corps restés au repos une demi-seconde ne sont plus simulés et sont dessinés estompés jusqu&apos;à ce que quelque chose les touche, qu&apos;on les fasse glisser ou qu&apos;une modification les réveille : les grands tas au repos ne coûtent presque rien</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::PlotsPanel</name>
    <message>
        <source>&amp;Pause plots</source>
        <translation>&amp;Pause des graphiques</translation>
    </message>
    <message>
        <source>Freeze the plots while the simulation goes on</source>
        <translation>Figer les graphiques pendant que la simulation continue</translation>
    </message>
    <message>
        <source>C&amp;lear</source>
        <translation>&amp;Effacer</translation>
    </message>
    <message>
        <source>Forget the recorded samples; the plots start again from now</source>
        <translation>Oublier les échantillons enregistrés ; les graphiques repartent de maintenant</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exporter</translation>
    </message>
    <message>
        <source>Energy</source>
        <translation>Énergie</translation>
    </message>
    <message>
        <source>Phase space</source>
        <translation>Espace des phases</translation>
    </message>
    <message>
        <source>Local error</source>
        <translation>Erreur locale</translation>
    </message>
    <message>
        <source>%1 as %2…</source>
        <translation>%1 en %2…</translation>
    </message>
    <message>
        <source>Click an object on the canvas to plot its phase space.</source>
        <translation>Cliquez un objet sur le canevas pour tracer son espace des phases.</translation>
    </message>
    <message>
        <source>The coordinate plotted against its velocity</source>
        <translation>La coordonnée en fonction de sa vitesse</translation>
    </message>
    <message>
        <source>x against vx</source>
        <translation>x en fonction de vx</translation>
    </message>
    <message>
        <source>y against vy</source>
        <translation>y en fonction de vy</translation>
    </message>
    <message>
        <source>angle against ω (boxes)</source>
        <translation>angle en fonction de ω (boîtes)</translation>
    </message>
    <message>
        <source>Local error estimate</source>
        <translation>Estimation de l’erreur locale</translation>
    </message>
    <message>
        <source>P&amp;hase space</source>
        <translation>Espace des p&amp;hases</translation>
    </message>
    <message>
        <source>Local e&amp;rror</source>
        <translation>E&amp;rreur locale</translation>
    </message>
    <message>
        <source>Resume &amp;plots</source>
        <translation>Reprendre les &amp;graphiques</translation>
    </message>
    <message>
        <source>Energy plot</source>
        <translation>Graphique d’énergie</translation>
    </message>
    <message>
        <source>Phase space plot</source>
        <translation>Portrait de phase</translation>
    </message>
    <message>
        <source>Local error plot</source>
        <translation>Graphique de l’erreur locale</translation>
    </message>
    <message>
        <source>At t = %1 s: kinetic %2 J, potential %3 J, total %4 J, work_nc %5 J, drift %6 J</source>
        <translation>À t = %1 s : cinétique %2 J, potentielle %3 J, totale %4 J, travail_nc %5 J, dérive %6 J</translation>
    </message>
    <message>
        <source>Latest: %1 = %2, %3 = %4</source>
        <translation>Dernier point : %1 = %2, %3 = %4</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::ProbeGraphView</name>
    <message>
        <source>probe to plot</source>
        <translation>sonde à tracer</translation>
    </message>
    <message>
        <source>time</source>
        <translation>temps</translation>
    </message>
    <message>
        <source>vs</source>
        <translation>en fonction de</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exporter</translation>
    </message>
    <message>
        <source>Save this graph as a picture or its samples as CSV</source>
        <translation>Enregistrer ce graphique comme image ou ses échantillons en CSV</translation>
    </message>
    <message>
        <source>As %1…</source>
        <translation>En %1…</translation>
    </message>
    <message>
        <source>Close this graph</source>
        <translation>Fermer ce graphique</translation>
    </message>
    <message>
        <source>time [s]</source>
        <translation>temps [s]</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::ProbePicker</name>
    <message>
        <source>Pick a probe, or type one (CONTRACT §7: ID.x, system.total, distance(A,B), …) and press Enter</source>
        <translation>Choisissez une sonde, ou tapez-en une (CONTRACT §7 : ID.x, system.total, distance(A,B), …) et appuyez sur Entrée</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::ProbeTableView</name>
    <message>
        <source>add a column</source>
        <translation>ajouter une colonne</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Retirer</translation>
    </message>
    <message>
        <source>Remove a column added here</source>
        <translation>Retirer une colonne ajoutée ici</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Copier</translation>
    </message>
    <message>
        <source>Copy the selected rows (or all) as tab-separated text</source>
        <translation>Copier les lignes sélectionnées (ou toutes) en texte séparé par des tabulations</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>Exporter en CSV…</translation>
    </message>
    <message>
        <source>No probes recorded yet: graph or time one, or add a column above.</source>
        <translation>Aucune sonde enregistrée : tracez-en une ou mesurez sa période, ou ajoutez une colonne ci-dessus.</translation>
    </message>
    <message numerus="yes">
        <source>%n sample(s)</source>
        <translation>
            <numerusform>%n échantillon</numerusform>
            <numerusform>%n échantillons</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>phasebox::ui::PropertiesPanel</name>
    <message>
        <source>Select an object on the canvas or in the scene list</source>
        <translation>Sélectionnez un objet sur le canevas ou dans la liste de la scène</translation>
    </message>
    <message>
        <source>%1: %2 … %3 %4 (scientific notation such as 1e6 is accepted)</source>
        <translation>%1 : %2 … %3 %4 (la notation scientifique comme 1e6 est acceptée)</translation>
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
        <translation>grandeur</translation>
    </message>
    <message>
        <source>value</source>
        <translation>valeur</translation>
    </message>
    <message>
        <source>unit</source>
        <translation>unité</translation>
    </message>
    <message>
        <source>Right-click a row to graph it or time its period</source>
        <translation>Clic droit sur une ligne pour la tracer ou mesurer sa période</translation>
    </message>
    <message>
        <source>Click an object on the canvas to read its state.</source>
        <translation>Cliquez un objet sur le canevas pour lire son état.</translation>
    </message>
    <message>
        <source>Graph %1 against time</source>
        <translation>Tracer %1 en fonction du temps</translation>
    </message>
    <message>
        <source>Time the period of %1</source>
        <translation>Mesurer la période de %1</translation>
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
        <translation>, fixée</translation>
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
        <translation>%1, immobile</translation>
    </message>
    <message>
        <source>%1, m %2 kg</source>
        <translation>%1, m %2 kg</translation>
    </message>
    <message>
        <source>through %1, normal %2</source>
        <translation>par %1, normale %2</translation>
    </message>
    <message>
        <source>anchor %1</source>
        <translation>point d’attache %1</translation>
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
        <translation>le monde</translation>
    </message>
    <message>
        <source>%1 of %2 on a %3</source>
        <translation>%1 de %2 (%3)</translation>
    </message>
    <message>
        <source>circle</source>
        <translation>cercle</translation>
    </message>
    <message>
        <source>line</source>
        <translation>droite</translation>
    </message>
    <message>
        <source>%1: %2 – %3</source>
        <translation>%1 : %2 – %3</translation>
    </message>
    <message>
        <source>, %1 m</source>
        <translation>, %1 m</translation>
    </message>
    <message>
        <source>, motor %1 rad/s</source>
        <translation>, moteur %1 rad/s</translation>
    </message>
    <message numerus="yes">
        <source>%n node(s)</source>
        <translation>
            <numerusform>%n nœud</numerusform>
            <numerusform>%n nœuds</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 × %2 nodes, %3 kg, pinned %4</source>
        <translation>%1 × %2 nœuds, %3 kg, fixé %4</translation>
    </message>
    <message>
        <source>Filter by id or summary</source>
        <translation>Filtrer : identifiant, résumé</translation>
    </message>
    <message>
        <source>Filter objects</source>
        <translation>Filtrer les objets</translation>
    </message>
    <message>
        <source>Id</source>
        <translation>Identifiant</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>Résumé</translation>
    </message>
    <message>
        <source>… and %1 more</source>
        <translation>… et %1 de plus</translation>
    </message>
    <message>
        <source>Particles</source>
        <translation>Particules</translation>
    </message>
    <message>
        <source>Boxes</source>
        <translation>Boîtes</translation>
    </message>
    <message>
        <source>Planes</source>
        <translation>Plans</translation>
    </message>
    <message>
        <source>Springs</source>
        <translation>Ressorts</translation>
    </message>
    <message>
        <source>Cloths</source>
        <translation>Tissus</translation>
    </message>
    <message>
        <source>Joints</source>
        <translation>Liaisons</translation>
    </message>
    <message>
        <source>r %1 m</source>
        <translation>r %1 m</translation>
    </message>
    <message numerus="yes">
        <source>%n vertices</source>
        <translation>
            <numerusform>%n sommet</numerusform>
            <numerusform>%n sommets</numerusform>
        </translation>
    </message>
    <message>
        <source>Disks</source>
        <translation>Disques</translation>
    </message>
    <message>
        <source>Polygons</source>
        <translation>Polygones</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::ScientificSpinBox</name>
    <message>
        <source>a number is needed</source>
        <translation>un nombre est nécessaire</translation>
    </message>
    <message>
        <source>“%1” is not a number</source>
        <translation>« %1 » n’est pas un nombre</translation>
    </message>
    <message>
        <source>must be ≥ %1</source>
        <translation>doit être ≥ %1</translation>
    </message>
    <message>
        <source>must be ≤ %1</source>
        <translation>doit être ≤ %1</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::TimelineBar</name>
    <message>
        <source>Jump to the start (Home)</source>
        <translation>Aller au début (Origine)</translation>
    </message>
    <message>
        <source>One frame back (,)</source>
        <translation>Une image en arrière (,)</translation>
    </message>
    <message>
        <source>One frame forward (.)</source>
        <translation>Une image en avant (.)</translation>
    </message>
    <message>
        <source>Recorded time</source>
        <translation>Temps enregistré</translation>
    </message>
    <message>
        <source>Drag to any recorded moment; Play goes on from there</source>
        <translation>Faites glisser vers tout moment enregistré ; Lecture reprend de là</translation>
    </message>
    <message>
        <source>Memory the recording holds, of its budget</source>
        <translation>Mémoire occupée par l’enregistrement, sur son budget</translation>
    </message>
    <message>
        <source>Recording budget</source>
        <translation>Budget de l’enregistrement</translation>
    </message>
    <message>
        <source>The recording&apos;s memory budget: beyond it older frames are thinned</source>
        <translation>Le budget mémoire de l’enregistrement : au-delà, les images anciennes sont éclaircies</translation>
    </message>
    <message>
        <source> MB</source>
        <translation> Mo</translation>
    </message>
    <message>
        <source>%1 / %2 s</source>
        <translation>%1 / %2 s</translation>
    </message>
    <message>
        <source>%1 MB of</source>
        <translation>%1 Mo sur</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::TimerView</name>
    <message>
        <source>Period timer</source>
        <translation>Mesure de période</translation>
    </message>
    <message>
        <source>probe to time, e.g. p0.x</source>
        <translation>sonde à chronométrer, p. ex. p0.x</translation>
    </message>
    <message>
        <source>Probe:</source>
        <translation>Sonde :</translation>
    </message>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>crossing t [s]</source>
        <translation>passage t [s]</translation>
    </message>
    <message>
        <source>interval [s]</source>
        <translation>intervalle [s]</translation>
    </message>
    <message>
        <source>Stopwatch (simulated time)</source>
        <translation>Chronomètre (temps simulé)</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Démarrer</translation>
    </message>
    <message>
        <source>Lap</source>
        <translation>Tour</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Réinitialiser</translation>
    </message>
    <message>
        <source>split [s]</source>
        <translation>temps intermédiaire [s]</translation>
    </message>
    <message>
        <source>lap [s]</source>
        <translation>tour [s]</translation>
    </message>
    <message>
        <source>Pick a probe, then press Play: the period is measured from its upward crossings of the middle of its range.</source>
        <translation>Choisissez une sonde, puis appuyez sur Lecture : la période est mesurée à partir de ses passages montants par le milieu de sa plage.</translation>
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
        <translation>Arrêter</translation>
    </message>
</context>
</TS>
