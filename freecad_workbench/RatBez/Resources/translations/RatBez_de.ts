<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de" sourcelanguage="en">
<context>
    <name>App::Property</name>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>A point on the axis of revolution: typed for AxisMode Custom, else the axis used</source>
        <translation>Ein Punkt auf der Drehachse: bei Achsmodus Custom eingegeben, sonst von der verwendeten Achse übernommen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>A straight edge or a datum line to revolve about (AxisMode Reference). AxisPoint and AxisDirection follow it</source>
        <translation>Eine gerade Kante oder eine Bezugslinie als Drehachse (Achsmodus Reference). Achspunkt und Achsrichtung folgen ihr</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>A straight edge or datum line giving the direction when DirectionMode is Edge</source>
        <translation>Eine gerade Kante oder Bezugslinie, die die Richtung angibt, wenn Richtungsmodus Edge ist</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Align</source>
        <translation>Ausrichten</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Angle</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Angle of revolution in degrees, in (0, 360]; other values are refused. The profile turns counterclockwise about AxisDirection (clockwise with Reversed)</source>
        <translation>Drehwinkel in Grad, in (0, 360]; andere Werte werden abgelehnt. Das Profil dreht sich gegen den Uhrzeigersinn um die Achsrichtung (mit Umgekehrt im Uhrzeigersinn)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Axis Direction</source>
        <translation>Achsrichtung</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Axis Mode</source>
        <translation>Achsmodus</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Axis Point</source>
        <translation>Achspunkt</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Axis Reference</source>
        <translation>Achsreferenz</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Center</source>
        <translation>Mittelpunkt</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Center of the base circle</source>
        <translation>Mittelpunkt des Grundkreises</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Center of the sphere</source>
        <translation>Mittelpunkt der Kugel</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Center of the torus</source>
        <translation>Mittelpunkt des Torus</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Close the curve smoothly back to the first point (a periodic B-spline, smooth at the first point too)</source>
        <translation>Die Kurve glatt zum ersten Punkt zurückführen und schließen (ein periodischer B-Spline, auch am ersten Punkt glatt)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Closed</source>
        <translation>Geschlossen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Closed planar profile to extrude: a sketch, a 2D object, a wire, edges or one face. Closed loops inside the outer one (a face&apos;s holes, inner loops of a sketch) become holes through the solid</source>
        <translation>Geschlossenes ebenes Profil zum Extrudieren: eine Skizze, ein 2D-Objekt, ein Kantenzug, Kanten oder eine Fläche. Geschlossene Konturen innerhalb der äußeren (die Löcher einer Fläche, innere Konturen einer Skizze) werden zu Löchern durch den Körper</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Closed planar profile to sweep: a sketch, a 2D object, a wire, edges or one face (without holes), crossing the path (not in a plane containing the path&apos;s starting tangent)</source>
        <translation>Geschlossenes ebenes Profil, das entlang des Pfads geführt wird: eine Skizze, ein 2D-Objekt, ein Kantenzug, Kanten oder eine Fläche (ohne Löcher); es muss den Pfad kreuzen (darf nicht in einer Ebene liegen, die die Anfangstangente des Pfads enthält)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Closed planar profiles to loft through, in order (at least two): sketches, 2D objects, wires, edges or faces without holes, each entirely in front of the previous one&apos;s plane. The solid is capped by the first and last</source>
        <translation>Geschlossene ebene Profile, durch die der Loft führt, in Reihenfolge (mindestens zwei): Skizzen, 2D-Objekte, Kantenzüge, Kanten oder Flächen ohne Löcher, jedes vollständig vor der Ebene des vorherigen. Der Körper wird vom ersten und letzten abgeschlossen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Control net, row by row: (DegreeU + 1) rows along u of (DegreeV + 1) poles along v. Changing a degree regenerates a flat net over the same extent</source>
        <translation>Kontrollnetz, Zeile für Zeile: (Grad U + 1) Zeilen entlang u mit je (Grad V + 1) Polen entlang v. Das Ändern eines Grades erzeugt ein ebenes Netz über dieselbe Ausdehnung neu</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Control points; the degree is their number minus one</source>
        <translation>Kontrollpunkte; der Grad ist ihre Anzahl minus eins</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Degree</source>
        <translation>Grad</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Degree U</source>
        <translation>Grad U</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Degree V</source>
        <translation>Grad V</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Degree in u: the net has DegreeU + 1 rows of poles</source>
        <translation>Grad in u: das Netz hat Grad U + 1 Zeilen von Polen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Degree in v: every row has DegreeV + 1 poles</source>
        <translation>Grad in v: jede Zeile hat Grad V + 1 Pole</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Degree of the curve (needs at least Degree + 1 points, fewer with end tangents)</source>
        <translation>Grad der Kurve (braucht mindestens Grad + 1 Punkte, mit Endtangenten weniger)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Degree of the surface across the sections (at most the number of sections minus one is used); the surface passes through every section exactly</source>
        <translation>Grad der Fläche quer zu den Querschnitten (verwendet wird höchstens die Anzahl der Querschnitte minus eins); die Fläche verläuft exakt durch jeden Querschnitt</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Direction Mode</source>
        <translation>Richtungsmodus</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Direction Reference</source>
        <translation>Richtungsreferenz</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Direction of the axis of revolution: typed for AxisMode Custom, else the axis used</source>
        <translation>Richtung der Drehachse: bei Achsmodus Custom eingegeben, sonst von der verwendeten Achse übernommen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Direction of the cone&apos;s axis (any non-zero length)</source>
        <translation>Richtung der Kegelachse (beliebige Länge ungleich null)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Direction of the cylinder&apos;s axis (any non-zero length)</source>
        <translation>Richtung der Zylinderachse (beliebige Länge ungleich null)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Direction of the extrusion when DirectionMode is Custom (any non-zero length)</source>
        <translation>Richtung der Extrusion, wenn Richtungsmodus Custom ist (beliebige Länge ungleich null)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Direction of the torus&apos; axis (any non-zero length)</source>
        <translation>Richtung der Torusachse (beliebige Länge ungleich null)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Distance</source>
        <translation>Abstand</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Distance from the axis to the center of the tube (must exceed MinorRadius)</source>
        <translation>Abstand von der Achse zur Mitte des Rohrs (muss größer als Kleiner Radius sein)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>End Tangent</source>
        <translation>Endtangente</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>End Tangents</source>
        <translation>Endtangenten</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Exact Area</source>
        <translation>Exakte Fläche</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Exact Volume</source>
        <translation>Exaktes Volumen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Extrude Distance / 2 to each side of the profile</source>
        <translation>Abstand / 2 zu jeder Seite des Profils extrudieren</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Extrude the other way</source>
        <translation>In die andere Richtung extrudieren</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>First closed planar profile: a sketch, a 2D object, a wire, edges or one face (without holes)</source>
        <translation>Erstes geschlossenes ebenes Profil: eine Skizze, ein 2D-Objekt, ein Kantenzug, Kanten oder eine Fläche (ohne Löcher)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Give the curve&apos;s direction at its ends (StartTangent, EndTangent); open curves only</source>
        <translation>Die Richtung der Kurve an ihren Enden vorgeben (Starttangente, Endtangente); nur für offene Kurven</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Height</source>
        <translation>Höhe</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Height of the cone along its axis</source>
        <translation>Höhe des Kegels entlang seiner Achse</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Height of the cylinder along its axis</source>
        <translation>Höhe des Zylinders entlang seiner Achse</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Join consecutive sections by straight rulings (degree 1 across)</source>
        <translation>Aufeinanderfolgende Querschnitte durch Geraden verbinden (Grad 1 quer)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Kernel</source>
        <translation>Kern</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Largest distance in mm from the true sweep where it is not rational (paths of lines and circular arcs give the exact solid); &gt; 0</source>
        <translation>Größter Abstand in mm vom wahren Sweep, wo dieser nicht rational ist (Pfade aus Geraden und Kreisbögen ergeben den exakten Körper); &gt; 0</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Length of the extrusion along the direction; a negative Distance extrudes the other way</source>
        <translation>Länge der Extrusion entlang der Richtung; ein negativer Abstand extrudiert in die andere Richtung</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Major Radius</source>
        <translation>Großer Radius</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Match the profiles by arc length: each runs the same way, each starts where the rulings to the one before it are shortest (least twist), and every corner or joint of one meets the point of the other at the same fraction of its length; the first profile&apos;s start vertex sets the seam. Off: the profiles&apos; start vertices and parameters are matched as they are</source>
        <translation>Die Profile nach Bogenlänge zuordnen: alle laufen in dieselbe Richtung, jedes beginnt dort, wo die Verbindungsgeraden zum vorherigen am kürzesten sind (geringste Verdrehung), und jede Ecke oder Verbindungsstelle des einen trifft den Punkt des anderen beim selben Bruchteil seiner Länge; der Startpunkt des ersten Profils legt die Naht fest. Aus: Startpunkte und Parameter der Profile werden so zugeordnet, wie sie sind</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Minor Radius</source>
        <translation>Kleiner Radius</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Normal: along the profile&apos;s normal (a sketch&apos;s or face&apos;s normal); Edge: along DirectionReference; Custom: along Direction</source>
        <translation>Normal: entlang der Normalen des Profils (der Normalen einer Skizze oder Fläche); Edge: entlang Richtungsreferenz; Custom: entlang Richtung</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>One weight &gt; 0 per pole for a rational curve; empty for a polynomial curve</source>
        <translation>Ein Gewicht &gt; 0 je Pol für eine rationale Kurve; leer für eine polynomiale Kurve</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>One weight &gt; 0 per pole, in the order of Poles, for a rational surface; empty for a polynomial surface</source>
        <translation>Ein Gewicht &gt; 0 je Pol, in der Reihenfolge der Pole, für eine rationale Fläche; leer für eine polynomiale Fläche</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Parameterization</source>
        <translation>Parametrisierung</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Path</source>
        <translation>Pfad</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Path to sweep along: a sketch, a wire or edges making one tangent-continuous chain. The profile is carried with a rotation-minimising frame; a closed path closes the solid on itself</source>
        <translation>Pfad, entlang dem das Profil geführt wird: eine Skizze, ein Kantenzug oder Kanten, die eine tangentenstetige Kette bilden. Das Profil wird mit einem rotationsminimierenden Dreibein mitgeführt; ein geschlossener Pfad schließt den Körper in sich</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Poles</source>
        <translation>Pole</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Profile</source>
        <translation>Profil</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Profile to revolve: a sketch, a 2D object, a wire, edges or one face (without holes). It must be closed, or open with both ends on the axis, and must not cross the axis</source>
        <translation>Zu rotierendes Profil: eine Skizze, ein 2D-Objekt, ein Kantenzug, Kanten oder eine Fläche (ohne Löcher). Es muss geschlossen sein oder offen mit beiden Enden auf der Achse, und es darf die Achse nicht kreuzen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Profile1</source>
        <translation>Profil1</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Profile2</source>
        <translation>Profil2</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Radius of the base circle (at Center)</source>
        <translation>Radius des Grundkreises (am Mittelpunkt)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Radius of the cylinder</source>
        <translation>Radius des Zylinders</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Radius of the sphere</source>
        <translation>Radius der Kugel</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Radius of the top circle (0 for a pointed cone)</source>
        <translation>Radius des Deckkreises (0 für einen spitzen Kegel)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Radius of the tube</source>
        <translation>Radius des Rohrs</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Radius1</source>
        <translation>Radius1</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Radius2</source>
        <translation>Radius2</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Rat Bez</source>
        <translation>RatBez</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Reversed</source>
        <translation>Umgekehrt</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Revolve Angle / 2 to each side of the profile instead of Angle to one side</source>
        <translation>Um Winkel / 2 zu jeder Seite des Profils rotieren statt um Winkel zu einer Seite</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Revolve the other way (clockwise about AxisDirection)</source>
        <translation>In die andere Richtung rotieren (im Uhrzeigersinn um die Achsrichtung)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Ruled</source>
        <translation>Regelfläche</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Second closed planar profile, entirely in front of the first one&apos;s plane; straight rulings join the two (matched as Align says)</source>
        <translation>Zweites geschlossenes ebenes Profil, vollständig vor der Ebene des ersten; Geraden verbinden die beiden (zugeordnet, wie Ausrichten es festlegt)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Sections</source>
        <translation>Querschnitte</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Start Tangent</source>
        <translation>Starttangente</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Start Vertices</source>
        <translation>Startpunkte</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Surface area of the exact solid computed by the ratbez kernel, in mm^2. FreeCAD&apos;s Shape.Area agrees with it as Shape.Volume does (see ExactVolume)</source>
        <translation>Oberfläche des exakten Körpers, berechnet vom ratbez-Kern, in mm^2. FreeCADs Shape.Area stimmt damit überein wie Shape.Volume (siehe Exaktes Volumen)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Symmetric</source>
        <translation>Symmetrisch</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>The direction the curve arrives at its last point in</source>
        <translation>Die Richtung, in der die Kurve an ihrem letzten Punkt ankommt</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>The direction the curve leaves its first point in</source>
        <translation>Die Richtung, in der die Kurve ihren ersten Punkt verlässt</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>The points to pass through, in order (used when Source is empty)</source>
        <translation>Die Punkte, durch die die Kurve verläuft, in Reihenfolge (verwendet, wenn Quelle leer ist)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>The vertex each profile starts at, in profile order, counted from 1 along its edges (0 or missing: where the profile starts). With Align only the first profile&apos;s matters (the seam); without, every profile&apos;s start is matched to the others&apos;</source>
        <translation>Der Knotenpunkt, an dem jedes Profil beginnt, in der Reihenfolge der Profile, gezählt ab 1 entlang seiner Kanten (0 oder fehlend: wo das Profil beginnt). Mit Ausrichten zählt nur der des ersten Profils (die Naht); ohne wird der Anfang jedes Profils dem der anderen zugeordnet</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Tolerance</source>
        <translation>Toleranz</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Vertical / Horizontal: the profile plane&apos;s vertical or horizontal axis (a sketch&apos;s V or H axis), found again at every recompute, so the axis moves with the sketch; X, Y, Z: a global axis; Reference: AxisReference; Custom: AxisPoint and AxisDirection</source>
        <translation>Vertical / Horizontal: die vertikale oder horizontale Achse der Profilebene (V- oder H-Achse einer Skizze), bei jeder Neuberechnung neu bestimmt, sodass die Achse mit der Skizze mitwandert; X, Y, Z: eine globale Achse; Reference: Achsreferenz; Custom: Achspunkt und Achsrichtung</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Volume of the exact solid computed by the ratbez kernel (certified Gauss quadrature on the exact surfaces), in mm^3, Placement not applied. FreeCAD&apos;s own Shape.Volume, Part &gt; Check geometry and Measure read the faces RatBez hands to FreeCAD (a primitive&apos;s analytic ones, as Part&apos;s; otherwise B-spline faces, one per face, each arc in an exact form OpenCASCADE&apos;s fixed Gauss rule reads) and agree with this to about 1e-9; within 1e-4 where a profile is a B-spline the kernel hands over with its own knots (an extruded sketch spline: 1.5e-5)</source>
        <translation>Volumen des exakten Körpers, berechnet vom ratbez-Kern (zertifizierte Gauß-Quadratur auf den exakten Flächen), in mm^3, ohne Platzierung. FreeCADs eigenes Shape.Volume, Part &gt; Geometrie überprüfen und Messen lesen die Flächen, die RatBez an FreeCAD übergibt (die analytischen eines Grundelements, wie bei Part; sonst B-Spline-Flächen, eine je Fläche, jeder Bogen in einer exakten Form, die die feste Gauß-Regel von OpenCASCADE liest), und stimmen damit auf etwa 1e-9 überein; auf 1e-4, wo ein Profil ein B-Spline ist, den der Kern mit seinen eigenen Knoten übergibt (ein extrudierter Skizzen-Spline: 1.5e-5)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Weights</source>
        <translation>Gewichte</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Where along the curve each point falls: chord (steps as long as the distances, Eq. 9.5), centripetal (their square roots, Eq. 9.6: no overshoot at sharp turns) or uniform (Eq. 9.3)</source>
        <translation>Wo entlang der Kurve jeder Punkt liegt: chord (Schritte so lang wie die Abstände, Gl. 9.5), centripetal (deren Quadratwurzeln, Gl. 9.6: kein Überschwingen an scharfen Knicken) oder uniform (Gl. 9.3)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Where the points come from, in order: selected vertices, or a Draft wire or B-spline (its points), or any object (its vertices). Empty: the Points list</source>
        <translation>Woher die Punkte kommen, in Reihenfolge: ausgewählte Knotenpunkte, ein Draft-Linienzug oder Draft-B-Spline (seine Punkte) oder ein beliebiges Objekt (seine Knotenpunkte). Leer: die Liste Punkte</translation>
    </message>
