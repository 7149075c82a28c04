// Spur gear: 23 teeth from one polygon, linear_extrude, a hub and a set-screw hole.
$fn=64;
module tooth_profile(n, m){
  r=n*m/2; ra=r+m; rf=r-1.25*m;
  pts=[for(i=[0:n-1]) each [
      [rf*cos(360*i/n-360/n*0.3), rf*sin(360*i/n-360/n*0.3)],
      [ra*cos(360*i/n-360/n*0.12), ra*sin(360*i/n-360/n*0.12)],
      [ra*cos(360*i/n+360/n*0.12), ra*sin(360*i/n+360/n*0.12)],
      [rf*cos(360*i/n+360/n*0.3), rf*sin(360*i/n+360/n*0.3)]]];
  polygon(pts);
}
difference(){
  union(){ linear_extrude(8) tooth_profile(23,2); cylinder(d=16,h=16); }
  translate([0,0,-1]) cylinder(d=5,h=30);
  translate([0,0,12]) rotate([0,90,0]) cylinder(d=3,h=20);
}
