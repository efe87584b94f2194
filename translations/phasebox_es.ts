<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es" sourcelanguage="en">
<context>
    <name>Charts</name>
    <message>
        <source>kinetic</source>
        <translation>cinética</translation>
    </message>
    <message>
        <source>potential</source>
        <translation>potencial</translation>
    </message>
    <message>
        <source>total</source>
        <translation>total</translation>
    </message>
    <message>
        <source>work_nc</source>
        <translation>W_nc</translation>
    </message>
    <message>
        <source>drift</source>
        <translation>deriva</translation>
    </message>
    <message>
        <source>correction</source>
        <translation>corrección</translation>
    </message>
    <message>
        <source>time [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>energy [J]</source>
        <translation>energía [J]</translation>
    </message>
    <message>
        <source>local error per step</source>
        <translation>error local por paso</translation>
    </message>
    <message>
        <source>error [m]</source>
        <translation>error [m]</translation>
    </message>
    <message>
        <source>simulation</source>
        <translation>simulación</translation>
    </message>
    <message>
        <source>start</source>
        <translation>inicio</translation>
    </message>
</context>
<context>
    <name>CompareRun</name>
    <message>
        <source>Drag the timeline to an earlier moment first: the run is compared from there.</source>
        <translation>Arrastre primero la línea de tiempo a un momento anterior: la ejecución se compara desde allí.</translation>
    </message>
    <message>
        <source>The recording holds no state before this moment.</source>
        <translation>La grabación no contiene ningún estado anterior a este momento.</translation>
    </message>
    <message>
        <source>The scene cannot be built for the ghost.</source>
        <translation>No se puede construir la escena para el fantasma.</translation>
    </message>
    <message>
        <source>The recorded frames are of other objects than the scene&apos;s.</source>
        <translation>Los fotogramas grabados son de otros objetos que los de la escena.</translation>
    </message>
    <message>
        <source>Compare from here</source>
        <translation>Comparar desde aquí</translation>
    </message>
</context>
<context>
    <name>DivergenceText</name>
    <message>
        <source>a position or speed grew so large that it is no longer a number</source>
        <translation>una posición o velocidad creció tanto que ya no es un número</translation>
    </message>
    <message>
        <source>its energy grew without bound</source>
        <translation>su energía creció sin límite</translation>
    </message>
    <message>
        <source>the adaptive method could not keep its error small enough</source>
        <translation>el método adaptativo no pudo mantener su error lo bastante pequeño</translation>
    </message>
    <message>
        <source>cloth &apos;%1&apos;, the node in row %2 from the top, column %3 from the left</source>
        <translation>tela «%1», el nodo de la fila %2 desde arriba, columna %3 desde la izquierda</translation>
    </message>
    <message>
        <source>particle &apos;%1&apos;</source>
        <translation>partícula «%1»</translation>
    </message>
    <message>
        <source>disk &apos;%1&apos;</source>
        <translation>disco «%1»</translation>
    </message>
    <message>
        <source>polygon &apos;%1&apos;</source>
        <translation>polígono «%1»</translation>
    </message>
    <message>
        <source>box &apos;%1&apos;</source>
        <translation>caja «%1»</translation>
    </message>
    <message>
        <source>The simulation became unstable. Try a smaller time step, more sub-steps or Implicit Euler.</source>
        <translation>La simulación se volvió inestable. Pruebe un paso de tiempo menor, más subpasos o Euler implícito.</translation>
    </message>
    <message>
        <source>The simulation became unstable at t = %1: %2. It was paused and put back to t = %3.</source>
        <translation>La simulación se volvió inestable en t = %1: %2. Se pausó y se devolvió a t = %3.</translation>
    </message>
    <message>
        <source>It started at %1.</source>
        <translation>Empezó en %1.</translation>
    </message>
    <message>
        <source>a smaller time step: dt below %1</source>
        <translation>un paso de tiempo menor: dt por debajo de %1</translation>
    </message>
    <message>
        <source>%1 sub-steps per step (same dt, each step cut into %1 pieces)</source>
        <translation>%1 subpasos por paso (mismo dt, cada paso dividido en %1 partes)</translation>
    </message>
    <message>
        <source>a smaller time step (half of dt = %1)</source>
        <translation>un paso de tiempo menor (la mitad de dt = %1)</translation>
    </message>
    <message>
        <source>%1 sub-steps per step</source>
        <translation>%1 subpasos por paso</translation>
    </message>
    <message>
        <source>%1, which stays stable at any time step (it damps fast motion)</source>
        <translation>%1, que es estable con cualquier paso de tiempo (amortigua el movimiento rápido)</translation>
    </message>
    <message>
        <source>start the chain from joint &apos;%1&apos; to joint &apos;%2&apos; with some sag: it is pulled straight between two fixed points, where it cannot sag without stretching, and the forces that keep it straight grow without bound as it moves</source>
        <translation>empezar la cadena de la articulación «%1» a la articulación «%2» con algo de comba: está tensada en línea recta entre dos puntos fijos, donde no puede combarse sin estirarse, y las fuerzas que la mantienen recta crecen sin límite en cuanto se mueve</translation>
    </message>
    <message>
        <source>or free one end of that chain</source>
        <translation>o soltar un extremo de esa cadena</translation>
    </message>
    <message>
        <source>softer springs or cloth (a lower stiffness)</source>
        <translation>muelles o telas más blandos (una rigidez menor)</translation>
    </message>
    <message>
        <source>impulse contacts instead of penalty contacts</source>
        <translation>contactos por impulsos en lugar de contactos por penalización</translation>
    </message>
    <message>
        <source>What to try:</source>
        <translation>Qué probar:</translation>
    </message>
    <message>
        <source>Stability advisor: %1</source>
        <translation>Asesor de estabilidad: %1</translation>
    </message>
</context>
<context>
    <name>Integrators</name>
    <message>
        <source>Explicit Euler</source>
        <extracomment>integrator: explicit_euler</extracomment>
        <translation>Euler explícito</translation>
    </message>
    <message>
        <source>1</source>
        <extracomment>integrator: explicit_euler evaluations</extracomment>
        <translation>1</translation>
    </message>
    <message>
        <source>Forward Euler on (x, v): first order, gains energy on every oscillation.</source>
        <extracomment>integrator: explicit_euler summary</extracomment>
        <translation>Euler hacia delante sobre (x, v): primer orden, gana energía en cada oscilación.</translation>
    </message>
    <message>
        <source>Symplectic Euler</source>
        <extracomment>integrator: symplectic_euler</extracomment>
        <translation>Euler simpléct.</translation>
    </message>
    <message>
        <source>Semi-implicit Euler: velocity first, then position with the new velocity; bounded energy.</source>
        <extracomment>integrator: symplectic_euler summary</extracomment>
        <translation>Euler semiimplícito: primero la velocidad, luego la posición con la velocidad nueva; energía acotada.</translation>
    </message>
    <message>
        <source>Midpoint (RK2)</source>
        <extracomment>integrator: midpoint</extracomment>
        <translation>P. medio (RK2)</translation>
    </message>
    <message>
        <source>2</source>
        <extracomment>integrator: midpoint evaluations</extracomment>
        <translation>2</translation>
    </message>
    <message>
        <source>Explicit midpoint: a half step to estimate the slope, then a full step with it.</source>
        <extracomment>integrator: midpoint summary</extracomment>
        <translation>Punto medio explícito: medio paso para estimar la pendiente y luego un paso entero con ella.</translation>
    </message>
    <message>
        <source>Heun (explicit trapezoid)</source>
        <extracomment>integrator: heun</extracomment>
        <translation>Heun (trapecio expl.)</translation>
    </message>
    <message>
        <source>Average of the slopes at the start and at an Euler-predicted end point.</source>
        <extracomment>integrator: heun summary</extracomment>
        <translation>Media de las pendientes al principio y en un punto final predicho con Euler.</translation>
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
        <translation>Runge-Kutta clásico de cuarto orden: cuatro pendientes con pesos 1/6, 1/3, 1/3, 1/6.</translation>
    </message>
    <message>
        <source>Velocity Verlet</source>
        <extracomment>integrator: velocity_verlet</extracomment>
        <translation>Verlet de veloc.</translation>
    </message>
    <message>
        <source>Position from the current acceleration, velocity from the average of old and new ones.</source>
        <extracomment>integrator: velocity_verlet summary</extracomment>
        <translation>Posición a partir de la aceleración actual, velocidad a partir de la media de la antigua y la nueva.</translation>
    </message>
    <message>
        <source>Implicit Euler</source>
        <extracomment>integrator: implicit_euler</extracomment>
        <translation>Euler implícito</translation>
    </message>
    <message>
        <source>1 + Jacobian per Newton iteration</source>
        <extracomment>integrator: implicit_euler evaluations</extracomment>
        <translation>1 + jacobiana por iteración de Newton</translation>
    </message>
    <message>
        <source>Backward Euler, Newton-linearised (Baraff &amp; Witkin): unconditionally stable, dissipative.</source>
        <extracomment>integrator: implicit_euler summary</extracomment>
        <translation>Euler hacia atrás, linealizado con Newton (Baraff &amp; Witkin): incondicionalmente estable, disipativo.</translation>
    </message>
    <message>
        <source>Implicit midpoint</source>
        <extracomment>integrator: implicit_midpoint</extracomment>
        <translation>P. medio implícito</translation>
    </message>
    <message>
        <source>1 + Jacobian per Newton iteration (to convergence)</source>
        <extracomment>integrator: implicit_midpoint evaluations</extracomment>
        <translation>1 + jacobiana por iteración de Newton (hasta converger)</translation>
    </message>
    <message>
        <source>Implicit midpoint rule: symplectic, second order, conserves a linear spring&apos;s energy.</source>
        <extracomment>integrator: implicit_midpoint summary</extracomment>
        <translation>Regla del punto medio implícita: simpléctica, de segundo orden, conserva la energía de un muelle lineal.</translation>
    </message>
    <message>
        <source>Adaptive Euler (step doubling)</source>
        <extracomment>integrator: adaptive_euler</extracomment>
        <translation>Euler adaptativo (duplicación)</translation>
    </message>
    <message>
        <source>2 per attempt</source>
        <extracomment>integrator: adaptive_euler evaluations</extracomment>
        <translation>2 por intento</translation>
    </message>
    <message>
        <source>Explicit Euler whose step size follows the error of one step against two half steps.</source>
        <extracomment>integrator: adaptive_euler summary</extracomment>
        <translation>Euler explícito cuyo paso sigue el error de un paso frente a dos medios pasos.</translation>
    </message>
    <message>
        <source>Dormand–Prince 5(4)</source>
        <extracomment>integrator: rk45</extracomment>
        <translation>Dormand-Prince 5(4)</translation>
    </message>
    <message>
        <source>6 per attempt (+1 per call)</source>
        <extracomment>integrator: rk45 evaluations</extracomment>
        <translation>6 por intento (+1 por llamada)</translation>
    </message>
    <message>
        <source>Embedded Runge–Kutta pair with error control; the reference for the accuracy lab.</source>
        <extracomment>integrator: rk45 summary</extracomment>
        <translation>Par de Runge-Kutta encajado con control del error; la referencia del laboratorio de precisión.</translation>
    </message>
</context>
<context>
    <name>MeasureOverlay</name>
    <message>
        <source>gravity</source>
        <translation>peso</translation>
    </message>
    <message>
        <source>drag</source>
        <translation>resistencia del aire</translation>
    </message>
    <message>
        <source>newtonian gravity</source>
        <translation>gravitación newtoniana</translation>
    </message>
    <message>
        <source>buoyancy</source>
        <translation>empuje</translation>
    </message>
    <message>
        <source>wind</source>
        <translation>viento</translation>
    </message>
    <message>
        <source>flocking</source>
        <translation>bandada</translation>
    </message>
    <message>
        <source>coulomb</source>
        <translation>Coulomb</translation>
    </message>
    <message>
        <source>penalty contacts</source>
        <translation>contactos por penalización</translation>
    </message>
    <message>
        <source>spring %1</source>
        <translation>muelle %1</translation>
    </message>
    <message>
        <source>contact</source>
        <translation>contacto</translation>
    </message>
    <message>
        <source>joint %1</source>
        <translation>unión %1</translation>
    </message>
    <message>
        <source>Free body: %1, m = %2 kg</source>
        <translation>Cuerpo libre: %1, m = %2 kg</translation>
    </message>
    <message>
        <source>forces: 1 px = %1 N, net %2 N</source>
        <translation>fuerzas: 1 px = %1 N, resultante %2 N</translation>
    </message>
    <message>
        <source>momentum 0</source>
        <translation>cantidad de movimiento 0</translation>
    </message>
    <message>
        <source>momentum: 1 px = %1 kg·m/s</source>
        <translation>cantidad de movimiento: 1 px = %1 kg·m/s</translation>
    </message>
    <message>
        <source>Free body: select a moving body</source>
        <translation>Cuerpo libre: seleccione un cuerpo en movimiento</translation>
    </message>
    <message>
        <source>system: p = (%1, %2) kg·m/s, CM ◑</source>
        <translation>sistema: p = (%1, %2) kg·m/s, CM ◑</translation>
    </message>
</context>
<context>
    <name>ObjectKind</name>
    <message>
        <source>particle</source>
        <extracomment>kind: particle</extracomment>
        <translation>partícula</translation>
    </message>
    <message>
        <source>box</source>
        <extracomment>kind: box</extracomment>
        <translation>caja</translation>
    </message>
    <message>
        <source>disk</source>
        <extracomment>kind: disk</extracomment>
        <translation>disco</translation>
    </message>
    <message>
        <source>polygon</source>
        <extracomment>kind: polygon</extracomment>
        <translation>polígono</translation>
    </message>
    <message>
        <source>plane</source>
        <extracomment>kind: plane</extracomment>
        <translation>plano</translation>
    </message>
    <message>
        <source>spring</source>
        <extracomment>kind: spring</extracomment>
        <translation>muelle</translation>
    </message>
    <message>
        <source>cloth</source>
        <extracomment>kind: cloth</extracomment>
        <translation>tela</translation>
    </message>
    <message>
        <source>joint</source>
        <extracomment>kind: joint</extracomment>
        <translation>unión</translation>
    </message>
    <message>
        <source>object</source>
        <extracomment>kind: object</extracomment>
        <translation>objeto</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>diverged</source>
        <translation>divergió</translation>
    </message>
    <message>
        <source>Phasebox User Guide</source>
        <translation>Guía de usuario de Phasebox</translation>
    </message>
    <message>
        <source>User guide</source>
        <translation>Guía de usuario</translation>
    </message>
    <message>
        <source>The user guide is missing from this build.</source>
        <translation>La guía de usuario falta en esta compilación.</translation>
    </message>
    <message>
        <source>Keyboard Shortcuts</source>
        <translation>Atajos de teclado</translation>
    </message>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>Atajos de teclado</translation>
    </message>
    <message>
        <source>action</source>
        <translation>acción</translation>
    </message>
    <message>
        <source>keys</source>
        <translation>teclas</translation>
    </message>
    <message>
        <source>Every menu command that has a key, as this window has them now.</source>
        <translation>Cada orden de menú que tiene una tecla, tal como las tiene ahora esta ventana.</translation>
    </message>
    <message>
        <source>Phasebox scenes (*.phasebox.json *.json);;All files (*)</source>
        <translation>Escenas de Phasebox (*.phasebox.json *.json);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Add %1 %2</source>
        <translation>Añadir %1 %2</translation>
    </message>
    <message numerus="yes">
        <source>Paste %n objects</source>
        <translation>
            <numerusform>Pegar %n objeto</numerusform>
            <numerusform>Pegar %n objetos</numerusform>
        </translation>
    </message>
    <message>
        <source>nothing to add</source>
        <translation>nada que añadir</translation>
    </message>
    <message>
        <source>nothing to delete: no object has the id %1</source>
        <translation>nada que borrar: ningún objeto tiene el id %1</translation>
    </message>
    <message>
        <source>Delete %1</source>
        <translation>Borrar %1</translation>
    </message>
    <message numerus="yes">
        <source>Delete %n objects</source>
        <translation>
            <numerusform>Borrar %n objeto</numerusform>
            <numerusform>Borrar %n objetos</numerusform>
        </translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>Mover %1</translation>
    </message>
    <message>
        <source>unknown object id %1</source>
        <translation>id de objeto desconocido %1</translation>
    </message>
    <message>
        <source>the position of %1 must be finite</source>
        <translation>la posición de %1 debe ser finita</translation>
    </message>
    <message>
        <source>the position of %1 must lie within ±%2 m</source>
        <translation>la posición de %1 debe estar dentro de ±%2 m</translation>
    </message>
    <message>
        <source>%1 %2 has no property &quot;%3&quot;</source>
        <translation>%1 %2 no tiene la propiedad «%3»</translation>
    </message>
    <message>
        <source>Set %1 of %2</source>
        <translation>Cambiar %1 de %2</translation>
    </message>
    <message>
        <source>Pin %1</source>
        <translation>Fijar %1</translation>
    </message>
    <message>
        <source>Unpin %1</source>
        <translation>Soltar %1</translation>
    </message>
    <message>
        <source>Make %1 static</source>
        <translation>Hacer estático %1</translation>
    </message>
    <message>
        <source>Make %1 dynamic</source>
        <translation>Hacer dinámico %1</translation>
    </message>
    <message>
        <source>only particles and rigid bodies can be pinned</source>
        <translation>solo las partículas y los sólidos rígidos se pueden fijar</translation>
    </message>
    <message>
        <source>Change simulation settings</source>
        <translation>Cambiar los ajustes de la simulación</translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation>Cambiar %1</translation>
    </message>
    <message>
        <source>the CSV file</source>
        <translation>el archivo CSV</translation>
    </message>
    <message>
        <source>position error [m], lower is better</source>
        <translation>error de posición [m], más abajo es mejor</translation>
    </message>
    <message>
        <source>CPU time [s], left is faster</source>
        <translation>tiempo de CPU [s], más a la izquierda es más rápido</translation>
    </message>
    <message>
        <source>%1 %2 hangs between two bodies; move them instead</source>
        <translation>%1 %2 cuelga entre dos cuerpos; mueva los cuerpos</translation>
    </message>
    <message>
        <source>%1 %2 moves with its bodies; move them instead</source>
        <translation>%1 %2 se mueve con sus cuerpos; mueva los cuerpos</translation>
    </message>
</context>
<context>
    <name>RewindCommand</name>
    <message>
        <source>Play from t = %1 s</source>
        <translation>Reproducir desde t = %1 s</translation>
    </message>
</context>
<context>
    <name>SceneTexts</name>
    <message>
        <source>Bouncing balls: restitution</source>
        <extracomment>scenes/bouncing-balls.phasebox.json: name</extracomment>
        <translation>Pelotas que rebotan: restitución</translation>
    </message>
    <message>
        <source>Four balls fall from 2 m onto a hard floor. The coefficient of restitution e is the ratio of the speeds after and before the bounce, so each ball climbs back to e²·h: 2 m, 1.28 m, 0.5 m and 0.08 m for e = 1, 0.8, 0.5 and 0.2. Watch the kinetic and potential energy trade places, and each bounce of the lossy balls move energy into work_nc.</source>
        <extracomment>scenes/bouncing-balls.phasebox.json: description</extracomment>
        <translation>Cuatro pelotas caen desde 2 m sobre un suelo duro. El coeficiente de restitución e es el cociente entre las velocidades después y antes del rebote, así que cada pelota vuelve a subir hasta e²·h: 2 m, 1,28 m, 0,5 m y 0,08 m para e = 1, 0,8, 0,5 y 0,2. Observe cómo la energía cinética y la potencial intercambian sus papeles, y cómo cada rebote de las pelotas con pérdidas pasa energía a work_nc.</translation>
    </message>
    <message>
        <source>Box on an incline: stick or slide</source>
        <extracomment>scenes/box-incline.phasebox.json: name</extracomment>
        <translation>Caja en un plano inclinado: quieta o deslizando</translation>
    </message>
    <message>
        <source>Two boxes sit on two ramps, both at θ = 30° (tan θ = 0.58). On the left the friction coefficient is μ = 0.7 &gt; tan θ, so static friction holds the box still; on the right μ = 0.4 &lt; tan θ, so the box slides down with a = g(sin θ − μ cos θ) = 1.5 m/s². The rule: a box sticks when tan θ ≤ μ. Change the friction of a box and of its ramp to find the tipping point (their contact takes √(μ₁·μ₂) of the two).</source>
        <extracomment>scenes/box-incline.phasebox.json: description</extracomment>
        <translation>Dos cajas están sobre dos rampas, ambas a θ = 30° (tan θ = 0,58). A la izquierda el coeficiente de rozamiento es μ = 0,7 &gt; tan θ, así que el rozamiento estático mantiene la caja quieta; a la derecha μ = 0,4 &lt; tan θ, así que la caja desliza hacia abajo con a = g(sen θ − μ cos θ) = 1,5 m/s². La regla: una caja se queda quieta cuando tan θ ≤ μ. Cambie el rozamiento de una caja y de su rampa para encontrar el punto de vuelco (su contacto toma √(μ₁·μ₂) de los dos).</translation>
    </message>
    <message>
        <source>Pyramid of boxes</source>
        <extracomment>scenes/box-pyramid.phasebox.json: name</extracomment>
        <translation>Pirámide de cajas</translation>
    </message>
    <message>
        <source>Fifty-five 1 m boxes stacked in 10 rows on the ground, friction 0.6. A good contact solver keeps the pyramid standing still, with no creeping or jitter. It runs velocity Verlet, which is exact under constant gravity, so the drift stays at zero; switch to symplectic Euler and the drift stays flat too once the stack has settled in its first second (about −0.15 J): the contacts&apos; forces act inside the method&apos;s step, so a box at rest leaves the method nothing to get wrong. The contact solver takes the inner sub-steps a stack needs by itself: the scene runs at the format&apos;s defaults, one step per frame.</source>
        <extracomment>scenes/box-pyramid.phasebox.json: description</extracomment>
        <translation>Cincuenta y cinco cajas de 1 m apiladas en 10 filas sobre el suelo, rozamiento 0,6. Un buen solucionador de contactos mantiene la pirámide quieta, sin arrastres ni temblores. Usa Verlet de velocidades, que es exacto con gravedad constante, así que la deriva se queda en cero; cambie a Euler simpléctico y la deriva también se queda plana en cuanto la pila se asienta en su primer segundo (unos −0,15 J): las fuerzas de los contactos actúan dentro del paso del método, así que una caja en reposo no le deja al método nada en que equivocarse. El solucionador de contactos elige por sí mismo los subpasos internos que necesita una pila: la escena corre con los valores por defecto del formato, un paso por fotograma.</translation>
    </message>
    <message>
        <source>Motor car climbing a ramp</source>
        <extracomment>scenes/car.phasebox.json: name</extracomment>
        <translation>Coche con motor subiendo una rampa</translation>
    </message>
    <message>
        <source>A toy car climbs a ramp: a 4 kg box body rides on two rigid disk wheels (radius 0.3 m, 2 kg, friction 1) hinged at their axles, and each axle has a motor that turns its wheel at −3 rad/s relative to the body with at most 40 N·m. The joint angle is the wheel&apos;s angle minus the body&apos;s, so a negative speed turns the wheels clockwise and drives the car towards +x at about 0.9 m/s. It rolls along the ground, climbs the 15° ramp and drives on along the 1 m high plateau. The motors&apos; work ends up as the car&apos;s potential energy (78 J by the plateau) and its motion: the energy plot books it in work_nc (82 J in 10 s, the motors&apos; push less what friction takes) while correction stays near zero, because the motors push inside the method&apos;s step, as the contacts do; the hinges hold the wheels to well under a millimetre.</source>
        <extracomment>scenes/car.phasebox.json: description</extracomment>
        <translation>Un coche de juguete sube una rampa: una caja de 4 kg como carrocería va sobre dos ruedas de disco rígidas (radio 0,3 m, 2 kg, rozamiento 1) unidas con bisagras en sus ejes, y cada eje tiene un motor que gira su rueda a −3 rad/s respecto a la carrocería con 40 N·m como máximo. El ángulo de la unión es el ángulo de la rueda menos el de la carrocería, así que una velocidad negativa gira las ruedas en sentido horario y lleva el coche hacia +x a unos 0,9 m/s. Rueda por el suelo, sube la rampa de 15° y sigue por la meseta de 1 m de altura. El trabajo de los motores acaba como energía potencial del coche (78 J al llegar a la meseta) y como su movimiento: la gráfica de energía lo anota en work_nc (82 J en 10 s, el empuje de los motores menos lo que se lleva el rozamiento) mientras la corrección se queda cerca de cero, porque los motores empujan dentro del paso del método, como los contactos; las bisagras sujetan las ruedas con mucho menos de un milímetro de error.</translation>
    </message>
    <message>
        <source>Chain bridge</source>
        <extracomment>scenes/chain-bridge.phasebox.json: name</extracomment>
        <translation>Puente de cadena</translation>
    </message>
    <message>
        <source>A bridge of ten wooden planks, 0.6 m by 0.12 m and 2 kg each, hinged end to end and hinged to the world at both ends, hangs between two pillars, and a 4 kg crate falls onto it from 2 m. Frictionless hinges pass forces but no turning moments, so the bridge hangs like a chain: the horizontal pull is the same all along it and each plank is steeper than its inner neighbour by the same step in slope, a discrete catenary, which is the shape it starts in. Watch the crate land, the bridge bounce and sway and the dip settle under the crate; drag the crate along the bridge, or drop more boxes on it. The hinges hold the planks together to well under a millimetre.</source>
        <extracomment>scenes/chain-bridge.phasebox.json: description</extracomment>
        <translation>Un puente de diez tablas de madera, de 0,6 m por 0,12 m y 2 kg cada una, unidas por bisagras extremo con extremo y al mundo en ambos lados, cuelga entre dos pilares, y una caja de 4 kg cae sobre él desde 2 m. Las bisagras sin rozamiento transmiten fuerzas pero no momentos, así que el puente cuelga como una cadena: la tensión horizontal es la misma a lo largo de todo él y cada tabla es más empinada que su vecina interior en el mismo paso de pendiente, una catenaria discreta, que es la forma en que empieza. Observe cómo cae la caja, cómo el puente rebota y se balancea y cómo se asienta el hundimiento bajo la caja; arrastre la caja por el puente o deje caer más cajas sobre él. Las bisagras mantienen unidas las tablas con mucho menos de un milímetro de error.</translation>
    </message>
    <message>
        <source>Flag in the wind</source>
        <extracomment>scenes/cloth-flag.phasebox.json: name</extracomment>
        <translation>Bandera al viento</translation>
    </message>
    <message>
        <source>A 2 m × 1.2 m cloth of 20 × 12 nodes (0.5 kg) is held along its left edge by a pole and released level. Each node feels its weight m·g and the wind&apos;s drag b·(w − v), so the flag swings down and settles where they balance, at tan α = m·g/(b·w) = 0.51, α = 27° below level. The cloth springs are stiff, so it runs implicit Euler at the frame step: switch to symplectic Euler and watch it blow up and be stopped as diverging.</source>
        <extracomment>scenes/cloth-flag.phasebox.json: description</extracomment>
        <translation>Una tela de 2 m × 1,2 m de 20 × 12 nodos (0,5 kg) está sujeta por su borde izquierdo a un mástil y se suelta horizontal. Cada nodo siente su peso m·g y el arrastre del viento b·(w − v), así que la bandera cae y se asienta donde se equilibran, en tan α = m·g/(b·w) = 0,51, α = 27° por debajo de la horizontal. Los muelles de la tela son rígidos, así que corre con Euler implícito al paso del fotograma: cambie a Euler simpléctico y vea cómo estalla y se detiene por divergencia.</translation>
    </message>
    <message>
        <source>Damped oscillators</source>
        <extracomment>scenes/damped-oscillators.phasebox.json: name</extracomment>
        <translation>Osciladores amortiguados</translation>
    </message>
    <message>
        <source>Three 1 kg balls hang on springs of k = 20 N/m and rest length 1 m, with damping c = 1, 8.944 and 25 N·s/m: under-damped, critically damped and over-damped (ζ = c/(2·√(k·m)) = 0.11, 1 and 2.8). Each is released at the spring&apos;s rest length and falls toward its equilibrium m·g/k = 0.49 m lower. What to watch: the under-damped ball overshoots and rings down with the envelope e^(−ζωt) at ω = √(k/m) = 4.47 rad/s; the critically damped one gets there fastest without overshooting; the over-damped one creeps in slowly, held back by its own damper. View → Exact Solution draws the closed form of each (dashed), and the energy plot shows work_nc taking the energy the dampers turn into heat.</source>
        <extracomment>scenes/damped-oscillators.phasebox.json: description</extracomment>
        <translation>Tres pelotas de 1 kg cuelgan de muelles de k = 20 N/m y longitud natural 1 m, con amortiguamiento c = 1, 8,944 y 25 N·s/m: subamortiguado, con amortiguamiento crítico y sobreamortiguado (ζ = c/(2·√(k·m)) = 0,11, 1 y 2,8). Cada una se suelta en la longitud natural de su muelle y cae hacia su equilibrio m·g/k = 0,49 m más abajo. Qué observar: la pelota subamortiguada se pasa y oscila cada vez menos con la envolvente e^(−ζωt) con ω = √(k/m) = 4,47 rad/s; la de amortiguamiento crítico llega antes sin pasarse; la sobreamortiguada se acerca despacio, frenada por su propio amortiguador. Ver → Solución exacta dibuja la forma cerrada de cada una (a trazos), y la gráfica de energía muestra cómo work_nc recoge la energía que los amortiguadores convierten en calor.</translation>
    </message>
    <message>
        <source>Springs, a pendulum and a swinging box</source>
        <extracomment>scenes/demo.phasebox.json: name</extracomment>
        <translation>Muelles, un péndulo y una caja que oscila</translation>
    </message>
    <message>
        <source>A ball on a spring, a two-ball spring pendulum and a box hung from one corner. Switch the integrator while it runs and watch the drift line in the energy plot: explicit Euler gains energy so fast that the run is stopped as diverging within a second and a half; symplectic Euler and Verlet keep the drift small, swinging about zero; implicit Euler steadily loses energy. The total falls a little under every method because the box&apos;s spring has a damper: that loss is work_nc, not drift.</source>
        <extracomment>scenes/demo.phasebox.json: description</extracomment>
        <translation>Una pelota en un muelle, un péndulo de muelle de dos pelotas y una caja colgada de una esquina. Cambie el integrador mientras corre y observe la línea de deriva en la gráfica de energía: Euler explícito gana energía tan deprisa que la ejecución se detiene por divergir en menos de un segundo y medio; Euler simpléctico y Verlet mantienen la deriva pequeña, oscilando alrededor de cero; Euler implícito pierde energía sin parar. El total baja un poco con todos los métodos porque el muelle de la caja tiene un amortiguador: esa pérdida es work_nc, no deriva.</translation>
    </message>
    <message>
        <source>Dominoes</source>
        <extracomment>scenes/dominoes.phasebox.json: name</extracomment>
        <translation>Fichas de dominó</translation>
    </message>
    <message>
        <source>Twenty dominoes (0.1 m × 1 m) stand 0.5 m apart and the first is given a push. Each one tips the next, and the wave of falling dominoes runs down the row at a steady speed. Watch the potential energy fall steadily while the wave passes (several dominoes are falling at any moment), and the contacts&apos; work_nc take it away: about 7 J in all.</source>
        <extracomment>scenes/dominoes.phasebox.json: description</extracomment>
        <translation>Veinte fichas de dominó (0,1 m × 1 m) están a 0,5 m unas de otras y la primera recibe un empujón. Cada una tumba a la siguiente, y la onda de fichas que caen recorre la fila a velocidad constante. Observe cómo la energía potencial baja de forma continua mientras pasa la onda (en cada momento caen varias fichas), y cómo el work_nc de los contactos se la lleva: unos 7 J en total.</translation>
    </message>
    <message>
        <source>Elastic gas</source>
        <extracomment>scenes/elastic-gas.phasebox.json: name</extracomment>
        <translation>Gas elástico</translation>
    </message>
    <message>
        <source>212 disks bounce in a closed 6 m box with restitution 1, no friction and no gravity; all start at nearly the same speed (1.3 to 1.7 m/s) in random directions. Collisions share the energy out into a spread of speeds (the Maxwell–Boltzmann distribution) while the total kinetic energy stays constant: watch the flat line in the energy plot. The big heavy disk in the middle jiggles under the random kicks: Brownian motion.</source>
        <extracomment>scenes/elastic-gas.phasebox.json: description</extracomment>
        <translation>212 discos rebotan en una caja cerrada de 6 m con restitución 1, sin rozamiento y sin gravedad; todos empiezan casi con la misma rapidez (de 1,3 a 1,7 m/s) en direcciones al azar. Los choques reparten la energía en un abanico de rapideces (la distribución de Maxwell-Boltzmann) mientras la energía cinética total se mantiene constante: observe la línea plana de la gráfica de energía. El disco grande y pesado del centro se agita con los golpes al azar: movimiento browniano.</translation>
    </message>
    <message>
        <source>Galton board</source>
        <extracomment>scenes/galton-board.phasebox.json: name</extracomment>
        <translation>Tablero de Galton</translation>
    </message>
    <message>
        <source>A Galton board: sixty balls fall in a column onto nine staggered rows of pegs and pile up in the bins below. At each row a ball goes left or right about equally often, so where it lands counts its rights against its lefts: for many balls and rows the piles would approach the binomial distribution, which looks like the bell curve. These sixty make a rough mound under the drop, wider than the binomial, because the balls bounce and knock each other across more than one peg at a time. The pegs are static rigid disks; the balls are particles that collide with each other (particle_collisions) and with the pegs, walls and floor. The pegs and the bin walls are frictionless: a ball is a particle, which slides rather than rolls, and friction would hold one that lands near a peg&apos;s top there for good, while in a real board it rolls off.</source>
        <extracomment>scenes/galton-board.phasebox.json: description</extracomment>
        <translation>Un tablero de Galton: sesenta bolas caen en columna sobre nueve filas escalonadas de clavos y se amontonan en los compartimentos de abajo. En cada fila una bola va a la izquierda o a la derecha con más o menos la misma frecuencia, así que donde cae cuenta sus derechas frente a sus izquierdas: con muchas bolas y filas los montones se acercarían a la distribución binomial, que parece la campana de Gauss. Estas sesenta forman un montículo irregular bajo el punto de caída, más ancho que la binomial, porque las bolas rebotan y se empujan unas a otras a través de más de un clavo a la vez. Los clavos son discos rígidos estáticos; las bolas son partículas que chocan entre sí (particle_collisions) y con los clavos, las paredes y el suelo. Los clavos y las paredes de los compartimentos no tienen rozamiento: una bola es una partícula, que desliza en vez de rodar, y el rozamiento retendría para siempre a una que cayera cerca de lo alto de un clavo, mientras que en un tablero real rueda y cae.</translation>
    </message>
    <message>
        <source>Newton&apos;s cradle</source>
        <extracomment>scenes/newtons-cradle.phasebox.json: name</extracomment>
        <translation>Péndulo de Newton</translation>
    </message>
    <message>
        <source>Five steel balls hang on stiff strings, touching; the left ball is pulled out and let go. With restitution 1 the collision passes momentum and energy down the row, so the last ball flies out at the speed the first came in, and the middle balls hardly move. Count the balls that swing out, and watch the kinetic and potential energy trade places.</source>
        <extracomment>scenes/newtons-cradle.phasebox.json: description</extracomment>
        <translation>Cinco bolas de acero cuelgan de hilos rígidos, tocándose; la bola de la izquierda se aparta y se suelta. Con restitución 1 el choque pasa la cantidad de movimiento y la energía a lo largo de la fila, así que la última bola sale con la velocidad con la que llegó la primera, y las bolas del medio apenas se mueven. Cuente las bolas que salen y observe cómo la energía cinética y la potencial intercambian sus papeles.</translation>
    </message>
    <message>
        <source>Orbit around a star</source>
        <extracomment>scenes/orbit.phasebox.json: name</extracomment>
        <translation>Órbita alrededor de una estrella</translation>
    </message>
    <message>
        <source>A ship on a circular orbit (r = 4 m, v = √(GM/r) = 5 m/s, one lap in 5.0 s) and a comet on an ellipse go round a star of GM = 100 (G = 1, so the numbers stay classroom-sized). RK4 keeps both orbits closed and the energy flat. Switch to explicit Euler and watch the orbits spiral outwards as the total energy climbs; symplectic Euler keeps them closed.</source>
        <extracomment>scenes/orbit.phasebox.json: description</extracomment>
        <translation>Una nave en órbita circular (r = 4 m, v = √(GM/r) = 5 m/s, una vuelta en 5,0 s) y un cometa en una elipse giran alrededor de una estrella de GM = 100 (G = 1, para que los números sean de aula). RK4 mantiene ambas órbitas cerradas y la energía plana. Cambie a Euler explícito y vea cómo las órbitas se abren en espiral mientras sube la energía total; Euler simpléctico las mantiene cerradas.</translation>
    </message>
    <message>
        <source>Pendulum on a stiff spring</source>
        <extracomment>scenes/pendulum-stiff-spring.phasebox.json: name</extracomment>
        <translation>Péndulo en un muelle rígido</translation>
    </message>
    <message>
        <source>A 1 kg bob swings on a 2 m rod that is really a stiff spring (k = 10 000 N/m). The swing is slow (T ≈ 2π√(L/g) = 2.8 s, about 7% longer at this 60° amplitude) but the rod&apos;s stretching mode is fast (ω = √(k/m) = 100 rad/s), and that fast mode is what limits the time step. Try explicit Euler and watch it blow up; implicit Euler is stable but visibly damps the swing; symplectic Euler with sub-steps keeps the energy bounded.</source>
        <extracomment>scenes/pendulum-stiff-spring.phasebox.json: description</extracomment>
        <translation>Una masa de 1 kg oscila en una varilla de 2 m que en realidad es un muelle rígido (k = 10 000 N/m). La oscilación es lenta (T ≈ 2π√(L/g) = 2,8 s, un 7 % más con esta amplitud de 60°) pero el modo de estiramiento de la varilla es rápido (ω = √(k/m) = 100 rad/s), y ese modo rápido es el que limita el paso de tiempo. Pruebe Euler explícito y vea cómo estalla; Euler implícito es estable pero amortigua la oscilación a la vista; Euler simpléctico con subpasos mantiene la energía acotada.</translation>
    </message>
    <message>
        <source>Pendulum wave</source>
        <extracomment>scenes/pendulum-wave.phasebox.json: name</extracomment>
        <translation>Onda de péndulos</translation>
    </message>
    <message>
        <source>Twelve pendulums hang side by side, their lengths chosen so that in 60 s the longest makes 51 swings, the next 52, and so on to 62 for the shortest (T = 60/(51 + n) s, L = g·(T/2π)²). Released together from 10°, they drift out of step: after 15 s they form a travelling snake, after 30 s two rows swinging against each other, and at 60 s they all line up again. Each one is a simple pendulum, so View → Exact Solution draws where the closed form puts it (dashed): at 10° the period is 0.19% longer than the small-angle 2π·√(L/g) the lengths were chosen for, so the real line-up comes about 0.1 s late. Try RK4 or a smaller dt and watch the bobs stay on their ghosts; explicit Euler lets every swing grow until, after about 8 s, the run is stopped as diverging.</source>
        <extracomment>scenes/pendulum-wave.phasebox.json: description</extracomment>
        <translation>Doce péndulos cuelgan uno al lado de otro, con longitudes elegidas para que en 60 s el más largo haga 51 oscilaciones, el siguiente 52, y así hasta 62 el más corto (T = 60/(51 + n) s, L = g·(T/2π)²). Soltados juntos desde 10°, se desacompasan: a los 15 s forman una serpiente que avanza, a los 30 s dos filas que oscilan una contra otra, y a los 60 s se alinean todos de nuevo. Cada uno es un péndulo simple, así que Ver → Solución exacta dibuja dónde lo pone la forma cerrada (a trazos): a 10° el periodo es un 0,19 % más largo que el 2π·√(L/g) de ángulos pequeños con el que se eligieron las longitudes, así que la alineación real llega unos 0,1 s tarde. Pruebe RK4 o un dt menor y vea cómo las masas se quedan sobre sus fantasmas; Euler explícito hace crecer cada oscilación hasta que, a los 8 s más o menos, la ejecución se detiene por divergir.</translation>
    </message>
    <message>
        <source>Polygon pile</source>
        <extracomment>scenes/polygon-pile.phasebox.json: name</extracomment>
        <translation>Montón de polígonos</translation>
    </message>
    <message>
        <source>A pile of polygons: triangles to heptagons of several sizes dropped into a bin. Each is a rigid convex polygon whose mass and moment of inertia come from its vertices; they collide face to face and corner to face, tumble, and settle into a heap that stands. Select one to see its properties, or add more with the Add polygon tool and watch the heap take them.</source>
        <extracomment>scenes/polygon-pile.phasebox.json: description</extracomment>
        <translation>Un montón de polígonos: de triángulos a heptágonos de varios tamaños, dejados caer en un recipiente. Cada uno es un polígono convexo rígido cuya masa y momento de inercia salen de sus vértices; chocan cara con cara y esquina con cara, dan tumbos y se asientan en un montón que se sostiene. Seleccione uno para ver sus propiedades, o añada más con la herramienta Añadir polígono y vea cómo el montón los acoge.</translation>
    </message>
    <message>
        <source>Projectiles with air drag</source>
        <extracomment>scenes/projectile-drag.phasebox.json: name</extracomment>
        <translation>Proyectiles con resistencia del aire</translation>
    </message>
    <message>
        <source>Four balls of the same size are launched together at 10 m/s and 45° through air with quadratic drag F = −c‖v‖v (c = 0.004 kg/m). The drag force is the same on all, so the light balls slow down far more: the terminal speed √(mg/c) is 7 m/s for 20 g, 16 m/s for 0.1 kg, 35 m/s for 0.5 kg and 157 m/s for 10 kg. Without drag all would land 10.2 m away: compare the ranges and the lopsided paths. In the energy plot work_nc slopes gently down in flight as drag takes its share (most of the 20 g ball&apos;s energy, a hundredth of the 10 kg ball&apos;s), then drops as each ball lands dead in the ground, which work_nc counts too.</source>
        <extracomment>scenes/projectile-drag.phasebox.json: description</extracomment>
        <translation>Cuatro pelotas del mismo tamaño se lanzan juntas a 10 m/s y 45° por el aire con resistencia cuadrática F = −c‖v‖v (c = 0,004 kg/m). La fuerza de resistencia es la misma para todas, así que las pelotas ligeras se frenan mucho más: la velocidad límite √(mg/c) es 7 m/s para 20 g, 16 m/s para 0,1 kg, 35 m/s para 0,5 kg y 157 m/s para 10 kg. Sin resistencia todas caerían a 10,2 m: compare los alcances y las trayectorias asimétricas. En la gráfica de energía work_nc baja suavemente en vuelo mientras la resistencia se lleva su parte (la mayor parte de la energía de la pelota de 20 g, una centésima de la de 10 kg), y luego cae de golpe cuando cada pelota aterriza muerta en el suelo, lo que work_nc también cuenta.</translation>
    </message>
    <message>
        <source>Ragdoll on the stairs</source>
        <extracomment>scenes/ragdoll.phasebox.json: name</extracomment>
        <translation>Muñeco de trapo en la escalera</translation>
    </message>
    <message>
        <source>A ragdoll of ten boxes (torso, head, upper and lower arms, thighs and shins; 32 kg in all) joined by nine hinges with limits: the neck turns half a radian either way, elbows and knees bend one way only, shoulders and hips swing outwards but not across the body. It is pushed off the top of a flight of stairs and tumbles down them. Where it ends is chaotic: a nanometre&apos;s nudge to the torso changes the whole tumble, and it may end up on the bottom step, on the floor or against the low wall at the foot of the stairs. Hinged neighbours do not collide with each other, but every other pair of limbs does, and so do the limbs and the steps. Watch the hinges hold (well under a millimetre) while the limits stop the joints at their ends.</source>
        <extracomment>scenes/ragdoll.phasebox.json: description</extracomment>
        <translation>Un muñeco de trapo de diez cajas (torso, cabeza, brazos y antebrazos, muslos y espinillas; 32 kg en total) unidas por nueve bisagras con límites: el cuello gira medio radián a cada lado, codos y rodillas se doblan en un solo sentido, hombros y caderas se abren hacia fuera pero no cruzan el cuerpo. Se le empuja desde lo alto de un tramo de escalera y baja rodando. Dónde termina es caótico: un empujón de un nanómetro al torso cambia toda la caída, y puede acabar en el último escalón, en el suelo o contra el muro bajo al pie de la escalera. Los vecinos unidos por bisagras no chocan entre sí, pero cualquier otro par de miembros sí, y también los miembros con los escalones. Observe cómo aguantan las bisagras (con mucho menos de un milímetro de error) mientras los límites detienen las articulaciones en sus extremos.</translation>
    </message>
    <message>
        <source>Chain of springs</source>
        <extracomment>scenes/spring-chain.phasebox.json: name</extracomment>
        <translation>Cadena de muelles</translation>
    </message>
    <message>
        <source>Ten 0.1 kg beads joined by springs hang from a fixed hook and are released from a horizontal line. Watch the chain whip down and swing like a rope, and notice that the top spring stretches most: it carries the weight of every bead below it. The spring damping turns the swing&apos;s energy into work_nc in the energy plot, so the total slowly falls while the drift stays near zero.</source>
        <extracomment>scenes/spring-chain.phasebox.json: description</extracomment>
        <translation>Diez cuentas de 0,1 kg unidas por muelles cuelgan de un gancho fijo y se sueltan desde una línea horizontal. Observe cómo la cadena baja como un látigo y oscila como una cuerda, y fíjese en que el muelle de arriba es el que más se estira: soporta el peso de todas las cuentas que tiene debajo. El amortiguamiento de los muelles convierte la energía de la oscilación en work_nc en la gráfica de energía, así que el total baja despacio mientras la deriva se queda cerca de cero.</translation>
    </message>
    <message>
        <source>Spring oscillator: T = 2π√(m/k)</source>
        <extracomment>scenes/spring-oscillator.phasebox.json: name</extracomment>
        <translation>Oscilador de muelle: T = 2π√(m/k)</translation>
    </message>
    <message>
        <source>Two balls bounce on identical springs (k = 39.48 N/m); the right one is 4 times heavier. The period T = 2π√(m/k) is exactly 1 s for the 1 kg ball and 2 s for the 4 kg ball, and gravity only moves the equilibrium down by mg/k without changing the period. Switch to explicit Euler and watch the bounce grow and the total energy climb in the energy plot; symplectic Euler and Verlet keep it bounded.</source>
        <extracomment>scenes/spring-oscillator.phasebox.json: description</extracomment>
        <translation>Dos pelotas oscilan en muelles idénticos (k = 39,48 N/m); la de la derecha es 4 veces más pesada. El periodo T = 2π√(m/k) es exactamente 1 s para la pelota de 1 kg y 2 s para la de 4 kg, y la gravedad solo baja el equilibrio en mg/k sin cambiar el periodo. Cambie a Euler explícito y vea crecer la oscilación y subir la energía total en la gráfica de energía; Euler simpléctico y Verlet la mantienen acotada.</translation>
    </message>
    <message>
        <source>Stiff spring: explicit methods blow up</source>
        <extracomment>scenes/stiff-spring-blowup.phasebox.json: name</extracomment>
        <translation>Muelle rígido: los métodos explícitos estallan</translation>
    </message>
    <message>
        <source>A 1 kg ball swings on a very stiff spring (k = 100 000 N/m, so ω = √(k/m) = 316 rad/s) at the frame step dt = 1/60 s: ω·dt = 5.3, far past the stability limits of the explicit methods (ω·dt &lt; 2 for symplectic Euler and Verlet, 2.83 for RK4). Implicit Euler stays stable, but pays with numerical damping: watch the swing die away and the drift fall in the energy plot. Switch to symplectic Euler and the spring explodes within a few frames and is stopped as diverging; implicit midpoint is stable and keeps the energy.</source>
        <extracomment>scenes/stiff-spring-blowup.phasebox.json: description</extracomment>
        <translation>Una pelota de 1 kg oscila en un muelle muy rígido (k = 100 000 N/m, así que ω = √(k/m) = 316 rad/s) con el paso de fotograma dt = 1/60 s: ω·dt = 5,3, muy por encima de los límites de estabilidad de los métodos explícitos (ω·dt &lt; 2 para Euler simpléctico y Verlet, 2,83 para RK4). Euler implícito sigue estable, pero paga con amortiguamiento numérico: vea cómo se apaga la oscilación y baja la deriva en la gráfica de energía. Cambie a Euler simpléctico y el muelle estalla en pocos fotogramas y se detiene por divergencia; el punto medio implícito es estable y conserva la energía.</translation>
    </message>
    <message>
        <source>Lesson: the Atwood machine</source>
        <extracomment>lessons/atwood-machine.phasebox.json: name</extracomment>
        <translation>Lección: la máquina de Atwood</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: two Atwood machines, each a pair of weights on a massless rope over two fixed pulleys, 3 kg against 1 kg on the left and 1.1 kg against 0.9 kg on the right; each heavy weight starts 3 m above the floor. 2) Read each heavy weight&apos;s acceleration off the graph of its vy in the Instruments dock (left_heavy.vy, right_heavy.vy): while it falls the line is straight and its slope is −a; or time the fall with the stopwatch (Instruments, Timer) and work out a = 2·h/t². 3) Select a weight, change its mass, Reset and read the new slope. What to watch: the left pair accelerates at g/2 = 4.905 m/s² and lands after 1.11 s at 5.4 m/s; the right pair accelerates at g/10 = 0.981 m/s² and lands after 2.47 s at 2.4 m/s. When a heavy weight lands its partner stops too, because Phasebox&apos;s pulley rope never goes slack (a real light weight would coast on upwards for a moment). Why: the rope does not stretch, so the two weights move at the same speed, one up and one down, and it pulls each of them up with the same tension T. Newton&apos;s second law for each weight, m1·a = m1·g − T and m2·a = T − m2·g, added together gives a = g·(m1 − m2)/(m1 + m2): gravity pulls on the difference of the masses but has to accelerate their sum. Then T = 2·m1·m2·g/(m1 + m2), which is 14.7 N on the left, between the light weight&apos;s 9.8 N and the heavy one&apos;s 29.4 N, and 9.71 N on the right. George Atwood described the machine in 1784 to slow free fall down enough to time it by hand: with nearly equal masses a is a small fraction of g. The mass does not cancel here as it does for a pendulum, because the two weights share one acceleration.</source>
        <extracomment>lessons/atwood-machine.phasebox.json: description</extracomment>
        <translation>Pruebe esto: 1) Pulse Reproducir: dos máquinas de Atwood, cada una un par de pesas en una cuerda sin masa sobre dos poleas fijas, 3 kg frente a 1 kg a la izquierda y 1,1 kg frente a 0,9 kg a la derecha; cada pesa pesada empieza 3 m por encima del suelo. 2) Lea la aceleración de cada pesa pesada en la gráfica de su vy del panel Instrumentos (left_heavy.vy, right_heavy.vy): mientras cae la línea es recta y su pendiente es −a; o cronometre la caída (Instrumentos, Temporizador) y calcule a = 2·h/t². 3) Seleccione una pesa, cambie su masa, pulse Reiniciar y lea la nueva pendiente. Qué observar: el par de la izquierda acelera a g/2 = 4,905 m/s² y llega al suelo tras 1,11 s a 5,4 m/s; el de la derecha acelera a g/10 = 0,981 m/s² y llega tras 2,47 s a 2,4 m/s. Cuando una pesa pesada llega al suelo su compañera también se para, porque la cuerda de la polea de Phasebox nunca se afloja (una pesa ligera real seguiría subiendo un momento). Por qué: la cuerda no se estira, así que las dos pesas se mueven con la misma rapidez, una hacia arriba y otra hacia abajo, y tira de cada una hacia arriba con la misma tensión T. La segunda ley de Newton para cada pesa, m1·a = m1·g − T y m2·a = T − m2·g, sumadas dan a = g·(m1 − m2)/(m1 + m2): la gravedad tira de la diferencia de las masas pero tiene que acelerar su suma. Entonces T = 2·m1·m2·g/(m1 + m2), que es 14,7 N a la izquierda, entre los 9,8 N de la pesa ligera y los 29,4 N de la pesada, y 9,71 N a la derecha. George Atwood describió la máquina en 1784 para frenar la caída libre lo suficiente como para cronometrarla a mano: con masas casi iguales a es una pequeña fracción de g. Aquí la masa no se simplifica como en un péndulo, porque las dos pesas comparten una misma aceleración.</translation>
    </message>
    <message>
        <source>Lesson: a bead on a hoop</source>
        <extracomment>lessons/bead-on-hoop.phasebox.json: name</extracomment>
        <translation>Lección: una cuenta en un aro</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: a 1 kg bead slides without friction on a circular wire of radius 1 m, released from rest level with the centre of the hoop, 90° from the bottom. 2) Read the period off the period timer in the Instruments dock, which times bead.x, or click the bead and watch its loop in the Phase space plot. 3) Reset, switch the integrator to explicit Euler and then to RK4, and compare the swings and the energy plot. What to watch: the bead swings up to the same height on the other side and back with a period of 2.3678 s, the period of a 1 m pendulum released at 90°; at the bottom it passes at √(2·g·R) = 4.43 m/s. Under explicit Euler each swing climbs higher than the last until Phasebox stops the run as diverging; under RK4 the energy stays put. Why: the wire can push only at right angles to itself, so like the pendulum&apos;s rod it does no work, and the bead moves exactly as a pendulum bob on a massless rod to the centre, T = 4·√(R/g)·K(sin(θ0/2)). Phasebox treats the wire as a constraint C(x) = ‖x − c‖ − R = 0, Witkin and Baraff&apos;s bead on a wire: at every force evaluation it solves for the force that keeps C from changing, the part of gravity that would pull the bead off the wire plus the centripetal force m·v²/R that bends its path. That force is the wire&apos;s normal force: at the bottom it is m·g + m·v²/R = 3·m·g = 29.4 N, three times the bead&apos;s weight, whatever the radius. The little drift off the wire that a finite step leaves is projected away after each step, and any energy that takes shows in the plot as correction. The same machinery holds the rods, hinges and pulleys of the other joint lessons.</source>
        <extracomment>lessons/bead-on-hoop.phasebox.json: description</extracomment>
        <translation>Pruebe esto: 1) Pulse Reproducir: una cuenta de 1 kg desliza sin rozamiento por un alambre circular de 1 m de radio, soltada desde el reposo a la altura del centro del aro, a 90° del fondo. 2) Lea el periodo en el medidor de periodo del panel Instrumentos, que mide bead.x, o haga clic en la cuenta y observe su lazo en la gráfica del espacio de fases. 3) Pulse Reiniciar, cambie el integrador a Euler explícito y luego a RK4, y compare las oscilaciones y la gráfica de energía. Qué observar: la cuenta sube hasta la misma altura al otro lado y vuelve con un periodo de 2,3678 s, el de un péndulo de 1 m soltado a 90°; abajo pasa a √(2·g·R) = 4,43 m/s. Con Euler explícito cada oscilación sube más que la anterior hasta que Phasebox detiene la ejecución por divergencia; con RK4 la energía se mantiene. Por qué: el alambre solo puede empujar perpendicularmente a sí mismo, así que, como la varilla de un péndulo, no hace trabajo, y la cuenta se mueve exactamente como la masa de un péndulo en una varilla sin masa hasta el centro, T = 4·√(R/g)·K(sen(θ0/2)). Phasebox trata el alambre como una ligadura C(x) = ‖x − c‖ − R = 0, la cuenta en un alambre de Witkin y Baraff: en cada evaluación de fuerza calcula la fuerza que impide que C cambie, la parte de la gravedad que sacaría la cuenta del alambre más la fuerza centrípeta m·v²/R que curva su trayectoria. Esa fuerza es la normal del alambre: abajo vale m·g + m·v²/R = 3·m·g = 29,4 N, tres veces el peso de la cuenta, sea cual sea el radio. El pequeño desvío del alambre que deja un paso finito se proyecta fuera tras cada paso, y la energía que eso cuesta aparece en la gráfica como corrección. La misma maquinaria sostiene las varillas, bisagras y poleas de las demás lecciones de uniones.</translation>
    </message>
    <message>
        <source>Lesson: the three kinds of spring in a cloth</source>
        <extracomment>lessons/cloth-springs.phasebox.json: name</extracomment>
        <translation>Lección: los tres tipos de muelle de una tela</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: three cloths, 1.2 m square, hang under implicit Euler from two nodes of their top edge, a quarter of the way in from each side. The left one has structural, shear and bend springs; the middle one has no shear springs; the right one has neither shear nor bend springs. 2) Select a cloth and change its stiffness, then Reset and play again: give the right one its bend springs back (bend 20), or take the bend springs away from the left one. What to watch: the full cloth hangs as a flat sheet and even its top corners outside the pins stay up; without shear springs the squares of the mesh fold into diamonds, the corners swing down and the cloth narrows to about 0.7 m; without bend springs as well it narrows further, to about 0.55 m, and its folds become sharp creases where the middle one&apos;s are rounded. Why: structural springs keep each thread from stretching, but a square of four of them folds like a hinge at no cost, so they alone cannot hold a shape. Shear springs across both diagonals cut every square into triangles, which cannot fold: with them the cloth keeps its shape and the bend springs have nothing left to do (the left cloth without them looks the same). Bend springs join each node to the node two places along a thread and stretch only when the thread kinks, so where the mesh does fold they spread each fold over several nodes instead of one sharp crease. In this flat world a cloth can fold only within its own plane; in 3D, where a sheet bends out of its plane without stretching anything, bend springs are what give cloth its drape. Stiff structural springs are also why cloth wants an implicit integrator: at k = 2 000 N/m on nodes of 7 g the threads vibrate far too fast for an explicit method at dt = 1/60 s.</source>
        <extracomment>lessons/cloth-springs.phasebox.json: description</extracomment>
        <translation>Pruebe esto: 1) Pulse Reproducir: tres telas de 1,2 m de lado cuelgan con Euler implícito de dos nodos de su borde superior, a un cuarto de cada lado. La izquierda tiene muelles estructurales, de cizalla y de flexión; la del medio no tiene muelles de cizalla; la derecha no tiene ni de cizalla ni de flexión. 2) Seleccione una tela y cambie su rigidez, luego pulse Reiniciar y reproduzca de nuevo: devuelva a la derecha sus muelles de flexión (bend 20), o quite a la izquierda los suyos. Qué observar: la tela completa cuelga como una lámina plana e incluso sus esquinas superiores fuera de los puntos de sujeción se mantienen arriba; sin muelles de cizalla los cuadrados de la malla se pliegan en rombos, las esquinas caen y la tela se estrecha hasta unos 0,7 m; sin muelles de flexión además se estrecha más, hasta unos 0,55 m, y sus pliegues se vuelven dobleces marcados donde los de la del medio son redondeados. Por qué: los muelles estructurales impiden que cada hilo se estire, pero un cuadrado de cuatro de ellos se pliega como una bisagra sin coste, así que solos no pueden mantener una forma. Los muelles de cizalla en ambas diagonales cortan cada cuadrado en triángulos, que no se pueden plegar: con ellos la tela conserva su forma y los muelles de flexión no tienen nada que hacer (la tela de la izquierda sin ellos se ve igual). Los muelles de flexión unen cada nodo con el que está dos puestos más allá a lo largo de un hilo y solo se estiran cuando el hilo se dobla, así que, donde la malla se pliega, reparten cada pliegue entre varios nodos en vez de un doblez marcado. En este mundo plano una tela solo puede plegarse dentro de su propio plano; en 3D, donde una lámina se curva fuera de su plano sin estirar nada, los muelles de flexión son los que dan a la tela su caída. Los muelles estructurales rígidos son también la razón de que una tela pida un integrador implícito: con k = 2 000 N/m en nodos de 7 g los hilos vibran demasiado rápido para un método explícito con dt = 1/60 s.</translation>
    </message>
    <message>
        <source>Lesson: the double pendulum is chaotic</source>
        <extracomment>lessons/double-pendulum.phasebox.json: name</extracomment>
        <translation>Lección: el péndulo doble es caótico</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: two identical double pendulums, 1 kg bobs on massless rods 1 m long, start from rest nearly upside down, both rods at 170° from the vertical; the right one&apos;s lower rod is turned a billionth of a radian (1e-9 rad) further than the left one&apos;s, a millionth of a millimetre at its bob. 2) Watch them swing in step and note the time when the graphs in the Instruments dock first differ: a2.x and b2.x, the lower bobs&apos; x, and distance(a2,b2), which stays at 4.5 m while they move as one. 3) Reset, set dt to 1/1200 s and play again. What to watch: for about 8 s the two move as one; by 12 s the lower bobs are visibly apart and by 14 s they swing quite differently, although both keep their energy (under RK4 the total in the energy plot stays flat to a few microjoules). At dt = 1/1200 s they part at about the same time, but after 12 s both move differently from the run at 1/600 s. Why: the two bobs pull on each other through the lower rod, and the equations of their motion are nonlinear, so the motion is chaotic: two starts a tiny distance d apart separate roughly as d·e^(λt), here with λ ≈ 1.3 per second, ten times further every 2 s or so. That is why a billionth of a radian becomes a visible gap in about 12 s, and a start a thousand times closer would part only about 5 s later. The integrator&apos;s own error grows at the same rate: RK4 at dt = 1/600 s is a few millionths of a metre off after 5 s, millimetres off after 10 s, and after 15 s no run predicts where the real pendulum is. Both pendulums make nearly the same error at each step, which is why their difference still follows the physics. Chaos is not randomness: the motion is fully determined by its start, and a run repeated with the same numbers gives exactly the same motion.</source>
        <extracomment>lessons/double-pendulum.phasebox.json: description</extracomment>
        <translation>Pruebe esto: 1) Pulse Reproducir: dos péndulos dobles idénticos, masas de 1 kg en varillas sin masa de 1 m, empiezan en reposo casi boca abajo, con ambas varillas a 170° de la vertical; la varilla inferior del de la derecha está girada una milmillonésima de radián (1e-9 rad) más que la del izquierdo, una millonésima de milímetro en su masa. 2) Véalos oscilar a la par y anote el instante en que las gráficas del panel Instrumentos empiezan a diferir: a2.x y b2.x, la x de las masas inferiores, y distance(a2,b2), que se queda en 4,5 m mientras se mueven como uno solo. 3) Pulse Reiniciar, ponga dt a 1/1200 s y reproduzca de nuevo. Qué observar: durante unos 8 s los dos se mueven como uno; a los 12 s las masas inferiores están visiblemente separadas y a los 14 s oscilan de forma muy distinta, aunque ambos conservan su energía (con RK4 el total de la gráfica de energía se mantiene plano a unos pocos microjulios). Con dt = 1/1200 s se separan más o menos en el mismo instante, pero tras 12 s ambos se mueven de forma distinta a la ejecución con 1/600 s. Por qué: las dos masas tiran una de otra a través de la varilla inferior, y sus ecuaciones del movimiento son no lineales, así que el movimiento es caótico: dos inicios a una distancia diminuta d se separan más o menos como d·e^(λt), aquí con λ ≈ 1,3 por segundo, diez veces más cada 2 s más o menos. Por eso una milmillonésima de radián se convierte en una separación visible en unos 12 s, y un inicio mil veces más cercano se separaría solo unos 5 s más tarde. El propio error del integrador crece al mismo ritmo: RK4 con dt = 1/600 s se desvía unas millonésimas de metro tras 5 s, milímetros tras 10 s, y tras 15 s ninguna ejecución predice dónde está el péndulo real. Ambos péndulos cometen casi el mismo error en cada paso, por eso su diferencia sigue obedeciendo a la física. El caos no es azar: el movimiento está totalmente determinado por su inicio, y una ejecución repetida con los mismos números da exactamente el mismo movimiento.</translation>
    </message>
    <message>
        <source>Lesson: explicit Euler spirals out of an orbit</source>
        <extracomment>lessons/euler-orbit-spiral.phasebox.json: name</extracomment>
        <translation>Lección: Euler explícito se sale de la órbita en espiral</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play and watch two planets on circular orbits (r = 3 m and 5 m) round a star of G·M = 100 under explicit Euler at dt = 1/60 s. 2) Open the energy plot: the total climbs step after step; the graphs in the Instruments dock show each planet&apos;s distance from the star, distance(star,inner) and distance(star,outer). 3) Reset, switch the integrator to symplectic Euler and play again, then to RK4. What to watch: under explicit Euler both orbits spiral outwards, the inner one faster (after 20 s it has doubled in size, its distance from the star has passed 6 m, and the outer one has grown by more than a third, past 6.7 m); symplectic Euler keeps both closed with a wobble of about two percent; RK4 keeps them circular. Why: explicit Euler moves the planet along the tangent with the old velocity, and a tangent always leads outside a circle, so every step lifts the planet a little. On a circular orbit of angular speed ω each step raises the energy by about 2·(ω·dt)² of its size, a growth that never stops and is more than four and a half times larger for the faster inner orbit. Symplectic Euler uses the new velocity to move, and that small change makes it preserve a slightly perturbed energy, so the error stays bounded instead of piling up. RK4 is simply accurate: its error per lap is about (ω·dt)⁴ smaller. Halve dt and the energy climbs half as fast: explicit Euler is a first-order method, so its error shrinks only in proportion to the step.</source>
        <extracomment>lessons/euler-orbit-spiral.phasebox.json: description</extracomment>
        <translation>Pruebe esto: 1) Pulse Reproducir y observe dos planetas en órbitas circulares (r = 3 m y 5 m) alrededor de una estrella de G·M = 100 con Euler explícito y dt = 1/60 s. 2) Abra la gráfica de energía: el total sube paso a paso; las gráficas del panel Instrumentos muestran la distancia de cada planeta a la estrella, distance(star,inner) y distance(star,outer). 3) Pulse Reiniciar, cambie el integrador a Euler simpléctico y reproduzca de nuevo, y luego a RK4. Qué observar: con Euler explícito ambas órbitas se abren en espiral, la interior más deprisa (tras 20 s ha doblado su tamaño, su distancia a la estrella ha pasado de 6 m, y la exterior ha crecido más de un tercio, por encima de 6,7 m); Euler simpléctico mantiene ambas cerradas con un bamboleo de un dos por ciento; RK4 las mantiene circulares. Por qué: Euler explícito mueve el planeta a lo largo de la tangente con la velocidad antigua, y una tangente siempre lleva fuera de una circunferencia, así que cada paso eleva un poco el planeta. En una órbita circular de velocidad angular ω cada paso aumenta la energía en unos 2·(ω·dt)² de su valor, un crecimiento que nunca se detiene y que es más de cuatro veces y media mayor en la órbita interior, más rápida. Euler simpléctico usa la velocidad nueva para mover, y ese pequeño cambio le hace conservar una energía ligeramente perturbada, así que el error se mantiene acotado en lugar de acumularse. RK4 es simplemente preciso: su error por vuelta es unas (ω·dt)⁴ veces menor. Reduzca dt a la mitad y la energía sube la mitad de rápido: Euler explícito es un método de primer orden, así que su error solo disminuye en proporción al paso.</translation>
    </message>
    <message>
        <source>Lesson: an impulse sets a box spinning</source>
        <extracomment>lessons/impulse-spin.phasebox.json: name</extracomment>
        <translation>Lección: un impulso hace girar una caja</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: in empty space (no gravity) a 100 g pellet flies at 20 m/s into the left face of a 2 kg box, 0.15 m above the box&apos;s centre. 2) Read the box&apos;s speed and spin after the hit in the table in the Instruments dock (box.speed, and box.omega, negative when it turns clockwise), then Reset, drag the pellet up or down (or set its position y to 0) and play again. What to watch: the box drifts off at 1.41 m/s and turns clockwise at about 2 rad/s; a pellet aimed at the centre line pushes it without any spin, one aimed below the centre spins it the other way. Why: the contact pushes with one short, large force, an impulse J along the face&apos;s normal, and the same J changes the box&apos;s momentum by J and its angular momentum by r × J, where r runs from the centre of mass to the contact point: an off-centre push always turns. With restitution e = 0.5 and no friction, J = (1 + e)·m·v/(1 + m/M + m·d²/I) for an offset d, so the box moves at J/M and turns at J·d/I with I = M·(w² + h²)/12. Nothing outside the pellet and the box acts on them, so their total momentum and their angular momentum about any fixed point, the point of impact for instance, are the same after the hit as before, which is how the numbers above were worked out. The kinetic energy is not kept: the inelastic part of the bounce appears in work_nc. The dashed outline is that closed form (View → Exact Solution): with no force between the impacts, every integrator follows it to rounding.</source>
        <extracomment>lessons/impulse-spin.phasebox.json: description</extracomment>
        <translation>Pruebe esto: 1) Pulse Reproducir: en el espacio vacío (sin gravedad) un perdigón de 100 g vuela a 20 m/s contra la cara izquierda de una caja de 2 kg, 0,15 m por encima del centro de la caja. 2) Lea la rapidez y el giro de la caja tras el golpe en la tabla del panel Instrumentos (box.speed, y box.omega, negativa cuando gira en sentido horario); luego pulse Reiniciar, arrastre el perdigón arriba o abajo (o ponga su posición y a 0) y reproduzca de nuevo. Qué observar: la caja se aleja a 1,41 m/s y gira en sentido horario a unos 2 rad/s; un perdigón dirigido a la línea central la empuja sin ningún giro, uno dirigido por debajo del centro la hace girar al revés. Por qué: el contacto empuja con una fuerza breve y grande, un impulso J según la normal de la cara, y el mismo J cambia la cantidad de movimiento de la caja en J y su momento angular en r × J, donde r va del centro de masas al punto de contacto: un empujón descentrado siempre hace girar. Con restitución e = 0,5 y sin rozamiento, J = (1 + e)·m·v/(1 + m/M + m·d²/I) para un desplazamiento d, así que la caja se mueve a J/M y gira a J·d/I con I = M·(w² + h²)/12. Nada fuera del perdigón y la caja actúa sobre ellos, así que su cantidad de movimiento total y su momento angular respecto a cualquier punto fijo, por ejemplo el punto de impacto, son los mismos después del golpe que antes, y así se calcularon los números de arriba. La energía cinética no se conserva: la parte inelástica del rebote aparece en work_nc. El contorno a trazos es esa forma cerrada (Ver → Solución exacta): sin fuerzas entre los impactos, todos los integradores la siguen hasta el redondeo.</translation>
    </message>
    <message>
        <source>Lesson: midpoint against RK4</source>
        <extracomment>lessons/midpoint-vs-rk4.phasebox.json: name</extracomment>
        <translation>Lección: punto medio frente a RK4</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: a ball on a spring (k = 4 N/m, m = 1 kg, so ω = 2 rad/s and the period is π s) swings under the midpoint method at a coarse dt = 0.1 s, next to its exact solution x = cos 2t. 2) Watch the graph of ball.vx against ball.x in the Instruments dock, the phase portrait: the exact motion is a closed ellipse. 3) Reset and switch to RK4 at the same dt; then try midpoint at dt = 0.05 s, which costs as many force evaluations per second as RK4 at 0.1 s. What to watch: midpoint&apos;s ellipse slowly grows and its swing runs ahead of the exact one (after 20 s by about a quarter of a radian); RK4&apos;s stays on the exact curve to four decimals. Why: both methods sample the force inside the step, midpoint once and RK4 three times, and the weights of RK4 cancel the error terms up to the fourth power of ω·dt, midpoint&apos;s only up to the second. Halving dt divides midpoint&apos;s error by 4 and RK4&apos;s by 16, so at equal cost RK4 still wins by a wide margin on a smooth problem like this one. Midpoint&apos;s amplification per step is √(1 + (ω·dt)⁴/4), slightly above 1, which is why its energy creeps up. The command phasebox-cli accuracy on this file draws the work-precision diagram that shows it across many step sizes.</source>
        <extracomment>lessons/midpoint-vs-rk4.phasebox.json: description</extracomment>
        <translation>Pruebe esto: 1) Pulse Reproducir: una pelota en un muelle (k = 4 N/m, m = 1 kg, así que ω = 2 rad/s y el periodo es π s) oscila con el método del punto medio con un dt grueso de 0,1 s, junto a su solución exacta x = cos 2t. 2) Observe la gráfica de ball.vx frente a ball.x en el panel Instrumentos, el retrato de fases: el movimiento exacto es una elipse cerrada. 3) Pulse Reiniciar y cambie a RK4 con el mismo dt; luego pruebe el punto medio con dt = 0,05 s, que cuesta tantas evaluaciones de fuerza por segundo como RK4 con 0,1 s. Qué observar: la elipse del punto medio crece despacio y su oscilación se adelanta a la exacta (tras 20 s en un cuarto de radián más o menos); la de RK4 se queda sobre la curva exacta con cuatro decimales. Por qué: ambos métodos muestrean la fuerza dentro del paso, el punto medio una vez y RK4 tres veces, y los pesos de RK4 cancelan los términos de error hasta la cuarta potencia de ω·dt, los del punto medio solo hasta la segunda. Reducir dt a la mitad divide el error del punto medio entre 4 y el de RK4 entre 16, así que a igual coste RK4 sigue ganando con holgura en un problema suave como este. La amplificación por paso del punto medio es √(1 + (ω·dt)⁴/4), algo por encima de 1, y por eso su energía sube poco a poco. La orden phasebox-cli accuracy sobre este archivo dibuja el diagrama trabajo-precisión que lo muestra con muchos tamaños de paso.</translation>
    </message>
    <message>
        <source>Lesson: restitution and friction</source>
        <extracomment>lessons/restitution-friction.phasebox.json: name</extracomment>
        <translation>Lección: restitución y rozamiento</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play. On the left three balls fall 2 m onto a floor; on the right three crates slide at 4 m/s along strips of ice, wood and rubber. 2) Read each ball&apos;s rebound off the graphs in the Instruments dock, e090.y, e060.y and e030.y (each ball&apos;s centre, 0.15 m above its lowest point), and where each crate stops off the table of on_ice.x, on_wood.x and on_rubber.x (each starts at x = 0.5 m). 3) Select a ball and change its restitution, or a crate and its strip and change their friction, then Reset and play again. What to watch: each ball climbs back to e²·h, 1.62 m, 0.72 m and 0.18 m for e = 0.9, 0.6 and 0.3; each crate stops after v²/(2·μ·g), 8.2 m on ice (μ = 0.1), 2.0 m on wood (μ = 0.4) and 1.0 m on rubber (μ = 0.8); the energy the bounces and the sliding lose appears in work_nc. Why: restitution e is the ratio of the speeds just after and just before a bounce, and since the height a ball reaches goes with the square of its speed, it rebounds to e² of its drop. Kinetic friction opposes sliding with a force μ times the normal force, here μ·m·g, so the crate decelerates uniformly at μ·g whatever its mass. A pair of materials combines as max(e₁, e₂) and √(μ₁·μ₂): the floor has e = 0, so each ball&apos;s own e counts, and each crate has the same μ as its strip. A bounce is an impulse the solver applies at the moment of impact, while a steady slide&apos;s friction, like the floor&apos;s push under a resting body, acts as a force inside the integrator&apos;s step; a bounce slower than the restitution threshold (1 m/s times 1 − e) is treated as inelastic, which is why small hops end in rest instead of going on for ever; with e = 1 every bounce is elastic.</source>
        <extracomment>lessons/restitution-friction.phasebox.json: description</extracomment>
        <translation>Pruebe esto: 1) Pulse Reproducir. A la izquierda tres pelotas caen 2 m sobre un suelo; a la derecha tres cajas deslizan a 4 m/s sobre tiras de hielo, madera y goma. 2) Lea el rebote de cada pelota en las gráficas del panel Instrumentos, e090.y, e060.y y e030.y (el centro de cada pelota, 0,15 m por encima de su punto más bajo), y dónde se para cada caja en la tabla de on_ice.x, on_wood.x y on_rubber.x (cada una empieza en x = 0,5 m). 3) Seleccione una pelota y cambie su restitución, o una caja y su tira y cambie su rozamiento; luego pulse Reiniciar y reproduzca de nuevo. Qué observar: cada pelota vuelve a subir hasta e²·h, 1,62 m, 0,72 m y 0,18 m para e = 0,9, 0,6 y 0,3; cada caja se para tras v²/(2·μ·g), 8,2 m sobre hielo (μ = 0,1), 2,0 m sobre madera (μ = 0,4) y 1,0 m sobre goma (μ = 0,8); la energía que pierden los rebotes y el deslizamiento aparece en work_nc. Por qué: la restitución e es el cociente entre las velocidades justo después y justo antes de un rebote, y como la altura que alcanza una pelota va con el cuadrado de su velocidad, rebota hasta e² de su caída. El rozamiento dinámico se opone al deslizamiento con una fuerza μ veces la normal, aquí μ·m·g, así que la caja frena uniformemente a μ·g sea cual sea su masa. Un par de materiales se combina como max(e₁, e₂) y √(μ₁·μ₂): el suelo tiene e = 0, así que cuenta la e de cada pelota, y cada caja tiene la misma μ que su tira. Un rebote es un impulso que el solucionador aplica en el momento del impacto, mientras que el rozamiento de un deslizamiento constante, como el empuje del suelo bajo un cuerpo en reposo, actúa como una fuerza dentro del paso del integrador; un rebote más lento que el umbral de restitución (1 m/s por 1 − e) se trata como inelástico, y por eso los saltitos acaban en reposo en lugar de seguir para siempre; con e = 1 todo rebote es elástico.</translation>
    </message>
    <message>
        <source>Lesson: the rolling race</source>
        <extracomment>lessons/rolling-race.phasebox.json: name</extracomment>
        <translation>Lección: la carrera rodando</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play and watch the three start together from rest on the same 20° slope, each 5 m (along the slope) from its finish. The ramps run on past the finish, so all three are still on them when the race ends at 3 s. 2) Guess the order first, then read it off the race: the graphs in the Instruments dock show slider.speed, disk.speed and box.speed, each a straight line whose slope is the body&apos;s acceleration. 3) Select the box or a ramp and change its friction, Reset, and race again. What to watch: the frictionless disk slides at g·sin θ = 3.36 m/s² and finishes 5 m in 1.73 s; the rolling disk (μ = 0.5) turns as it goes and accelerates at ⅔·g·sin θ = 2.24 m/s², finishing in 2.11 s; the box (μ = 0.2) slides at g·(sin θ − μ·cos θ) = 1.51 m/s², finishing in 2.57 s. The rolling disk loses no energy: work_nc stays at zero for it while the box&apos;s friction takes energy out. Why: a disk that rolls without slipping must spin up as it speeds up, so part of the work gravity does goes into ½·I·ω², with I = ½·m·r² and ω = v/r. Its kinetic energy is then ¾·m·v² instead of ½·m·v², so its acceleration is ⅔ of the frictionless g·sin θ, whatever its mass or radius. Static friction makes it roll but does no work, because the point of contact does not move. It needs only μ ≥ ⅓·tan θ = 0.12 to roll on this slope; with less, the disk slides and spins up more slowly. The box&apos;s kinetic friction does work, μ·m·g·cos θ per metre, which is why it comes last.</source>
        <extracomment>lessons/rolling-race.phasebox.json: description</extracomment>
        <translation>Pruebe esto: 1) Pulse Reproducir y observe cómo los tres salen juntos desde el reposo en la misma pendiente de 20°, cada uno a 5 m (a lo largo de la pendiente) de su meta. Las rampas siguen más allá de la meta, así que los tres siguen sobre ellas cuando la carrera termina a los 3 s. 2) Adivine primero el orden y luego léalo en la carrera: las gráficas del panel Instrumentos muestran slider.speed, disk.speed y box.speed, cada una una recta cuya pendiente es la aceleración del cuerpo. 3) Seleccione la caja o una rampa y cambie su rozamiento, pulse Reiniciar y vuelva a correr. Qué observar: el disco sin rozamiento desliza a g·sen θ = 3,36 m/s² y recorre los 5 m en 1,73 s; el disco que rueda (μ = 0,5) gira mientras avanza y acelera a ⅔·g·sen θ = 2,24 m/s², llegando en 2,11 s; la caja (μ = 0,2) desliza a g·(sen θ − μ·cos θ) = 1,51 m/s², llegando en 2,57 s. El disco que rueda no pierde energía: su work_nc se queda en cero mientras el rozamiento de la caja le quita energía. Por qué: un disco que rueda sin deslizar debe girar más deprisa a medida que acelera, así que parte del trabajo de la gravedad va a ½·I·ω², con I = ½·m·r² y ω = v/r. Su energía cinética es entonces ¾·m·v² en lugar de ½·m·v², así que su aceleración es ⅔ del g·sen θ sin rozamiento, sean cuales sean su masa y su radio. El rozamiento estático lo hace rodar pero no hace trabajo, porque el punto de contacto no se mueve. Solo necesita μ ≥ ⅓·tan θ = 0,12 para rodar en esta pendiente; con menos, el disco desliza y gira más despacio. El rozamiento dinámico de la caja sí hace trabajo, μ·m·g·cos θ por metro, y por eso llega la última.</translation>
    </message>
    <message>
        <source>Lesson: the simple pendulum</source>
        <extracomment>lessons/simple-pendulum.phasebox.json: name</extracomment>
        <translation>Lección: el péndulo simple</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: two 1 kg bobs hang on massless rigid rods 1 m long, the left one released from rest at 90° from the vertical (level with its pivot), the right one at 10°. 2) Read each period off the period timer in the Instruments dock: it times rod90.angle, the 90° pendulum&apos;s swing from straight down, as the mean interval between its upward crossings; choose rod10.angle as its probe to time the 10° one from then on (or click a bob and watch its loop in the Phase space plot close). 3) Reset and switch the integrator to explicit Euler, then RK4, and watch the swings and the energy plot; then try a smaller dt. What to watch: the 10° pendulum swings with a period of 2.0099 s, hardly more than the small-angle 2π·√(L/g) = 2.006 s; the 90° one takes 2.3678 s, 18% longer, so it falls further and further behind. Under symplectic Euler the energy wobbles a little but stays put; under explicit Euler the swings grow every period until Phasebox stops the run as diverging; RK4 keeps the energy to many decimals. Why: the rod holds the bob on a circle, so only gravity&apos;s component along the circle, −m·g·sin θ, speeds it up or slows it down, and the mass cancels. For small angles sin θ ≈ θ, the motion is simple harmonic and T = 2π·√(L/g) whatever the amplitude. Farther out sin θ &lt; θ, the pull back is weaker than the linear one, and the swing takes longer: the exact period is T = 4·√(L/g)·K(sin(θ0/2)), with K the complete elliptic integral of the first kind. With L = 1 m and g = 9.81 m/s² this gives 2.0099 s at 10° and 2.3678 s at 90°. The rod&apos;s pull does no work, because it is always at right angles to the motion: the energy plot&apos;s total is the integrator&apos;s doing.</source>
        <extracomment>lessons/simple-pendulum.phasebox.json: description</extracomment>
        <translation>Pruebe esto: 1) Pulse Reproducir: dos masas de 1 kg cuelgan de varillas rígidas sin masa de 1 m, la izquierda soltada desde el reposo a 90° de la vertical (a la altura de su eje), la derecha a 10°. 2) Lea cada periodo en el medidor de periodo del panel Instrumentos: mide rod90.angle, la desviación del péndulo de 90° respecto a la vertical, como el intervalo medio entre sus cruces ascendentes; elija rod10.angle como sonda para medir desde entonces el de 10° (o haga clic en una masa y vea cerrarse su lazo en la gráfica del espacio de fases). 3) Pulse Reiniciar y cambie el integrador a Euler explícito, luego a RK4, y observe las oscilaciones y la gráfica de energía; después pruebe un dt menor. Qué observar: el péndulo de 10° oscila con un periodo de 2,0099 s, apenas más que el 2π·√(L/g) = 2,006 s de ángulos pequeños; el de 90° tarda 2,3678 s, un 18 % más, así que se va quedando cada vez más atrás. Con Euler simpléctico la energía se tambalea un poco pero se mantiene; con Euler explícito las oscilaciones crecen en cada periodo hasta que Phasebox detiene la ejecución por divergencia; RK4 mantiene la energía con muchos decimales. Por qué: la varilla mantiene la masa sobre una circunferencia, así que solo la componente de la gravedad a lo largo de ella, −m·g·sen θ, la acelera o la frena, y la masa se simplifica. Para ángulos pequeños sen θ ≈ θ, el movimiento es armónico simple y T = 2π·√(L/g) sea cual sea la amplitud. Más lejos sen θ &lt; θ, la fuerza recuperadora es más débil que la lineal y la oscilación tarda más: el periodo exacto es T = 4·√(L/g)·K(sen(θ0/2)), con K la integral elíptica completa de primera especie. Con L = 1 m y g = 9,81 m/s² da 2,0099 s a 10° y 2,3678 s a 90°. El tirón de la varilla no hace trabajo, porque siempre es perpendicular al movimiento: el total de la gráfica de energía es obra del integrador.</translation>
    </message>
    <message>
        <source>Lesson: a stiff spring, explicit against implicit</source>
        <extracomment>lessons/stiff-spring-implicit.phasebox.json: name</extracomment>
        <translation>Lección: un muelle rígido, explícito frente a implícito</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: a 1 kg bob swings on a soft spring (k = 10 N/m) with a 10 g bead fastened to it by a very stiff spring (k = 10 000 N/m), under implicit Euler at dt = 1/60 s. 2) Reset, switch to symplectic Euler and play; then try RK4. 3) Go back to implicit Euler and compare with implicit midpoint. What to watch: the explicit methods blow up within a few frames and the world stops them as diverging, although the motion you see is the slow 2-second swing of the soft spring; implicit Euler runs, but the swing dies away, to half its size in 10 s (look at the drift in the energy plot); implicit midpoint runs and keeps the swing. Why: the bead on its stiff spring vibrates at ω = √(k·(1/m₁ + 1/m₂)) ≈ 1 000 rad/s, so ω·dt ≈ 17, far past the explicit methods&apos; stability limits (ω·dt &lt; 2 for symplectic Euler, 2.8 for RK4): the stiffest spring sets the step for the whole scene, even when its own motion is invisible. An implicit method evaluates the force at the end of the step and solves for it, which is stable at any step. Backward Euler pays with numerical damping of every motion, about (ω·dt)²/2 of the amplitude per step, while implicit midpoint keeps the energy of the slow swing. Symplectic Euler needs ω·h &lt; 2 here: 9 sub-steps per frame (RK4, stable to 2.8, needs 6), for a motion you cannot even see.</source>
        <extracomment>lessons/stiff-spring-implicit.phasebox.json: description</extracomment>
        <translation>Pruebe esto: 1) Pulse Reproducir: una masa de 1 kg oscila en un muelle blando (k = 10 N/m) con una cuenta de 10 g sujeta a ella por un muelle muy rígido (k = 10 000 N/m), con Euler implícito y dt = 1/60 s. 2) Pulse Reiniciar, cambie a Euler simpléctico y reproduzca; luego pruebe RK4. 3) Vuelva a Euler implícito y compárelo con el punto medio implícito. Qué observar: los métodos explícitos estallan en pocos fotogramas y el mundo los detiene por divergencia, aunque el movimiento que se ve es la lenta oscilación de 2 segundos del muelle blando; Euler implícito funciona, pero la oscilación se apaga, a la mitad en 10 s (mire la deriva en la gráfica de energía); el punto medio implícito funciona y conserva la oscilación. Por qué: la cuenta en su muelle rígido vibra a ω = √(k·(1/m₁ + 1/m₂)) ≈ 1 000 rad/s, así que ω·dt ≈ 17, muy por encima de los límites de estabilidad de los métodos explícitos (ω·dt &lt; 2 para Euler simpléctico, 2,8 para RK4): el muelle más rígido fija el paso de toda la escena, aunque su propio movimiento sea invisible. Un método implícito evalúa la fuerza al final del paso y la despeja, lo que es estable con cualquier paso. Euler hacia atrás paga con amortiguamiento numérico de todo movimiento, unos (ω·dt)²/2 de la amplitud por paso, mientras que el punto medio implícito conserva la energía de la oscilación lenta. Euler simpléctico necesita aquí ω·h &lt; 2: 9 subpasos por fotograma (RK4, estable hasta 2,8, necesita 6), para un movimiento que ni siquiera se ve.</translation>
    </message>
    <message>
        <source>Lesson: three ways to collide</source>
        <extracomment>lessons/three-ways-to-collide.phasebox.json: name</extracomment>
        <translation>Lección: tres maneras de chocar</translation>
    </message>
    <message>
        <source>Try this: 1) Press Play: a 1 kg ball with restitution 0.8 drops 2 m onto the ground, four 1 kg boxes stand in a stack and a Newton&apos;s cradle of five 1 kg balls on 2 m rods is released from 40°, all under impulse contacts (Parameters, Contacts); read the ball&apos;s bounces off the graph of ball.y in the Instruments dock (its centre: it touches the ground at ball.y = 0.25 m). 2) Reset, choose Penalty in Contacts and play again; watch the energy plot and click the dropped ball to see its phase plot. 3) Reset, choose Kinematic and play once more; each time, compare the step cost in the Effects panel. What to watch: under impulses the ball rebounds to 1.26 m (e²·h = 1.28 m), the stack stands still and the cradle hands the swing down the row to the last ball, which rises as high as the first one fell. Under penalty the dashed ghost beside the ball is the closed form of its bounces (free fall, then the damped contact spring; View → Exact Solution), and the phase plot of the ball draws it as a dashed curve. The ball sinks 4.6 cm into the ground and stays in contact for 0.026 s, half an oscillation of the contact spring, π·√(m/k)/√(1 − ζ²) with k = 14,400 N/m (the automatic choice, ω·h = 0.5 at dt = 1/240 s); it leaves at 0.80 of its speed, e = exp(−ζπ/√(1 − ζ²)) with ζ = c/(2·√(k·m)) = 0.071 from the contact damping c = 17 N·s/m. The stack sags a few millimetres, and in the cradle every ball swings: the momentum spreads along the row. Under kinematic the ball rebounds to 1.27 m as under impulses, but the energy plot&apos;s correction line climbs, about 0.8 J a second, while the drift line falls about as fast and work_nc falls with each bounce: every push out of an overlap adds energy, and the resting bodies&apos; fall back into the next overlap takes it out again. Why: kinematic response is geometry first: it moves overlapping bodies apart and flips the approaching velocity, exact for one isolated bounce, but it knows no forces, so a resting body is lifted and dropped again at every step. The penalty method makes contact a force, a stiff damped spring at each overlapping point, so the integrator treats it like any spring: ½·k·d² is in the potential energy, a bounce is half an oscillation, and a stiffer spring needs a smaller step (the stability advisor asks ω·h ≤ 1 of explicit methods). In a row of touching balls those springs form a chain that carries waves, so the cradle&apos;s momentum disperses instead of passing on whole. Impulses solve for the velocity changes that stop each approach at once, with restitution and friction as rules on those changes, which is why stacks rest and the cradle works, at the price of an iterative solver after every step. Penalty costs least per step but needs small steps when stiff; impulses cost most per step but hold a stack at any step.</source>
        <extracomment>lessons/three-ways-to-collide.phasebox.json: description</extracomment>
        <translation>Pruebe esto: 1) Pulse Reproducir: una pelota de 1 kg con restitución 0,8 cae 2 m sobre el suelo, cuatro cajas de 1 kg forman una pila y un péndulo de Newton de cinco bolas de 1 kg en varillas de 2 m se suelta desde 40°, todo con contactos por impulsos (Parámetros, Contactos); lea los rebotes de la pelota en la gráfica de ball.y del panel Instrumentos (su centro: toca el suelo en ball.y = 0,25 m). 2) Pulse Reiniciar, elija Penalización en Contactos y reproduzca de nuevo; observe la gráfica de energía y haga clic en la pelota que cae para ver su diagrama de fases. 3) Pulse Reiniciar, elija Cinemático y reproduzca una vez más; cada vez, compare el coste del paso en el panel Efectos. Qué observar: con impulsos la pelota rebota hasta 1,26 m (e²·h = 1,28 m), la pila se queda quieta y el péndulo de Newton pasa la oscilación a lo largo de la fila hasta la última bola, que sube tan alto como cayó la primera. Con penalización, el fantasma a trazos junto a la pelota es la forma cerrada de sus rebotes (caída libre y luego el muelle de contacto amortiguado; Ver → Solución exacta), y el diagrama de fases de la pelota la dibuja como una curva a trazos. La pelota se hunde 4,6 cm en el suelo y se queda en contacto 0,026 s, media oscilación del muelle de contacto, π·√(m/k)/√(1 − ζ²) con k = 14 400 N/m (la elección automática, ω·h = 0,5 con dt = 1/240 s); sale con 0,80 de su velocidad, e = exp(−ζπ/√(1 − ζ²)) con ζ = c/(2·√(k·m)) = 0,071 a partir del amortiguamiento de contacto c = 17 N·s/m. La pila se hunde unos milímetros, y en el péndulo de Newton oscilan todas las bolas: la cantidad de movimiento se reparte por la fila. Con cinemático la pelota rebota hasta 1,27 m como con impulsos, pero la línea de corrección de la gráfica de energía sube, unos 0,8 J por segundo, mientras la línea de deriva baja más o menos igual de rápido y work_nc baja con cada rebote: cada empujón fuera de un solapamiento añade energía, y la caída de los cuerpos en reposo hacia el siguiente solapamiento la vuelve a quitar. Por qué: la respuesta cinemática es ante todo geometría: separa los cuerpos solapados y da la vuelta a la velocidad de acercamiento, exacta para un rebote aislado, pero no conoce fuerzas, así que un cuerpo en reposo se levanta y se vuelve a dejar caer en cada paso. El método de penalización hace del contacto una fuerza, un muelle rígido amortiguado en cada punto solapado, así que el integrador lo trata como cualquier muelle: ½·k·d² está en la energía potencial, un rebote es media oscilación y un muelle más rígido necesita un paso menor (el asesor de estabilidad pide ω·h ≤ 1 a los métodos explícitos). En una fila de bolas que se tocan esos muelles forman una cadena que transmite ondas, así que la cantidad de movimiento del péndulo de Newton se dispersa en lugar de pasar entera. Los impulsos calculan los cambios de velocidad que detienen cada acercamiento de inmediato, con la restitución y el rozamiento como reglas sobre esos cambios, y por eso las pilas reposan y el péndulo de Newton funciona, al precio de un solucionador iterativo tras cada paso. La penalización cuesta menos por paso pero necesita pasos pequeños cuando es rígida; los impulsos cuestan más por paso pero sostienen una pila con cualquier paso.</translation>
    </message>