</context>
<context>
    <name>RatBez</name>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>&apos;{}&apos; has no edges</source>
        <translation>&apos;{}&apos; hat keine Kanten</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>&apos;{}&apos; has no element {} ({})</source>
        <translation>&apos;{}&apos; hat kein Element {} ({})</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>&apos;{}&apos; has no shape</source>
        <translation>&apos;{}&apos; hat keine Form</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>&apos;{}&apos; is a solid or has several faces; select one face or its edges</source>
        <translation>&apos;{}&apos; ist ein Volumenkörper oder hat mehrere Flächen; eine Fläche oder ihre Kanten auswählen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>A dialog is already open in the task panel</source>
        <translation>Im Aufgabenbereich ist bereits ein Dialog geöffnet</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Add point</source>
        <translation>Punkt hinzufügen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Add pole</source>
        <translation>Pol hinzufügen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Add selection</source>
        <translation>Auswahl hinzufügen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Align sections (least twist)</source>
        <translation>Querschnitte ausrichten (geringste Verdrehung)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Angle</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Append a pole beyond the last one (the degree goes up by one)</source>
        <translation>Einen Pol nach dem letzten anhängen (der Grad steigt um eins)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Append the selected sketches, wires, edges or faces as sections</source>
        <translation>Die ausgewählten Skizzen, Kantenzüge, Kanten oder Flächen als Querschnitte anhängen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/dialogs.py"/>
        <source>Automatic</source>
        <translation>Automatisch</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Axis direction</source>
        <translation>Achsrichtung</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Axis point</source>
        <translation>Achspunkt</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Browse...</source>
        <translation>Durchsuchen...</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Bézier curve</source>
        <translation>Bézierkurve</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Bézier surface</source>
        <translation>Bézierfläche</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Center</source>
        <translation>Mittelpunkt</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Checked: RatBez&apos;s reading of &apos;{}&apos; (the solid RatBez exports and hands back), not FreeCAD&apos;s shape itself; Part &gt; Check geometry checks that.
