// Name tag: a hull plate with embossed text and a hole.
$fn=40;
difference(){
  union(){
    hull(){ translate([0,0,0]) cylinder(r=5,h=3); translate([70,0,0]) cylinder(r=5,h=3); translate([0,20,0]) cylinder(r=5,h=3); translate([70,20,0]) cylinder(r=5,h=3);}
    translate([8,5,2.9]) linear_extrude(1.5) text("Thingi 10K", size=8);
  }
  translate([-1,10,-1]) cylinder(d=4,h=10);
}
