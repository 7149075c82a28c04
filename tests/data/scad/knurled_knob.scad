// Knurled knob: rotate_extrude profile, 24 grooves, a D-shaped shaft hole.
$fn=72;
difference(){
  union(){
    rotate_extrude() polygon([[0,0],[15,0],[16,2],[16,12],[12,16],[5,18],[0,18]]);
  }
  for(a=[0:15:359]) rotate([0,0,a]) translate([16.5,0,-1]) cylinder(d=2,h=14,$fn=12);
  difference(){ translate([0,0,-1]) cylinder(d=6.2,h=12); translate([1.8,-5,-2]) cube([5,10,20]); }
}