</context>
<context>
    <name>Schema</name>
    <message>
        <source>Width</source>
        <translation>Ancho</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Alto</translation>
    </message>
    <message>
        <source>Columns</source>
        <translation>Columnas</translation>
    </message>
    <message>
        <source>Rows</source>
        <translation>Filas</translation>
    </message>
    <message>
        <source>%1 lower</source>
        <translation>%1 inferior</translation>
    </message>
    <message>
        <source>%1 upper</source>
        <translation>%1 superior</translation>
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
        <translation>cómo avanza el tiempo</translation>
    </message>
    <message>
        <source>Integrator</source>
        <extracomment>schema: simulation.integrator</extracomment>
        <translation>Integrador</translation>
    </message>
    <message>
        <source>Time step</source>
        <extracomment>schema: simulation.dt</extracomment>
        <translation>Paso de tiempo</translation>
    </message>
    <message>
        <source>Sub-steps</source>
        <extracomment>schema: simulation.substeps</extracomment>
        <translation>Subpasos</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <extracomment>schema: simulation.tolerance</extracomment>
        <translation>Tolerancia</translation>
    </message>
    <message>
        <source>Newton iterations</source>
        <extracomment>schema: simulation.newton_iterations</extracomment>
        <translation>Iteraciones de Newton</translation>
    </message>
    <message>
        <source>Duration</source>
        <extracomment>schema: simulation.duration</extracomment>
        <translation>Duración</translation>
    </message>
    <message>
        <source>Contact solver</source>
        <extracomment>schema: simulation.solver</extracomment>
        <translation>Solucionador de contactos</translation>
    </message>
    <message>
        <source>Contact model</source>
        <extracomment>schema: simulation.contact_model</extracomment>
        <translation>Modelo de contacto</translation>
    </message>
    <message>
        <source>Contact stiffness</source>
        <extracomment>schema: simulation.contact_stiffness</extracomment>
        <translation>Rigidez de contacto</translation>
    </message>
    <message>
        <source>Contact damping</source>
        <extracomment>schema: simulation.contact_damping</extracomment>
        <translation>Amortiguamiento de contacto</translation>
    </message>
    <message>
        <source>Uniform gravity: F = m·g on every dynamic body</source>
        <extracomment>schema: gravity</extracomment>
        <translation>Gravedad uniforme: F = m·g sobre cada cuerpo dinámico</translation>
    </message>
    <message>
        <source>g</source>
        <extracomment>schema: gravity.g</extracomment>
        <translation>g</translation>
    </message>
    <message>
        <source>Air drag: F = −b·v − c·‖v‖·v, torque −β·ω</source>
        <extracomment>schema: drag</extracomment>
        <translation>Resistencia del aire: F = −b·v − c·‖v‖·v, momento −β·ω</translation>
    </message>
    <message>
        <source>Linear b</source>
        <extracomment>schema: drag.linear</extracomment>
        <translation>Lineal b</translation>
    </message>
    <message>
        <source>Quadratic c</source>
        <extracomment>schema: drag.quadratic</extracomment>
        <translation>Cuadrática c</translation>
    </message>
    <message>
        <source>Angular β</source>
        <extracomment>schema: drag.angular</extracomment>
        <translation>Angular β</translation>
    </message>
    <message>
        <source>Newtonian gravity toward attractors (and between particles if mutual)</source>
        <extracomment>schema: newtonian_gravity</extracomment>
        <translation>Gravitación newtoniana hacia los atractores (y entre partículas si es mutua)</translation>
    </message>
    <message>
        <source>G</source>
        <extracomment>schema: newtonian_gravity.G</extracomment>
        <translation>G</translation>
    </message>
    <message>
        <source>Attractors</source>
        <extracomment>schema: newtonian_gravity.attractors</extracomment>
        <translation>Atractores</translation>
    </message>
    <message>
        <source>Mutual</source>
        <extracomment>schema: newtonian_gravity.mutual</extracomment>
        <translation>Mutua</translation>
    </message>
    <message>
        <source>Softening ε</source>
        <extracomment>schema: newtonian_gravity.softening</extracomment>
        <translation>Suavizado ε</translation>
    </message>
    <message>
        <source>Buoyancy ρ·A_sub·‖g‖ on the submerged part below the surface</source>
        <extracomment>schema: buoyancy</extracomment>
        <translation>Empuje ρ·A_sub·‖g‖ sobre la parte sumergida bajo la superficie</translation>
    </message>
    <message>
        <source>Fluid density ρ</source>
        <extracomment>schema: buoyancy.fluid_density</extracomment>
        <translation>Densidad del fluido ρ</translation>
    </message>
    <message>
        <source>Surface y</source>
        <extracomment>schema: buoyancy.surface_y</extracomment>
        <translation>Superficie y</translation>
    </message>
    <message>
        <source>Drag b_f</source>
        <extracomment>schema: buoyancy.drag</extracomment>
        <translation>Resistencia b_f</translation>
    </message>
    <message>
        <source>Wind: F = b·(w − v) on particles</source>
        <extracomment>schema: wind</extracomment>
        <translation>Viento: F = b·(w − v) sobre las partículas</translation>
    </message>
    <message>
        <source>Velocity w</source>
        <extracomment>schema: wind.velocity</extracomment>
        <translation>Velocidad w</translation>
    </message>
    <message>
        <source>Drag b</source>
        <extracomment>schema: wind.drag</extracomment>
        <translation>Resistencia b</translation>
    </message>
    <message>
        <source>Boids steering: separation, alignment, cohesion (Reynolds 1987)</source>
        <extracomment>schema: flocking</extracomment>
        <translation>Guiado de bandada: separación, alineación, cohesión (Reynolds 1987)</translation>
    </message>
    <message>
        <source>Radius</source>
        <extracomment>schema: flocking.radius</extracomment>
        <translation>Radio</translation>
    </message>
    <message>
        <source>Separation</source>
        <extracomment>schema: flocking.separation</extracomment>
        <translation>Separación</translation>
    </message>
    <message>
        <source>Alignment</source>
        <extracomment>schema: flocking.alignment</extracomment>
        <translation>Alineación</translation>
    </message>
    <message>
        <source>Cohesion</source>
        <extracomment>schema: flocking.cohesion</extracomment>
        <translation>Cohesión</translation>
    </message>
    <message>
        <source>Maximum speed</source>
        <extracomment>schema: flocking.max_speed</extracomment>
        <translation>Velocidad máxima</translation>
    </message>
    <message>
        <source>Particle–particle disk contacts</source>
        <extracomment>schema: particle_collisions</extracomment>
        <translation>Contactos de disco entre partículas</translation>
    </message>
    <message>
        <source>Restitution e</source>
        <extracomment>schema: particle_collisions.restitution</extracomment>
        <translation>Restitución e</translation>
    </message>
    <message>
        <source>Coulomb&apos;s law between charged particles</source>
        <extracomment>schema: coulomb</extracomment>
        <translation>Ley de Coulomb entre partículas cargadas</translation>
    </message>
    <message>
        <source>k</source>
        <extracomment>schema: coulomb.k</extracomment>
        <translation>k</translation>
    </message>
    <message>
        <source>fixed points of newtonian_gravity</source>
        <extracomment>schema: attractors</extracomment>
        <translation>puntos fijos de newtonian_gravity</translation>
    </message>
    <message>
        <source>Position</source>
        <extracomment>schema: attractors.position</extracomment>
        <translation>Posición</translation>
    </message>
    <message>
        <source>Mass</source>
        <extracomment>schema: attractors.mass</extracomment>
        <translation>Masa</translation>
    </message>
    <message>
        <source>point masses, drawn as disks</source>
        <extracomment>schema: particles</extracomment>
        <translation>masas puntuales, dibujadas como discos</translation>
    </message>
    <message>
        <source>Id</source>
        <extracomment>schema: particles.id</extracomment>
        <translation>Id</translation>
    </message>
    <message>
        <source>Velocity</source>
        <extracomment>schema: particles.velocity</extracomment>
        <translation>Velocidad</translation>
    </message>
    <message>
        <source>Pinned</source>
        <extracomment>schema: particles.pinned</extracomment>
        <translation>Fija</translation>
    </message>
    <message>
        <source>Restitution</source>
        <extracomment>schema: particles.restitution</extracomment>
        <translation>Restitución</translation>
    </message>
    <message>
        <source>Friction</source>
        <extracomment>schema: particles.friction</extracomment>
        <translation>Rozamiento</translation>
    </message>
    <message>
        <source>Charge</source>
        <extracomment>schema: particles.charge</extracomment>
        <translation>Carga</translation>
    </message>
    <message>
        <source>rigid rectangles</source>
        <extracomment>schema: boxes</extracomment>
        <translation>rectángulos rígidos</translation>
    </message>
    <message>
        <source>Size</source>
        <extracomment>schema: boxes.size</extracomment>
        <translation>Tamaño</translation>
    </message>
    <message>
        <source>Angle</source>
        <extracomment>schema: boxes.angle</extracomment>
        <translation>Ángulo</translation>
    </message>
    <message>
        <source>Angular velocity ω</source>
        <extracomment>schema: boxes.angular_velocity</extracomment>
        <translation>Velocidad angular ω</translation>
    </message>
    <message>
        <source>Density</source>
        <extracomment>schema: boxes.density</extracomment>
        <translation>Densidad</translation>
    </message>
    <message>
        <source>Static</source>
        <extracomment>schema: boxes.static</extracomment>
        <translation>Estático</translation>
    </message>
    <message>
        <source>rigid disks: they turn, so they roll</source>
        <extracomment>schema: disks</extracomment>
        <translation>discos rígidos: giran, así que ruedan</translation>
    </message>
    <message>
        <source>rigid convex polygons</source>
        <extracomment>schema: polygons</extracomment>
        <translation>polígonos convexos rígidos</translation>
    </message>
    <message>
        <source>Vertices</source>
        <extracomment>schema: polygons.vertices</extracomment>
        <translation>Vértices</translation>
    </message>
    <message>
        <source>static half-planes, solid opposite the normal</source>
        <extracomment>schema: planes</extracomment>
        <translation>semiplanos estáticos, sólidos en el lado opuesto a la normal</translation>
    </message>
    <message>
        <source>Point</source>
        <extracomment>schema: planes.point</extracomment>
        <translation>Punto</translation>
    </message>
    <message>
        <source>Normal</source>
        <extracomment>schema: planes.normal</extracomment>
        <translation>Normal</translation>
    </message>
    <message>
        <source>damped springs between two objects or an anchor</source>
        <extracomment>schema: springs</extracomment>
        <translation>muelles amortiguados entre dos objetos o un anclaje</translation>
    </message>
    <message>
        <source>End a</source>
        <extracomment>schema: springs.a</extracomment>
        <translation>Extremo a</translation>
    </message>
    <message>
        <source>End b</source>
        <extracomment>schema: springs.b</extracomment>
        <translation>Extremo b</translation>
    </message>
    <message>
        <source>Anchor</source>
        <extracomment>schema: springs.anchor</extracomment>
        <translation>Anclaje</translation>
    </message>
    <message>
        <source>Point on a</source>
        <extracomment>schema: springs.a_point</extracomment>
        <translation>Punto en a</translation>
    </message>
    <message>
        <source>Point on b</source>
        <extracomment>schema: springs.b_point</extracomment>
        <translation>Punto en b</translation>
    </message>
    <message>
        <source>Stiffness k</source>
        <extracomment>schema: springs.stiffness</extracomment>
        <translation>Constante elástica k</translation>
    </message>
    <message>
        <source>Damping c</source>
        <extracomment>schema: springs.damping</extracomment>
        <translation>Amortiguamiento c</translation>
    </message>
    <message>
        <source>Rest length</source>
        <extracomment>schema: springs.rest_length</extracomment>
        <translation>Longitud natural</translation>
    </message>
    <message>
        <source>grids of particles joined by springs</source>
        <extracomment>schema: cloths</extracomment>
        <translation>rejillas de partículas unidas por muelles</translation>
    </message>
    <message>
        <source>Origin</source>
        <extracomment>schema: cloths.origin</extracomment>
        <translation>Origen</translation>
    </message>
    <message>
        <source>Resolution</source>
        <extracomment>schema: cloths.resolution</extracomment>
        <translation>Resolución</translation>
    </message>
    <message>
        <source>Mass (total)</source>
        <extracomment>schema: cloths.mass</extracomment>
        <translation>Masa (total)</translation>
    </message>
    <message>
        <source>Stiffness</source>
        <extracomment>schema: cloths.stiffness</extracomment>
        <translation>Rigidez</translation>
    </message>
    <message>
        <source>Damping</source>
        <extracomment>schema: cloths.damping</extracomment>
        <translation>Amortiguamiento</translation>
    </message>
    <message>
        <source>Node radius</source>
        <extracomment>schema: cloths.radius</extracomment>
        <translation>Radio de los nodos</translation>
    </message>
    <message>
        <source>joints holding bodies together: hinges, rods, ropes, welds, pulleys, tracks</source>
        <extracomment>schema: joints</extracomment>
        <translation>uniones que sujetan cuerpos: bisagras, varillas, cuerdas, soldaduras, poleas, guías</translation>
    </message>
    <message>
        <source>Type</source>
        <extracomment>schema: joints.type</extracomment>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>Body a</source>
        <extracomment>schema: joints.a</extracomment>
        <translation>Cuerpo a</translation>
    </message>
    <message>
        <source>Body b</source>
        <extracomment>schema: joints.b</extracomment>
        <translation>Cuerpo b</translation>
    </message>
    <message>
        <source>Length</source>
        <extracomment>schema: joints.length</extracomment>
        <translation>Longitud</translation>
    </message>
    <message>
        <source>Limits</source>
        <extracomment>schema: joints.limits</extracomment>
        <translation>Límites</translation>
    </message>
    <message>
        <source>Motor</source>
        <extracomment>schema: joints.motor</extracomment>
        <translation>Motor</translation>
    </message>
    <message>
        <source>Ground a</source>
        <extracomment>schema: joints.ground_a</extracomment>
        <translation>Punto fijo a</translation>
    </message>
    <message>
        <source>Ground b</source>
        <extracomment>schema: joints.ground_b</extracomment>
        <translation>Punto fijo b</translation>
    </message>
    <message>
        <source>Ratio</source>
        <extracomment>schema: joints.ratio</extracomment>
        <translation>Relación</translation>
    </message>
    <message>
        <source>Circle</source>
        <extracomment>schema: joints.circle</extracomment>
        <translation>Circunferencia</translation>
    </message>
    <message>
        <source>Line</source>
        <extracomment>schema: joints.line</extracomment>
        <translation>Recta</translation>
    </message>
    <message>
        <source>a cloth&apos;s spring stiffnesses</source>
        <extracomment>schema: stiffness</extracomment>
        <translation>las rigideces de los muelles de una tela</translation>
    </message>
    <message>
        <source>Structural stiffness</source>
        <extracomment>schema: stiffness.structural</extracomment>
        <translation>Rigidez estructural</translation>
    </message>
    <message>
        <source>Shear stiffness</source>
        <extracomment>schema: stiffness.shear</extracomment>
        <translation>Rigidez de cizalla</translation>
    </message>
    <message>
        <source>Bend stiffness</source>
        <extracomment>schema: stiffness.bend</extracomment>
        <translation>Rigidez de flexión</translation>
    </message>
    <message>
        <source>a hinge&apos;s motor</source>
        <extracomment>schema: motor</extracomment>
        <translation>el motor de una bisagra</translation>
    </message>
    <message>
        <source>Speed</source>
        <extracomment>schema: motor.speed</extracomment>
        <translation>Velocidad</translation>
    </message>
    <message>
        <source>Maximum torque</source>
        <extracomment>schema: motor.max_torque</extracomment>
        <translation>Par máximo</translation>
    </message>
    <message>
        <source>the circle of a track</source>
        <extracomment>schema: circle</extracomment>
        <translation>la circunferencia de una guía</translation>
    </message>
    <message>
        <source>Centre</source>
        <extracomment>schema: circle.center</extracomment>
        <translation>Centro</translation>
    </message>
    <message>
        <source>the line of a track</source>
        <extracomment>schema: line</extracomment>
        <translation>la recta de una guía</translation>
    </message>
    <message>
        <source>Direction</source>
        <extracomment>schema: line.direction</extracomment>
        <translation>Dirección</translation>
    </message>
    <message>
        <source>Sleep</source>
        <extracomment>schema: simulation.sleep</extracomment>
        <translation>Reposo</translation>
    </message>