</source>
        <translation>Geprüft: der Körper, als den RatBez &apos;{}&apos; liest (den RatBez exportiert und zurückgibt), nicht FreeCADs Form selbst; die prüft Part &gt; Geometrie überprüfen.
</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Checking &apos;{}&apos; against OpenCASCADE...</source>
        <translation>&apos;{}&apos; wird gegen OpenCASCADE geprüft...</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/dialogs.py"/>
        <source>Chordal tolerance:</source>
        <translation>Sehnentoleranz:</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Closed</source>
        <translation>Geschlossen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Cone</source>
        <translation>Kegel</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create a rational Bézier curve; its poles and weights are edited in a table</source>
        <translation>Eine rationale Bézierkurve erzeugen; ihre Pole und Gewichte werden in einer Tabelle bearbeitet</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create a rational Bézier surface patch; its degrees, poles and weights are edited in a table</source>
        <translation>Ein rationales Bézierflächenstück erzeugen; Grade, Pole und Gewichte werden in einer Tabelle bearbeitet</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create an exact rational (truncated) cone solid</source>
        <translation>Einen exakten rationalen (Stumpf-)Kegel erzeugen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create an exact rational cylinder solid</source>
        <translation>Einen exakten rationalen Zylinder erzeugen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create an exact rational sphere solid</source>
        <translation>Eine exakte rationale Kugel erzeugen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create an exact rational torus solid</source>
        <translation>Einen exakten rationalen Torus erzeugen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_command.py"/>
        <source>Create the B-spline curve through the selected vertices (in the order picked), through a selected Draft wire&apos;s or B-spline&apos;s points, or through points edited in the task panel (The NURBS Book A9.1: chord-length, centripetal or uniform parameters; closed curves; end tangents)</source>
        <translation>Die B-Spline-Kurve durch die ausgewählten Knotenpunkte (in der Reihenfolge der Auswahl), durch die Punkte eines ausgewählten Draft-Linienzugs oder Draft-B-Splines oder durch im Aufgabenbereich bearbeitete Punkte erzeugen (The NURBS Book A9.1: Sehnenlängen-, zentripetale oder gleichmäßige Parameter; geschlossene Kurven; Endtangenten)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create {}</source>
        <translation>{} erzeugen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Custom</source>
        <translation>Benutzerdefiniert</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Custom direction</source>
        <translation>Benutzerdefinierte Richtung</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Cylinder</source>
        <translation>Zylinder</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Default chordal tolerance</source>
        <translation>Standard-Sehnentoleranz</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Degree</source>
        <translation>Grad</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Degree across</source>
        <translation>Grad quer</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>DegreeU</source>
        <translation>Grad U</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>DegreeV</source>
        <translation>Grad V</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Distance</source>
        <translation>Abstand</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Do you want to close this dialog?</source>
        <translation>Möchten Sie diesen Dialog schließen?</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Done</source>
        <translation>Fertig</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Down</source>
        <translation>Nach unten</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <location filename="../../ratbez_wb/view_providers.py"/>
        <source>Edit {}</source>
        <translation>{} bearbeiten</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>End tangent</source>
        <translation>Endtangente</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>End tangents</source>
        <translation>Endtangenten</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Export (OpenSCAD, 3MF)</source>
        <translation>Export (OpenSCAD, 3MF)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/dialogs.py"/>
        <source>Export RatBez solid</source>
        <translation>RatBez-Körper exportieren</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Export folder</source>
        <translation>Exportordner</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/dialogs.py"/>
        <source>Export tolerance</source>
        <translation>Exporttoleranz</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/dialogs.py"/>
        <source>Export {} solids</source>
        <translation>{} Körper exportieren</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Extrude</source>
        <translation>Extrudieren</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Extrude the selected closed planar sketch, wire, edges or face into an exact prism; inner loops become holes. Direction (the profile&apos;s normal to start with), distance, reversed and symmetric are set in the task panel</source>
        <translation>Die ausgewählte geschlossene ebene Skizze, den Kantenzug, die Kanten oder die Fläche zu einem exakten Prisma extrudieren; innere Konturen werden zu Löchern. Richtung (anfangs die Normale des Profils), Abstand, Umkehrung und Symmetrie werden im Aufgabenbereich eingestellt</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>First profile</source>
        <translation>Erstes Profil</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Folder the export dialog starts in; it remembers the last one used</source>
        <translation>Ordner, in dem der Exportdialog beginnt; er merkt sich den zuletzt verwendeten</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>For developers: besides the one-line message, a failed recompute prints the Python traceback (every time), as FreeCAD does for an exception</source>
        <translation>Für Entwickler: Zusätzlich zur einzeiligen Meldung gibt eine fehlgeschlagene Neuberechnung (jedes Mal) den Python-Traceback aus, wie FreeCAD es bei einer Ausnahme tut</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Geometry in FreeCAD</source>
        <translation>Geometrie in FreeCAD</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Height</source>
        <translation>Höhe</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_command.py"/>
        <source>Interpolate points</source>
        <translation>Punkte interpolieren</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Interpolate the selected vertices (in the order picked), or the points of the selected Draft wire or B-spline, or the selected object&apos;s vertices</source>
        <translation>Die ausgewählten Knotenpunkte (in der Reihenfolge der Auswahl), die Punkte des ausgewählten Draft-Linienzugs oder Draft-B-Splines oder die Knotenpunkte des ausgewählten Objekts interpolieren</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Join the two selected closed planar profiles (sketches, wires, edges or faces without holes) by straight rulings into an exact solid capped by them; the profiles can be changed in the task panel</source>
        <translation>Die beiden ausgewählten geschlossenen ebenen Profile (Skizzen, Kantenzüge, Kanten oder Flächen ohne Löcher) durch Geraden zu einem exakten Körper verbinden, der von ihnen abgeschlossen wird; die Profile können im Aufgabenbereich geändert werden</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/dialogs.py"/>
        <source>Largest distance between the mesh and the exact surfaces (Automatic: the kernel&apos;s default, 1e-3 of the solid&apos;s size, or more for a part read from a file whose faces the file gives a larger tolerance)</source>
        <translation>Größter Abstand zwischen dem Netz und den exakten Flächen (Automatisch: der Standardwert des Kerns, 1e-3 der Größe des Körpers, oder mehr für ein aus einer Datei gelesenes Teil, dessen Flächen die Datei mit einer größeren Toleranz angibt)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Location</source>
        <translation>Lage</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Loft</source>
        <translation>Loft</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Loft an exact solid through the selected closed planar profiles, in the order selected, passing through each exactly and capped by the first and last; the sections, their order, the degree across them and ruled lofting are set in the task panel</source>
        <translation>Einen exakten Körper als Loft durch die ausgewählten geschlossenen ebenen Profile erzeugen, in der Reihenfolge der Auswahl, exakt durch jedes hindurch und vom ersten und letzten abgeschlossen; die Querschnitte, ihre Reihenfolge, der Grad quer zu ihnen und ein Loft aus Regelflächen werden im Aufgabenbereich eingestellt</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>MajorRadius</source>
        <translation>Großer Radius</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Make the selected sketch, wire, edges or face the profile</source>
        <translation>Die ausgewählte Skizze, den Kantenzug, die Kanten oder die Fläche zum Profil machen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Make the selected sketch, wire, edges or face this profile</source>
        <translation>Die ausgewählte Skizze, den Kantenzug, die Kanten oder die Fläche zu diesem Profil machen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Messages</source>
        <translation>Meldungen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>MinorRadius</source>
        <translation>Kleiner Radius</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Move the selected section one place earlier</source>
        <translation>Den ausgewählten Querschnitt eine Stelle nach vorn schieben</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Move the selected section one place later</source>
        <translation>Den ausgewählten Querschnitt eine Stelle nach hinten schieben</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>OpenCASCADE Bézier curves have at most {} poles, got {}</source>
        <translation>Bézierkurven in OpenCASCADE haben höchstens {} Pole, hier sind es {}</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>OpenCASCADE could not read the kernel&apos;s B-rep ({})</source>
        <translation>OpenCASCADE konnte die B-Rep des Kerns nicht lesen ({})</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>OpenCASCADE&apos;s geometry departs from the kernel&apos;s by {:.3g}</source>
        <translation>OpenCASCADEs Geometrie weicht um {:.3g} von der des Kerns ab</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Own points</source>
        <translation>Eigene Punkte</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Parameterization</source>
        <translation>Parametrisierung</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Path</source>
        <translation>Pfad</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Picked edge or datum line</source>
        <translation>Gewählte Kante oder Bezugslinie</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Points from</source>
        <translation>Punkte aus</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Press, select the path&apos;s edges or its sketch in the 3D view or the tree, and press Done</source>
        <translation>Drücken, die Kanten des Pfads oder seine Skizze in der 3D-Ansicht oder der Baumansicht auswählen und Fertig drücken</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Primitives, extrusions and revolutions on Part&apos;s analytic surfaces</source>
        <translation>Grundkörper, Extrusionen und Rotationskörper auf den analytischen Flächen von Part</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Print Python tracebacks of failed recomputes</source>
        <translation>Python-Tracebacks fehlgeschlagener Neuberechnungen ausgeben</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Profile</source>
        <translation>Profil</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Profile&apos;s horizontal axis</source>
        <translation>Horizontale Achse des Profils</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Profile&apos;s normal</source>
        <translation>Normale des Profils</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Profile&apos;s vertical axis</source>
        <translation>Vertikale Achse des Profils</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>P{}</source>
        <translation>P{}</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Radius1</source>
        <translation>Radius1</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Radius2</source>
        <translation>Radius2</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>RatBez</source>
        <translation>RatBez</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez Bézier curve</source>
        <translation>RatBez-Bézierkurve</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez Bézier surface</source>
        <translation>RatBez-Bézierfläche</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez cone</source>
        <translation>RatBez-Kegel</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez cylinder</source>
        <translation>RatBez-Zylinder</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez extrude</source>
        <translation>RatBez-Extrusion</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>RatBez interpolate</source>
        <translation>RatBez-Interpolation</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez loft</source>
        <translation>RatBez-Loft</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez revolve</source>
        <translation>RatBez-Rotation</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez ruled solid</source>
        <translation>RatBez-Regelflächenkörper</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez sphere</source>
        <translation>RatBez-Kugel</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez sweep</source>
        <translation>RatBez-Sweep</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez torus</source>
        <translation>RatBez-Torus</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>RatBez: cannot check &apos;{}&apos;: {}
