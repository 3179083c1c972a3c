offset(r=1) square(5);
offset(delta=-1, chamfer=true) circle(4, $fn=8);
