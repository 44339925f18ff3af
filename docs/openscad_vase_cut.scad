// The vase ratbez exported (ratbez export examples/vase.json -o vase.scad), bored out and
// with a quarter cut away, in OpenSCAD's own CSG.
use <vase.scad>

difference() {
    vase();
    translate([0, 0, 3]) cylinder(r1 = 3, r2 = 2.5, h = 20, $fn = 96);  // a bore from the top
    cube([20, 20, 30]);                                                 // a quarter cut away
}