</source>
        <translation>RatBez: &apos;{}&apos; kann nicht geprüft werden: {}
</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez: close the open task panel first
</source>
        <translation>RatBez: zuerst den offenen Aufgabenbereich schließen
</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>RatBez: export of {} failed: {}
</source>
        <translation>RatBez: Export von {} fehlgeschlagen: {}
</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>RatBez: select the solids to export
</source>
        <translation>RatBez: die zu exportierenden Körper auswählen
</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>RatBez: the check of &apos;{}&apos; was stopped
</source>
        <translation>RatBez: die Prüfung von &apos;{}&apos; wurde abgebrochen
</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>RatBez: wrote {} to {}
</source>
        <translation>RatBez: {} nach {} geschrieben
</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Rational (a weight per pole)</source>
        <translation>Rational (ein Gewicht je Pol)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Remove point</source>
        <translation>Punkt entfernen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Remove pole</source>
        <translation>Pol entfernen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Remove the selected pole, or the last one</source>
        <translation>Den ausgewählten Pol entfernen, sonst den letzten</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Remove the selected section</source>
        <translation>Den ausgewählten Querschnitt entfernen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Reversed</source>
        <translation>Umgekehrt</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Revolve</source>
        <translation>Rotieren</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Revolve the selected sketch, wire, edges or face into an exact solid; the axis (the profile&apos;s vertical axis to start with, as a sketch&apos;s V axis), the angle and a symmetric revolution are set in the task panel</source>
        <translation>Die ausgewählte Skizze, den Kantenzug, die Kanten oder die Fläche zu einem exakten Körper rotieren; die Achse (anfangs die vertikale Achse des Profils, wie die V-Achse einer Skizze), der Winkel und eine symmetrische Rotation werden im Aufgabenbereich eingestellt</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Ruled solid</source>
        <translation>Regelflächenkörper</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Ruled surface</source>
        <translation>Regelfläche</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Second profile</source>
        <translation>Zweites Profil</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Sections, in order</source>
        <translation>Querschnitte, in Reihenfolge</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Select a sketch, a wire, edges or one face first</source>
        <translation>Zuerst eine Skizze, einen Kantenzug, Kanten oder eine Fläche auswählen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Select a straight edge or a datum line</source>
        <translation>Eine gerade Kante oder eine Bezugslinie auswählen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Select sketches, wires, edges or faces first</source>
        <translation>Zuerst Skizzen, Kantenzüge, Kanten oder Flächen auswählen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Select two or more vertices, a Draft wire or B-spline, or an object first</source>
        <translation>Zuerst zwei oder mehr Knotenpunkte, einen Draft-Linienzug oder Draft-B-Spline oder ein Objekt auswählen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Select...</source>
        <translation>Auswählen...</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Sphere</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Start tangent</source>
        <translation>Starttangente</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Start vertex of the selected section</source>
        <translation>Startpunkt des ausgewählten Querschnitts</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Start vertex, first</source>
        <translation>Startpunkt, erstes Profil</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Start vertex, second</source>
        <translation>Startpunkt, zweites Profil</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Stop following the selection: interpolate the table of points below</source>
        <translation>Der Auswahl nicht mehr folgen: die Punkttabelle unten interpolieren</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Sweep</source>
        <translation>Sweep</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Sweep the selected closed planar profile along a path (selected second, or picked in the task panel) into a solid: exact along straight lines and circular arcs, within a tolerance elsewhere; the profile keeps its attitude to the path (rotation-minimising frame)</source>
        <translation>Das ausgewählte geschlossene ebene Profil entlang eines Pfads (als zweites ausgewählt oder im Aufgabenbereich gewählt) zu einem Körper führen: exakt entlang Geraden und Kreisbögen, sonst innerhalb einer Toleranz; das Profil behält seine Ausrichtung zum Pfad (rotationsminimierendes Dreibein)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Symmetric to the profile&apos;s plane</source>
        <translation>Symmetrisch zur Profilebene</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>The axis: the profile plane&apos;s vertical or horizontal axis (a sketch&apos;s V or H axis), a global axis through the origin, a straight edge or datum line picked in the 3D view or the tree, or any point and direction</source>
        <translation>Die Achse: die vertikale oder horizontale Achse der Profilebene (V- oder H-Achse einer Skizze), eine globale Achse durch den Ursprung, eine in der 3D-Ansicht oder der Baumansicht gewählte gerade Kante oder Bezugslinie oder ein beliebiger Punkt mit Richtung</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>The same exact shape as Part&apos;s primitive, which OpenCASCADE&apos;s booleans, fillets and BOP check handle best. Off: the kernel&apos;s rational B-spline faces (booleans are slower and the BOP check can flag a B-spline sphere&apos;s poles). Exports always use the kernel&apos;s exact solid</source>
        <translation>Dieselbe exakte Form wie das Grundelement von Part, mit der die booleschen Operationen, Verrundungen und die BOP-Prüfung von OpenCASCADE am besten umgehen. Aus: die rationalen B-Spline-Flächen des Kerns (boolesche Operationen sind langsamer, und die BOP-Prüfung kann die Pole einer B-Spline-Kugel beanstanden). Exporte verwenden immer den exakten Körper des Kerns</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Tolerance (mm)</source>
        <translation>Toleranz (mm)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Torus</source>
        <translation>Torus</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Up</source>
        <translation>Nach oben</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Use selection</source>
        <translation>Auswahl verwenden</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Weight</source>
        <translation>Gewicht</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>X axis</source>
        <translation>X-Achse</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Y axis</source>
        <translation>Y-Achse</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Z axis</source>
        <translation>Z-Achse</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>a loft needs at least 2 sections, got {}</source>
        <translation>ein Loft braucht mindestens 2 Querschnitte, vorhanden sind {}</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>an edge cannot be converted to a NURBS curve</source>
        <translation>eine Kante kann nicht in eine NURBS-Kurve umgewandelt werden</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>an edge gives an inconsistent B-spline ({} knots for {} poles of degree {})</source>
        <translation>eine Kante ergibt einen inkonsistenten B-Spline ({} Knoten für {} Pole vom Grad {})</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>an edge of type {} cannot be converted to a NURBS curve</source>
        <translation>eine Kante vom Typ {} kann nicht in eine NURBS-Kurve umgewandelt werden</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>close the open task panel first</source>
        <translation>zuerst den offenen Aufgabenbereich schließen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>edge {}</source>
        <translation>Kante {}</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>element {} of &apos;{}&apos; is a {}, not an edge or a face</source>
        <translation>Element {} von &apos;{}&apos; ist vom Typ {}, weder Kante noch Fläche</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>internal error: {}</source>
        <translation>interner Fehler: {}</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>is a face; a path is a sketch, a wire or edges</source>
        <translation>ist eine Fläche; ein Pfad ist eine Skizze, ein Kantenzug oder Kanten</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>is not a number: &apos;{}&apos;</source>
        <translation>ist keine Zahl: &apos;{}&apos;</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>is not closed; an extrusion needs a closed profile</source>
        <translation>ist nicht geschlossen; eine Extrusion braucht ein geschlossenes Profil</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>is not planar</source>
        <translation>ist nicht eben</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>its loops make {} separate regions; make one feature per region</source>
        <translation>seine Konturen bilden {} getrennte Bereiche; für jeden Bereich ein eigenes Objekt erstellen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>its own start</source>
        <translation>eigener Anfang</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>its {} closed loops do not make a face ({})</source>
        <translation>seine {} geschlossenen Konturen ergeben keine Fläche ({})</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>its {} edges form {} separate chains; a path is one chain</source>
        <translation>seine {} Kanten bilden {} getrennte Ketten; ein Pfad ist eine einzige Kette</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>its {} edges form {} separate chains; a profile is one chain, or closed loops that nest</source>
        <translation>seine {} Kanten bilden {} getrennte Ketten; ein Profil ist eine einzige Kette oder ineinanderliegende geschlossene Konturen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>must be a length &gt; 0 (mm), got {:g}</source>
        <translation>muss eine Länge &gt; 0 (mm) sein, ist aber {:g}</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>must be a non-zero length (negative: the other way)</source>
        <translation>muss eine Länge ungleich null sein (negativ: in die andere Richtung)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>must be in (0, 360] degrees, got {:g}</source>
        <translation>muss in (0, 360] Grad liegen, ist aber {:g}</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>must have finite coordinates, got {}</source>
        <translation>muss endliche Koordinaten haben, ist aber {}</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>must not be the zero vector</source>
        <translation>darf nicht der Nullvektor sein</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>nothing is linked</source>
        <translation>nichts verknüpft</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>one weight per pole is needed ({}), got {}</source>
        <translation>je Pol wird ein Gewicht benötigt ({}), vorhanden sind {}</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>point {}</source>
        <translation>Punkt {}</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>pole {}</source>
        <translation>Pol {}</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>pole {} of {} has a coordinate beyond {:g}</source>
        <translation>Pol {} von {} hat eine Koordinate jenseits von {:g}</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>press Select..., select its edges or its sketch in the 3D view or the tree, then press Done</source>
        <translation>Auswählen... drücken, seine Kanten oder seine Skizze in der 3D-Ansicht oder der Baumansicht auswählen, dann Fertig drücken</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>section {} ({})</source>
        <translation>Querschnitt {} ({})</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>select a closed planar profile first (and then the path, or pick it in the task panel)</source>
        <translation>zuerst ein geschlossenes ebenes Profil auswählen (und dann den Pfad, oder ihn im Aufgabenbereich wählen)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>select a sketch, a wire, edges or one face first</source>
        <translation>zuerst eine Skizze, einen Kantenzug, Kanten oder eine Fläche auswählen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>select a straight edge or a datum line</source>
        <translation>eine gerade Kante oder eine Bezugslinie auswählen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>select at least two closed planar profiles, in order, first</source>
        <translation>zuerst mindestens zwei geschlossene ebene Profile in Reihenfolge auswählen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>select its edges or its sketch in the 3D view or the tree, then press Done</source>
        <translation>seine Kanten oder seine Skizze in der 3D-Ansicht oder der Baumansicht auswählen, dann Fertig drücken</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>select one face, or edges, not both</source>
        <translation>eine Fläche oder Kanten auswählen, nicht beides</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>select one straight edge or a datum line</source>
        <translation>eine einzige gerade Kante oder eine Bezugslinie auswählen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>select two closed planar profiles first</source>
        <translation>zuerst zwei geschlossene ebene Profile auswählen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>start vertex {} does not exist: the profile has {} vertices (0 for its own start)</source>
        <translation>Startpunkt {} existiert nicht: das Profil hat {} Knotenpunkte (0 für seinen eigenen Anfang)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>the Bézier surface does not give a valid face</source>
        <translation>die Bézierfläche ergibt keine gültige Fläche</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>the edge has no length</source>
        <translation>die Kante hat keine Länge</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>the face has {} hole(s); a face with holes cannot be revolved (select its outer edges)</source>
        <translation>die Fläche hat Löcher ({}); eine Fläche mit Löchern kann nicht rotiert werden (ihre äußeren Kanten auswählen)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>the face has {} hole(s); lofts, ruled solids and sweeps take profiles without holes (select the outer edges)</source>
        <translation>die Fläche hat Löcher ({}); Lofts, Regelflächenkörper und Sweeps nehmen nur Profile ohne Löcher (die äußeren Kanten auswählen)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>the kernel&apos;s B-rep could not be read by OpenCASCADE</source>
        <translation>die B-Rep des Kerns konnte von OpenCASCADE nicht gelesen werden</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>the kernel&apos;s B-rep holds {} solids instead of one</source>
        <translation>die B-Rep des Kerns enthält {} Volumenkörper statt einem</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>the kernel&apos;s B-rep is not a valid OpenCASCADE solid</source>
        <translation>die B-Rep des Kerns ist kein gültiger OpenCASCADE-Volumenkörper</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>the net needs (DegreeU + 1) x (DegreeV + 1) = {} poles, got {}</source>
        <translation>das Netz braucht (Grad U + 1) x (Grad V + 1) = {} Pole, vorhanden sind {}</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>the profile has no edges</source>
        <translation>das Profil hat keine Kanten</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>the solid reaches {:.3g} from the origin, more than OpenCASCADE can hold (1e99)</source>
        <translation>der Körper reicht bis {:.3g} vom Ursprung, mehr als OpenCASCADE fassen kann (1e99)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>the table below</source>
        <translation>der Tabelle unten</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>weight</source>
        <translation>Gewicht</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>{} (Esc stops it)</source>
        <translation>{} (Esc bricht ab)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>{} has no points to interpolate</source>
        <translation>{} hat keine Punkte zum Interpolieren</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>{} of &apos;{}&apos; is not straight</source>
        <translation>{} von &apos;{}&apos; ist nicht gerade</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>{} of {} is not a number: &apos;{}&apos;</source>
        <translation>{} von {} ist keine Zahl: &apos;{}&apos;</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>{}: {} is not a vertex</source>
        <translation>{}: {} ist kein Knotenpunkt</translation>
    </message>