</context>
<context>
    <name>StabilityText</name>
    <message>
        <source>%1 (stable below %2 s)</source>
        <translation>%1 (estable por debajo de %2 s)</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3 (below the linear limit %4 but above %5, the margin for penalty contacts): a contact that begins within a step can gain energy at every touch. Use dt/substeps below %6 s (%7 sub-steps).</source>
        <translation>%1 con un subpaso de %2 s tiene ω·h = %3 (por debajo del límite lineal %4 pero por encima de %5, el margen para los contactos por penalización): un contacto que empieza dentro de un paso puede ganar energía en cada toque. Use dt/subpasos por debajo de %6 s (%7 subpasos).</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3 (below the linear limit %4 but above %5, the margin for penalty contacts): a contact that begins within a step can gain energy at every touch. Use dt/substeps below %6 s (%7 sub-steps), or a method stable at this step: %8.</source>
        <translation>%1 con un subpaso de %2 s tiene ω·h = %3 (por debajo del límite lineal %4 pero por encima de %5, el margen para los contactos por penalización): un contacto que empieza dentro de un paso puede ganar energía en cada toque. Use dt/subpasos por debajo de %6 s (%7 subpasos) o un método estable con este paso: %8.</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3 (stable below %4): it will blow up. Use dt/substeps below %5 s (%6 sub-steps, more for a margin).</source>
        <translation>%1 con un subpaso de %2 s tiene ω·h = %3 (estable por debajo de %4): la simulación explotará. Use dt/subpasos por debajo de %5 s (%6 subpasos, más para tener margen).</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3 (stable below %4): it will blow up. Use dt/substeps below %5 s (%6 sub-steps, more for a margin), or a method stable at this step: %7.</source>
        <translation>%1 con un subpaso de %2 s tiene ω·h = %3 (estable por debajo de %4): la simulación explotará. Use dt/subpasos por debajo de %5 s (%6 subpasos, más para tener margen) o un método estable con este paso: %7.</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3: it gains energy at every step (its stiffest mode by a factor of about %4 per sub-step).</source>
        <translation>%1 con un subpaso de %2 s tiene ω·h = %3: gana energía en cada paso (su modo más rígido, en un factor de aproximadamente %4 por subpaso).</translation>
    </message>
    <message>
        <source>%1 at a sub-step of %2 s has ω·h = %3: it gains energy at every step (its stiffest mode by a factor of about %4 per sub-step). Use a method stable at this step: %5.</source>
        <translation>%1 con un subpaso de %2 s tiene ω·h = %3: gana energía en cada paso (su modo más rígido, en un factor de aproximadamente %4 por subpaso). Use un método estable con este paso: %5.</translation>
    </message>
    <message>
        <source>nothing in the scene oscillates</source>
        <translation>nada en la escena oscila</translation>
    </message>
    <message>
        <source>%1 is stable at this step (ω·h = %2)</source>
        <translation>%1 es estable con este paso (ω·h = %2)</translation>
    </message>
    <message>
        <source>Kinematic contacts cannot hold a stack (&quot;%1&quot; rests on &quot;%2&quot;): they only stop bodies moving into each other and push them apart, so the stack sinks into the floor. Use impulse contacts for stacks.</source>
        <translation>Los contactos cinemáticos no pueden sostener una pila («%1» descansa sobre «%2»): solo impiden que los cuerpos se muevan uno dentro del otro y los separan, así que la pila se hunde en el suelo. Use contactos por impulsos para las pilas.</translation>
    </message>
