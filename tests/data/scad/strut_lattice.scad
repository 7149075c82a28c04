// Strut lattice: 75 crossing cylinders in one union.
s=10; n=4; d=1.6;
$fn=12;
union(){
  for(i=[0:n]) for(j=[0:n]) {
    translate([i*s,j*s,0]) cylinder(d=d,h=n*s);
    translate([i*s,0,j*s]) rotate([-90,0,0]) cylinder(d=d,h=n*s);
    translate([0,i*s,j*s]) rotate([0,90,0]) cylinder(d=d,h=n*s);
  }
}
