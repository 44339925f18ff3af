<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" sourcelanguage="en">
<context>
    <name>App::Property</name>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>A point on the axis of revolution: typed for AxisMode Custom, else the axis used</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>A straight edge or a datum line to revolve about (AxisMode Reference). AxisPoint and AxisDirection follow it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>A straight edge or datum line giving the direction when DirectionMode is Edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Align</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Angle of revolution in degrees, in (0, 360]; other values are refused. The profile turns counterclockwise about AxisDirection (clockwise with Reversed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Axis Direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Axis Mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Axis Point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Axis Reference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Center</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Center of the base circle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Center of the sphere</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Center of the torus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Close the curve smoothly back to the first point (a periodic B-spline, smooth at the first point too)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Closed planar profile to extrude: a sketch, a 2D object, a wire, edges or one face. Closed loops inside the outer one (a face&apos;s holes, inner loops of a sketch) become holes through the solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Closed planar profile to sweep: a sketch, a 2D object, a wire, edges or one face (without holes), crossing the path (not in a plane containing the path&apos;s starting tangent)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Closed planar profiles to loft through, in order (at least two): sketches, 2D objects, wires, edges or faces without holes, each entirely in front of the previous one&apos;s plane. The solid is capped by the first and last</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Control net, row by row: (DegreeU + 1) rows along u of (DegreeV + 1) poles along v. Changing a degree regenerates a flat net over the same extent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Control points; the degree is their number minus one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Degree</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Degree U</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Degree V</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Degree in u: the net has DegreeU + 1 rows of poles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Degree in v: every row has DegreeV + 1 poles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Degree of the curve (needs at least Degree + 1 points, fewer with end tangents)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Degree of the surface across the sections (at most the number of sections minus one is used); the surface passes through every section exactly</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Direction Mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Direction Reference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Direction of the axis of revolution: typed for AxisMode Custom, else the axis used</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Direction of the cone&apos;s axis (any non-zero length)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Direction of the cylinder&apos;s axis (any non-zero length)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Direction of the extrusion when DirectionMode is Custom (any non-zero length)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Direction of the torus&apos; axis (any non-zero length)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Distance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Distance from the axis to the center of the tube (must exceed MinorRadius)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>End Tangent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>End Tangents</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Exact Area</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Exact Volume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Extrude Distance / 2 to each side of the profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Extrude the other way</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>First closed planar profile: a sketch, a 2D object, a wire, edges or one face (without holes)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Give the curve&apos;s direction at its ends (StartTangent, EndTangent); open curves only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Height of the cone along its axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Height of the cylinder along its axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Join consecutive sections by straight rulings (degree 1 across)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Kernel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Largest distance in mm from the true sweep where it is not rational (paths of lines and circular arcs give the exact solid); &gt; 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Length of the extrusion along the direction; a negative Distance extrudes the other way</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Major Radius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Match the profiles by arc length: each runs the same way, each starts where the rulings to the one before it are shortest (least twist), and every corner or joint of one meets the point of the other at the same fraction of its length; the first profile&apos;s start vertex sets the seam. Off: the profiles&apos; start vertices and parameters are matched as they are</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Minor Radius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Normal: along the profile&apos;s normal (a sketch&apos;s or face&apos;s normal); Edge: along DirectionReference; Custom: along Direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>One weight &gt; 0 per pole for a rational curve; empty for a polynomial curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>One weight &gt; 0 per pole, in the order of Poles, for a rational surface; empty for a polynomial surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Parameterization</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Path to sweep along: a sketch, a wire or edges making one tangent-continuous chain. The profile is carried with a rotation-minimising frame; a closed path closes the solid on itself</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Poles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Profile to revolve: a sketch, a 2D object, a wire, edges or one face (without holes). It must be closed, or open with both ends on the axis, and must not cross the axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Profile1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Profile2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Radius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Radius of the base circle (at Center)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Radius of the cylinder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Radius of the sphere</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Radius of the top circle (0 for a pointed cone)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Radius of the tube</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Radius1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Radius2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Rat Bez</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Reversed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Revolve Angle / 2 to each side of the profile instead of Angle to one side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Revolve the other way (clockwise about AxisDirection)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Ruled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Second closed planar profile, entirely in front of the first one&apos;s plane; straight rulings join the two (matched as Align says)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Sections</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Source</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Start Tangent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Start Vertices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Surface area of the exact solid computed by the ratbez kernel, in mm^2. FreeCAD&apos;s Shape.Area agrees with it as Shape.Volume does (see ExactVolume)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Symmetric</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>The direction the curve arrives at its last point in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>The direction the curve leaves its first point in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>The points to pass through, in order (used when Source is empty)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>The vertex each profile starts at, in profile order, counted from 1 along its edges (0 or missing: where the profile starts). With Align only the first profile&apos;s matters (the seam); without, every profile&apos;s start is matched to the others&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Tolerance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Vertical / Horizontal: the profile plane&apos;s vertical or horizontal axis (a sketch&apos;s V or H axis), found again at every recompute, so the axis moves with the sketch; X, Y, Z: a global axis; Reference: AxisReference; Custom: AxisPoint and AxisDirection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Volume of the exact solid computed by the ratbez kernel (certified Gauss quadrature on the exact surfaces), in mm^3, Placement not applied. FreeCAD&apos;s own Shape.Volume, Part &gt; Check geometry and Measure read the faces RatBez hands to FreeCAD (a primitive&apos;s analytic ones, as Part&apos;s; otherwise B-spline faces, one per face, each arc in an exact form OpenCASCADE&apos;s fixed Gauss rule reads) and agree with this to about 1e-9; within 1e-4 where a profile is a B-spline the kernel hands over with its own knots (an extruded sketch spline: 1.5e-5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>Weights</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Where along the curve each point falls: chord (steps as long as the distances, Eq. 9.5), centripetal (their square roots, Eq. 9.6: no overshoot at sharp turns) or uniform (Eq. 9.3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>Where the points come from, in order: selected vertices, or a Draft wire or B-spline (its points), or any object (its vertices). Empty: the Points list</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RatBez</name>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>&apos;{}&apos; has no edges</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>&apos;{}&apos; has no element {} ({})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>&apos;{}&apos; has no shape</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>&apos;{}&apos; is a solid or has several faces; select one face or its edges</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>(none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>A dialog is already open in the task panel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Add point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Add pole</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Add selection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Align sections (least twist)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Append a pole beyond the last one (the degree goes up by one)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Append the selected sketches, wires, edges or faces as sections</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/dialogs.py"/>
        <source>Automatic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Axis direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Axis point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Browse...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Bézier curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Bézier surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Center</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Checked: RatBez&apos;s reading of &apos;{}&apos; (the solid RatBez exports and hands back), not FreeCAD&apos;s shape itself; Part &gt; Check geometry checks that.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Checking &apos;{}&apos; against OpenCASCADE...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/dialogs.py"/>
        <source>Chordal tolerance:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Cone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create a rational Bézier curve; its poles and weights are edited in a table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create a rational Bézier surface patch; its degrees, poles and weights are edited in a table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create an exact rational (truncated) cone solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create an exact rational cylinder solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create an exact rational sphere solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create an exact rational torus solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_command.py"/>
        <source>Create the B-spline curve through the selected vertices (in the order picked), through a selected Draft wire&apos;s or B-spline&apos;s points, or through points edited in the task panel (The NURBS Book A9.1: chord-length, centripetal or uniform parameters; closed curves; end tangents)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Custom</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Custom direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Cylinder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Default chordal tolerance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Degree</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Degree across</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>DegreeU</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>DegreeV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Distance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Do you want to close this dialog?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Down</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <location filename="../../ratbez_wb/view_providers.py"/>
        <source>Edit {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>End tangent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>End tangents</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Export (OpenSCAD, 3MF)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/dialogs.py"/>
        <source>Export RatBez solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Export folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/dialogs.py"/>
        <source>Export tolerance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/dialogs.py"/>
        <source>Export {} solids</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Extrude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Extrude the selected closed planar sketch, wire, edges or face into an exact prism; inner loops become holes. Direction (the profile&apos;s normal to start with), distance, reversed and symmetric are set in the task panel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>First profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Folder the export dialog starts in; it remembers the last one used</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>For developers: besides the one-line message, a failed recompute prints the Python traceback (every time), as FreeCAD does for an exception</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Geometry in FreeCAD</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_command.py"/>
        <source>Interpolate points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Interpolate the selected vertices (in the order picked), or the points of the selected Draft wire or B-spline, or the selected object&apos;s vertices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Join the two selected closed planar profiles (sketches, wires, edges or faces without holes) by straight rulings into an exact solid capped by them; the profiles can be changed in the task panel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/dialogs.py"/>
        <source>Largest distance between the mesh and the exact surfaces (Automatic: the kernel&apos;s default, 1e-3 of the solid&apos;s size, or more for a part read from a file whose faces the file gives a larger tolerance)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Location</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Loft</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Loft an exact solid through the selected closed planar profiles, in the order selected, passing through each exactly and capped by the first and last; the sections, their order, the degree across them and ruled lofting are set in the task panel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>MajorRadius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Make the selected sketch, wire, edges or face the profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Make the selected sketch, wire, edges or face this profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Messages</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>MinorRadius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Move the selected section one place earlier</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Move the selected section one place later</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>OpenCASCADE Bézier curves have at most {} poles, got {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>OpenCASCADE could not read the kernel&apos;s B-rep ({})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>OpenCASCADE&apos;s geometry departs from the kernel&apos;s by {:.3g}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Own points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Parameterization</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Picked edge or datum line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Points from</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Press, select the path&apos;s edges or its sketch in the 3D view or the tree, and press Done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Primitives, extrusions and revolutions on Part&apos;s analytic surfaces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>Print Python tracebacks of failed recomputes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Profile&apos;s horizontal axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Profile&apos;s normal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Profile&apos;s vertical axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>P{}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Radius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Radius1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Radius2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>RatBez</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez Bézier curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez Bézier surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez cone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez cylinder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez extrude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>RatBez interpolate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez loft</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez revolve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez ruled solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez sphere</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez sweep</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez torus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>RatBez: cannot check &apos;{}&apos;: {}
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>RatBez: close the open task panel first
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>RatBez: export of {} failed: {}
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>RatBez: select the solids to export
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>RatBez: the check of &apos;{}&apos; was stopped
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>RatBez: wrote {} to {}
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Rational (a weight per pole)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Remove point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Remove pole</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Remove the selected pole, or the last one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Remove the selected section</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Reversed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Revolve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Revolve the selected sketch, wire, edges or face into an exact solid; the axis (the profile&apos;s vertical axis to start with, as a sketch&apos;s V axis), the angle and a symmetric revolution are set in the task panel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Ruled solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Ruled surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Second profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Sections, in order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Select a sketch, a wire, edges or one face first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Select a straight edge or a datum line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Select sketches, wires, edges or faces first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Select two or more vertices, a Draft wire or B-spline, or an object first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Select...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Sphere</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Start tangent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Start vertex of the selected section</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Start vertex, first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Start vertex, second</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>Stop following the selection: interpolate the table of points below</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Sweep</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Sweep the selected closed planar profile along a path (selected second, or picked in the task panel) into a solid: exact along straight lines and circular arcs, within a tolerance elsewhere; the profile keeps its attitude to the path (rotation-minimising frame)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Symmetric to the profile&apos;s plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>The axis: the profile plane&apos;s vertical or horizontal axis (a sketch&apos;s V or H axis), a global axis through the origin, a straight edge or datum line picked in the 3D view or the tree, or any point and direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/preferences_page.py"/>
        <source>The same exact shape as Part&apos;s primitive, which OpenCASCADE&apos;s booleans, fillets and BOP check handle best. Off: the kernel&apos;s rational B-spline faces (booleans are slower and the BOP check can flag a B-spline sphere&apos;s poles). Exports always use the kernel&apos;s exact solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Tolerance (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Torus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Use selection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Weight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>X axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Y axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>Z axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>a loft needs at least 2 sections, got {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>an edge cannot be converted to a NURBS curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>an edge gives an inconsistent B-spline ({} knots for {} poles of degree {})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>an edge of type {} cannot be converted to a NURBS curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>close the open task panel first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>edge {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>element {} of &apos;{}&apos; is a {}, not an edge or a face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>internal error: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>is a face; a path is a sketch, a wire or edges</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>is not a number: &apos;{}&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>is not closed; an extrusion needs a closed profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>is not planar</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>its loops make {} separate regions; make one feature per region</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>its own start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>its {} closed loops do not make a face ({})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>its {} edges form {} separate chains; a path is one chain</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>its {} edges form {} separate chains; a profile is one chain, or closed loops that nest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>must be a length &gt; 0 (mm), got {:g}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>must be a non-zero length (negative: the other way)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>must be in (0, 360] degrees, got {:g}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>must have finite coordinates, got {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>must not be the zero vector</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>nothing is linked</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>one weight per pole is needed ({}), got {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>point {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>pole {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>pole {} of {} has a coordinate beyond {:g}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>press Select..., select its edges or its sketch in the 3D view or the tree, then press Done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>section {} ({})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>select a closed planar profile first (and then the path, or pick it in the task panel)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>select a sketch, a wire, edges or one face first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>select a straight edge or a datum line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>select at least two closed planar profiles, in order, first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>select its edges or its sketch in the 3D view or the tree, then press Done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>select one face, or edges, not both</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>select one straight edge or a datum line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>select two closed planar profiles first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>start vertex {} does not exist: the profile has {} vertices (0 for its own start)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>the Bézier surface does not give a valid face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>the edge has no length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>the face has {} hole(s); a face with holes cannot be revolved (select its outer edges)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>the face has {} hole(s); lofts, ruled solids and sweeps take profiles without holes (select the outer edges)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>the kernel&apos;s B-rep could not be read by OpenCASCADE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>the kernel&apos;s B-rep holds {} solids instead of one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>the kernel&apos;s B-rep is not a valid OpenCASCADE solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/features.py"/>
        <source>the net needs (DegreeU + 1) x (DegreeV + 1) = {} poles, got {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>the profile has no edges</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>the solid reaches {:.3g} from the origin, more than OpenCASCADE can hold (1e99)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_panel.py"/>
        <source>the table below</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>weight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>{} (Esc stops it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>{} has no points to interpolate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/conversion.py"/>
        <source>{} of &apos;{}&apos; is not straight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/task_panels.py"/>
        <source>{} of {} is not a number: &apos;{}&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/curve_tools.py"/>
        <source>{}: {} is not a vertex</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RatBez_BezierCurve</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Bézier curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create a rational Bézier curve; its poles and weights are edited in a table</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RatBez_BezierSurface</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Bézier surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create a rational Bézier surface patch; its degrees, poles and weights are edited in a table</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RatBez_CheckOCCT</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Check against OpenCASCADE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Check the selected solids (RatBez, Part, PartDesign, imported) against OpenCASCADE: B-rep validity, deviation of the evaluations, volumes and areas; the report goes to the report view</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RatBez_Cone</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Cone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create an exact rational (truncated) cone solid</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RatBez_Cylinder</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create an exact rational cylinder solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Cylinder</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RatBez_ExportOpenSCAD</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Export to OpenSCAD or 3MF...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Write the selected solids as one OpenSCAD library (.scad: a module per solid in its colour, and one placing them all) or one 3MF file (an object per solid, named and coloured): watertight meshes within a chosen tolerance of the exact surfaces</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RatBez_Extrude</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Extrude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Extrude the selected closed planar sketch, wire, edges or face into an exact prism; inner loops become holes. Direction (the profile&apos;s normal to start with), distance, reversed and symmetric are set in the task panel</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RatBez_Interpolate</name>
    <message>
        <location filename="../../ratbez_wb/interpolate_command.py"/>
        <source>Create the B-spline curve through the selected vertices (in the order picked), through a selected Draft wire&apos;s or B-spline&apos;s points, or through points edited in the task panel (The NURBS Book A9.1: chord-length, centripetal or uniform parameters; closed curves; end tangents)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/interpolate_command.py"/>
        <source>Interpolate points</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RatBez_Loft</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Loft</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Loft an exact solid through the selected closed planar profiles, in the order selected, passing through each exactly and capped by the first and last; the sections, their order, the degree across them and ruled lofting are set in the task panel</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RatBez_Revolve</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Revolve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Revolve the selected sketch, wire, edges or face into an exact solid; the axis (the profile&apos;s vertical axis to start with, as a sketch&apos;s V axis), the angle and a symmetric revolution are set in the task panel</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RatBez_Ruled</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Join the two selected closed planar profiles (sketches, wires, edges or faces without holes) by straight rulings into an exact solid capped by them; the profiles can be changed in the task panel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Ruled solid</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RatBez_Sphere</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create an exact rational sphere solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Sphere</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RatBez_Sweep</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Sweep</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Sweep the selected closed planar profile along a path (selected second, or picked in the task panel) into a solid: exact along straight lines and circular arcs, within a tolerance elsewhere; the profile keeps its attitude to the path (rotation-minimising frame)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RatBez_Torus</name>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Create an exact rational torus solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ratbez_wb/commands.py"/>
        <source>Torus</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Workbench</name>
    <message>
        <location filename="../../InitGui.py"/>
        <source>RatBez</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../InitGui.py"/>
        <source>RatBez tools</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
