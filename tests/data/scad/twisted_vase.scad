// Twisted vase: a hollow linear_extrude with twist and scale.
difference(){
  linear_extrude(height=80, twist=120, slices=60, scale=1.4) offset(r=3) square(30,center=true);
  translate([0,0,2]) linear_extrude(height=80, twist=120*78/80, slices=60, scale=1.4*0.95) offset(r=1.5) square(27,center=true);
}
