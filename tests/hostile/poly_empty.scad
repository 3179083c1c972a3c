polyhedron();
polyhedron([], []);
polyhedron(points = [], faces = [[]]);
polyhedron(points = [[0, 0, 0]], faces = []);