</context>
<context>
    <name>RatBez_BezierCurve</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Bézier curve</source>
        <translation>Bézierkurve</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create a rational Bézier curve; its poles and weights are edited in a table</source>
        <translation>Eine rationale Bézierkurve erzeugen; ihre Pole und Gewichte werden in einer Tabelle bearbeitet</translation>
    </message>
</context>
<context>
    <name>RatBez_BezierSurface</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Bézier surface</source>
        <translation>Bézierfläche</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create a rational Bézier surface patch; its degrees, poles and weights are edited in a table</source>
        <translation>Ein rationales Bézierflächenstück erzeugen; Grade, Pole und Gewichte werden in einer Tabelle bearbeitet</translation>
    </message>
</context>
<context>
    <name>RatBez_CheckOCCT</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Check against OpenCASCADE</source>
        <translation>Mit OpenCASCADE prüfen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Check the selected solids (RatBez, Part, PartDesign, imported) against OpenCASCADE: B-rep validity, deviation of the evaluations, volumes and areas; the report goes to the report view</source>
        <translation>Die ausgewählten Körper (RatBez, Part, PartDesign, importiert) mit OpenCASCADE prüfen: Gültigkeit der B-Rep, Abweichung der Auswertungen, Volumen und Flächeninhalte; der Bericht erscheint im Ausgabefenster</translation>
    </message>