</context>
<context>
    <name>phasebox</name>
    <message>
        <source>the clip</source>
        <translation>el clip</translation>
    </message>
</context>
<context>
    <name>phasebox::AccuracyDialog</name>
    <message>
        <source>Accuracy Lab — what accuracy costs in time</source>
        <translation>Laboratorio de precisión: lo que cuesta la precisión en tiempo</translation>
    </message>
    <message>
        <source>Integrators to study</source>
        <translation>Integradores que estudiar</translation>
    </message>
    <message>
        <source>Step sizes, separated by commas; fractions such as 1/120 are fine. The adaptive methods sweep tolerances at the first dt instead.</source>
        <translation>Pasos separados por comas; se admiten fracciones como 1/120. Los métodos adaptativos recorren tolerancias en el primer dt.</translation>
    </message>
    <message>
        <source>Simulated seconds each run lasts; errors are measured at the end.</source>
        <translation>Segundos simulados que dura cada ejecución; los errores se miden al final.</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Ejecutar</translation>
    </message>
    <message>
        <source>&amp;Cancel</source>
        <translation>&amp;Cancelar</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>E&amp;xportar</translation>
    </message>
    <message>
        <source>&amp;dt list:</source>
        <translation>Lista de &amp;dt:</translation>
    </message>
    <message>
        <source>D&amp;uration [s]:</source>
        <translation>D&amp;uración [s]:</translation>
    </message>
    <message>
        <source>&amp;Integrators:</source>
        <translation>&amp;Integradores:</translation>
    </message>
    <message>
        <source>The largest position error you accept at the end time, in metres</source>
        <translation>El mayor error de posición que acepta en el instante final, en metros</translation>
    </message>
    <message>
        <source>&amp;Apply to the scene</source>
        <translation>&amp;Aplicar a la escena</translation>
    </message>
    <message>
        <source>Cheapest settings for an error of</source>
        <translation>Ajustes más baratos para un error de</translation>
    </message>
    <message>
        <source>m:</source>
        <translation>m:</translation>
    </message>
    <message>
        <source>Work-precision diagram</source>
        <translation>Diagrama trabajo-precisión</translation>
    </message>
    <message>
        <source>Each point is one run, labelled with its step dt. &lt;b&gt;Lower is better&lt;/b&gt; (a smaller error) and &lt;b&gt;left is faster&lt;/b&gt; (less CPU time): the best methods sit at the lower left. A steeper line is a higher order: halving dt divides the error by 2&lt;sup&gt;p&lt;/sup&gt;.</source>
        <translation>Cada punto es una ejecución, etiquetada con su paso dt. &lt;b&gt;Más abajo es mejor&lt;/b&gt; (un error menor) y &lt;b&gt;más a la izquierda es más rápido&lt;/b&gt; (menos tiempo de CPU): los mejores métodos quedan abajo a la izquierda. Una línea más inclinada es un orden mayor: reducir dt a la mitad divide el error entre 2&lt;sup&gt;p&lt;/sup&gt;.</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>integrador</translation>
    </message>
    <message>
        <source>dt</source>
        <translation>dt</translation>
    </message>
    <message>
        <source>tolerance</source>
        <translation>tolerancia</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>pasos</translation>
    </message>
    <message>
        <source>force evals</source>
        <translation>evaluaciones de fuerza</translation>
    </message>
    <message>
        <source>CPU [s]</source>
        <translation>CPU [s]</translation>
    </message>
    <message>
        <source>position error [m]</source>
        <translation>error de posición [m]</translation>
    </message>
    <message>
        <source>energy drift [J]</source>
        <translation>deriva de energía [J]</translation>
    </message>
    <message>
        <source>order</source>
        <translation>orden</translation>
    </message>
    <message>
        <source>measured order</source>
        <translation>orden medido</translation>
    </message>
    <message>
        <source>theory</source>
        <translation>teoría</translation>
    </message>
    <message>
        <source>what it means</source>
        <translation>qué significa</translation>
    </message>
    <message>
        <source>Rest the mouse on a row for the whole explanation</source>
        <translation>Deje el ratón sobre una fila para ver la explicación completa</translation>
    </message>
    <message>
        <source>&amp;Orders</source>
        <translation>Ó&amp;rdenes</translation>
    </message>
    <message>
        <source>A&amp;ll runs</source>
        <translation>&amp;Todas las ejecuciones</translation>
    </message>
    <message>
        <source>Scene: %1. Press Run: every checked method runs the scene at every dt on a copy; the open scene is not touched.</source>
        <translation>Escena: %1. Pulse Ejecutar: cada método marcado calcula la escena con cada dt sobre una copia; la escena abierta no se toca.</translation>
    </message>
    <message>
        <source>Check at least one integrator.</source>
        <translation>Marque al menos un integrador.</translation>
    </message>
    <message>
        <source>dt list: &quot;%1&quot; is not a step in (0, 1] s.</source>
        <translation>Lista de dt: «%1» no es un paso en (0, 1] s.</translation>
    </message>
    <message>
        <source>Duration: a number of seconds &gt; 0, please.</source>
        <translation>Duración: un número de segundos &gt; 0, por favor.</translation>
    </message>
    <message>
        <source>Running…</source>
        <translation>Ejecutando…</translation>
    </message>
    <message>
        <source>The study could not run: %1</source>
        <translation>El estudio no pudo ejecutarse: %1</translation>
    </message>
    <message>
        <source>%1: error at t = %2 s against CPU time</source>
        <translation>%1: error en t = %2 s frente al tiempo de CPU</translation>
    </message>
    <message>
        <source>Reference: %1. %2 runs%3.</source>
        <translation>Referencia: %1. %2 ejecuciones%3.</translation>
    </message>
    <message>
        <source> (cancelled)</source>
        <translation> (cancelado)</translation>
    </message>
    <message>
        <source>This scene has contacts: </source>
        <translation>Esta escena tiene contactos: </translation>
    </message>
    <message>
        <source>The end time was moved to %1 s, where the motion is fastest: at a turning point every method looks better than it is.</source>
        <translation>El instante final se movió a %1 s, donde el movimiento es más rápido: en un punto de retorno cualquier método parece mejor de lo que es.</translation>
    </message>
    <message>
        <source>diverged: unstable at this dt</source>
        <translation>divergió: inestable con este dt</translation>
    </message>
    <message>
        <source>unstable at this dt</source>
        <translation>inestable con este dt</translation>
    </message>
    <message>
        <source>The error does not shrink as the step is halved here: the method is unstable at this step, so this number is not its order.</source>
        <translation>Aquí el error no disminuye al reducir el paso a la mitad: el método es inestable con este paso, así que este número no es su orden.</translation>
    </message>
    <message>
        <source>round-off floor reached</source>
        <translation>límite de redondeo alcanzado</translation>
    </message>
    <message>
        <source>reference&apos;s accuracy reached</source>
        <translation>precisión de la referencia alcanzada</translation>
    </message>
    <message>
        <source>The error is already as small as rounding (or the reference) allows: smaller steps no longer improve it, so this number is not the method&apos;s order.</source>
        <translation>El error ya es tan pequeño como permite el redondeo (o la referencia): pasos menores ya no lo mejoran, así que este número no es el orden del método.</translation>
    </message>
    <message>
        <source>type an error such as 1e-4</source>
        <translation>escriba un error como 1e-4</translation>
    </message>
    <message>
        <source>run the study first</source>
        <translation>ejecute antes el estudio</translation>
    </message>
    <message>
        <source>no run reached it: try smaller steps or a higher-order method</source>
        <translation>ninguna ejecución lo alcanzó: pruebe pasos menores o un método de orden mayor</translation>
    </message>
    <message>
        <source>the scene has changed since this study: run it again to apply</source>
        <translation>la escena ha cambiado desde este estudio: vuelva a ejecutarlo para aplicarlo</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; at dt %2%3: error %4 m in %5 s of CPU</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; con dt %2%3: error %4 m en %5 s de CPU</translation>
    </message>
    <message>
        <source>, tolerance %1</source>
        <translation>, tolerancia %1</translation>
    </message>
    <message>
        <source>the CSV file</source>
        <translation>el archivo CSV</translation>
    </message>
    <message>
        <source>%1: error against CPU time</source>
        <translation>%1: error frente al tiempo de CPU</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportar</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Falló la exportación</translation>
    </message>
    <message>
        <source>Step sizes, separated by semicolons; fractions such as 1/120 are fine. The adaptive methods sweep tolerances at the first dt instead.</source>
        <translation>Pasos separados por punto y coma; se admiten fracciones como 1/120. Los métodos adaptativos recorren tolerancias en el primer dt.</translation>
    </message>
