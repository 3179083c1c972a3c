polyhedron(points=[[0,0,0],[1,0,0],[0,1,0],[0,0,1]], faces=[[0,1,2],[0,3,1],[0,2,3],[1,3,2]]);
hull() { cube(1); translate([2,0,0]) sphere(1); }