</context>
<context>
    <name>RatBez_Cone</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Cone</source>
        <translation>Kegel</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create an exact rational (truncated) cone solid</source>
        <translation>Einen exakten rationalen (Stumpf-)Kegel erzeugen</translation>
    </message>
</context>
<context>
    <name>RatBez_Cylinder</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create an exact rational cylinder solid</source>
        <translation>Einen exakten rationalen Zylinder erzeugen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Cylinder</source>
        <translation>Zylinder</translation>
    </message>
</context>
<context>
    <name>RatBez_ExportOpenSCAD</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Export to OpenSCAD or 3MF...</source>
        <translation>Nach OpenSCAD oder 3MF exportieren...</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Write the selected solids as one OpenSCAD library (.scad: a module per solid in its colour, and one placing them all) or one 3MF file (an object per solid, named and coloured): watertight meshes within a chosen tolerance of the exact surfaces</source>
        <translation>Die ausgewählten Körper als eine OpenSCAD-Bibliothek (.scad: ein Modul je Körper in seiner Farbe und eines, das sie alle platziert) oder als eine 3MF-Datei (ein Objekt je Körper, benannt und eingefärbt) schreiben: wasserdichte Netze innerhalb einer gewählten Toleranz zu den exakten Flächen</translation>
    </message>