</context>
<context>
    <name>phasebox::AnimationExport</name>
    <message>
        <source>%1: unknown clip format; known: %2</source>
        <translation>%1: formato de clip desconocido; conocidos: %2</translation>
    </message>
    <message>
        <source>Exporting %1…</source>
        <translation>Exportando %1…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Wrote %1 (%2 frames)</source>
        <translation>%1 escrito (%2 fotogramas)</translation>
    </message>
    <message>
        <source>Wrote %1; the run diverged: %2</source>
        <translation>%1 escrito; la simulación divergió: %2</translation>
    </message>
    <message>
        <source>Export cancelled; nothing was written</source>
        <translation>Exportación cancelada; no se escribió nada</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>La exportación falló</translation>
    </message>
</context>
<context>
    <name>phasebox::AnimationExportDialog</name>
    <message>
        <source>Export Animation</source>
        <translation>Exportar animación</translation>
    </message>
    <message>
        <source>Clip file</source>
        <translation>Archivo del clip</translation>
    </message>
    <message>
        <source>A .mp4 file (H.264 video) or a .gif file (animated GIF)</source>
        <translation>Un archivo .mp4 (vídeo H.264) o .gif (GIF animado)</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>&amp;Examinar…</translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation>&amp;Archivo:</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Start time</source>
        <translation>Instante inicial</translation>
    </message>
    <message>
        <source>Simulated time of the first frame</source>
        <translation>Tiempo simulado del primer fotograma</translation>
    </message>
    <message>
        <source>Fro&amp;m:</source>
        <translation>&amp;Desde:</translation>
    </message>
    <message>
        <source>Duration</source>
        <translation>Duración</translation>
    </message>
    <message>
        <source>Simulated seconds the clip shows</source>
        <translation>Segundos simulados que muestra el clip</translation>
    </message>
    <message>
        <source>&amp;Duration:</source>
        <translation>D&amp;uración:</translation>
    </message>
    <message>
        <source>Frames per second</source>
        <translation>Fotogramas por segundo</translation>
    </message>
    <message>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <source>Frame &amp;rate:</source>
        <translation>Frecuencia de &amp;fotogramas:</translation>
    </message>
    <message>
        <source>Width in pixels</source>
        <translation>Ancho en píxeles</translation>
    </message>
    <message>
        <source>Height in pixels</source>
        <translation>Alto en píxeles</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>&amp;Size:</source>
        <translation>&amp;Tamaño:</translation>
    </message>
    <message>
        <source>&amp;Plots beside the canvas (energy and phase space)</source>
        <translation>&amp;Gráficas junto al lienzo (energía y espacio de fases)</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportar</translation>
    </message>
    <message>
        <source>MP4 video (*.mp4);;Animated GIF (*.gif)</source>
        <translation>Vídeo MP4 (*.mp4);;GIF animado (*.gif)</translation>
    </message>
