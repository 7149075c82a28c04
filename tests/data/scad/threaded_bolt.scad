// Bolt: a thread by linear_extrude twisting a shifted circle 30 degrees per slice, a hex head.
$fn=32;
union(){
  linear_extrude(height=30, twist=-360*30/3, slices=120) translate([0.6,0]) circle(d=10);
  translate([0,0,-6]) cylinder(d=18,h=6,$fn=6);
}