</context>
<context>
    <name>RatBez_Extrude</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Extrude</source>
        <translation>Extrudieren</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Extrude the selected closed planar sketch, wire, edges or face into an exact prism; inner loops become holes. Direction (the profile&apos;s normal to start with), distance, reversed and symmetric are set in the task panel</source>
        <translation>Die ausgewählte geschlossene ebene Skizze, den Kantenzug, die Kanten oder die Fläche zu einem exakten Prisma extrudieren; innere Konturen werden zu Löchern. Richtung (anfangs die Normale des Profils), Abstand, Umkehrung und Symmetrie werden im Aufgabenbereich eingestellt</translation>
    </message>
</context>
<context>
    <name>RatBez_Interpolate</name>
    <message>
        <location filename="../../ratbez_wb/interpolate_command.py"/>
        <source>Create the B-spline curve through the selected vertices (in the order picked), through a selected Draft wire&apos;s or B-spline&apos;s points, or through points edited in the task panel (The NURBS Book A9.1: chord-length, centripetal or uniform parameters; closed curves; end tangents)</source>
        <translation>Die B-Spline-Kurve durch die ausgewählten Knotenpunkte (in der Reihenfolge der Auswahl), durch die Punkte eines ausgewählten Draft-Linienzugs oder Draft-B-Splines oder durch im Aufgabenbereich bearbeitete Punkte erzeugen (The NURBS Book A9.1: Sehnenlängen-, zentripetale oder gleichmäßige Parameter; geschlossene Kurven; Endtangenten)</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_command.py"/>
        <source>Interpolate points</source>
        <translation>Punkte interpolieren</translation>
    </message>