</context>
<context>
    <name>phasebox::AppearancePresenter</name>
    <message>
        <source>High &amp;Contrast</source>
        <translation>Alto &amp;contraste</translation>
    </message>
    <message>
        <source>White on black, with a yellow selection and focus: for a projector or for low vision</source>
        <translation>Blanco sobre negro, con selección y foco amarillos: para un proyector o para baja visión</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Line &amp;Width</source>
        <translation>&amp;Grosor de línea</translation>
    </message>
    <message>
        <source>Te&amp;xt Size</source>
        <translation>&amp;Tamaño del texto</translation>
    </message>
</context>
<context>
    <name>phasebox::CanvasPresenter</name>
    <message>
        <source> sides</source>
        <translation> lados</translation>
    </message>
    <message>
        <source>Sides of the regular polygon the Add polygon tool draws</source>
        <translation>Lados del polígono regular que dibuja la herramienta Añadir polígono</translation>
    </message>
    <message>
        <source>The kind of joint the Add joint tool makes</source>
        <translation>El tipo de unión que crea la herramienta Añadir unión</translation>
    </message>
    <message>
        <source>&amp;Fit Scene</source>
        <translation>&amp;Encuadrar la escena</translation>
    </message>
    <message>
        <source>F&amp;ollow</source>
        <translation>&amp;Seguir</translation>
    </message>
    <message>
        <source>Keep the selection, or every moving object, in view while it runs</source>
        <translation>Mantener a la vista la selección, o cada objeto en movimiento, mientras corre</translation>
    </message>
    <message>
        <source>Export &amp;Canvas as PNG…</source>
        <translation>Exportar el &amp;lienzo como PNG…</translation>
    </message>
    <message>
        <source>&amp;Trails</source>
        <translation>&amp;Trayectorias</translation>
    </message>
    <message>
        <source>&amp;Velocity Arrows</source>
        <translation>Flechas de &amp;velocidad</translation>
    </message>
    <message>
        <source>&amp;Force Arrows (springs, joints)</source>
        <translation>Flechas de &amp;fuerza (muelles, uniones)</translation>
    </message>
    <message>
        <source>Object &amp;Labels</source>
        <translation>&amp;Etiquetas de objetos</translation>
    </message>
    <message>
        <source>Metre &amp;Grid</source>
        <translation>&amp;Cuadrícula métrica</translation>
    </message>
    <message>
        <source>%1: cannot draw the picture</source>
        <translation>%1: no se puede dibujar la imagen</translation>
    </message>
    <message>
        <source>the picture</source>
        <translation>la imagen</translation>
    </message>
    <message>
        <source>Export Canvas</source>
        <translation>Exportar el lienzo</translation>
    </message>
    <message>
        <source>PNG (*.png)</source>
        <translation>PNG (*.png)</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Falló la exportación</translation>
    </message>
    <message>
        <source>Nothing selected. Tab walks the objects; with a drawing tool, the arrow keys move the cursor and Enter places the object there.</source>
        <translation>Nada seleccionado. Tab recorre los objetos; con una herramienta de dibujo, las flechas mueven el cursor e Intro coloca allí el objeto.</translation>
    </message>
    <message>
        <source>Selected: %1 %2.</source>
        <translation>Seleccionado: %1 %2.</translation>
    </message>
    <message>
        <source>Position %1, %2 m; velocity %3, %4 m/s.</source>
        <translation>Posición %1; %2 m; velocidad %3; %4 m/s.</translation>
    </message>
    <message>
        <source>Arrows move it (Shift: finely), Enter opens its properties.</source>
        <translation>Las flechas lo mueven (Mayús: con precisión), Intro abre sus propiedades.</translation>
    </message>
    <message>
        <source>hinge</source>
        <translation>bisagra</translation>
    </message>
    <message>
        <source>rod</source>
        <translation>varilla</translation>
    </message>
    <message>
        <source>rope</source>
        <translation>cuerda</translation>
    </message>
    <message>
        <source>weld</source>
        <translation>soldadura</translation>
    </message>
    <message>
        <source>pulley</source>
        <translation>polea</translation>
    </message>
    <message>
        <source>track</source>
        <translation>guía</translation>
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
        <translation>Esa esquina haría el polígono no convexo; los polígonos deben ser convexos (construya una forma cóncava con piezas convexas).</translation>
    </message>
    <message>
        <source>That corner is in a line with two others: move it off the line.</source>
        <translation>Esa esquina está en línea con otras dos: sáquela de la línea.</translation>
    </message>
    <message>
        <source>That corner is on top of another one.</source>
        <translation>Esa esquina está encima de otra.</translation>
    </message>
    <message>
        <source>That corner is refused: %1</source>
        <translation>Esa esquina se rechaza: %1</translation>
    </message>
    <message>
        <source>Select / move</source>
        <translation>Seleccionar / mover</translation>
    </message>
    <message>
        <source>Add particle</source>
        <translation>Añadir partícula</translation>
    </message>
    <message>
        <source>Add spring</source>
        <translation>Añadir muelle</translation>
    </message>
    <message>
        <source>Add cloth</source>
        <translation>Añadir tela</translation>
    </message>
    <message>
        <source>Add box</source>
        <translation>Añadir caja</translation>
    </message>
    <message>
        <source>Add disk</source>
        <translation>Añadir disco</translation>
    </message>
    <message>
        <source>Add polygon</source>
        <translation>Añadir polígono</translation>
    </message>
    <message>
        <source>Add plane</source>
        <translation>Añadir plano</translation>
    </message>
    <message>
        <source>Pin / unpin</source>
        <translation>Fijar / soltar</translation>
    </message>
    <message>
        <source>Add joint</source>
        <translation>Añadir unión</translation>
    </message>
    <message>
        <source>Ruler</source>
        <translation>Regla</translation>
    </message>
    <message>
        <source>Protractor</source>
        <translation>Transportador</translation>
    </message>
    <message>
        <source>Click to select (Shift adds), drag to move; while running, drag an object to pull it with a mouse spring.</source>
        <translation>Haga clic para seleccionar (Mayús añade), arrastre para mover; durante la ejecución, arrastre un objeto para tirar de él con un muelle del ratón.</translation>
    </message>
    <message>
        <source>Click to drop a particle; drag to give it a velocity.</source>
        <translation>Haga clic para soltar una partícula; arrastre para darle una velocidad.</translation>
    </message>
    <message>
        <source>Drag from an object to another, or to empty space for a fixed anchor.</source>
        <translation>Arrastre de un objeto a otro, o al vacío para un anclaje fijo.</translation>
    </message>
    <message>
        <source>Drag a rectangle: a cloth hung from its top corners.</source>
        <translation>Arrastre un rectángulo: una tela colgada de sus esquinas superiores.</translation>
    </message>
    <message>
        <source>Drag a rectangle: a box of that size.</source>
        <translation>Arrastre un rectángulo: una caja de ese tamaño.</translation>
    </message>
    <message>
        <source>Drag from the centre to the rim: a disk that rolls; click for one of 0.5 m.</source>
        <translation>Arrastre del centro al borde: un disco que rueda; haga clic para uno de 0,5 m.</translation>
    </message>
    <message>
        <source>Drag from the centre to a corner: a regular polygon, flat side down; or click the corners and close on the first (double click or Enter closes, Backspace undoes a corner, Esc drops the outline).</source>
        <translation>Arrastre del centro a una esquina: un polígono regular, con un lado plano abajo; o haga clic en las esquinas y cierre en la primera (doble clic o Intro cierra, Retroceso deshace una esquina, Esc descarta el contorno).</translation>
    </message>
    <message>
        <source>Drag a line along the surface; the solid side is to the right of the drag.</source>
        <translation>Arrastre una línea a lo largo de la superficie; el lado sólido queda a la derecha del arrastre.</translation>
    </message>
    <message>
        <source>Click a particle to pin or unpin it, a box or disk to make it static.</source>
        <translation>Haga clic en una partícula para fijarla o soltarla, en una caja o un disco para hacerlos estáticos.</translation>
    </message>
    <message>
        <source>Drag from a body to another, or to empty space for the fixed world: a hinge pivots where the drag starts; a rod or rope joins the two points; a weld holds two bodies together; a pulley hangs two bodies over two wheels a metre above; a track puts a particle on a hoop centred where the drag ends.</source>
        <translation>Arrastre de un cuerpo a otro, o al vacío para el mundo fijo: una bisagra gira donde empieza el arrastre; una varilla o una cuerda une los dos puntos; una soldadura mantiene dos cuerpos juntos; una polea cuelga dos cuerpos sobre dos ruedas un metro por encima; una guía pone una partícula en un aro centrado donde termina el arrastre.</translation>
    </message>
    <message>
        <source>Drag from one point to another to measure the distance; an end dropped on an object follows it. Click a ruler to select it, Esc or Delete removes it.</source>
        <translation>Arrastre de un punto a otro para medir la distancia; un extremo soltado sobre un objeto lo sigue. Haga clic en una regla para seleccionarla; Esc o Supr la quita.</translation>
    </message>
    <message>
        <source>Drag from the vertex along the first arm, then click the second arm: the angle between them. Ends dropped on objects follow them; Esc or Delete removes the selected one.</source>
        <translation>Arrastre desde el vértice a lo largo del primer brazo y luego haga clic en el segundo brazo: el ángulo entre ellos. Los extremos soltados sobre objetos los siguen; Esc o Supr quita el seleccionado.</translation>
    </message>
    <message>
        <source>Pulling %1 with a mouse spring</source>
        <translation>Tirando de %1 con un muelle del ratón</translation>
    </message>
    <message>
        <source>pulling %1</source>
        <translation>tirando de %1</translation>
    </message>
    <message>
        <source>v = %1 m/s</source>
        <translation>v = %1 m/s</translation>
    </message>
    <message>
        <source>anchor, %1</source>
        <translation>anclaje, %1</translation>
    </message>
    <message>
        <source>r = %1</source>
        <translation>r = %1</translation>
    </message>
    <message>
        <source>A spring starts on an object: drag from a particle or box.</source>
        <translation>Un muelle empieza en un objeto: arrastre desde una partícula o una caja.</translation>
    </message>
    <message>
        <source>A joint starts on a body: drag from a particle, box, disk or polygon.</source>
        <translation>Una unión empieza en un cuerpo: arrastre desde una partícula, caja, disco o polígono.</translation>
    </message>
    <message>
        <source>Only particles can be pinned and boxes and disks made static.</source>
        <translation>Solo se pueden fijar partículas y hacer estáticos cajas y discos.</translation>
    </message>
    <message>
        <source>A polygon needs at least three corners.</source>
        <translation>Un polígono necesita al menos tres esquinas.</translation>
    </message>
    <message>
        <source>Corner %1: click the next corner.</source>
        <translation>Esquina %1: haga clic en la siguiente esquina.</translation>
    </message>
    <message>
        <source>Corner %1: click the next, or the first corner (or Enter) to close.</source>
        <translation>Esquina %1: haga clic en la siguiente, o en la primera (o Intro) para cerrar.</translation>
    </message>
    <message numerus="yes">
        <source>%n corner(s)</source>
        <translation>
            <numerusform>%n esquina</numerusform>
            <numerusform>%n esquinas</numerusform>
        </translation>
    </message>
    <message>
        <source>Outline dropped.</source>
        <translation>Contorno descartado.</translation>
    </message>
    <message>
        <source>Drag to where the %1 ends: another body or a fixed point.</source>
        <translation>Arrastre hasta donde termina la %1: otro cuerpo o un punto fijo.</translation>
    </message>
    <message>
        <source>rod</source>
        <translation>varilla</translation>
    </message>
    <message>
        <source>rope</source>
        <translation>cuerda</translation>
    </message>
    <message>
        <source>A weld holds two bodies: drag from one onto the other.</source>
        <translation>Una soldadura une dos cuerpos: arrastre de uno al otro.</translation>
    </message>
    <message>
        <source>A pulley hangs two bodies: drag from one to the other.</source>
        <translation>Una polea cuelga dos cuerpos: arrastre de uno al otro.</translation>
    </message>
    <message>
        <source>Drag from a particle to the centre of its hoop.</source>
        <translation>Arrastre desde una partícula hasta el centro de su aro.</translation>
    </message>
</context>
<context>
    <name>phasebox::CompareDialog</name>
    <message>
        <source>Compare from Here</source>
        <translation>Comparar desde aquí</translation>
    </message>
    <message>
        <source>From t = %L1 s the run goes on with the settings below, while the recorded run (%2, dt %L3 s) is drawn beside it as a ghost.</source>
        <translation>Desde t = %L1 s la ejecución continúa con los ajustes de abajo, mientras la ejecución grabada (%2, dt %L3 s) se dibuja a su lado como un fantasma.</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>&amp;Integrator:</source>
        <translation>&amp;Integrador:</translation>
    </message>
    <message>
        <source>&amp;dt:</source>
        <translation>&amp;dt:</translation>
    </message>
    <message>
        <source>&amp;Contacts:</source>
        <translation>&amp;Contactos:</translation>
    </message>
    <message>
        <source>Co&amp;mpare</source>
        <translation>Co&amp;mparar</translation>
    </message>
</context>
<context>
    <name>phasebox::ComparePresenter</name>
    <message>
        <source>&amp;Compare from Here…</source>
        <translation>&amp;Comparar desde aquí…</translation>
    </message>
    <message>
        <source>Run on from the timeline&apos;s moment with another integrator, dt or contact model, with the recorded run beside it as a ghost</source>
        <translation>Continuar desde el momento de la línea de tiempo con otro integrador, dt o modelo de contacto, con la ejecución grabada al lado como fantasma</translation>
    </message>
    <message>
        <source>Compare…</source>
        <translation>Comparar…</translation>
    </message>
    <message>
        <source>&amp;Leave Compare</source>
        <translation>&amp;Salir de la comparación</translation>
    </message>
    <message>
        <source>Remove the recorded run&apos;s ghost from the canvas and the plots</source>
        <translation>Quitar el fantasma de la ejecución grabada del lienzo y de las gráficas</translation>
    </message>
    <message>
        <source>Leave compare</source>
        <translation>Fin comparación</translation>
    </message>
    <message>
        <source>Comparing from t = %L1 s: %2 against the recorded run (dashed).</source>
        <translation>Comparando desde t = %L1 s: %2 frente a la ejecución grabada (discontinua).</translation>
    </message>
    <message>
        <source>Drag the timeline to an earlier moment first: the run is compared from there.</source>
        <translation>Arrastre primero la línea de tiempo a un momento anterior: la ejecución se compara desde allí.</translation>
    </message>
    <message>
        <source>Left Compare: the recorded run&apos;s ghost is gone.</source>
        <translation>Comparación terminada: el fantasma de la ejecución grabada se ha quitado.</translation>
    </message>
    <message>
        <source>recorded: %1</source>
        <translation>grabado: %1</translation>
    </message>
    <message>
        <source>, dt %L1 s</source>
        <translation>, dt %L1 s</translation>
    </message>
    <message>
        <source>Ghost: the recorded run ended at t = %L1 s</source>
        <translation>Fantasma: la ejecución grabada terminó en t = %L1 s</translation>
    </message>
    <message>
        <source>Ghost: the recorded run, %1</source>
        <translation>Fantasma: la ejecución grabada, %1</translation>
    </message>
</context>
<context>
    <name>phasebox::DivergenceNotice</name>
    <message>
        <source>The simulation became unstable</source>
        <translation>La simulación se volvió inestable</translation>
    </message>
</context>
<context>
    <name>phasebox::Document</name>
    <message>
        <source>Switched to %1 so the %2 stays stable; Undo to go back to %3</source>
        <translation>Se cambió a %1 para que %2 siga estable; Deshacer vuelve a %3</translation>
    </message>
    <message>
        <source>unknown effect &quot;%1&quot;; known: %2</source>
        <translation>efecto desconocido «%1»; conocidos: %2</translation>
    </message>
    <message>
        <source>Switch on %1</source>
        <translation>Activar %1</translation>
    </message>
    <message>
        <source>Switch off %1</source>
        <translation>Desactivar %1</translation>
    </message>
    <message>
        <source>Change effects</source>
        <translation>Cambiar los efectos</translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation>Cambiar %1</translation>
    </message>
</context>
<context>
    <name>phasebox::EffectsPresenter</name>
    <message>
        <source>Runs because the scene has springs</source>
        <translation>Se ejecuta porque la escena tiene muelles</translation>
    </message>
    <message>
        <source>Runs because the scene holds things that can touch</source>
        <translation>Se ejecuta porque la escena contiene cosas que pueden tocarse</translation>
    </message>
    <message>
        <source>The integrator&apos;s own arithmetic</source>
        <translation>La aritmética propia del integrador</translation>
    </message>
    <message>
        <source>Costs per step of the whole run: a recorded frame keeps no timing of its own.</source>
        <translation>Coste por paso de toda la ejecución: un fotograma grabado no guarda tiempos propios.</translation>
    </message>
