polyhedron(points = [1, 2, 3], faces = "abc");
polyhedron(points = "x", faces = [[0, 1, 2]]);
polyhedron(points = [[0, 0], [1], []], faces = [[0, 1, 2]]);
polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0]], triangles = [[0, 1, 2]]);
polyhedron(points = [[0, 0, 0, 0], [1, 0, 0, 0], [0, 1, 0, 0]], faces = [[0, 1, 2]], convexity = -1);