</context>
<context>
    <name>RatBez_Loft</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Loft</source>
        <translation>Loft</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Loft an exact solid through the selected closed planar profiles, in the order selected, passing through each exactly and capped by the first and last; the sections, their order, the degree across them and ruled lofting are set in the task panel</source>
        <translation>Einen exakten Körper als Loft durch die ausgewählten geschlossenen ebenen Profile erzeugen, in der Reihenfolge der Auswahl, exakt durch jedes hindurch und vom ersten und letzten abgeschlossen; die Querschnitte, ihre Reihenfolge, der Grad quer zu ihnen und ein Loft aus Regelflächen werden im Aufgabenbereich eingestellt</translation>
    </message>
</context>
<context>
    <name>RatBez_Revolve</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Revolve</source>
        <translation>Rotieren</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Revolve the selected sketch, wire, edges or face into an exact solid; the axis (the profile&apos;s vertical axis to start with, as a sketch&apos;s V axis), the angle and a symmetric revolution are set in the task panel</source>
        <translation>Die ausgewählte Skizze, den Kantenzug, die Kanten oder die Fläche zu einem exakten Körper rotieren; die Achse (anfangs die vertikale Achse des Profils, wie die V-Achse einer Skizze), der Winkel und eine symmetrische Rotation werden im Aufgabenbereich eingestellt</translation>
    </message>
</context>
<context>
    <name>RatBez_Ruled</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Join the two selected closed planar profiles (sketches, wires, edges or faces without holes) by straight rulings into an exact solid capped by them; the profiles can be changed in the task panel</source>
        <translation>Die beiden ausgewählten geschlossenen ebenen Profile (Skizzen, Kantenzüge, Kanten oder Flächen ohne Löcher) durch Geraden zu einem exakten Körper verbinden, der von ihnen abgeschlossen wird; die Profile können im Aufgabenbereich geändert werden</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Ruled solid</source>
        <translation>Regelflächenkörper</translation>
    </message>
</context>
<context>
    <name>RatBez_Sphere</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create an exact rational sphere solid</source>
        <translation>Eine exakte rationale Kugel erzeugen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Sphere</source>
        <translation>Kugel</translation>
    </message>
</context>
<context>
    <name>RatBez_Sweep</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Sweep</source>
        <translation>Sweep</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Sweep the selected closed planar profile along a path (selected second, or picked in the task panel) into a solid: exact along straight lines and circular arcs, within a tolerance elsewhere; the profile keeps its attitude to the path (rotation-minimising frame)</source>
        <translation>Das ausgewählte geschlossene ebene Profil entlang eines Pfads (als zweites ausgewählt oder im Aufgabenbereich gewählt) zu einem Körper führen: exakt entlang Geraden und Kreisbögen, sonst innerhalb einer Toleranz; das Profil behält seine Ausrichtung zum Pfad (rotationsminimierendes Dreibein)</translation>
    </message>
</context>
<context>
    <name>RatBez_Torus</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create an exact rational torus solid</source>
        <translation>Einen exakten rationalen Torus erzeugen</translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Torus</source>
        <translation>Torus</translation>
    </message>
</context>
<context>
    <name>Workbench</name>
    <message>
        <location filename="../../InitGui.py"/>
        <source>RatBez</source>
        <translation>RatBez</translation>
    </message>
    <message>
        <location filename="../../InitGui.py"/>
        <source>RatBez tools</source>
        <translation>RatBez-Werkzeuge</translation>
    </message>
</context>
</TS>