</context>
<context>
    <name>phasebox::ExactPresenter</name>
    <message>
        <source>E&amp;xact Solution</source>
        <translation>Solución e&amp;xacta</translation>
    </message>
    <message>
        <source>Draw the exact (closed-form) motion beside the simulation, dashed, when the scene has one: oscillators, free fall, orbits, pendulums, Atwood machines, rolling and sliding on ramps (until a contact begins or ends)</source>
        <translation>Dibujar el movimiento exacto (en forma cerrada) junto a la simulación, a trazos, cuando la escena lo tiene: osciladores, caída libre, órbitas, péndulos, máquinas de Atwood, rodar y deslizar por rampas (hasta que empieza o termina un contacto)</translation>
    </message>
    <message>
        <source>exact</source>
        <translation>exacta</translation>
    </message>
    <message>
        <source>dashed: exact solution (%1)</source>
        <translation>a trazos: solución exacta (%1)</translation>
    </message>
    <message>
        <source>dashed: exact solution (%1) until t = %2 s, where a contact begins or ends</source>
        <translation>a trazos: solución exacta (%1) hasta t = %2 s, donde empieza o termina un contacto</translation>
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
        <translation>Energía (%1)</translation>
    </message>
    <message>
        <source>Phase space</source>
        <translation>Espacio de fases</translation>
    </message>
    <message>
        <source>Phase space of %1</source>
        <translation>Espacio de fases de %1</translation>
    </message>
</context>
<context>
    <name>phasebox::HelpWindows</name>
    <message>
        <source>About Phasebox</source>
        <translation>Acerca de Phasebox</translation>
    </message>
    <message>
        <source>&lt;b&gt;Phasebox %1&lt;/b&gt;&lt;p&gt;A 2D physics sandbox for the classroom: drop particles, springs, cloth and boxes into a scene, switch the integrator while it runs, and watch what accuracy costs.&lt;/p&gt;</source>
        <translation>&lt;b&gt;Phasebox %1&lt;/b&gt;&lt;p&gt;Un arenero de física 2D para el aula: ponga partículas, muelles, telas y cajas en una escena, cambie el integrador mientras corre y vea lo que cuesta la precisión.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>phasebox::InstrumentsPresenter</name>
    <message>
        <source>&amp;Instruments</source>
        <translation>&amp;Instrumentos</translation>
    </message>
    <message>
        <source>Start/Stop S&amp;topwatch</source>
        <translation>Iniciar/parar el &amp;cronómetro</translation>
    </message>
    <message>
        <source>The stopwatch on simulated time (Instruments → Timer)</source>
        <translation>El cronómetro en tiempo simulado (Instrumentos → Temporizador)</translation>
    </message>
    <message>
        <source>Stopwatch &amp;Lap</source>
        <translation>&amp;Vuelta del cronómetro</translation>
    </message>
    <message>
        <source>Probe Table as CSV…</source>
        <translation>Tabla de sondas como CSV…</translation>
    </message>
</context>
<context>
    <name>phasebox::LanguageMenu</name>
    <message>
        <source>&amp;System Language</source>
        <translation>Idioma del &amp;sistema</translation>
    </message>
    <message>
        <source>Phasebox will speak %1 from its next start.</source>
        <translation>Phasebox hablará %1 desde su próximo inicio.</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Idioma</translation>
    </message>
</context>
<context>
    <name>phasebox::MainWindow</name>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Falló el guardado automático: %1</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Nuevo</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Abrir…</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Guardar</translation>
    </message>
    <message>
        <source>Re&amp;vert</source>
        <translation>&amp;Revertir</translation>
    </message>
    <message>
        <source>Reopen the scene&apos;s file as it was last saved, dropping the edits</source>
        <translation>Volver a abrir el archivo de la escena tal como se guardó por última vez, descartando los cambios</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Guardar &amp;como…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Deshacer</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Rehacer</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Borrar</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Copiar</translation>
    </message>
    <message>
        <source>Cu&amp;t</source>
        <translation>Cor&amp;tar</translation>
    </message>
    <message>
        <source>&amp;Paste</source>
        <translation>&amp;Pegar</translation>
    </message>
    <message>
        <source>&amp;Accuracy Lab…</source>
        <translation>Laboratorio de &amp;precisión…</translation>
    </message>
    <message>
        <source>Error against CPU time for every integrator, on this scene</source>
        <translation>Error frente a tiempo de CPU para cada integrador, en esta escena</translation>
    </message>
    <message>
        <source>&amp;Presentation Mode</source>
        <translation>Modo &amp;presentación</translation>
    </message>
    <message>
        <source>Live &amp;Error Estimate</source>
        <translation>&amp;Estimación del error en vivo</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Guía de usuario</translation>
    </message>
    <message>
        <source>How to use Phasebox: the window, building scenes, measuring, files</source>
        <translation>Cómo usar Phasebox: la ventana, construir escenas, medir, archivos</translation>
    </message>
    <message>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>Atajos de &amp;teclado</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Abrir &amp;reciente</translation>
    </message>
    <message>
        <source>&amp;Examples</source>
        <translation>&amp;Ejemplos</translation>
    </message>
    <message>
        <source>&amp;Lessons</source>
        <translation>&amp;Lecciones</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>E&amp;xportar</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Editar</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulación</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Herramientas</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ver</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>Ay&amp;uda</translation>
    </message>
    <message>
        <source>&amp;About Phasebox</source>
        <translation>&amp;Acerca de Phasebox</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Principal</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parámetros</translation>
    </message>
    <message>
        <source>Effects</source>
        <translation>Efectos</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Escena</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Propiedades</translation>
    </message>
    <message>
        <source>Plots</source>
        <translation>Gráficas</translation>
    </message>
    <message>
        <source>Instruments</source>
        <translation>Instrumentos</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Notas</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Sin título</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>Revertir</translation>
    </message>
    <message>
        <source>Drop your changes and reopen %1 as it was last saved?</source>
        <translation>¿Descartar los cambios y volver a abrir %1 tal como se guardó por última vez?</translation>
    </message>
    <message>
        <source>Phasebox</source>
        <translation>Phasebox</translation>
    </message>
    <message>
        <source>The scene has unsaved changes. Save them?</source>
        <translation>La escena tiene cambios sin guardar. ¿Guardarlos?</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Idioma</translation>
    </message>
    <message>
        <source>Scene canvas</source>
        <translation>Lienzo de la escena</translation>
    </message>
    <message>
        <source>Export &amp;Animation…</source>
        <translation>Exportar &amp;animación…</translation>
    </message>
    <message>
        <source>The run as an MP4 or animated GIF clip, optionally with the plots</source>
        <translation>La simulación como clip MP4 o GIF animado, con las gráficas si se desea</translation>
    </message>
    <message>
        <source>&amp;Worker Threads</source>
        <translation>&amp;Hilos de trabajo</translation>
    </message>
</context>
<context>
    <name>phasebox::MeasureTools</name>
    <message>
        <source>Free-&amp;Body View</source>
        <translation>Vista de &amp;cuerpo libre</translation>
    </message>
    <message>
        <source>Draw the forces on the selected body by source, its momentum and the system&apos;s centre of mass</source>
        <translation>Dibujar las fuerzas sobre el cuerpo seleccionado por origen, su cantidad de movimiento y el centro de masas del sistema</translation>
    </message>
    <message>
        <source>&amp;Clear Measurements</source>
        <translation>&amp;Borrar las mediciones</translation>
    </message>
    <message>
        <source>--ruler &quot;%1&quot;: expected A,B with each an object id or X:Y</source>
        <translation>--ruler &quot;%1&quot;: se esperaba A,B, cada uno un id de objeto o X:Y</translation>
    </message>
    <message>
        <source>--protractor &quot;%1&quot;: expected A,B,C (the vertex B in the middle, as in angle(A,B,C)) with each an object id or X:Y</source>
        <translation>--protractor &quot;%1&quot;: se esperaba A,B,C (el vértice B en medio, como en angle(A,B,C)), cada uno un id de objeto o X:Y</translation>
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
        <translation>Ángulo %1</translation>
    </message>
    <message>
        <source>Drag from one point to the other to measure.</source>
        <translation>Arrastre de un punto al otro para medir.</translation>
    </message>
    <message>
        <source>Drag from the vertex along the first arm.</source>
        <translation>Arrastre desde el vértice a lo largo del primer brazo.</translation>
    </message>
    <message>
        <source>Distance %1</source>
        <translation>Distancia %1</translation>
    </message>
    <message>
        <source>Now click the second arm (Esc cancels).</source>
        <translation>Ahora haga clic en el segundo brazo (Esc cancela).</translation>
    </message>
</context>
<context>
    <name>phasebox::ParametersPresenter</name>
    <message>
        <source>&amp;Play</source>
        <translation>&amp;Reproducir</translation>
    </message>
    <message>
        <source>Play or pause the simulation (Space)</source>
        <translation>Reproducir o pausar la simulación (Espacio)</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pausa</translation>
    </message>
    <message>
        <source>S&amp;tep</source>
        <translation>&amp;Paso</translation>
    </message>
    <message>
        <source>Advance one step (S)</source>
        <translation>Avanzar un paso (S)</translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation>&amp;Reiniciar</translation>
    </message>
    <message>
        <source>Back to the setup (Ctrl+R)</source>
        <translation>Volver a la configuración inicial (Ctrl+R)</translation>
    </message>
    <message>
        <source>Next Integrator</source>
        <translation>Integrador siguiente</translation>
    </message>
    <message>
        <source>Previous Integrator</source>
        <translation>Integrador anterior</translation>
    </message>
    <message>
        <source>Double dt</source>
        <translation>Doblar dt</translation>
    </message>
    <message>
        <source>Halve dt</source>
        <translation>Reducir dt a la mitad</translation>
    </message>
    <message>
        <source>More Sub-steps</source>
        <translation>Más subpasos</translation>
    </message>
    <message>
        <source>Fewer Sub-steps</source>
        <translation>Menos subpasos</translation>
    </message>
    <message>
        <source>Faster</source>
        <translation>Más rápido</translation>
    </message>
    <message>
        <source>Slower</source>
        <translation>Más lento</translation>
    </message>
    <message>
        <source>Largest stable sub-step (stiffest mode ω = %1 rad/s):</source>
        <translation>Mayor subpaso estable (modo más rígido ω = %1 rad/s):</translation>
    </message>
    <message>
        <source>any</source>
        <translation>cualquiera</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Integrator: %1</source>
        <translation>Integrador: %1</translation>
    </message>
    <message>
        <source>dt = %1 s</source>
        <translation>dt = %1 s</translation>
    </message>
    <message>
        <source>%1 sub-steps</source>
        <translation>%1 subpasos</translation>
    </message>
    <message>
        <source>Applied %1 at dt %2 s</source>
        <translation>Aplicado %1 con dt %2 s</translation>
    </message>
</context>
<context>
    <name>phasebox::PeriodTimerPresenter</name>
    <message>
        <source>Pick a probe (an object&apos;s x for a swing), then press Play: the period is the mean interval between its upward crossings of the middle of its range.</source>
        <translation>Elija una sonda (la x de un objeto para una oscilación) y pulse Reproducir: el periodo es el intervalo medio entre sus cruces ascendentes por el centro de su rango.</translation>
    </message>
    <message>
        <source>%1 cannot be read in this scene.</source>
        <translation>%1 no se puede leer en esta escena.</translation>
    </message>
    <message numerus="yes">
        <source>Waiting for two upward crossings of the middle of the range of %1 (%n so far).</source>
        <translation>
            <numerusform>Esperando dos cruces ascendentes por el centro del rango de %1 (%n hasta ahora).</numerusform>
            <numerusform>Esperando dos cruces ascendentes por el centro del rango de %1 (%n hasta ahora).</numerusform>
        </translation>
    </message>
    <message>
        <source>Mean interval between the upward crossings of %1 through %2 %3, the middle of its range [%4, %5] %3, each interpolated within its step.</source>
        <translation>Intervalo medio entre los cruces ascendentes de %1 por %2 %3, el centro de su rango [%4, %5] %3, cada uno interpolado dentro de su paso.</translation>
    </message>
</context>
<context>
    <name>phasebox::PlotsPresenter</name>
    <message>
        <source>The live error estimate is off (View menu).</source>
        <translation>La estimación del error en vivo está desactivada (menú Ver).</translation>
    </message>
    <message>
        <source>No live error estimate: a step takes %1 ms, and the estimate would cost three more.</source>
        <translation>Sin estimación del error en vivo: un paso tarda %1 ms y la estimación costaría tres más.</translation>
    </message>
    <message>
        <source>Press Play: the error one step makes is estimated as the simulation runs.</source>
        <translation>Pulse Reproducir: el error que comete un paso se estima mientras corre la simulación.</translation>
    </message>
    <message>
        <source>Phase space</source>
        <translation>Espacio de fases</translation>
    </message>
    <message>
        <source>Phase space of %1</source>
        <translation>Espacio de fases de %1</translation>
    </message>
    <message>
        <source>Click an object first.</source>
        <translation>Haga clic antes en un objeto.</translation>
    </message>
    <message>
        <source>Only rigid bodies have an angle.</source>
        <translation>Solo los sólidos rígidos tienen un ángulo.</translation>
    </message>
    <message>
        <source>no object chosen for the phase plot: click one on the canvas</source>
        <translation>ningún objeto elegido para el diagrama de fases: haga clic en uno en el lienzo</translation>
    </message>
    <message>
        <source>Phase space of %1 (%2)</source>
        <translation>Espacio de fases de %1 (%2)</translation>
    </message>
    <message>
        <source>Energy Plot</source>
        <translation>Gráfica de energía</translation>
    </message>
    <message>
        <source>Phase Plot</source>
        <translation>Diagrama de fases</translation>
    </message>
    <message>
        <source>Error Plot</source>
        <translation>Gráfica del error</translation>
    </message>
    <message>
        <source>%1 as %2…</source>
        <translation>%1 como %2…</translation>
    </message>
    <message>
        <source>Export Plot</source>
        <translation>Exportar la gráfica</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Falló la exportación</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>Escrito %1</translation>
    </message>
    <message>
        <source>Energy&lt;br&gt;%1, dt %L2 s</source>
        <translation>Energía&lt;br&gt;%1, dt %L2 s</translation>
    </message>
    <message>
        <source>Local error per step&lt;br&gt;%1, dt %L2 s</source>
        <translation>Error local por paso&lt;br&gt;%1, dt %L2 s</translation>
    </message>
