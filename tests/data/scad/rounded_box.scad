// Rounded box: minkowski of a box and a sphere, a pocket, four screw holes.
$fn=48;
difference(){
  minkowski(){ cube([60,40,25],center=false); sphere(r=3,$fn=16); }
  translate([2,2,2]) cube([56,36,40]);
  for(x=[6,54]) for(y=[6,34]) translate([x,y,-5]) cylinder(d=3.2,h=50);
}
