// L bracket: a fillet cut by a cylinder, slots by hull, countersunk holes.
$fn=36;
difference(){
  union(){
    cube([50,30,4]);
    cube([4,30,40]);
    translate([4,0,4]) difference(){ cube([8,30,8]); translate([8,-1,8]) rotate([-90,0,0]) cylinder(r=8,h=32);}
  }
  for(y=[8,22]) { hull(){ translate([20,y,-1]) cylinder(d=4,h=6); translate([40,y,-1]) cylinder(d=4,h=6);} }
  for(z=[15,32]) translate([-1,15,z]) rotate([0,90,0]) { cylinder(d=4,h=6); translate([0,0,2]) cylinder(d1=4,d2=9,h=2.6);}
}