</context>
<context>
    <name>phasebox::ProbeGraphsPresenter</name>
    <message>
        <source>no graph %1</source>
        <translation>no hay gráfica %1</translation>
    </message>
    <message>
        <source>All %1 graphs are in use: close one first.</source>
        <translation>Las %1 gráficas están en uso: cierre una antes.</translation>
    </message>
    <message>
        <source>time [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>Pick a probe to plot, or type one (p0.x, system.total, distance(A,B), …).</source>
        <translation>Elija una sonda para representar, o escriba una (p0.x, system.total, distance(A,B), …).</translation>
    </message>
    <message>
        <source>%1 cannot be read in this scene (was its object deleted or renamed?)</source>
        <translation>%1 no se puede leer en esta escena (¿se borró o se renombró su objeto?)</translation>
    </message>
    <message>
        <source>Press Play: %1 is recorded at every step.</source>
        <translation>Pulse Reproducir: %1 se registra en cada paso.</translation>
    </message>
    <message>
        <source>Recorded since t = %1 s, when it was chosen.</source>
        <translation>Registrado desde t = %1 s, cuando se eligió.</translation>
    </message>
    <message>
        <source>graph %1 plots nothing: pick a probe first</source>
        <translation>la gráfica %1 no representa nada: elija antes una sonda</translation>
    </message>
    <message>
        <source>%1 against %2 — %3 (%4, dt %5 s)</source>
        <translation>%1 frente a %2 — %3 (%4, dt %5 s)</translation>
    </message>
    <message>
        <source>time</source>
        <translation>tiempo</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Sin título</translation>
    </message>
    <message>
        <source>Export Graph</source>
        <translation>Exportar la gráfica</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Falló la exportación</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>Escrito %1</translation>
    </message>
</context>
<context>
    <name>phasebox::ProbeRecorder</name>
    <message>
        <source>the CSV file</source>
        <translation>el archivo CSV</translation>
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
        <translation>%1 (no válida)</translation>
    </message>
    <message>
        <source>Export Probe Table</source>
        <translation>Exportar la tabla de sondas</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Falló la exportación</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>Escrito %1</translation>
    </message>
</context>
<context>
    <name>phasebox::PropertiesPresenter</name>
    <message>
        <source>Live at t = %1 s; Reset shows the setup</source>
        <translation>En vivo en t = %1 s; Reiniciar muestra la configuración inicial</translation>
    </message>
    <message>
        <source>The setup&apos;s numbers (the run is at t = %1 s)</source>
        <translation>Los números de la configuración inicial (la ejecución está en t = %1 s)</translation>
    </message>
    <message>
        <source>Setup: the state at t = 0, what Reset returns to</source>
        <translation>Configuración inicial: el estado en t = 0, al que vuelve Reiniciar</translation>
    </message>
    <message>
        <source>Recorded at t = %1 s; Reset shows the setup</source>
        <translation>Grabado en t = %1 s; Reiniciar muestra la configuración inicial</translation>
    </message>
</context>
<context>
    <name>phasebox::ReadoutsPresenter</name>
    <message>
        <source>cloth node</source>
        <translation>nodo de tela</translation>
    </message>
    <message>
        <source>pinned particle</source>
        <translation>partícula fija</translation>
    </message>
    <message>
        <source>particle</source>
        <translation>partícula</translation>
    </message>
    <message>
        <source>disk</source>
        <translation>disco</translation>
    </message>
    <message>
        <source>polygon</source>
        <translation>polígono</translation>
    </message>
    <message>
        <source>box</source>
        <translation>caja</translation>
    </message>
    <message>
        <source>static %1</source>
        <translation>%1 (inmóvil)</translation>
    </message>
    <message>
        <source>Click an object on the canvas to read its position, velocity, energy and momentum; Shift-click a second and a third for the distance and the angle between them.</source>
        <translation>Haga clic en un objeto del lienzo para leer su posición, velocidad, energía y cantidad de movimiento; Mayús+clic en un segundo y un tercero para la distancia y el ángulo entre ellos.</translation>
    </message>
    <message>
        <source>position (x, y)</source>
        <translation>posición (x, y)</translation>
    </message>
    <message>
        <source>velocity (vx, vy)</source>
        <translation>velocidad (vx, vy)</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>rapidez</translation>
    </message>
    <message>
        <source>angle</source>
        <translation>ángulo</translation>
    </message>
    <message>
        <source>angular velocity ω</source>
        <translation>velocidad angular ω</translation>
    </message>
    <message>
        <source>kinetic energy</source>
        <translation>energía cinética</translation>
    </message>
    <message>
        <source>momentum (px, py)</source>
        <translation>cantidad de movimiento (px, py)</translation>
    </message>
    <message>
        <source>angular momentum L</source>
        <translation>momento angular L</translation>
    </message>
    <message>
        <source>contact force</source>
        <translation>fuerza de contacto</translation>
    </message>
    <message>
        <source>distance %1–%2</source>
        <translation>distancia %1–%2</translation>
    </message>
    <message>
        <source>angle %1–%2–%3</source>
        <translation>ángulo %1–%2–%3</translation>
    </message>
    <message>
        <source>%1 (joint)</source>
        <translation>%1 (unión)</translation>
    </message>
    <message>
        <source>constraint force of %1</source>
        <translation>fuerza de ligadura de %1</translation>
    </message>
    <message>
        <source>angle of %1</source>
        <translation>ángulo de %1</translation>
    </message>
    <message>
        <source>live, t = %1 s</source>
        <translation>en vivo, t = %1 s</translation>
    </message>
    <message>
        <source>setup</source>
        <translation>configuración inicial</translation>
    </message>
    <message>
        <source>recorded, t = %1 s</source>
        <translation>grabado, t = %1 s</translation>
    </message>
</context>
<context>
    <name>phasebox::SceneBrowserPresenter</name>
    <message>
        <source>Nothing to copy: select objects first (a spring goes along with the objects it joins).</source>
        <translation>Nada que copiar: seleccione antes objetos (un muelle va con los objetos que une).</translation>
    </message>
    <message numerus="yes">
        <source>Copied %n object(s)</source>
        <translation>
            <numerusform>%n objeto copiado</numerusform>
            <numerusform>%n objetos copiados</numerusform>
        </translation>
    </message>
    <message>
        <source>Nothing to paste: copy objects first.</source>
        <translation>Nada que pegar: copie antes objetos.</translation>
    </message>
    <message>
        <source>the clipboard</source>
        <translation>el portapapeles</translation>
    </message>
    <message>
        <source>The clipboard holds no Phasebox objects: %1</source>
        <translation>El portapapeles no contiene objetos de Phasebox: %1</translation>
    </message>
    <message>
        <source>Nothing to paste: the clipboard&apos;s scene is empty.</source>
        <translation>Nada que pegar: la escena del portapapeles está vacía.</translation>
    </message>
</context>
<context>
    <name>phasebox::SceneFiles</name>
    <message>
        <source>Could not open %1</source>
        <translation>No se pudo abrir %1</translation>
    </message>
    <message>
        <source>Could not open the scene</source>
        <translation>No se pudo abrir la escena</translation>
    </message>
    <message>
        <source>%1

The open scene is unchanged.</source>
        <translation>%1

La escena abierta no ha cambiado.</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>Abierto %1</translation>
    </message>
    <message>
        <source>Open Scene</source>
        <translation>Abrir escena</translation>
    </message>
    <message>
        <source>Save Scene As</source>
        <translation>Guardar escena como</translation>
    </message>
    <message>
        <source>Could not save</source>
        <translation>No se pudo guardar</translation>
    </message>
    <message>
        <source>%1

The file on disk (if any) is unchanged.</source>
        <translation>%1

El archivo en disco (si lo hay) no ha cambiado.</translation>
    </message>
    <message>
        <source>Saving failed: %1</source>
        <translation>Falló el guardado: %1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Guardado %1</translation>
    </message>
    <message>
        <source>an unsaved scene</source>
        <translation>una escena sin guardar</translation>
    </message>
    <message>
        <source>Recover the last scene?</source>
        <translation>¿Recuperar la última escena?</translation>
    </message>
    <message>
        <source>Phasebox did not close properly last time. An autosave of %1 from %2 is available. Open it?</source>
        <translation>Phasebox no se cerró correctamente la última vez. Hay un guardado automático de %1 del %2. ¿Abrirlo?</translation>
    </message>
    <message>
        <source>Recovered from the autosave: save it to keep it.</source>
        <translation>Recuperado del guardado automático: guárdelo para conservarlo.</translation>
    </message>
    <message>
        <source>Could not recover</source>
        <translation>No se pudo recuperar</translation>
    </message>
</context>
<context>
    <name>phasebox::StatusPresenter</name>
    <message>
        <source>Step doubling at the current state: the error one step of this method makes now. Raise dt and watch it grow.</source>
        <translation>Duplicación del paso en el estado actual: el error que comete ahora un paso de este método. Aumente dt y vea cómo crece.</translation>
    </message>
    <message>
        <source>Not simulated yet by this version: %1</source>
        <translation>Esta versión aún no lo simula: %1</translation>
    </message>
    <message>
        <source>local error ≈ %L1 m</source>
        <translation>error local ≈ %L1 m</translation>
    </message>
    <message>
        <source>t = %L1 s</source>
        <translation>t = %L1 s</translation>
    </message>
    <message>
        <source>real-time factor %L1 (speed %L2×)</source>
        <translation>factor de tiempo real %L1 (velocidad %L2×)</translation>
    </message>
    <message>
        <source>paused (speed %L1×)</source>
        <translation>en pausa (velocidad %L1×)</translation>
    </message>
    <message>
        <source>%L1 ms per step</source>
        <translation>%L1 ms por paso</translation>
    </message>
    <message>
        <source>%L1 ms per step (live run)</source>
        <translation>%L1 ms por paso (ejecución en vivo)</translation>
    </message>
</context>
<context>
    <name>phasebox::TimelinePresenter</name>
    <message>
        <source>One Frame Back</source>
        <translation>Un fotograma atrás</translation>
    </message>
    <message>
        <source>One Frame Forward</source>
        <translation>Un fotograma adelante</translation>
    </message>
    <message>
        <source>Jump to Start</source>
        <translation>Saltar al inicio</translation>
    </message>
</context>
<context>
    <name>phasebox::WorkerMenu</name>
    <message numerus="yes">
        <source>&amp;Every Core (%n threads)</source>
        <translation>
            <numerusform>&amp;Todos los núcleos (%n hilo)</numerusform>
            <numerusform>&amp;Todos los núcleos (%n hilos)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n Thread(s)</source>
        <translation>
            <numerusform>%n hilo</numerusform>
            <numerusform>%n hilos</numerusform>
        </translation>
    </message>
    <message>
        <source>The step shares its work among every core.</source>
        <translation>El paso reparte su trabajo entre todos los núcleos.</translation>
    </message>
    <message numerus="yes">
        <source>The step runs on %n thread(s).</source>
        <translation>
            <numerusform>El paso se ejecuta en %n hilo.</numerusform>
            <numerusform>El paso se ejecuta en %n hilos.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>phasebox::ui::EffectsPanel</name>
    <message>
        <source>Spring forces; runs because the scene holds springs</source>
        <translation>Fuerzas de los muelles; se ejecuta porque la escena contiene muelles</translation>
    </message>
    <message>
        <source>Collision detection and contact impulses; runs because the scene holds things that can touch</source>
        <translation>Detección de colisiones e impulsos de contacto; se ejecuta porque la escena contiene cosas que pueden tocarse</translation>
    </message>
    <message>
        <source>The integrator&apos;s own arithmetic: the step minus its effects and contacts</source>
        <translation>La aritmética propia del integrador: el paso menos sus efectos y contactos</translation>
    </message>
    <message>
        <source>Newtonian gravity</source>
        <translation>Gravitación newtoniana</translation>
    </message>
    <message>
        <source>0 µs/step</source>
        <translation>0 µs/paso</translation>
    </message>
    <message>
        <source>%1/step</source>
        <translation>%1/paso</translation>
    </message>
    <message>
        <source>Effect</source>
        <translation>Efecto</translation>
    </message>
    <message>
        <source>CPU time</source>
        <translation>Tiempo de CPU</translation>
    </message>
    <message>
        <source>CPU time per step, over the last frames</source>
        <translation>Tiempo de CPU por paso, en los últimos fotogramas</translation>
    </message>
    <message>
        <source>&amp;Add effect</source>
        <translation>&amp;Añadir efecto</translation>
    </message>
    <message>
        <source>Add an effect the scene does not simulate yet</source>
        <translation>Añadir un efecto que la escena aún no simula</translation>
    </message>
    <message>
        <source>Time of one whole step: integrator, effects and contacts</source>
        <translation>Tiempo de un paso completo: integrador, efectos y contactos</translation>
    </message>
    <message>
        <source>total: %1 per step</source>
        <translation>total: %1 por paso</translation>
    </message>
    <message>
        <source>Stage of the step</source>
        <translation>Etapa del paso</translation>
    </message>
    <message>
        <source>per step</source>
        <translation>por paso</translation>
    </message>
    <message>
        <source>Where a step&apos;s time goes, stage by stage, in the order they run</source>
        <translation>A dónde va el tiempo de un paso, etapa por etapa, en el orden en que se ejecutan</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Peso</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>Resistencia del aire</translation>
    </message>
    <message>
        <source>Buoyancy</source>
        <translation>Empuje</translation>
    </message>
    <message>
        <source>Wind</source>
        <translation>Viento</translation>
    </message>
    <message>
        <source>Flocking</source>
        <translation>Bandada</translation>
    </message>
    <message>
        <source>Particle collisions</source>
        <translation>Choques entre partículas</translation>
    </message>
    <message>
        <source>Coulomb</source>
        <translation>Coulomb</translation>
    </message>
    <message>
        <source>Springs</source>
        <translation>Muelles</translation>
    </message>
    <message>
        <source>Contacts</source>
        <translation>Contactos</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>Integrador</translation>
    </message>
    <message>
        <source>Integrate</source>
        <translation>Integrar</translation>
    </message>
    <message>
        <source>Collide</source>
        <translation>Detectar colisiones</translation>
    </message>
    <message>
        <source>Solve contacts</source>
        <translation>Resolver contactos</translation>
    </message>
    <message>
        <source>Solve joints</source>
        <translation>Resolver uniones</translation>
    </message>
    <message>
        <source>Ledger</source>
        <translation>Balance de energía</translation>
    </message>
    <message>
        <source>Guard</source>
        <translation>Vigilancia</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::GraphsView</name>
    <message>
        <source>+ Add graph</source>
        <translation>+ Añadir gráfica</translation>
    </message>
    <message>
        <source>Another graph below, up to %1</source>
        <translation>Otra gráfica debajo, hasta %1</translation>
    </message>
    <message>
        <source>Any probe against time or another probe.</source>
        <translation>Cualquier sonda frente al tiempo u otra sonda.</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::InstrumentsPanel</name>
    <message>
        <source>Rea&amp;douts</source>
        <translation>&amp;Lecturas</translation>
    </message>
    <message>
        <source>&amp;Graphs</source>
        <translation>&amp;Gráficas</translation>
    </message>
    <message>
        <source>&amp;Timer</source>
        <translation>&amp;Temporizador</translation>
    </message>
    <message>
        <source>Ta&amp;ble</source>
        <translation>Ta&amp;bla</translation>
    </message>
    <message>
        <source>The selected object&apos;s state, live or as set up</source>
        <translation>El estado del objeto seleccionado, en vivo o en la configuración inicial</translation>
    </message>
    <message>
        <source>Any probe against time or against another</source>
        <translation>Cualquier sonda frente al tiempo o frente a otra</translation>
    </message>
    <message>
        <source>The period of any probe, and a stopwatch</source>
        <translation>El periodo de cualquier sonda, y un cronómetro</translation>
    </message>
    <message>
        <source>The recorded probes, for CSV and spreadsheets</source>
        <translation>Las sondas registradas, para CSV y hojas de cálculo</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::ParametersPanel</name>
    <message>
        <source>implicit</source>
        <translation>implícito</translation>
    </message>
    <message>
        <source>explicit</source>
        <translation>explícito</translation>
    </message>
    <message>
        <source>symplectic</source>
        <translation>simpléctico</translation>
    </message>
    <message>
        <source>not symplectic</source>
        <translation>no simpléctico</translation>
    </message>
    <message>
        <source>order %1 · %2 · %3</source>
        <translation>orden %1 · %2 · %3</translation>
    </message>
    <message>
        <source> · adaptive step</source>
        <translation> · paso adaptativo</translation>
    </message>
    <message>
        <source>%1 (%2)
%3
force evaluations per step: %4
%5</source>
        <translation>%1 (%2)
%3
evaluaciones de fuerza por paso: %4
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
        <translation>Reproducir</translation>
    </message>
    <message>
        <source>Play or pause (Space)</source>
        <translation>Reproducir o pausar (Espacio)</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Paso</translation>
    </message>
    <message>
        <source>Advance one step (S or Right)</source>
        <translation>Avanzar un paso (S o Derecha)</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reiniciar</translation>
    </message>
    <message>
        <source>Back to the scene&apos;s setup (R or Ctrl+R)</source>
        <translation>Volver a la configuración inicial de la escena (R o Ctrl+R)</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>The frame step: the time one step advances (%1 … %2 s).
The arrows halve or double it; 2e-4 style entry is accepted.</source>
        <translation>El paso de tiempo: el tiempo que avanza un paso (%1 … %2 s).
Las flechas lo reducen a la mitad o lo doblan; se admite escribir 2e-4.</translation>
    </message>
    <message>
        <source>1/n</source>
        <translation>1/n</translation>
    </message>
    <message>
        <source>Common frame steps</source>
        <translation>Pasos de tiempo habituales</translation>
    </message>
    <message>
        <source>dt presets</source>
        <translation>dt predefinidos</translation>
    </message>
    <message>
        <source>Each step is split into this many equal sub-steps</source>
        <translation>Cada paso se divide en este número de subpasos iguales</translation>
    </message>
    <message>
        <source>Local error tolerance of the adaptive methods (%1);
the arrows move it by a factor of ten</source>
        <translation>Tolerancia de error local de los métodos adaptativos (%1);
las flechas la cambian en un factor diez</translation>
    </message>
    <message>
        <source>Newton iterations of implicit Euler per step
(1 = the linearised step of Baraff &amp; Witkin)</source>
        <translation>Iteraciones de Newton de Euler implícito por paso
(1 = el paso linealizado de Baraff &amp; Witkin)</translation>
    </message>
    <message>
        <source>Impulses after the step, with friction and restitution: stacks rest</source>
        <translation>Impulsos tras el paso, con rozamiento y restitución: las pilas quedan en reposo</translation>
    </message>
    <message>
        <source>A stiff damped spring in each overlap, F = k·d + c·ḋ: a smooth force the integrator sees, with its potential ½·k·d² in the energy</source>
        <translation>Un muelle rígido amortiguado en cada solapamiento, F = k·d + c·ḋ: una fuerza suave que ve el integrador, con su energía potencial ½·k·d² en la energía</translation>
    </message>
    <message>
        <source>Move the bodies apart and reflect the approaching velocity by e; no forces</source>
        <translation>Separar los cuerpos y reflejar la velocidad de acercamiento por e; sin fuerzas</translation>
    </message>
    <message>
        <source> N/m</source>
        <translation> N/m</translation>
    </message>
    <message>
        <source>none yet</source>
        <translation>ninguna aún</translation>
    </message>
    <message>
        <source>Penalty stiffness k per contact point; the arrows move it by a factor of ten</source>
        <translation>Rigidez de penalización k por punto de contacto; las flechas la cambian en un factor diez</translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>Auto</translation>
    </message>
    <message>
        <source>Automatic stiffness: the lightest body gets ω·h = 0.5 at the step</source>
        <translation>Rigidez automática: el cuerpo más ligero obtiene ω·h = 0,5 con el paso</translation>
    </message>
    <message>
        <source> N·s/m</source>
        <translation> N·s/m</translation>
    </message>
    <message>
        <source>Penalty damping c per contact point</source>
        <translation>Amortiguamiento de penalización c por punto de contacto</translation>
    </message>
    <message>
        <source>Simulated seconds per second of wall time (slow motion below 1×)</source>
        <translation>Segundos simulados por segundo real (cámara lenta por debajo de 1×)</translation>
    </message>
    <message>
        <source>&amp;Integrator:</source>
        <translation>&amp;Integrador:</translation>
    </message>
    <message>
        <source>&amp;dt:</source>
        <translation>&amp;dt:</translation>
    </message>
    <message>
        <source>S&amp;ub-steps:</source>
        <translation>S&amp;ubpasos:</translation>
    </message>
    <message>
        <source>&amp;Tolerance:</source>
        <translation>&amp;Tolerancia:</translation>
    </message>
    <message>
        <source>&amp;Newton iter.:</source>
        <translation>Iter. &amp;Newton:</translation>
    </message>
    <message>
        <source>Newton iterations (implicit Euler only)</source>
        <translation>Iteraciones de Newton (solo Euler implícito)</translation>
    </message>
    <message>
        <source>&amp;Contacts:</source>
        <translation>&amp;Contactos:</translation>
    </message>
    <message>
        <source>Sti&amp;ffness:</source>
        <translation>Ri&amp;gidez:</translation>
    </message>
    <message>
        <source>Dam&amp;ping:</source>
        <translation>A&amp;mortig.:</translation>
    </message>
    <message>
        <source>Sp&amp;eed:</source>
        <translation>&amp;Velocidad:</translation>
    </message>
    <message>
        <source>dt</source>
        <translation>dt</translation>
    </message>
    <message>
        <source>tolerance</source>
        <translation>tolerancia</translation>
    </message>
    <message>
        <source> or </source>
        <translation> o </translation>
    </message>
    <message>
        <source>Impulse</source>
        <translation>Impulsos</translation>
    </message>
    <message>
        <source>Penalty</source>
        <translation>Penalización</translation>
    </message>
    <message>
        <source>Kinematic</source>
        <translation>Cinemático</translation>
    </message>
    <message>
        <source>Let resting &amp;bodies sleep</source>
        <translation>Dormir los cuerpos en re&amp;poso</translation>
    </message>
    <message>
        <source>Bodies that have stayed at rest for half a second are no longer simulated, and are drawn dimmed, until something touches them, drags them or an edit wakes them: large resting piles cost almost nothing</source>
        <translation>Los cuerpos que han estado en reposo medio segundo dejan de simularse y se dibujan atenuados hasta que algo los toca, se arrastran o una edición los despierta: los montones grandes en reposo casi no cuestan nada</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::PlotsPanel</name>
    <message>
        <source>&amp;Pause plots</source>
        <translation>&amp;Pausar gráficas</translation>
    </message>
    <message>
        <source>Freeze the plots while the simulation goes on</source>
        <translation>Congelar las gráficas mientras la simulación sigue</translation>
    </message>
    <message>
        <source>C&amp;lear</source>
        <translation>&amp;Limpiar</translation>
    </message>
    <message>
        <source>Forget the recorded samples; the plots start again from now</source>
        <translation>Olvidar las muestras registradas; las gráficas empiezan de nuevo desde ahora</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>E&amp;xportar</translation>
    </message>
    <message>
        <source>Energy</source>
        <translation>Energía</translation>
    </message>
    <message>
        <source>Phase space</source>
        <translation>Espacio de fases</translation>
    </message>
    <message>
        <source>Local error</source>
        <translation>Error local</translation>
    </message>
    <message>
        <source>%1 as %2…</source>
        <translation>%1 como %2…</translation>
    </message>
    <message>
        <source>Click an object on the canvas to plot its phase space.</source>
        <translation>Haga clic en un objeto del lienzo para representar su espacio de fases.</translation>
    </message>
    <message>
        <source>The coordinate plotted against its velocity</source>
        <translation>La coordenada frente a su velocidad</translation>
    </message>
    <message>
        <source>x against vx</source>
        <translation>x frente a vx</translation>
    </message>
    <message>
        <source>y against vy</source>
        <translation>y frente a vy</translation>
    </message>
    <message>
        <source>angle against ω (boxes)</source>
        <translation>ángulo frente a ω (cajas)</translation>
    </message>
    <message>
        <source>Local error estimate</source>
        <translation>Estimación del error local</translation>
    </message>
    <message>
        <source>P&amp;hase space</source>
        <translation>Espacio de &amp;fases</translation>
    </message>
    <message>
        <source>Local e&amp;rror</source>
        <translation>Error &amp;local</translation>
    </message>
    <message>
        <source>Resume &amp;plots</source>
        <translation>Reanudar &amp;gráficas</translation>
    </message>
    <message>
        <source>Energy plot</source>
        <translation>Gráfica de energía</translation>
    </message>
    <message>
        <source>Phase space plot</source>
        <translation>Diagrama del espacio de fases</translation>
    </message>
    <message>
        <source>Local error plot</source>
        <translation>Gráfica del error local</translation>
    </message>
    <message>
        <source>At t = %1 s: kinetic %2 J, potential %3 J, total %4 J, work_nc %5 J, drift %6 J</source>
        <translation>En t = %1 s: cinética %2 J, potencial %3 J, total %4 J, trabajo_nc %5 J, deriva %6 J</translation>
    </message>
    <message>
        <source>Latest: %1 = %2, %3 = %4</source>
        <translation>Último: %1 = %2, %3 = %4</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::ProbeGraphView</name>
    <message>
        <source>probe to plot</source>
        <translation>sonda que representar</translation>
    </message>
    <message>
        <source>time</source>
        <translation>tiempo</translation>
    </message>
    <message>
        <source>vs</source>
        <translation>frente a</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportar</translation>
    </message>
    <message>
        <source>Save this graph as a picture or its samples as CSV</source>
        <translation>Guardar esta gráfica como imagen o sus muestras como CSV</translation>
    </message>
    <message>
        <source>As %1…</source>
        <translation>Como %1…</translation>
    </message>
    <message>
        <source>Close this graph</source>
        <translation>Cerrar esta gráfica</translation>
    </message>
    <message>
        <source>time [s]</source>
        <translation>t [s]</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::ProbePicker</name>
    <message>
        <source>Pick a probe, or type one (CONTRACT §7: ID.x, system.total, distance(A,B), …) and press Enter</source>
        <translation>Elija una sonda, o escriba una (CONTRACT §7: ID.x, system.total, distance(A,B), …) y pulse Intro</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::ProbeTableView</name>
    <message>
        <source>add a column</source>
        <translation>añadir una columna</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Quitar</translation>
    </message>
    <message>
        <source>Remove a column added here</source>
        <translation>Quitar una columna añadida aquí</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Copiar</translation>
    </message>
    <message>
        <source>Copy the selected rows (or all) as tab-separated text</source>
        <translation>Copiar las filas seleccionadas (o todas) como texto separado por tabuladores</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>Exportar CSV…</translation>
    </message>
    <message>
        <source>No probes recorded yet: graph or time one, or add a column above.</source>
        <translation>Aún no hay sondas registradas: represente o cronometre una, o añada arriba una columna.</translation>
    </message>
    <message numerus="yes">
        <source>%n sample(s)</source>
        <translation>
            <numerusform>%n muestra</numerusform>
            <numerusform>%n muestras</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>phasebox::ui::PropertiesPanel</name>
    <message>
        <source>Select an object on the canvas or in the scene list</source>
        <translation>Seleccione un objeto en el lienzo o en la lista de la escena</translation>
    </message>
    <message>
        <source>%1: %2 … %3 %4 (scientific notation such as 1e6 is accepted)</source>
        <translation>%1: %2 … %3 %4 (se admite notación científica como 1e6)</translation>
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
        <translation>magnitud</translation>
    </message>
    <message>
        <source>value</source>
        <translation>valor</translation>
    </message>
    <message>
        <source>unit</source>
        <translation>unidad</translation>
    </message>
    <message>
        <source>Right-click a row to graph it or time its period</source>
        <translation>Clic derecho en una fila para representarla o medir su periodo</translation>
    </message>
    <message>
        <source>Click an object on the canvas to read its state.</source>
        <translation>Haga clic en un objeto del lienzo para leer su estado.</translation>
    </message>
    <message>
        <source>Graph %1 against time</source>
        <translation>Representar %1 frente al tiempo</translation>
    </message>
    <message>
        <source>Time the period of %1</source>
        <translation>Medir el periodo de %1</translation>
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
        <translation>, fija</translation>
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
        <translation>%1, estático</translation>
    </message>
    <message>
        <source>%1, m %2 kg</source>
        <translation>%1, m %2 kg</translation>
    </message>
    <message>
        <source>through %1, normal %2</source>
        <translation>por %1, normal %2</translation>
    </message>
    <message>
        <source>anchor %1</source>
        <translation>anclaje %1</translation>
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
        <translation>el mundo</translation>
    </message>
    <message>
        <source>%1 of %2 on a %3</source>
        <translation>%1 de %2 (%3)</translation>
    </message>
    <message>
        <source>circle</source>
        <translation>circunferencia</translation>
    </message>
    <message>
        <source>line</source>
        <translation>recta</translation>
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
        <translation>, motor %1 rad/s</translation>
    </message>
    <message numerus="yes">
        <source>%n node(s)</source>
        <translation>
            <numerusform>%n nodo</numerusform>
            <numerusform>%n nodos</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 × %2 nodes, %3 kg, pinned %4</source>
        <translation>%1 × %2 nodos, %3 kg, fijada %4</translation>
    </message>
    <message>
        <source>Filter by id or summary</source>
        <translation>Filtrar por id o resumen</translation>
    </message>
    <message>
        <source>Filter objects</source>
        <translation>Filtrar objetos</translation>
    </message>
    <message>
        <source>Id</source>
        <translation>Id</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>Resumen</translation>
    </message>
    <message>
        <source>… and %1 more</source>
        <translation>… y %1 más</translation>
    </message>
    <message>
        <source>Particles</source>
        <translation>Partículas</translation>
    </message>
    <message>
        <source>Boxes</source>
        <translation>Cajas</translation>
    </message>
    <message>
        <source>Planes</source>
        <translation>Planos</translation>
    </message>
    <message>
        <source>Springs</source>
        <translation>Muelles</translation>
    </message>
    <message>
        <source>Cloths</source>
        <translation>Telas</translation>
    </message>
    <message>
        <source>Joints</source>
        <translation>Uniones</translation>
    </message>
    <message>
        <source>r %1 m</source>
        <translation>r %1 m</translation>
    </message>
    <message numerus="yes">
        <source>%n vertices</source>
        <translation>
            <numerusform>%n vértice</numerusform>
            <numerusform>%n vértices</numerusform>
        </translation>
    </message>
    <message>
        <source>Disks</source>
        <translation>Discos</translation>
    </message>
    <message>
        <source>Polygons</source>
        <translation>Polígonos</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::ScientificSpinBox</name>
    <message>
        <source>a number is needed</source>
        <translation>hace falta un número</translation>
    </message>
    <message>
        <source>“%1” is not a number</source>
        <translation>«%1» no es un número</translation>
    </message>
    <message>
        <source>must be ≥ %1</source>
        <translation>debe ser ≥ %1</translation>
    </message>
    <message>
        <source>must be ≤ %1</source>
        <translation>debe ser ≤ %1</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::TimelineBar</name>
    <message>
        <source>Jump to the start (Home)</source>
        <translation>Saltar al inicio (Inicio)</translation>
    </message>
    <message>
        <source>One frame back (,)</source>
        <translation>Un fotograma atrás (,)</translation>
    </message>
    <message>
        <source>One frame forward (.)</source>
        <translation>Un fotograma adelante (.)</translation>
    </message>
    <message>
        <source>Recorded time</source>
        <translation>Tiempo grabado</translation>
    </message>
    <message>
        <source>Drag to any recorded moment; Play goes on from there</source>
        <translation>Arrastre a cualquier momento grabado; Iniciar sigue desde allí</translation>
    </message>
    <message>
        <source>Memory the recording holds, of its budget</source>
        <translation>Memoria que ocupa la grabación, de su límite</translation>
    </message>
    <message>
        <source>Recording budget</source>
        <translation>Límite de la grabación</translation>
    </message>
    <message>
        <source>The recording&apos;s memory budget: beyond it older frames are thinned</source>
        <translation>El límite de memoria de la grabación: por encima se aclaran los fotogramas antiguos</translation>
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
        <translation>%1 MB de</translation>
    </message>
</context>
<context>
    <name>phasebox::ui::TimerView</name>
    <message>
        <source>Period timer</source>
        <translation>Medidor de periodo</translation>
    </message>
    <message>
        <source>probe to time, e.g. p0.x</source>
        <translation>sonda que cronometrar, p. ej. p0.x</translation>
    </message>
    <message>
        <source>Probe:</source>
        <translation>Sonda:</translation>
    </message>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>crossing t [s]</source>
        <translation>cruce t [s]</translation>
    </message>
    <message>
        <source>interval [s]</source>
        <translation>intervalo [s]</translation>
    </message>
    <message>
        <source>Stopwatch (simulated time)</source>
        <translation>Cronómetro (tiempo simulado)</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Iniciar</translation>
    </message>
    <message>
        <source>Lap</source>
        <translation>Vuelta</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reiniciar</translation>
    </message>
    <message>
        <source>split [s]</source>
        <translation>parcial [s]</translation>
    </message>
    <message>
        <source>lap [s]</source>
        <translation>vuelta [s]</translation>
    </message>
    <message>
        <source>Pick a probe, then press Play: the period is measured from its upward crossings of the middle of its range.</source>
        <translation>Elija una sonda y pulse Reproducir: el periodo se mide a partir de sus cruces ascendentes por el centro de su rango.</translation>
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
        <translation>Parar</translation>
    </message>
</context>
</TS>
